#include "workbench/profiles/conicity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "workbench/core/error.hpp"

namespace rb::profiles {

RollingRadiusDifference::RollingRadiusDifference(std::vector<double> y, std::vector<double> dr)
    : y_(std::move(y)), dr_(std::move(dr)) {
  setUp();
}

RollingRadiusDifference::RollingRadiusDifference(std::vector<double> y, std::vector<double> dr,
                                                 const std::vector<DrJump>& jumps) {
  const std::size_t n = y.size();
  RB_CHECK(n >= 3 && dr.size() == n, "a rolling radius difference needs >= 3 samples");
  for (std::size_t i = 1; i < n; ++i) {
    RB_CHECK(y[i] > y[i - 1], "rolling radius difference: y must be strictly increasing");
  }
  std::vector<DrJump> js = jumps;
  std::sort(js.begin(), js.end(), [](const DrJump& a, const DrJump& b) { return a.y < b.y; });
  std::size_t j = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (; j < js.size() && js[j].y <= y[i]; ++j) {
      y_.insert(y_.end(), {js[j].y, js[j].y});
      dr_.insert(dr_.end(), {js[j].left, js[j].right});
    }
    if (y_.empty() || y[i] > y_.back()) {  // a jump at a sample replaces the sample
      y_.push_back(y[i]);
      dr_.push_back(dr[i]);
    }
  }
  RB_CHECK(j == js.size(), "rolling radius difference: a jump beyond the data");
  setUp();
}

void RollingRadiusDifference::setUp() {
  const std::size_t n = y_.size();
  RB_CHECK(n >= 3 && dr_.size() == n, "a rolling radius difference needs >= 3 samples");
  for (std::size_t i = 1; i < n; ++i) {
    const bool jump = y_[i] == y_[i - 1];
    RB_CHECK(y_[i] > y_[i - 1] || (jump && i >= 2 && i + 1 < n && y_[i - 2] < y_[i]),
             "rolling radius difference: y must be increasing, a jump (y given twice) inside the "
             "data");
    if (jump) jumps_.push_back({y_[i], dr_[i - 1], dr_[i]});
  }
  cum_.assign(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) {
    cum_[i] = cum_[i - 1] + 0.5 * (dr_[i] + dr_[i - 1]) * (y_[i] - y_[i - 1]);
  }
  // Centre: global minimum of the (piecewise quadratic) integral, the middle of a flat minimum.
  const double best = integralMinimum();
  y0_ = middleOfFlatMinimum(best);
  RB_CHECK(y0_ > y_.front() && y0_ < y_.back(),
           "rolling radius difference: no restoring zero crossing inside the data (dr must "
           "increase through zero)");
  i0_ = best;
}

double RollingRadiusDifference::integralMinimum() {
  // On a segment with dr crossing from - to +, the minimum is at the zero of the linear dr.
  const std::size_t n = y_.size();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    if (cum_[i] < best) {
      best = cum_[i];
      y0_ = y_[i];
    }
    if (i + 1 < n && dr_[i] < 0.0 && dr_[i + 1] > 0.0) {
      const double t = -dr_[i] / (dr_[i + 1] - dr_[i]);
      const double yz = y_[i] + t * (y_[i + 1] - y_[i]);
      const double c = cum_[i] + 0.5 * dr_[i] * (yz - y_[i]);
      if (c < best) {
        best = c;
        y0_ = yz;
      }
    }
  }
  return best;
}

double RollingRadiusDifference::middleOfFlatMinimum(double best) const {
  // A flat minimum (dr = 0 over a range, e.g. a dead band between contact jumps): the middle of
  // the flat part does not change tan(gamma_e) but gives the natural centre.
  const std::size_t n = y_.size();
  double scale = 0.0;
  for (const double c : cum_) scale = std::max(scale, std::abs(c - best));
  const double tol = 1e-12 * scale;
  double lo = y0_, hi = y0_;
  for (std::size_t i = 0; i < n; ++i) {
    if (y_[i] < y0_ && cum_[i] <= best + tol) {
      bool flat = true;  // every sample between y_i and y0 at the minimum too
      for (std::size_t j = i; j < n && y_[j] < y0_; ++j) flat = flat && cum_[j] <= best + tol;
      if (flat) lo = std::min(lo, y_[i]);
    }
  }
  for (std::size_t i = n; i-- > 0;) {
    if (y_[i] > y0_ && cum_[i] <= best + tol) {
      bool flat = true;
      for (std::size_t j = i + 1; j-- > 0 && y_[j] > y0_;) flat = flat && cum_[j] <= best + tol;
      if (flat) hi = std::max(hi, y_[i]);
    }
  }
  return 0.5 * (lo + hi);
}

std::size_t RollingRadiusDifference::segment(double y) const {
  const auto it = std::upper_bound(y_.begin() + 1, y_.end() - 1, y);
  return static_cast<std::size_t>(it - y_.begin()) - 1;
}

double RollingRadiusDifference::dr(double y) const {
  y = std::clamp(y, y_.front(), y_.back());
  const std::size_t i = segment(y);
  const double t = (y - y_[i]) / (y_[i + 1] - y_[i]);
  return dr_[i] + t * (dr_[i + 1] - dr_[i]);
}

double RollingRadiusDifference::potential(double y) const {
  y = std::clamp(y, y_.front(), y_.back());
  const std::size_t i = segment(y);
  const double u = y - y_[i];
  const double slope = (dr_[i + 1] - dr_[i]) / (y_[i + 1] - y_[i]);
  return cum_[i] + dr_[i] * u + 0.5 * slope * u * u - i0_;
}

