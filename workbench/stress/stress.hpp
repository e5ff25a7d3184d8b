#pragma once
// `workbench stress SCENARIO.lua`: one of the users' three asks run on any scenario
// (docs/stress.md): does the scenario stay numerically stable when it is made harder? The
// scenario is hardened along named axes (plan.hpp); every hardened case runs with a set of
// integrator settings and with its own tight-tolerance reference, each run in its own process
// (runStudySpec); the verdict (verdict.hpp) classifies every run (ok, inaccurate, failed cleanly,
// failed badly), writes stress.csv, prints the map and checks an expectation file; plots/rbplot
// stress draws the map.
#include <string>
#include <vector>

#include "workbench/study/command.hpp"

namespace rb::stress {

struct StressOptions : study::ScenarioCommandOptions {
  std::vector<std::string> axes;         // --axes: empty = every axis that applies
  std::vector<std::string> values;       // --values AXIS=v1,v2,...
  std::vector<std::string> integrators;  // --integrators METHOD:VALUE[:paper],...
  std::string reference = "bdf:1e-9";    // the reference setting of every hardened case
  double run_timeout = 1800.0;           // [s] wall time after which a run counts as hung
  double tolerance = 1.0;                // [mm] largest wheelset lateral error of an "ok" run
  bool quick = false;                    // hardest value per axis, two settings, at most 2 s
  double quickSeconds = 2.0;             // [s] run length with --quick
  std::string expect;                    // expectation file (docs/stress.md)
};

// Runs the command; returns the process exit code (0 the map was made, 1 bad input, 2 no case
// could run, 4 the figure failed, 5 an outcome differs from the expectation file). Throws
// InputError for a bad scenario or option.
int runStress(const StressOptions& options);

}  // namespace rb::stress
