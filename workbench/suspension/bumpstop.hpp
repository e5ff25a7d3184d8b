#pragma once
// Nonlinear bumpstop law (paper Table 4, Appendix A, Fig. 27): force as a piecewise-cubic function
// of the deformation through a table, zero inside the clearance, odd in d (symmetric in +-d).
//
// Table: points (d_k, F_k) with d_k >= 0 strictly increasing and F_k >= 0 non-decreasing, F_0 = 0.
// The clearance c is the largest d_k of the leading points with F = 0 (Table 4: 0 and 25 mm give
// c = 25 mm). For |d| <= c the force is 0; for c <= |d| <= d_last it is the monotone piecewise
// cubic Hermite interpolant (PCHIP, Fritsch-Carlson slopes) through the remaining points, with
// slope 0 at the clearance so the force is C1 there; beyond d_last it continues linearly with the
// end slope. F(-d) = -F(d).
//
// Why PCHIP and not a C2 spline: Table 4 jumps from 29.2 kN at 60 mm to 230 kN at 65 mm; a C2
// (not-a-knot or natural) spline through it oscillates and gives a non-monotone force law (see
// tests/suspension). The paper says "cubic splines"; PCHIP is a cubic spline in the piecewise sense
// (C1, cubic on every interval) that keeps the table's monotonicity and never goes negative.
#include <string>
#include <vector>

namespace rb::suspension {

class BumpstopLaw {
 public:
  BumpstopLaw() = default;
  // Every problem of a table as a message ("table: d must be strictly increasing (d[3] = ...)");
  // empty if the table is valid.
  static std::vector<std::string> check(const std::vector<double>& d, const std::vector<double>& f);
  // Builds from a VALID table (check() first; violations are internal errors).
  BumpstopLaw(const std::vector<double>& d, const std::vector<double>& f);

  double clearance() const { return c_; }
  // Force [N], odd in d.
  double force(double d) const;
  // dF/dd [N/m], even in d.
  double stiffness(double d) const;
  // Stored energy: integral of F from 0 to |d| [J].
  double energy(double d) const;

 private:
  std::size_t interval(double a) const;
  double c_ = 0.0;
  std::vector<double> x_;     // knots from the clearance on
  std::vector<double> coef_;  // 4 per interval: F = c0 + c1 t + c2 t^2 + c3 t^3, t = a - x_k
  std::vector<double> e_;     // energy at each knot
  double end_slope_ = 0.0;
};

}  // namespace rb::suspension
