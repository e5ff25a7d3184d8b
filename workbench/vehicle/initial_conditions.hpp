#pragma once
// Initial conditions of a run (vehicle.initial): offsets of body coordinates and rates added to
// the state a vehicle ODE starts in (VehicleOde::initialState: static equilibrium, wheelsets
// centred), e.g. the lateral kick of a hunting-stability run.
#include <Eigen/Dense>
#include <span>
#include <string>

#include "workbench/vehicle/spec.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::vehicle {

// "y", "yaw_dot", ...: the scenario key of coordinate c (kY .. kYaw) or its rate.
std::string initialConditionKey(int coord, bool rate);

// Adds every condition to y0 (a state of `ode`). Throws rb::InputError at the condition's loc
// when its body does not exist or its coordinate is not a state of the model (a wheelset's z or
// roll on contact, a frame, a guided wheelset), or its value is not finite.
void applyInitialConditions(const VehicleOde& ode, std::span<const InitialCondition> conditions,
                            Eigen::VectorXd& y0);

}  // namespace rb::vehicle
