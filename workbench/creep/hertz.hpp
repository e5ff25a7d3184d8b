#pragma once
// Hertz elliptic contact between wheel and rail (non-conformal, both bodies of one material).
//
// Geometry. In the contact frame x is the rolling direction, y lateral, z the common normal. Near
// the contact point the gap between the undeformed surfaces is h(x, y) = A x^2 + B y^2, with the
// RELATIVE principal curvatures
//
//   A = (k_wheel,x + k_rail,x) / 2,   B = (k_wheel,y + k_rail,y) / 2,
//
// where k is a principal curvature of one surface, POSITIVE when that surface is convex (curves
// away from the other body; centre of curvature inside the body) and negative when concave. The
// principal directions of both bodies are assumed aligned with x and y (true for a wheel and a
// straight rail at zero yaw; the error of neglecting a small yaw angle is second order).
// For a wheel (surface of revolution) the caller must use the NORMAL curvatures:
//   k_wheel,x = cos(gamma) / r   (r rolling radius at the contact, gamma contact angle: the angle
//                                 between the contact normal and the wheel radius; Meusnier),
//   k_wheel,y = the curvature of the wheel profile (convex > 0; the S1002 tread and throat are
//               concave, the flange flank is straight, the flange tip convex),
//   k_rail,x  = 0 (straight rail), k_rail,y = 1/R of the rail head arc (convex > 0).
// Hertz theory needs A > 0 and B > 0 (isHertzian()).
//
// Ellipse (Hertz theory, e.g. Johnson, Contact Mechanics, 1985, sections 3.5 and 4.2; the same
// equations as CONTACT's hzcalc3d; their m, n table: tests/data/creep/derived_hertz_m_n_table.txt).
// With E* = E / (2 (1 - nu^2)) (equal materials), major semi-axis a_M along the direction of the
// SMALLER relative curvature, minor semi-axis b_m, g = b_m / a_M <= 1, e^2 = 1 - g^2 and K = K(e),
// E = E(e) the complete elliptic integrals:
//
//   min(A,B) / max(A,B) = g^2 (K - E) / (E - g^2 K)          (shape equation, solved for g)
//   a_M = m c0,  b_m = n c0,  c0 = [3 N / (4 E* (A + B))]^(1/3)
//   m = (2 E / (pi g^2))^(1/3),  n = (2 E g / pi)^(1/3)
//   delta = 3 N K / (2 pi a_M E*)       (mutual approach)
//   p0 = 3 N / (2 pi a b)                (maximum pressure)
//
// Hence delta = lambda N^(2/3) and N = K_H delta^(3/2) with the Hertz stiffness
//
//   K_H = [ (3 K / (2 pi E* m)) (4 E* (A + B) / 3)^(1/3) ]^(-3/2)      [N/m^1.5]
//
// which is the paper's Khertz of Eq. (20) (section 5.3). Circular check (A = B = 1/(2R), R the
// effective radius 1/R = 1/R_1 + 1/R_2): a^3 = 3 N R / (4 E*) = 3 N R (1 - nu^2) / (2 E),
// delta = a^2 / R, K_H = (4/3) E* sqrt(R). (The often quoted a^3 = 3 N R (1 - nu^2) / (4 E) holds
// for two equal spheres of radius R, i.e. with the effective radius R/2.)
//
// The shape equation is solved for u = ln g by a safeguarded secant iteration started at
// g = (A/B)^(2/3) (a classical approximation, within 30 % for A/B >= 2e-3); 5-7 evaluations give g
// to ~1e-15 relative (shape-equation residual < 1e-13 for A/B in [1e-9, 1]). The left side is
// evaluated as g^2 S / (e^2 - S) with S = 1 - E/K from the AGM, which has no cancellation at g
// -> 1. Allocation-free.
#include <cmath>

namespace rb::creep {

// Elastic material of wheel and rail (same material).
struct Material {
  double E = 2.1e11;  // Young's modulus [Pa] (paper section 5.3)
  double nu = 0.28;   // Poisson's ratio [-] (paper section 5.3)
};

inline double shearModulus(const Material& m) {
  return m.E / (2.0 * (1.0 + m.nu));
}
// E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) for two bodies of the same material.
inline double contactModulus(const Material& m) {
  return m.E / (2.0 * (1.0 - m.nu * m.nu));
}

// Relative principal curvatures of the gap h = A x^2 + B y^2 [1/m].
struct RelativeCurvatures {
  double A = 0.0;  // rolling direction x
  double B = 0.0;  // lateral direction y
};

// Principal curvatures of the two surfaces [1/m], convex positive (see the header comment).
inline RelativeCurvatures relativeCurvatures(double wheel_rolling_curv, double wheel_lateral_curv,
                                             double rail_rolling_curv, double rail_lateral_curv) {
  return {0.5 * (wheel_rolling_curv + rail_rolling_curv),
          0.5 * (wheel_lateral_curv + rail_lateral_curv)};
}

// A > 0 and B > 0, both finite: a Hertz point contact exists.
inline bool isHertzian(const RelativeCurvatures& k) {
  return k.A > 0.0 && k.B > 0.0 && std::isfinite(k.A) && std::isfinite(k.B);
}

// Load-independent shape of the ellipse.
struct HertzShape {
  double g = 1.0;             // minor / major semi-axis ratio, (0, 1]
  double m = 1.0;             // major semi-axis coefficient (see header)
  double n = 1.0;             // minor semi-axis coefficient
  double K = 0.0;             // K(e), e = sqrt(1 - g^2)
  double E = 0.0;             // E(e)
  bool rolling_major = true;  // the major axis is along x (A <= B)
  int iterations = 0;         // shape-equation evaluations used (diagnostic)
  // a/b with a along x and b along y.
  double aOverB() const { return rolling_major ? 1.0 / g : g; }
};

// Requires isHertzian({A, B}) (always-on check).
HertzShape hertzShape(double A, double B);

struct HertzContact {
  double a = 0.0;        // semi-axis along the rolling direction x [m]
  double b = 0.0;        // semi-axis along the lateral direction y [m]
  double delta = 0.0;    // mutual approach (penetration of the undeformed surfaces) [m]
  double p0 = 0.0;       // maximum pressure [Pa]
  double k_hertz = 0.0;  // N = k_hertz delta^1.5 [N/m^1.5] (independent of N)
  HertzShape shape;
};

// Contact under normal force N [N]. N <= 0 (no contact) gives a = b = delta = p0 = 0 (k_hertz and
// shape are still filled). Requires isHertzian(k) and a valid material (E > 0, -1 < nu < 0.5).
HertzContact hertz(const Material& mat, const RelativeCurvatures& k, double N);

// The same with the load-independent shape already solved (hertzShape(k.A, k.B)), e.g. stored in
// a contact table: no root finding, ~20 ns instead of ~0.7 us.
HertzContact hertz(const Material& mat, const RelativeCurvatures& k, const HertzShape& shape,
                   double N);

// K_H alone (same value as hertz(...).k_hertz).
double hertzStiffness(const Material& mat, const RelativeCurvatures& k);

// K_H for an already solved shape.
double hertzStiffness(const Material& mat, const RelativeCurvatures& k, const HertzShape& shape);

}  // namespace rb::creep
