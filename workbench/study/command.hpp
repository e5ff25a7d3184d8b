#pragma once
// What the analyses that run variants of one scenario (precision, stress, effects, and the
// stability drivers) have in common: the scenario, the overrides applied to every variant, the
// output folder and the runs at once; their command lines are in app/scenario_command.cpp.
#include <string>
#include <vector>

#include "workbench/scenario/scenario.hpp"
#include "workbench/study/runner.hpp"

namespace rb::study {

struct ScenarioCommandOptions {
  std::string scenario;                // the user's scenario (.lua)
  std::vector<std::string> overrides;  // --set block.key=value, applied to every case
  std::string out;                     // output folder (default out/<scenario stem>_<command>)
  std::string root;                    // project root
  std::string program;                 // the workbench executable that runs the cases
  int jobs = 0;                        // cases at once, 0 = number of cores
};

// The user's scenario loaded with `overrides` (instead of the options' own): what a case of the
// command runs. Throws InputError (file:line) when the scenario refuses them.
scenario::ScenarioSpec loadCommandScenario(const ScenarioCommandOptions& options,
                                           const std::vector<std::string>& overrides);

// The study options of the command's runs: its program, root and jobs, `file` the scenario, `out`
// the output folder (given, or out/<scenario stem>_<command>).
StudyOptions commandStudyOptions(const ScenarioCommandOptions& options, const std::string& command);

}  // namespace rb::study
