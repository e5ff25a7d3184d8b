#pragma once
// The cases of `workbench effects` for one loaded scene: the full scene (role "baseline"), one
// case per optional effect the scene has with that effect switched off (role "effect_off",
// override run.effects.<name>=false) and, with two or more, every one of them off (role
// "minimal"). Each case also carries the command's common overrides.
#include <string>
#include <vector>

#include "workbench/scenario/scenario.hpp"
#include "workbench/scenario/study.hpp"

namespace rb::effects {

// An effect of the scene as the command reports it.
struct SceneEffect {
  scenario::Effect effect;
  std::string state;  // "measured" (switched off in its case), "always on" (part of the
                      // model), "off in the scene" (the scene's own switch)
};

// Every effect of the name table the scene has, in table order.
std::vector<SceneEffect> sceneEffects(const scenario::ScenarioSpec& spec);

// The override that switches `e` off: "run.effects.<name>=false".
std::string effectOffOverride(scenario::Effect e);

// The study of the scene `scenarioPath` (as `spec` was loaded from it, `common` applied to every
// case): baseline, one case per measured effect, minimal.
scenario::StudySpec effectsStudy(const std::string& scenarioPath,
                                 const scenario::ScenarioSpec& spec,
                                 const std::vector<std::string>& common, int repeats);

}  // namespace rb::effects
