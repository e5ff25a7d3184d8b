#pragma once
// `workbench modes SCENARIO.lua`: linearised stability of the vehicle (docs/stability.md): the
// steady state on the scenario's track at each speed, the Jacobian of the full model there, its
// eigenvalues and eigenvectors, the modes labelled from their dominant coordinates, and the
// linear critical speed where the least damped hunting mode crosses zero damping.
#include <string>

#include "workbench/study/command.hpp"

namespace rb::modes {

struct ModesOptions : study::ScenarioCommandOptions {
  std::string speeds;   // "a:b:n" [m/s], n speeds from a to b; "" = the scenario's speed
  std::string contact;  // "kec" / "lut": the contact method ("" = the scenario's; kec for a
                        // vehicle file)
  bool no_plots = false;
  double distance = 0.0;  // [m] travelled distance of the linearisation point (in a curve)
  double fd_scale = 1.0;  // multiplies the finite-difference steps (stability::StepRule)
};

// Returns the process exit code (0 ok, 1 bad input, 2 the analysis failed, 4 figures failed).
// Throws InputError for a bad scenario or option.
int runModes(const ModesOptions& options);

}  // namespace rb::modes
