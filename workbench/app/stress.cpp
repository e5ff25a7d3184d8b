#include "workbench/app/stress.hpp"

#include <CLI/CLI.hpp>
#include <iostream>

namespace rb::app {

CLI::App* addStressCommand(CLI::App& app, StressOptions& o) {
  auto* c = app.add_subcommand("stress", "not yet implemented");
  c->add_option("scenario", o.scenario, "scenario file (.lua)")->required();
  c->add_option("--set", o.overrides, "override a scenario value: block.key=value")
      ->allow_extra_args(false);
  c->add_option("--out", o.out, "output folder (default out/<scenario>_stress)");
  c->add_option("--jobs", o.jobs, "cases at once (default: cores)");
  return c;
}

int runStress(const StressOptions& o) {
  std::cerr << "workbench stress " << o.scenario << ": not implemented yet\n";
  return 1;
}

}  // namespace rb::app
