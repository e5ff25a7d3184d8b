#include "workbench/study/command.hpp"

#include <filesystem>

namespace rb::study {

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

}  // namespace rb::study