double RollingRadiusDifference::crossingLeft(double C, std::size_t k0) const {
  for (std::size_t i = k0 + 1; i-- > 0;) {
    const double ya = y_[i];
    if (potential(ya) >= C) {
      double a = ya, b = std::min(y_[i + 1], y0_);
      for (int it = 0; it < 200 && b - a > 1e-14 * (1.0 + std::abs(a)); ++it) {
        const double m = 0.5 * (a + b);
        (potential(m) >= C ? a : b) = m;
      }
      return 0.5 * (a + b);
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double RollingRadiusDifference::crossingRight(double C, std::size_t k0) const {
  for (std::size_t i = k0 + 1; i < y_.size(); ++i) {
    const double yb = y_[i];
    if (potential(yb) >= C) {
      double a = std::max(y_[i - 1], y0_), b = yb;
      for (int it = 0; it < 200 && b - a > 1e-14 * (1.0 + std::abs(b)); ++it) {
        const double m = 0.5 * (a + b);
        (potential(m) >= C ? b : a) = m;
      }
      return 0.5 * (a + b);
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

bool RollingRadiusDifference::oscillation(double yhat, Oscillation& out) const {
  // The motion at level C stays in the connected part of {I < C} around y0. Its end points move
  // outward monotonically with C, so y2 - y1 is monotone in C: bisection.
  const std::size_t n = y_.size();
  const std::size_t k0 = segment(y0_);  // y0 in [y_k0, y_k0+1]
  auto crossing = [&](double C, int dir) {
    return dir < 0 ? crossingLeft(C, k0) : crossingRight(C, k0);
  };
  // Highest level reachable on both sides.
  double cmax = std::numeric_limits<double>::infinity();
  {
    double left = 0.0, right = 0.0;
    for (std::size_t i = 0; i <= k0; ++i) left = std::max(left, potential(y_[i]));
    for (std::size_t i = k0 + 1; i < n; ++i) right = std::max(right, potential(y_[i]));
    cmax = std::min(left, right);
  }
  auto width = [&](double C) { return crossing(C, +1) - crossing(C, -1); };
  if (!(cmax > 0.0) || !(width(cmax) >= 2.0 * yhat)) return false;
  double lo = 0.0, hi = cmax;
  for (int it = 0; it < 200; ++it) {
    const double m = 0.5 * (lo + hi);
    (width(m) < 2.0 * yhat ? lo : hi) = m;
    if (hi - lo <= 1e-15 * hi) break;
  }
  out.level = hi;
  out.y1 = crossing(hi, -1);
  out.y2 = crossing(hi, +1);
  return true;
}

double RollingRadiusDifference::tanGammaE(double yhat, int intervals) const {
  RB_CHECK(yhat > 0.0 && intervals > 0, "tanGammaE needs yhat > 0");
  Oscillation osc;
  if (!oscillation(yhat, osc)) return std::numeric_limits<double>::quiet_NaN();
  // Panels between the theta of the jumps inside (y1, y2), y = ym - a cos(theta) increasing with
  // theta; each gets its share of the intervals (at least one).
  const double ym = 0.5 * (osc.y1 + osc.y2), a = 0.5 * (osc.y2 - osc.y1);
  double J = 0.0, th_a = 0.0;
  for (const DrJump& jp : jumps_) {
    if (jp.y <= osc.y1 || jp.y >= osc.y2) continue;
    const double th_j = std::acos(std::clamp((ym - jp.y) / a, -1.0, 1.0));
    if (th_j <= th_a) continue;
    const int m =
        std::max(1, static_cast<int>(std::lround(intervals * (th_j - th_a) / std::numbers::pi)));
    J += panel(osc, th_a, th_j, m);
    th_a = th_j;
  }
  const int m = std::max(
      1, static_cast<int>(std::lround(intervals * (std::numbers::pi - th_a) / std::numbers::pi)));
  J += panel(osc, th_a, std::numbers::pi, m);
  return std::pow(std::numbers::pi / J, 2);
}

double RollingRadiusDifference::panel(const Oscillation& osc, double th_a, double th_b,
                                      int intervals) const {
  const double ym = 0.5 * (osc.y1 + osc.y2), a = 0.5 * (osc.y2 - osc.y1);
  const double dth = (th_b - th_a) / intervals;
  double J = 0.0;
  for (int k = 0; k < intervals; ++k) {
    const double th = th_a + (k + 0.5) * dth;
    const double q = osc.level - potential(ym - a * std::cos(th));
    if (q > 0.0) J += a * std::sin(th) / std::sqrt(q);
  }
  return J * dth;
}

double RollingRadiusDifference::tanGammaHarmonic(double yhat, int intervals) const {
  RB_CHECK(yhat > 0.0 && intervals > 0, "tanGammaHarmonic needs yhat > 0");
  if (y0_ - yhat < y_.front() || y0_ + yhat > y_.back()) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double dphi = 2.0 * std::numbers::pi / intervals;
  double b1 = 0.0;
  for (int k = 0; k < intervals; ++k) {
    const double phi = (k + 0.5) * dphi;
    b1 += dr(y0_ + yhat * std::sin(phi)) * std::sin(phi);
  }
  b1 *= dphi / std::numbers::pi;  // first Fourier sine coefficient of dr(y0 + yhat sin phi)
  return b1 / (2.0 * yhat);
}

}  // namespace rb::profiles
