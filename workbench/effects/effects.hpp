#pragma once
// `workbench effects SCENARIO.lua`: one of the users' three asks run on any scenario
// (docs/effects.md): the scene with each of its optional effects switched off in turn
// (run.effects, workbench/scenario/effect_names.hpp), what each costs (callgrind instructions per
// right-hand-side evaluation, CPU time per evaluation beside it) and what it changes in the answer
// (the wheelsets' lateral displacement and yaw against the full scene).
#include <set>
#include <string>
#include <vector>

#include "workbench/study/command.hpp"

namespace rb::effects {

struct EffectsOptions : study::ScenarioCommandOptions {
  std::set<std::string> given;       // the options typed (a typed 0 is refused, not a default)
  int repeats = 3;                   // runs per case: CPU time per evaluation is their median
  double duration = 0.0;             // [s] simulated time of every case (0: the scene's)
  double distance = 0.0;             // [m] travelled distance of every case (0: the scene's)
  double cost_duration = 2.0;        // [s] simulated time of each callgrind run
  bool no_callgrind = false;         // skip the instruction counts
  bool quick = false;                // tests: 0.2 s, one repeat, no callgrind
  std::string quantities = "y,yaw";  // change in answer: y, yaw, Q, Fy (comma separated)
};

// Runs the command; returns the process exit code (0 ok, 1 bad input, 2 no case ran, 4 figures
// failed). Throws InputError for a bad scenario or option.
int runEffects(const EffectsOptions& options);

}  // namespace rb::effects
