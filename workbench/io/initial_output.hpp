#pragma once
// /initial_conditions in the result file: the initial conditions a run was given
// (vehicle.initial) and the full state it started from, with the name of every component.
#include <string>
#include <vector>

#include "workbench/io/result_file.hpp"
#include "workbench/io/schema.hpp"

namespace rb::io {

struct InitialConditionsRecord {
  // The given conditions, one entry each: body name, key ("y", "yaw_dot"), value [SI], unit.
  std::vector<std::string> body, key, unit;
  std::vector<double> value;
  // State component names ("car.y", "ws1.psi_dot", "series[3].f"), the static-equilibrium state
  // (VehicleOde::initialState) and the start state (equilibrium plus the conditions).
  std::vector<std::string> state_names;
  std::vector<double> equilibrium, state;
};

// Writes /initial_conditions/{body, key, value, unit, state_names, equilibrium, state} and the
// group attribute `count` (number of conditions) into the group g: /initial_conditions, or
// /vehicles/<name>/initial_conditions for a vehicle of a run of several. Returns the /schema rows
// of the datasets written (the caller writes /schema/initial_conditions once per file).
std::vector<SchemaEntry> writeInitialConditions(ResultFile& f, const InitialConditionsRecord& r,
                                                const std::string& g = "/initial_conditions");

}  // namespace rb::io
