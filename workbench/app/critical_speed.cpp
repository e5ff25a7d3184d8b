#include "workbench/app/critical_speed.hpp"

#include <CLI/CLI.hpp>
#include <stdexcept>

#include "workbench/app/stability_scene.hpp"

namespace rb::app {

CLI::App* addCriticalSpeedCommand(CLI::App& app, CriticalSpeedOptions& o) {
  auto* c = addScenarioCommand(app, "critical-speed",
                               "nonlinear critical speed: ramp-down or bisection, bifurcation "
                               "diagram",
                               o);
  c->add_option("--method", o.method, "ramp, bisection or both")
      ->check(CLI::IsMember({"ramp", "bisection", "both"}));
  c->add_option("--criterion", o.criterion, "amplitude or en14363")
      ->check(CLI::IsMember({"amplitude", "en14363"}));
  c->add_option("--contact", o.contact, "contact method kec or lut (default: the scenario's)");
  c->add_flag("--no-plots", o.no_plots, "no figures");
  return c;
}

int runCriticalSpeed(const CriticalSpeedOptions& o) {
  const StudyOptions so = commandStudyOptions(o, "critical_speed");
  const StabilityScene scene =
      loadStabilityScene(o.scenario, o.contact, o.overrides, o.root, so.out);
  (void)scene;
  throw std::runtime_error("workbench critical-speed: not implemented yet");
}

}  // namespace rb::app
