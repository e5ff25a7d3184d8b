#include "workbench/assessment/en12299.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "workbench/core/error.hpp"

namespace rb::assessment::en12299 {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kButterworthQ = std::numbers::sqrt2 / 2.0;
constexpr double kBandLowPassRatio = 0.4;  // H_l kept while f2 < 0.4 fs

// The continuous sections of W (see the header); the step is absent when f5 is infinite.
struct Sections {
  AnalogSection high, low, transition, step;
  bool has_step = false;
};

Sections sections(const WeightingParameters& p) {
  const double w1 = kTwoPi * p.f1;
  const double w2 = kTwoPi * p.f2;
  const double w3 = kTwoPi * p.f3;
  const double w4 = kTwoPi * p.f4;
  Sections s;
  s.high = {0.0, 0.0, 1.0, w1 * w1, w1 / p.Q1, 1.0};
  s.low = {w2 * w2, 0.0, 0.0, w2 * w2, w2 / p.Q2, 1.0};
  s.transition = {1.0, 1.0 / w3, 0.0, 1.0, 1.0 / (p.Q4 * w4), 1.0 / (w4 * w4)};
  s.has_step = std::isfinite(p.f5);
  if (s.has_step) {
    const double w5 = kTwoPi * p.f5;
    const double w6 = kTwoPi * p.f6;
    s.step = {p.K, p.K / (p.Q5 * w5), p.K / (w5 * w5), 1.0, 1.0 / (p.Q6 * w6), 1.0 / (w6 * w6)};
  } else {
    s.step = {p.K, 0.0, 0.0, 1.0, 0.0, 0.0};  // the gain alone
  }
  return s;
}

}  // namespace

WeightingParameters parameters(Weighting w) {
  const double q = kButterworthQ;
  switch (w) {
    case Weighting::Wb:
      return {0.4, q, 100.0, q, 16.0, 16.0, 0.63, 2.5, 0.8, 4.0, 0.8, 0.4};
    case Weighting::Wc:
      return {0.4, q, 100.0, q, 8.0, 8.0, 0.63, kInf, 1.0, kInf, 1.0, 1.0};
    case Weighting::Wd:
      break;
  }
  return {0.4, q, 100.0, q, 2.0, 2.0, 0.63, kInf, 1.0, kInf, 1.0, 1.0};
}

std::complex<double> response(Weighting w, double f_hz) {
  const Sections s = sections(parameters(w));
  return analogResponse(s.high, f_hz) * analogResponse(s.low, f_hz) *
         analogResponse(s.transition, f_hz) * analogResponse(s.step, f_hz);
}

Cascade weightingFilter(Weighting w, double dt) {
  const WeightingParameters p = parameters(w);
  const Sections s = sections(p);
  Cascade c;
  c.push(bilinear(s.high, dt, p.f1));
  if (p.f2 < kBandLowPassRatio / dt) c.push(bilinear(s.low, dt, p.f2));
  c.push(bilinear(s.transition, dt, p.f4));
  if (s.has_step) {
    c.push(bilinear(s.step, dt, std::sqrt(p.f5 * p.f6)));
  } else {
    c.sections[c.size - 1].b0 *= p.K;  // a pure gain scales the last numerator
    c.sections[c.size - 1].b1 *= p.K;
    c.sections[c.size - 1].b2 *= p.K;
  }
  return c;
}

std::vector<double> weighted(std::span<const double> a, Weighting w, double dt) {
  std::vector<double> y(a.size());
  applyCascade(weightingFilter(w, dt), a, y);
  return y;
}

const char* comfortClass(double n) {
  if (n < 1.0) return "very comfortable";
  if (n < 2.0) return "comfortable";
  if (n < 4.0) return "medium";
  if (n < 5.0) return "uncomfortable";
  return "very uncomfortable";
}

MeanComfort meanComfort(std::span<const double> ax, std::span<const double> ay,
                        std::span<const double> az, double dt, double limit) {
  RB_CHECK(ax.size() == ay.size() && ay.size() == az.size(),
           "the three accelerations differ in number of samples");
  const auto p95 = [dt](std::span<const double> a, Weighting w) {
    const std::vector<double> rms = blockRms(weighted(a, w, dt), dt, kBlockDuration);
    RB_CHECK(!rms.empty(), "the mean comfort needs at least one 5 s block");
    return percentile(rms, kComfortPercentile);
  };
  MeanComfort m;
  m.a_x95 = p95(ax, Weighting::Wd);
  m.a_y95 = p95(ay, Weighting::Wd);
  m.a_z95 = p95(az, Weighting::Wb);
  m.blocks = ax.size() / static_cast<std::size_t>(std::lround(kBlockDuration / dt));
  const double n_mv = 6.0 * std::sqrt(m.a_x95 * m.a_x95 + m.a_y95 * m.a_y95 + m.a_z95 * m.a_z95);
  m.check = check(n_mv, limit);
  return m;
}

std::vector<double> continuousComfort(std::span<const double> a, Axis axis, double dt) {
  const Weighting w = axis == Axis::Z ? Weighting::Wb : Weighting::Wd;
  std::vector<double> n = trailingRms(weighted(a, w, dt), dt, kBlockDuration);
  for (double& v : n) v *= 4.0;
  return n;
}

}  // namespace rb::assessment::en12299
