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
#include <vector>

#include "workbench/contact/lut.hpp"

namespace rb::contact {

struct RollingRadiusTable {
  double xi_g = 0.0;                             // [m] gauge variation of the table line
  std::vector<double> y;                         // [m] LUT lateral grid
  std::vector<double> z, phi;                    // [m], [rad] wheelset height and roll
  std::vector<double> r_left, r_right, delta_r;  // [m]
  std::vector<double> gamma_left, gamma_right, delta_gamma;  // [rad]
};

// At the LUT y nodes for gauge variation xi_g (default 0): the node values when xi_g is a gauge
// node, the interpolant otherwise.
RollingRadiusTable rollingRadiusDifference(const LutTable& lut, double xi_g = 0.0);

}  // namespace rb::contact
