#include "workbench/app/scenario_command.hpp"

#include <CLI/CLI.hpp>

namespace rb::app {

CLI::App* addScenarioCommand(CLI::App& app, const std::string& name, const std::string& description,
                             ScenarioCommandOptions& o) {
  auto* c = app.add_subcommand(name, description);
  c->add_option("scenario", o.scenario, "scenario file (.lua)")->required();
  c->add_option("--set", o.overrides, "override a scenario value in every case: block.key=value")
      ->allow_extra_args(false);
  c->add_option("--out", o.out, "output folder (default out/<scenario>_" + name + ")");
  c->add_option("--jobs", o.jobs, "runs at once (default: cores; 1 for quiet CPU timings)");
  return c;
}

}  // namespace rb::app
