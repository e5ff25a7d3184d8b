#pragma once
// The start state of a vehicle with its initial conditions (vehicle.initial).
#include <Eigen/Dense>
#include <span>

#include "workbench/vehicle/spec.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::run {

// y: the vehicle's static equilibrium (VehicleOde::initialState at t = 0). Adds the position
// offsets of `initial`, lets every other coordinate of the equilibrium settle around the offset
// ones, which are held (on wheel/rail contact: ContactVehicleOde::settle; a guided vehicle's
// bodies keep the plain offsets), then adds the rates: a lateral kick moves one wheelset, not the
// wheelset into its rail. Throws rb::InputError as applyInitialConditions and settle.
void startWithInitialConditions(vehicle::VehicleOde& ode,
                                std::span<const vehicle::InitialCondition> initial,
                                Eigen::VectorXd& y);

}  // namespace rb::run
