#include "workbench/effects/cases.hpp"

namespace rb::effects {

using scenario::Effect;

std::vector<SceneEffect> sceneEffects(const scenario::ScenarioSpec& spec) {
  std::vector<SceneEffect> out;
  for (const auto& entry : scenario::kEffectSwitches) {
    const auto& sw = spec.run.effects[scenario::effectIndex(entry.effect)];
    if (!sw.present) continue;
    if (entry.effect == Effect::FlangeContact)
      out.push_back({entry.effect, "always on"});
    else
      out.push_back({entry.effect, sw.on ? "measured" : "off in the scene"});
  }
  return out;
}

std::string effectOffOverride(Effect e) {
  return "run.effects." + std::string(nameOf(e)) + "=false";
}

scenario::StudySpec effectsStudy(const std::string& scenarioPath,
                                 const scenario::ScenarioSpec& spec,
                                 const std::vector<std::string>& common, int repeats) {
  scenario::StudySpec st;
  st.file = scenarioPath + " (effects)";
  st.base = scenarioPath;
  st.repeats = repeats;
  st.loc = {scenarioPath, 0};
  auto add = [&](std::vector<std::string> offs, std::string label, std::string role) {
    std::vector<std::string> ov = common;
    ov.insert(ov.end(), offs.begin(), offs.end());
    st.cases.push_back({scenario::studyCaseId(ov, ""),
                        ov,
                        std::move(label),
                        scenarioPath,
                        std::move(role),
                        {},
                        {}});
  };
  add({}, "full scene", "baseline");
  std::vector<std::string> all;
  for (const auto& se : sceneEffects(spec)) {
    if (se.state != "measured") continue;
    all.push_back(effectOffOverride(se.effect));
    add({all.back()}, "no " + std::string(nameOf(se.effect)), "effect_off");
  }
  if (all.size() >= 2) add(all, "minimal", "minimal");
  return st;
}

}  // namespace rb::effects
