#pragma once
// Derived wheelset geometry from the LUT: rolling radius difference and contact
// angle difference as plain arrays, the input of the EN 15302 equivalent conicity
// (rb::profiles::RollingRadiusDifference, workbench/profiles/conicity.hpp).
//
// Sign convention: y positive to the LEFT (paper frame), delta_r = r_left - r_right. This is the
// EN 15302 convention "rolling radius of the wheel on the side the wheelset moved toward minus that
// of the other wheel": delta_r increases through zero (restoring), as conicity.hpp expects. (The
// Annex E data in shared/reference/en15302 list r_right - r_left against a y positive to the
// right, which is the same function.) Contact angles follow geometry.hpp (positive when the normal
// leans toward the track centre); delta_gamma = gamma_left - gamma_right.
//
// Contact-point jumps: where the rigid contact point of a wheel jumps (Eq. 12 changes branch),
// r of that wheel and so delta_r jump. Between two nodes the jump position is found from the two
// branches of Eq. (12) themselves: both are followed by Newton in y, and the valid one is the one
// that holds the wheelset higher (the lower one penetrates at the other branch's contact point),
// so the jump is where their heights z coincide (two-point contact of that wheel). The one-sided
// limits of delta_r there are those of the two branches, the input of the exact-jump treatment of
// the EN 15302 equivalent conicity (conicity.hpp).
#include <vector>

#include "workbench/contact/geometry.hpp"
#include "workbench/contact/lut.hpp"
#include "workbench/profiles/conicity.hpp"

namespace rb::contact {

// A jump of delta_r at y (rigid contact, Eq. 12): limits for y -> y- (left) and y -> y+ (right).
struct DeltaRJump {
  Side side = Side::Left;                          // the wheel whose contact point jumps
  double y = 0.0;                                  // [m]
  double delta_r_left = 0.0, delta_r_right = 0.0;  // [m]
  double s_w_left = 0.0, s_w_right = 0.0;          // [m] that wheel's contact point either side
  double z = 0.0, phi = 0.0;                       // [m], [rad] wheelset pose at the jump
  // delta_r on either branch between the neighbouring node and the jump (y increasing, nodes and
  // jump excluded): near a jump a branch may bend sharply (a contact branch close to its end),
  // which the node spacing does not resolve.
  std::vector<double> y_left, delta_r_left_branch, y_right, delta_r_right_branch;
};

struct RollingRadiusTable {
  double xi_g = 0.0;                             // [m] gauge variation of the table line
  std::vector<double> y;                         // [m] LUT lateral grid
  std::vector<double> z, phi;                    // [m], [rad] wheelset height and roll
  std::vector<double> r_left, r_right, delta_r;  // [m]
  std::vector<double> gamma_left, gamma_right, delta_gamma;  // [rad]
  std::vector<DeltaRJump> jumps;  // y increasing; empty unless located with a solver
};

// At the LUT y nodes for gauge variation xi_g (default 0): the node values when xi_g is a gauge
// node, the interpolant otherwise.
RollingRadiusTable rollingRadiusDifference(const LutTable& lut, double xi_g = 0.0);
// The same, plus the delta_r jumps located with `solver` (built from the LUT's configuration):
// between neighbouring nodes where the contact point of a wheel moves more than
// config.jump_threshold, the jump is bracketed to `tolerance` in y by bisection on the sign of
// z_left_branch - z_right_branch (see above). At most one jump per node interval.
RollingRadiusTable rollingRadiusDifference(const LutTable& lut, const ContactSolver& solver,
                                           double xi_g = 0.0, double tolerance = 1e-10);

// The input of the EN 15302 equivalent conicity: the node samples, the branch samples next to
// each jump, and the jumps as exact discontinuities.
profiles::RollingRadiusDifference conicityInput(const RollingRadiusTable& table);

}  // namespace rb::contact
