#pragma once
// Creepages (normalised rigid slip) of the wheel relative to the rail at a contact point.
//
// Contact frame: right-handed (x, y, n) at the contact point, x tangent in the ROLLING direction
// (the direction of travel of the vehicle along the rail), y the lateral tangent, n = x cross y
// the common normal. Kalker's theory and Polach's method assume x points along the direction of
// motion so that the leading edge of the contact ellipse is at x = +a (this decides the sign of
// the spin-lateral coupling).
//
// Definitions (forces on the WHEEL oppose them; polach.hpp):
//   s_x = (v_wheel - v_rail) . x / V_ref                    longitudinal creepage [-]
//   s_y = (v_wheel - v_rail) . y / V_ref                    lateral creepage [-]
//   phi = sigma (omega_wheel - omega_rail) . n / V_ref      spin creepage [1/m]
// with v_wheel, v_rail the velocities of the MATERIAL points of wheel and rail at the contact,
// omega the angular velocities, V_ref = max(|V|, v_min) and sigma = sign(V) (+1 at V = 0).
// V is the reference (forward) speed, e.g. the wheelset's speed along the track.
//
// Running backwards (V < 0) in the same frame: the leading edge moves to x = -a. Rotating the frame
// by 180 deg about n gives (s_x, s_y, phi) -> (-s_x, -s_y, +phi) and the forces change sign back,
// so with the odd symmetry F(-s) = -F(s) of the creep laws the forces are computed correctly in the
// original frame if phi is multiplied by sigma = sign(V). This helper does that.
//
// Low speed: V_ref = max(|V|, v_min) avoids the division by zero at standstill. Below v_min the
// creepages become proportional to the slip velocity, i.e. the creep force turns into a stiff
// viscous law (slope G a b c11 / v_min for s_x); creep theory itself is not valid there.
// kMinReferenceSpeed = 0.1 m/s (1 % of the slowest speeds of interest, 10 m/s).
#include <cmath>

namespace rb::creep {

inline constexpr double kMinReferenceSpeed = 0.1;  // [m/s]

struct Creepages {
  double sx = 0.0;   // longitudinal creepage [-]
  double sy = 0.0;   // lateral creepage [-]
  double phi = 0.0;  // spin creepage [1/m]
  double v = 0.0;    // V_ref used for the normalisation [m/s]; slip velocity = creepage * v
                     // (only the falling friction law of polach.hpp uses it)
};

// std::fmax(a, b) (the other argument when one is NaN, else the larger) written out: the
// compiler calls libm for std::fmax on x86-64, this inlines to compares. Bit-identical.
inline double fmaxOf(double a, double b) {
  if (std::isnan(a)) return b;
  if (std::isnan(b)) return a;
  return a < b ? b : a;
}

// dv_long, dv_lat: velocity of the wheel material point relative to the rail material point at the
// contact, along x and y [m/s]; domega_n: relative angular velocity (wheel - rail) about n [rad/s];
// V: reference speed [m/s] (signed); v_min > 0: lower bound of |V| [m/s].
inline Creepages creepagesFromKinematics(double dv_long, double dv_lat, double domega_n, double V,
                                         double v_min = kMinReferenceSpeed) {
  const double v_ref = fmaxOf(std::fabs(V), v_min);
  const double inv = 1.0 / v_ref;
  const double sigma = V < 0.0 ? -1.0 : 1.0;
  return {dv_long * inv, dv_lat * inv, sigma * domega_n * inv, v_ref};
}

}  // namespace rb::creep
