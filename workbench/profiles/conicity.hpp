#pragma once
// Equivalent conicity tan(gamma_e) from a rolling-radius-difference function, EN 15302.
//
// EN 15302 defines the equivalent conicity through Klingel's formula: tan(gamma_e) is the conicity
// of the coned wheelset whose kinematic (creep-free) lateral oscillation of amplitude y-hat has the
// same wavelength lambda as that of the real wheelset, lambda = 2 pi sqrt(e r0 / tan gamma_e)
// (e: half the distance between the contact points, r0: rolling radius). The wavelength of the real
// wheelset follows from integrating the nonlinear kinematic equation (Annex B, "integration of the
// nonlinear differential equation"):
//     dy/dx = psi,   dpsi/dx = -dr(y) / (2 e r0)
// which has the first integral psi^2 = (C - I(y)) / (e r0), I(y) = integral_{y0}^{y} dr(u) du,
// with y0 the centre position (dr(y0) = 0, minimum of I). For an amplitude y-hat the turning points
// y1 < y0 < y2 satisfy I(y1) = I(y2) = C and y2 - y1 = 2 y-hat (for unequal wheels the motion is
// not symmetric about y0: y-hat is half the peak-to-peak value), and
//     lambda = 2 integral_{y1}^{y2} dy / psi = 2 sqrt(e r0) J,   J = integral dy / sqrt(C - I(y)),
// so that tan(gamma_e) = 4 pi^2 e r0 / lambda^2 = (pi / J)^2, independent of e and r0.
// Check: a cone, dr = 2 g y, gives I = g y^2, J = pi / sqrt(g), tan(gamma_e) = g.
//
// Numerics: dr is interpolated linearly between its samples (dr has kinks and jumps at contact
// point jumps), so I is piecewise quadratic and evaluated exactly; C is found by bisection on
// y2 - y1 = 2 y-hat; J is integrated after the substitution y = ym - a cos(theta) (ym, a the
// centre and half-width of [y1, y2]), which removes the 1/sqrt singularities at the turning points,
// with the composite midpoint rule in theta.
//
// Also offered, for comparison only: the harmonic-linearisation (describing-function) estimate
//     tan(gamma_e) ~ (1 / (2 y-hat)) (1/pi) integral_0^{2 pi} dr(y0 + y-hat sin phi) sin phi dphi,
// which is exact for a cone but is NOT the EN 15302 definition.
//
// Sign convention: dr must increase through its zero (a restoring function): dr = r_l - r_r for y
// positive to the left (paper frame), which is the EN 15302 convention r of the wheel on the side
// the wheelset moved toward minus the other. Units: y and dr in the same unit (mm or m).
#include <cstddef>
#include <vector>

namespace rb::profiles {

class RollingRadiusDifference {
 public:
  // y strictly increasing (at least 3 samples), dr(y) at these y.
  RollingRadiusDifference(std::vector<double> y, std::vector<double> dr);

  double centre() const { return y0_; }  // y0: minimum of I(y), where dr = 0
  double dr(double y) const;             // linear interpolation (clamped to the data range)
  double potential(double y) const;      // I(y) = integral_{y0}^{y} dr

  struct Oscillation {
    double y1 = 0.0, y2 = 0.0;  // turning points
    double level = 0.0;         // C = I(y1) = I(y2)
  };
  // Turning points for amplitude yhat; false if the oscillation leaves the data range.
  bool oscillation(double yhat, Oscillation& out) const;

  // EN 15302 equivalent conicity at amplitude yhat (> 0); NaN when the data do not reach the
  // turning points. `intervals`: midpoint-rule subintervals in theta.
  double tanGammaE(double yhat, int intervals = 4096) const;
  // Harmonic-linearisation estimate (see above); NaN when y0 +- yhat leaves the data.
  double tanGammaHarmonic(double yhat, int intervals = 4096) const;

 private:
  std::size_t segment(double y) const;
  // Global minimum of the piecewise quadratic I over the data (value; sets y0_ to its position).
  double integralMinimum();
  // y0_ moved to the middle of the flat part of the minimum `best` around it.
  double middleOfFlatMinimum(double best) const;
  // Crossing of I = C going left / right from y0 (y0 in segment k0); NaN if not within the data.
  double crossingLeft(double C, std::size_t k0) const;
  double crossingRight(double C, std::size_t k0) const;
  std::vector<double> y_, dr_, cum_;  // cum_[i] = integral_{y_0}^{y_i} dr (from the first sample)
  double y0_ = 0.0, i0_ = 0.0;        // centre and integral_{y_first}^{y0} dr
};

}  // namespace rb::profiles
