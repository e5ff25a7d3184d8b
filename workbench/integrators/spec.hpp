#pragma once
// Solver choice as read from a scenario's solver{} block. Strings stay at this boundary: the
// registry turns `method` into an integrator and lists valid names/options for errors and help.
#include <string>

#include "workbench/core/error.hpp"

namespace rb::integ {

// How the fixed-step methods integrate the components the model declares stiff
// (OdeSystem::stiffComponents: free wheelset spin rates, series-damper forces): classically, or
// exponentially on their diagonal Jacobian entry (exponential.hpp).
enum class StiffTreatment { Explicit, Exponential };

struct SolverSpec {
  std::string method = "abm";  // registry name: rk4, abm, dopri5, bdf, ida
  double step = 1e-3;     // [s] fixed step (rk4, abm); initial step hint for adaptive (0 = auto)
  double rtol = 1e-6;     // [-] relative tolerance (adaptive methods)
  double atol = 1e-6;     // [-] absolute tolerance, in state units (adaptive methods)
  double max_step = 0.0;  // [s] maximum step, 0 = unlimited (adaptive methods)
  int max_order = 5;      // [-] BDF maximum order 1..5
  long max_steps = 0;     // [-] cap on internal steps per output interval, 0 = solver default
  std::string jacobian = "auto";  // "auto" (model's if it has one, else finite differences), "fd"
  StiffTreatment stiff = StiffTreatment::Explicit;  // rk4, abm
  // Run a fixed step beyond the stability limit of the model's stiffest mode anyway (studies of
  // the paper's settings); otherwise compile() refuses it.
  bool accept_unstable_step = false;
  SourceLoc loc;
};

}  // namespace rb::integ
