#pragma once
// What `workbench run` and `workbench check` do, separated from argument parsing so that tests
// can drive them.
#include <string>
#include <vector>

namespace rb::app {

struct RunOptions {
  std::string scenario;
  std::vector<std::string> overrides;
  std::string out;   // result file; default out/<scenario stem>.h5
  std::string root;  // project root
  bool quiet = false;
  // Rhs stage timing (workbench/run/run_stats.hpp): 1 evaluation in stage_period is timed, 0 off;
  // < 0: the environment's RAILBENCH_STAGE_SAMPLING, else 64.
  int stage_period = -1;
};

// Loads, validates and compiles everything the scenario asks for; throws InputError.
void checkScenario(const RunOptions& options);
// Runs the scenario and writes the result. Returns the process exit code (0 ok, 2 run failed).
int runScenario(const RunOptions& options);

}  // namespace rb::app
