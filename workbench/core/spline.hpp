#pragma once
// Cubic spline interpolation y(x) on a strictly increasing grid (track preprocessor, paper section
// 2.1 and Fig. 4; later wheel/rail profiles and contact tables).
//
// End conditions: NotAKnot is the default. It imposes a continuous third derivative at the second
// and the second-to-last knot, so the end intervals get no artificial condition and the
// interpolation error stays O(h^4) up to the ends. The natural spline (y'' = 0 at both ends) is
// offered for data that really is straight at its ends; used elsewhere it forces a wrong second
// derivative at the ends (for the track: zero curvature at the end of a curve) and degrades the
// error there to O(h^2).
//
// Evaluation is allocation-free. The interval of x is found in O(1) on a uniform grid (detected
// at construction) and by binary search otherwise. Outside [x_0, x_{n-1}] the end cubic pieces are
// extended (extrapolation); callers that need another policy clamp x themselves.
//
// CubicSplineSet interpolates several channels on one grid and evaluates them with a single
// interval lookup; CubicSpline is the one-channel convenience form.
#include <cassert>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace rb {

enum class SplineEnd { NotAKnot, Natural };

// Knots with interval lookup.
class SplineGrid {
 public:
  SplineGrid() = default;
  // x strictly increasing and finite, at least 2 points (always-on check).
  explicit SplineGrid(std::vector<double> x);
  // x_i = x0 + i h, i = 0..n-1 (n >= 2, h > 0).
  static SplineGrid uniform(double x0, double h, std::size_t n);

  std::size_t size() const { return x_.size(); }
  double front() const { return x_.front(); }
  double back() const { return x_.back(); }
  double operator[](std::size_t i) const { return x_[i]; }
  const std::vector<double>& knots() const { return x_; }
  bool isUniform() const { return uniform_; }

  // Index i of the interval [x_i, x_{i+1}] holding x, clamped to [0, n-2] (so points outside the
  // grid map to the end intervals).
  std::size_t interval(double x) const {
    assert(x_.size() >= 2);
    const std::size_t last = x_.size() - 2;
    if (uniform_) {
      const double t = (x - x_.front()) * inv_h_;
      if (!(t > 0.0)) return 0;  // also NaN
      if (t >= static_cast<double>(last)) return last;
      auto i = static_cast<std::size_t>(t);
      // Guard against rounding of (x - x0)/h at a knot.
      if (i < last && x >= x_[i + 1]) ++i;
      if (i > 0 && x < x_[i]) --i;
      return i;
    }
    return searchInterval(x);
  }

 private:
  std::size_t searchInterval(double x) const;
  std::vector<double> x_;
  bool uniform_ = false;
  double inv_h_ = 0.0;
};

// Several cubic splines on one grid. Coefficients are stored interval by interval so one lookup
// serves all channels.
class CubicSplineSet {
 public:
  CubicSplineSet() = default;
  // ys[c][i] is channel c at knot i; every channel has grid.size() values (always-on check).
  CubicSplineSet(SplineGrid grid, const std::vector<std::vector<double>>& ys,
                 SplineEnd end = SplineEnd::NotAKnot);

  std::size_t channels() const { return m_; }
  const SplineGrid& grid() const { return grid_; }

  // Values (and optionally first and second derivatives) of all channels at x. Each span must
  // have channels() entries; an empty span skips that order.
  void eval(double x, std::span<double> v, std::span<double> d1 = {},
            std::span<double> d2 = {}) const {
    assert(v.empty() || v.size() == m_);
    assert(d1.empty() || d1.size() == m_);
    assert(d2.empty() || d2.size() == m_);
    const std::size_t i = grid_.interval(x);
    const double t = x - grid_[i];
    const double* c = &coef_[i * m_ * 4];
    for (std::size_t k = 0; k < m_; ++k, c += 4) {
      if (!v.empty()) v[k] = c[0] + t * (c[1] + t * (c[2] + t * c[3]));
      if (!d1.empty()) d1[k] = c[1] + t * (2.0 * c[2] + t * 3.0 * c[3]);
      if (!d2.empty()) d2[k] = 2.0 * c[2] + 6.0 * t * c[3];
    }
  }

  // One channel: value, first and second derivative.
  double value(std::size_t channel, double x) const { return poly(channel, x, 0); }
  double deriv1(std::size_t channel, double x) const { return poly(channel, x, 1); }
  double deriv2(std::size_t channel, double x) const { return poly(channel, x, 2); }

 private:
  double poly(std::size_t channel, double x, int order) const {
    assert(channel < m_);
    const std::size_t i = grid_.interval(x);
    const double t = x - grid_[i];
    const double* c = &coef_[(i * m_ + channel) * 4];
    if (order == 0) return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
    if (order == 1) return c[1] + t * (2.0 * c[2] + t * 3.0 * c[3]);
    return 2.0 * c[2] + 6.0 * t * c[3];
  }

  SplineGrid grid_;
  std::size_t m_ = 0;
  // coef_[((i * m_) + c) * 4 + p]: y = sum_p coef * (x - x_i)^p on interval i, channel c.
  std::vector<double> coef_;
};

// One cubic spline y(x).
class CubicSpline {
 public:
  CubicSpline() = default;
  CubicSpline(std::vector<double> x, const std::vector<double>& y,
              SplineEnd end = SplineEnd::NotAKnot);
  CubicSpline(SplineGrid grid, const std::vector<double>& y, SplineEnd end = SplineEnd::NotAKnot);

  double operator()(double x) const { return set_.value(0, x); }
  double value(double x) const { return set_.value(0, x); }
  double deriv1(double x) const { return set_.deriv1(0, x); }
  double deriv2(double x) const { return set_.deriv2(0, x); }
  const SplineGrid& grid() const { return set_.grid(); }

 private:
  CubicSplineSet set_;
};

}  // namespace rb
