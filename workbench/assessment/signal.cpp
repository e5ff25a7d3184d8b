#include "workbench/assessment/signal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "workbench/core/error.hpp"

namespace rb::assessment {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Second-order Butterworth prototype of quality factor q at w (rad/s).
AnalogSection lowPassPrototype(double w, double q) {
  return {w * w, 0.0, 0.0, w * w, w / q, 1.0};
}
AnalogSection highPassPrototype(double w, double q) {
  return {0.0, 0.0, 1.0, w * w, w / q, 1.0};
}

void checkCorner(double f_hz, double dt) {
  RB_CHECK(dt > 0.0 && f_hz > 0.0 && f_hz < 0.5 / dt,
           "filter corner " + std::to_string(f_hz) + " Hz must lie in (0, " +
               std::to_string(0.5 / dt) + ") Hz, the Nyquist band of dt = " + std::to_string(dt));
}

// Running window over track length: the samples with p - window < s_j <= p, both ends moved
// forward only, so the whole series costs O(n). square selects the mean of x^2.
DistanceSeries slidingWindow(std::span<const double> x, std::span<const double> s, double window,
                             double step, bool square) {
  RB_CHECK(x.size() == s.size(), "signal and distance samples differ in number");
  RB_CHECK(window > 0.0 && step > 0.0, "sliding window and step must be positive");
  DistanceSeries out;
  if (s.empty()) return out;
  const double tol = 1e-9 * window;  // distances built as i * ds carry rounding
  const std::size_t n = s.size();
  std::size_t lo = 0;
  std::size_t hi = 0;  // samples [lo, hi) are in the window
  double sum = 0.0;
  const auto term = [square](double v) { return square ? v * v : v; };
  for (std::size_t k = 0;; ++k) {
    const double p = s[0] + window + static_cast<double>(k) * step;
    if (p > s[n - 1] + tol) break;
    for (; hi < n && s[hi] <= p + tol; ++hi) sum += term(x[hi]);
    for (; lo < hi && s[lo] <= p - window + tol; ++lo) sum -= term(x[lo]);
    RB_CHECK(hi > lo, "a sliding window of " + std::to_string(window) +
                          " m holds no sample: the sample spacing exceeds the window");
    const double mean = sum / static_cast<double>(hi - lo);
    out.position.push_back(p);
    out.value.push_back(square ? std::sqrt(std::max(mean, 0.0)) : mean);
  }
  return out;
}

std::size_t samplesPerBlock(double dt, double block_s) {
  RB_CHECK(dt > 0.0 && block_s >= dt, "a block must hold at least one sample interval");
  return static_cast<std::size_t>(std::lround(block_s / dt));
}

}  // namespace

std::complex<double> analogResponse(const AnalogSection& h, double f_hz) {
  const std::complex<double> s(0.0, kTwoPi * f_hz);
  return (h.B0 + s * (h.B1 + s * h.B2)) / (h.A0 + s * (h.A1 + s * h.A2));
}

Section bilinear(const AnalogSection& h, double dt, double prewarp_hz) {
  double k = 2.0 / dt;
  if (prewarp_hz > 0.0) {
    checkCorner(prewarp_hz, dt);
    const double wp = kTwoPi * prewarp_hz;
    k = wp / std::tan(0.5 * wp * dt);
  }
  const double k2 = k * k;
  // (B0 + B1 s + B2 s^2) (1 + z^-1)^2 with s = k (1 - z^-1)/(1 + z^-1), likewise the denominator.
  const double n0 = h.B0 + h.B1 * k + h.B2 * k2;
  const double n1 = 2.0 * (h.B0 - h.B2 * k2);
  const double n2 = h.B0 - h.B1 * k + h.B2 * k2;
  const double d0 = h.A0 + h.A1 * k + h.A2 * k2;
  const double d1 = 2.0 * (h.A0 - h.A2 * k2);
  const double d2 = h.A0 - h.A1 * k + h.A2 * k2;
  return {n0 / d0, n1 / d0, n2 / d0, d1 / d0, d2 / d0};
}

void Cascade::push(const Section& s) {
  RB_CHECK(size < kMaxSections, "a filter cascade holds at most four sections");
  sections[size++] = s;
}

std::complex<double> digitalResponse(const Cascade& c, double f_hz, double dt) {
  const std::complex<double> zi = std::polar(1.0, -kTwoPi * f_hz * dt);  // z^-1
  std::complex<double> h(1.0, 0.0);
  for (std::size_t i = 0; i < c.size; ++i) {
    const Section& q = c.sections[i];
    h *= (q.b0 + zi * (q.b1 + zi * q.b2)) / (1.0 + zi * (q.a1 + zi * q.a2));
  }
  return h;
}

