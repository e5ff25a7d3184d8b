#pragma once
// Reinsch smoothing spline (Reinsch 1967; Green & Silverman 1994, ch. 2): the function f that
// minimises
//     sum_i w_i (y_i - f(x_i))^2 + lambda * integral f''(x)^2 dx
// over all twice-differentiable f. It is a natural cubic spline with knots at the data points;
// lambda = 0 gives the interpolating natural spline. Solved in O(n) with a banded (pentadiagonal)
// LDL^T factorisation.
//
// lambda carries units [y^2 / (x^-3)]: prefer lambdaForLength(), which turns a smoothing LENGTH l
// (same unit as x) into lambda = l^4 w_mean / h_mean (h_mean the mean point spacing). For evenly
// spaced data the spline then acts as the low-pass filter 1 / (1 + (l omega)^4): wavelengths much
// longer than 2 pi l pass unchanged, the half-amplitude wavelength is 2 pi l.
#include <vector>

#include "workbench/core/spline.hpp"

namespace rb::profiles {

class SmoothingSpline {
 public:
  // x strictly increasing, at least 3 points; w > 0 (empty w = all ones); lambda >= 0.
  // `curve` is the cubic spline through the fitted values: Natural gives the exact Reinsch
  // minimiser; NotAKnot interpolates the same fitted values without imposing f'' = 0 at the ends,
  // which is better where the data are curved at their ends (for lambda = 0 it is the not-a-knot
  // interpolant of the data).
  SmoothingSpline(std::vector<double> x, const std::vector<double>& y, std::vector<double> w,
                  double lambda, SplineEnd curve = SplineEnd::Natural);

  static double lambdaForLength(const std::vector<double>& x, const std::vector<double>& w,
                                double length);

  const std::vector<double>& fitted() const { return fitted_; }  // f(x_i)
  double value(double x) const { return spline_.value(x); }
  double deriv1(double x) const { return spline_.deriv1(x); }
  double deriv2(double x) const { return spline_.deriv2(x); }
  double xMin() const { return spline_.grid().front(); }
  double xMax() const { return spline_.grid().back(); }

 private:
  std::vector<double> fitted_;
  CubicSpline spline_;
};

}  // namespace rb::profiles
