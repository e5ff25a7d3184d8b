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
// Numerics: dr is interpolated linearly between its samples, so I is piecewise quadratic and
// evaluated exactly. A contact-point jump of either wheel makes dr jump (the rolling radius of
// that wheel changes at once): such a jump is given explicitly, as a repeated y whose first value
// is the left limit dr(y_j-) and second the right limit dr(y_j+), so that dr is linear between
// the samples on either side and never interpolated across the jump; I then has a kink at y_j and
// stays exact. (Interpolating across a jump spreads the step over one sample interval and shifts I
// by up to half a step times that interval, which at an amplitude just beyond the jump moves the
// turning point and J by O(1).) C is found by bisection on y2 - y1 = 2 y-hat; J is integrated after
// the substitution y = ym - a cos(theta) (ym, a the centre and half-width of [y1, y2]), which
// removes the 1/sqrt singularities at the turning points, with the composite midpoint rule in
// theta, split at the theta of every jump inside (y1, y2) so that no midpoint panel straddles a
// kink of I (a jump just inside a turning point would otherwise cost O(h) accuracy).
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

// A discontinuity of dr at y: dr -> left as y -> y-, dr -> right as y -> y+.
struct DrJump {
  double y = 0.0;
  double left = 0.0, right = 0.0;
};

class RollingRadiusDifference {
 public:
  // y non-decreasing (at least 3 samples), dr(y) at these y. A y given twice is a jump: the first
  // value is the left limit, the second the right limit (no y more than twice, none at the ends).
  RollingRadiusDifference(std::vector<double> y, std::vector<double> dr);
  // Continuous samples (y strictly increasing) plus jumps strictly inside the data range; a jump
  // at a sample position replaces that sample.
  RollingRadiusDifference(std::vector<double> y, std::vector<double> dr,
                          const std::vector<DrJump>& jumps);

  double centre() const { return y0_; }  // y0: minimum of I(y), where dr = 0
  double dr(double y) const;  // linear interpolation (clamped to the data); right limit at a jump
  double potential(double y) const;  // I(y) = integral_{y0}^{y} dr
  const std::vector<DrJump>& jumps() const { return jumps_; }

  struct Oscillation {
    double y1 = 0.0, y2 = 0.0;  // turning points
    double level = 0.0;         // C = I(y1) = I(y2)
  };
  // Turning points for amplitude yhat; false if the oscillation leaves the data range.
  bool oscillation(double yhat, Oscillation& out) const;

  // EN 15302 equivalent conicity at amplitude yhat (> 0); NaN when the data do not reach the
  // turning points. `intervals`: midpoint-rule subintervals in theta over [0, pi] (shared among
  // the panels between jumps in proportion to their length).
  double tanGammaE(double yhat, int intervals = 4096) const;
  // Harmonic-linearisation estimate (see above); NaN when y0 +- yhat leaves the data.
  double tanGammaHarmonic(double yhat, int intervals = 4096) const;

 private:
  // Checks the samples, collects the jumps and builds cum_, y0_, i0_.
  void setUp();
  // Segment [y_i, y_i+1] of positive length containing y (the right one at a jump).
  std::size_t segment(double y) const;
  // Global minimum of the piecewise quadratic I over the data (value; sets y0_ to its position).
  double integralMinimum();
  // y0_ moved to the middle of the flat part of the minimum `best` around it.
  double middleOfFlatMinimum(double best) const;
  // Crossing of I = C going left / right from y0 (y0 in segment k0); NaN if not within the data.
  double crossingLeft(double C, std::size_t k0) const;
  double crossingRight(double C, std::size_t k0) const;
  // J = integral_{th_a}^{th_b} a sin(theta) / sqrt(C - I(ym - a cos theta)) d theta, midpoint rule.
  double panel(const Oscillation& osc, double th_a, double th_b, int intervals) const;
  std::vector<double> y_, dr_, cum_;  // cum_[i] = integral_{y_0}^{y_i} dr (from the first sample)
  std::vector<DrJump> jumps_;         // the repeated y of y_, increasing
  double y0_ = 0.0, i0_ = 0.0;        // centre and integral_{y_first}^{y0} dr
};

}  // namespace rb::profiles