void applyCascade(const Cascade& c, std::span<const double> x, std::span<double> y) {
  RB_CHECK(x.size() == y.size(), "filter input and output differ in length");
  if (x.empty()) return;
  if (y.data() != x.data()) std::copy(x.begin(), x.end(), y.begin());
  double level = x[0];  // the constant input each section starts from
  for (std::size_t i = 0; i < c.size; ++i) {
    const Section& q = c.sections[i];
    const double gain = (q.b0 + q.b1 + q.b2) / (1.0 + q.a1 + q.a2);
    const double out = gain * level;
    // Transposed direct form II in the steady state of the constant input 'level'.
    double z2 = q.b2 * level - q.a2 * out;
    double z1 = q.b1 * level - q.a1 * out + z2;
    for (double& v : y) {
      const double in = v;
      v = q.b0 * in + z1;
      z1 = q.b1 * in - q.a1 * v + z2;
      z2 = q.b2 * in - q.a2 * v;
    }
    level = out;
  }
}

Cascade butterworthLowPass4(double fc_hz, double dt) {
  checkCorner(fc_hz, dt);
  // 4th-order Butterworth: pole pairs at 22.5 and 67.5 degrees from the negative real axis,
  // Q = 1 / (2 cos(theta)).
  const double w = kTwoPi * fc_hz;
  Cascade c;
  for (const double theta : {std::numbers::pi / 8.0, 3.0 * std::numbers::pi / 8.0}) {
    c.push(bilinear(lowPassPrototype(w, 0.5 / std::cos(theta)), dt, fc_hz));
  }
  return c;
}

Cascade butterworthHighPass2(double fc_hz, double dt) {
  checkCorner(fc_hz, dt);
  Cascade c;
  c.push(bilinear(highPassPrototype(kTwoPi * fc_hz, std::numbers::sqrt2 / 2.0), dt, fc_hz));
  return c;
}

Cascade butterworthBandPass(double f_low_hz, double f_high_hz, double dt) {
  RB_CHECK(f_low_hz < f_high_hz, "band-pass needs f_low < f_high");
  checkCorner(f_low_hz, dt);
  checkCorner(f_high_hz, dt);
  const double q = std::numbers::sqrt2 / 2.0;
  Cascade c;
  c.push(bilinear(highPassPrototype(kTwoPi * f_low_hz, q), dt, f_low_hz));
  c.push(bilinear(lowPassPrototype(kTwoPi * f_high_hz, q), dt, f_high_hz));
  return c;
}

Cascade resonatorBandPass(double f_centre_hz, double bandwidth_hz, double dt) {
  checkCorner(f_centre_hz, dt);
  RB_CHECK(bandwidth_hz > 0.0, "band-pass bandwidth must be positive");
  const double w0 = kTwoPi * f_centre_hz;
  const double b = kTwoPi * bandwidth_hz;  // w0 / Q
  Cascade c;
  c.push(bilinear({0.0, b, 0.0, w0 * w0, b, 1.0}, dt, f_centre_hz));
  return c;
}

DistanceSeries slidingMean(std::span<const double> x, std::span<const double> s, double window,
                           double step) {
  return slidingWindow(x, s, window, step, false);
}

DistanceSeries slidingRms(std::span<const double> x, std::span<const double> s, double window,
                          double step) {
  return slidingWindow(x, s, window, step, true);
}

std::vector<double> blockRms(std::span<const double> x, double dt, double block_s) {
  const std::size_t m = samplesPerBlock(dt, block_s);
  std::vector<double> out;
  out.reserve(x.size() / m);
  for (std::size_t start = 0; start + m <= x.size(); start += m) {
    double sum = 0.0;
    for (std::size_t i = start; i < start + m; ++i) sum += x[i] * x[i];
    out.push_back(std::sqrt(sum / static_cast<double>(m)));
  }
  return out;
}

std::vector<double> trailingRms(std::span<const double> x, double dt, double block_s) {
  const std::size_t m = samplesPerBlock(dt, block_s);
  std::vector<double> out(x.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sum += x[i] * x[i];
    if (i >= m) sum -= x[i - m] * x[i - m];
    const auto count = static_cast<double>(std::min(i + 1, m));
    out[i] = std::sqrt(std::max(sum, 0.0) / count);
  }
  return out;
}

double percentile(std::span<const double> x, double p) {
  RB_CHECK(!x.empty(), "percentile of an empty series");
  RB_CHECK(p >= 0.0 && p <= 100.0, "percentile must lie in [0, 100]");
  std::vector<double> v(x.begin(), x.end());
  const double h = static_cast<double>(v.size() - 1) * p / 100.0;
  const auto i = static_cast<std::size_t>(std::floor(h));
  // Only the order statistics x_(i) and x_(i+1) enter: a selection (O(n)) gives the very values
  // a full sort (O(n log n)) would put there.
  const auto at = v.begin() + static_cast<std::ptrdiff_t>(i);
  std::nth_element(v.begin(), at, v.end());
  if (i + 1 >= v.size()) return *at;
  const double next = *std::min_element(at + 1, v.end());
  return *at + (h - static_cast<double>(i)) * (next - *at);
}

double maxAbs(std::span<const double> x) {
  RB_CHECK(!x.empty(), "maximum of an empty series");
  double m = 0.0;
  for (const double v : x) m = std::max(m, std::fabs(v));
  return m;
}

}  // namespace rb::assessment
