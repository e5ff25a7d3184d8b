#pragma once
// `workbench effects SCENARIO.lua`: one of the users' three asks run on any scenario (docs/three_asks.md).
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rb::app {

struct EffectsOptions {
  std::string scenario;                // the user's scenario (.lua)
  std::vector<std::string> overrides;  // --set block.key=value, applied to every case
  std::string out;                     // output folder (default out/<scenario stem>_effects)
  std::string root;                    // project root
  std::string program;                 // the workbench executable that runs the cases
  int jobs = 0;                        // cases at once, 0 = number of cores
};

// Declares the subcommand and its options on `app` (filled into `options` when parsed).
CLI::App* addEffectsCommand(CLI::App& app, EffectsOptions& options);

// Runs the command; returns the process exit code (0 ok, 1 bad input, 2 no case ran, 4 figures
// failed). Throws InputError for a bad scenario or option.
int runEffects(const EffectsOptions& options);

}  // namespace rb::app
