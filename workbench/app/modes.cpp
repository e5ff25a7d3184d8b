#include "workbench/app/modes.hpp"

#include <CLI/CLI.hpp>
#include <stdexcept>

#include "workbench/app/stability_scene.hpp"

namespace rb::app {

CLI::App* addModesCommand(CLI::App& app, ModesOptions& o) {
  auto* c = addScenarioCommand(
      app, "modes", "linearised stability: modes, damping versus speed, linear critical speed", o);
  c->add_option("--speeds", o.speeds, "speeds a:b:n [m/s] (default: the scenario's speed)");
  c->add_option("--contact", o.contact, "contact method kec or lut (default: the scenario's)");
  c->add_flag("--no-plots", o.no_plots, "no figures");
  return c;
}

int runModes(const ModesOptions& o) {
  const StudyOptions so = commandStudyOptions(o, "modes");
  const StabilityScene scene =
      loadStabilityScene(o.scenario, o.contact, o.overrides, o.root, so.out);
  (void)scene;
  throw std::runtime_error("workbench modes: not implemented yet");
}

}  // namespace rb::app
