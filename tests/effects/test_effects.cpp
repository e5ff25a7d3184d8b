// run.effects switches (workbench/scenario/effect_names.hpp): each switched-off effect is absent
// from the compiled model and its result, an unknown name or a switch the scene cannot use is a
// file:line error, and the cases of `workbench effects` follow the scene.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/app/h5read.hpp"
#include "tests/app/scenario_run.hpp"
#include "workbench/effects/cases.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/scenario/schema.hpp"

namespace {

using rb::scenario::Effect;

const std::string kCase3 = "scenarios/studies/case3_base.lua";
const std::string kCase1 = "scenarios/validation/case1_R500_kec.lua";

std::string path(const std::string& rel) {
  return std::string(RB_SOURCE_DIR) + "/" + rel;
}

rb::scenario::ScenarioSpec load(const std::string& file, std::vector<std::string> ov = {}) {
  rb::scenario::LoadOptions lo;
  lo.root = RB_SOURCE_DIR;
  lo.overrides = std::move(ov);
  return rb::scenario::loadScenario(path(file), lo);
}

rb::run::Model compiled(const std::string& file, std::vector<std::string> ov) {
  rb::run::CompileOptions c;
  c.scenario = path(file);
  c.root = RB_SOURCE_DIR;
  c.overrides = std::move(ov);
  return rb::run::compile(c);
}

// The message of the InputError that loading throws, "" when it loads.
std::string loadError(const std::string& file, std::vector<std::string> ov = {}) {
  try {
    load(file, std::move(ov));
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "";
}

bool hasKind(const rb::run::Model& m, const std::string& kind) {
  const auto& k = m.lead().vehicle.element_kinds;
  return std::find(k.begin(), k.end(), kind) != k.end();
}

TEST(Effects, SchemaListsEverySwitchOfTheEffectTable) {
  const auto& b = rb::scenario::block("run.effects");
  ASSERT_EQ(b.keys.size(), rb::scenario::kEffectSwitches.size());
  for (const auto& e : rb::scenario::kEffectSwitches) {
    const std::string name(rb::nameOf(e.effect));
    const auto* k = b.key(name);
    ASSERT_NE(k, nullptr) << name;
    EXPECT_EQ(k->def, "true");
    EXPECT_EQ(k->help, e.help);
    EXPECT_EQ(rb::parse<Effect>(name), e.effect);
  }
  // What a run records but a user cannot switch is no key of run.effects.
  for (const char* recorded : {"guided_wheelsets", "contact", "normal_forces", "wheelset_spin",
                               "spring_dampers", "shear_springs", "bending_springs"})
    EXPECT_EQ(b.key(recorded), nullptr) << recorded;
  EXPECT_NE(rb::scenario::referenceText().find("run.effects = { ... }"), std::string::npos);
}

TEST(Effects, PresentEffectsFollowTheScene) {
  const auto s3 = load(kCase3);
  for (Effect e : {Effect::Irregularities, Effect::BumpStops, Effect::SeriesDampers,
                   Effect::CreepForces, Effect::Patches, Effect::FlangeContact})
    EXPECT_TRUE(s3.run.effects[rb::scenario::effectIndex(e)].present) << rb::nameOf(e);
  for (Effect e : {Effect::ElementOutputs, Effect::BodyAccelerations, Effect::Assessment})
    EXPECT_FALSE(s3.run.effects[rb::scenario::effectIndex(e)].present) << rb::nameOf(e);
  const auto s1 = load(kCase1);
  EXPECT_FALSE(s1.run.effects[rb::scenario::effectIndex(Effect::Irregularities)].present);
  EXPECT_TRUE(s1.run.effects[rb::scenario::effectIndex(Effect::Assessment)].present);
  // A guided vehicle has no wheel/rail effects.
  const auto g = load("scenarios/vehicle/manchester_guided_r500.lua");
  EXPECT_FALSE(g.run.effects[rb::scenario::effectIndex(Effect::CreepForces)].present);
  EXPECT_FALSE(g.run.effects[rb::scenario::effectIndex(Effect::FlangeContact)].present);
  EXPECT_TRUE(g.run.effects[rb::scenario::effectIndex(Effect::ElementOutputs)].present);
  EXPECT_TRUE(g.run.effects[rb::scenario::effectIndex(Effect::BodyAccelerations)].present);
}

TEST(Effects, BumpStopsOffLeavesNoBumpstopInTheCompiledVehicle) {
  const auto full = compiled(kCase3, {});
  const auto off = compiled(kCase3, {"run.effects.bump_stops=false"});
  EXPECT_TRUE(hasKind(full, "bumpstop"));
  EXPECT_FALSE(hasKind(off, "bumpstop"));
  EXPECT_TRUE(off.lead().vehicle.bumpstops.empty());
  EXPECT_EQ(full.lead().vehicle.bumpstops.size(), 2U);
}

TEST(Effects, PlainSeriesDampersHaveFewerStates) {
  const auto full = compiled(kCase3, {});
  const auto off = compiled(kCase3, {"run.effects.series_dampers=false"});
  const auto nFull = rb::run::makeVehicleOde(full)->size();
  const auto nOff = rb::run::makeVehicleOde(off)->size();
  EXPECT_EQ(nFull - nOff, static_cast<int>(full.lead().vehicle.series_dampers.size()));
  EXPECT_GT(full.lead().vehicle.series_dampers.size(), 0U);
  EXPECT_TRUE(off.lead().vehicle.series_dampers.empty());
  EXPECT_FALSE(hasKind(off, "series_damper"));
}

TEST(Effects, SwitchesOffEveryOutputAndTheCreepLaw) {
  const auto s = load("scenarios/vehicle/manchester_guided_r500.lua",
                      {"run.effects.element_outputs=false", "run.effects.body_accelerations=false",
                       "run.effects.assessment=false"});
  EXPECT_TRUE(s.run.output_elements.empty());
  EXPECT_FALSE(s.run.body_accelerations);
  EXPECT_FALSE(s.run.assessment.stability || s.run.assessment.comfort);
  const auto c = load(kCase1, {"run.effects.creep_forces=false", "run.effects.patches=false"});
  EXPECT_EQ(c.contact.creep, rb::dynamics::CreepModel::None);
  EXPECT_FALSE(c.run.output_patches);
}

// Two short runs; the body series of both, or empty when a run failed.
std::vector<double> ws1y(const std::string& file, std::vector<std::string> ov,
                         const std::string& name) {
  ov.emplace_back("run.duration=0.3");
  const auto out = h5test::freshResult("rb_effects_test", name);
  hid_t f = h5test::runAndOpen(h5test::quietRun(file, out, ov));
  if (f < 0) return {};
  auto y = h5test::dataset(f, "/bodies/ws1/y");
  H5Fclose(f);
  return y;
}

TEST(Effects, IrregularitiesOffIsTheSceneWithoutThem) {
  const auto off = ws1y(kCase3, {"run.effects.irregularities=false"}, "irr_off.h5");
  const auto without = ws1y("scenarios/studies/bases/no_irregularities.lua", {}, "irr_none.h5");
  const auto with = ws1y(kCase3, {}, "irr_on.h5");
  ASSERT_FALSE(off.empty());
  EXPECT_EQ(off, without);
  EXPECT_NE(off, with);
}

TEST(Effects, PlainDampersAreTheWagonBuiltWithThem) {
  const auto off = ws1y(kCase3, {"run.effects.series_dampers=false"}, "sd_off.h5");
  const auto plain = ws1y("scenarios/studies/bases/no_series_dampers.lua", {}, "sd_plain.h5");
  ASSERT_FALSE(off.empty());
  EXPECT_EQ(off, plain);
}

TEST(Effects, ElementOutputsOffWritesNoElements) {
  const auto out = h5test::freshResult("rb_effects_test", "elements_off.h5");
  hid_t f = h5test::runAndOpen(
      h5test::quietRun("scenarios/studies/bases/element_outputs.lua", out,
                       {"run.effects.element_outputs=false", "run.duration=0.05"}));
  ASSERT_GE(f, 0);
  EXPECT_FALSE(h5test::exists(f, "/elements"));
  H5Fclose(f);
}

TEST(Effects, UnknownEffectNameIsAFileLineError) {
  const std::string e = loadError("tests/effects/data/unknown_effect.lua");
  EXPECT_NE(e.find("unknown_effect.lua:8:"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown key 'bump_stop' (did you mean 'bump_stops'?)"), std::string::npos) << e;
  const std::string c = loadError(kCase1, {"run.effects.irregularity=false"});
  EXPECT_NE(c.find("<command line>"), std::string::npos) << c;
  EXPECT_NE(c.find("did you mean 'irregularities'"), std::string::npos) << c;
}

TEST(Effects, ASwitchTheSceneCannotUseIsAnError) {
  // Case 1 runs on a perfect track: there are no irregularities to switch off.
  const std::string e = loadError(kCase1, {"run.effects.irregularities=false"});
  EXPECT_NE(e.find("run.effects.irregularities = false: nothing to switch off, the track has no "
                   "irregularities"),
            std::string::npos)
      << e;
  const std::string g =
      loadError("scenarios/vehicle/manchester_guided_r500.lua", {"run.effects.creep_forces=false"});
  EXPECT_NE(g.find("nothing to switch off"), std::string::npos) << g;
  const std::string f = loadError("tests/effects/data/flange_off.lua");
  EXPECT_NE(f.find("flange_off.lua:8:"), std::string::npos) << f;
  EXPECT_NE(f.find("cannot be switched off without changing the physics"), std::string::npos) << f;
  EXPECT_NE(loadError(kCase1, {"run.effects.patches=1"}).find("patches"), std::string::npos);
  // Switching on what the scene lacks is harmless (default on when the scene has it).
  EXPECT_EQ(loadError(kCase1, {"run.effects.irregularities=true"}), "");
}

TEST(Effects, CasesOfTheCommandFollowTheScene) {
  const auto spec = load(kCase3);
  const auto st = rb::effects::effectsStudy(kCase3, spec, {"run.duration=1"}, 2);
  std::vector<std::string> labels;
  for (const auto& c : st.cases) labels.push_back(c.label);
  const std::vector<std::string> want = {
      "full scene",      "no irregularities", "no bump_stops", "no series_dampers",
      "no creep_forces", "no patches",        "minimal"};
  EXPECT_EQ(labels, want);
  EXPECT_EQ(st.cases.front().role, "baseline");
  EXPECT_EQ(st.cases.back().overrides.size(), 6U);  // the length and 5 switches
  for (const auto& c : st.cases) EXPECT_EQ(c.overrides.front(), "run.duration=1");
  // Flange contact is reported, never measured.
  bool flange = false;
  for (const auto& se : rb::effects::sceneEffects(spec))
    flange = flange || (se.effect == Effect::FlangeContact && se.state == "always on");
  EXPECT_TRUE(flange);
  // An effect the scene switched off itself is not measured again.
  const auto own = load(kCase3, {"run.effects.bump_stops=false"});
  EXPECT_EQ(rb::effects::effectsStudy(kCase3, own, {}, 1).cases.size(), 6U);
}

}  // namespace
