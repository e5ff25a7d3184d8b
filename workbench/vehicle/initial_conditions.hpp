#pragma once
// Initial conditions of a run (vehicle.initial): offsets of body coordinates and rates added to
// the state a vehicle ODE starts in (VehicleOde::initialState: static equilibrium, wheelsets
// centred), e.g. the lateral kick of a hunting-stability run.
#include <Eigen/Dense>
#include <span>
#include <string>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/vehicle/spec.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::vehicle {

// "y", "yaw_dot", ...: the scenario key of coordinate c (kY .. kYaw) or its rate.
std::string initialConditionKey(int coord, bool rate);

// Adds every problem of the conditions on `ode` to d at the condition's loc, naming the key
// vehicle.initial.BODY.KEY: a body that does not exist, a coordinate that is not a state of the
// model, a value that is not finite.
void checkInitialConditions(const VehicleOde& ode, std::span<const InitialCondition> conditions,
                            Diagnostics& d);

// Adds every condition to y0 (a state of `ode`). Throws rb::InputError with the problems of
// checkInitialConditions. A zero value leaves y0 untouched bit for bit (a -0.0 stays -0.0).
void applyInitialConditions(const VehicleOde& ode, std::span<const InitialCondition> conditions,
                            Eigen::VectorXd& y0);

}  // namespace rb::vehicle
