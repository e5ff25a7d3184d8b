#include "workbench/app/scenario_command.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>

namespace rb::app {

CLI::App* addScenarioCommand(CLI::App& app, const std::string& name, const std::string& description,
                             ScenarioCommandOptions& o) {
  auto* c = app.add_subcommand(name, description);
  c->add_option("scenario", o.scenario, "scenario file (.lua)")->required();
  c->add_option("--set", o.overrides, "override a scenario value in every case: block.key=value")
      ->allow_extra_args(false);
  c->add_option("--out", o.out, "output folder (default out/<scenario>_" + name + ")");
  c->add_option("--jobs", o.jobs,
                "runs at once, 0..4 x cores (default 0: cores; 1 for quiet CPU timings)");
  return c;
}

scenario::ScenarioSpec loadCommandScenario(const ScenarioCommandOptions& o,
                                           const std::vector<std::string>& overrides) {
  scenario::LoadOptions lo;
  lo.root = o.root;
  lo.overrides = overrides;
  return scenario::loadScenario(o.scenario, lo);
}

StudyOptions commandStudyOptions(const ScenarioCommandOptions& o, const std::string& command) {
  StudyOptions so;
  so.file = o.scenario;
  so.root = o.root;
  so.program = o.program;
  so.jobs = o.jobs;
  so.out = o.out.empty() ? (std::filesystem::path("out") /
                            (std::filesystem::path(o.scenario).stem().string() + "_" + command))
                               .string()
                         : o.out;
  return so;
}

}  // namespace rb::app
