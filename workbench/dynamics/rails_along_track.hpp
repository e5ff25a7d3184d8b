#pragma once
// Whether a vehicle's rails change along the track (profiles.rail_slices or extra_rails on either
// side): the analyses that need the same rails everywhere (a steady state, a speed ramp, a scaled
// curve radius) ask it.
#include <cstddef>

#include "workbench/dynamics/spec.hpp"

namespace rb::dynamics {

inline bool railsAlongTrack(const ProfilesSpec& p) {
  for (std::size_t side = 0; side < 2; ++side)
    if (!p.rail_slices[side].empty() || !p.extra_rails[side].empty()) return true;
  return false;
}

}  // namespace rb::dynamics
