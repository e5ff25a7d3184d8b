#pragma once
// `workbench critical-speed SCENARIO.lua`: the nonlinear critical speed of the vehicle
// (docs/stability.md) by the ramp-down method (a kicked run above the critical speed that
// decelerates until the limit cycle dies) or by bisection on constant-speed runs (the kicked
// motion decays or grows), with the limit-cycle amplitude versus speed (bifurcation diagram).
#include <string>

#include "workbench/app/scenario_command.hpp"

namespace rb::app {

struct CriticalSpeedOptions : ScenarioCommandOptions {
  std::string method = "ramp";          // "ramp", "bisection" or "both"
  std::string criterion = "amplitude";  // "amplitude" (wheelset lateral) or "en14363" (bogie
                                        // frame lateral acceleration, EN 14363 stability)
  std::string contact;                  // "kec" / "lut" ("" = the scenario's; kec for a vehicle
                                        // file)
  bool no_plots = false;
};

CLI::App* addCriticalSpeedCommand(CLI::App& app, CriticalSpeedOptions& options);

// Returns the process exit code (0 ok, 1 bad input, 2 the search failed, 4 figures failed).
// Throws InputError for a bad scenario or option.
int runCriticalSpeed(const CriticalSpeedOptions& options);

}  // namespace rb::app
