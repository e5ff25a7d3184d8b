#pragma once
// The nominal rolling (tape-circle) radius r0 a wheel has when a scenario does not give one: the
// Manchester benchmark vehicle 1's 0.46 m (the paper's Table 1 gives 0.457 m for its own wagon).
// The vehicle's wheel radius, the profiles' r0, the contact geometry's r0, the scenario schema and
// the generated stability scene all default to it.
namespace rb::profiles {

inline constexpr double kNominalWheelRadius = 0.46;  // [m]

}  // namespace rb::profiles
