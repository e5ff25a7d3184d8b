#include "workbench/app/effects.hpp"

#include <CLI/CLI.hpp>
#include <iostream>

namespace rb::app {

CLI::App* addEffectsCommand(CLI::App& app, EffectsOptions& o) {
  auto* c = app.add_subcommand("effects", "not yet implemented");
  c->add_option("scenario", o.scenario, "scenario file (.lua)")->required();
  c->add_option("--set", o.overrides, "override a scenario value: block.key=value")
      ->allow_extra_args(false);
  c->add_option("--out", o.out, "output folder (default out/<scenario>_effects)");
  c->add_option("--jobs", o.jobs, "cases at once (default: cores)");
  return c;
}

int runEffects(const EffectsOptions& o) {
  std::cerr << "workbench effects " << o.scenario << ": not implemented yet\n";
  return 1;
}

}  // namespace rb::app
