// The hardened cases of `workbench stress` (workbench/stress/plan.hpp) on the scenarios they
// change: a single vehicle's contact{} and speed, and a train's, where every vehicle is hardened
// (the scenario's contact{} and each vehicle's own) and a train starts at one speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "workbench/scenario/scenario.hpp"
#include "workbench/stress/plan.hpp"

namespace {

rb::scenario::ScenarioSpec load(const std::string& path) {
  rb::scenario::LoadOptions lo;
  lo.root = ".";
  return rb::scenario::loadScenario(path, lo);
}

const rb::stress::Hardened* find(const rb::stress::Plan& p, const std::string& axis) {
  for (const auto& h : p.cases)
    if (h.axis == axis) return &h;
  return nullptr;
}

bool has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

bool noted(const rb::stress::Plan& p, const std::string& words) {
  return std::any_of(p.notes.begin(), p.notes.end(),
                     [&](const std::string& n) { return n.find(words) != std::string::npos; });
}

TEST(StressPlan, ASingleVehicleIsHardenedThroughItsContactAndSpeed) {
  const auto spec = load("scenarios/default/case3_kec_fast.lua");
  const auto p = rb::stress::planAxes(spec, {{}, {}, true});
  const auto* mu = find(p, "friction");
  ASSERT_NE(mu, nullptr);
  EXPECT_EQ(mu->overrides, std::vector<std::string>{"contact.mu=0.6"});
  const auto* v = find(p, "speed");
  ASSERT_NE(v, nullptr);
  EXPECT_TRUE(has(v->overrides, "vehicle.speed=40")) << v->overrides.front();
  EXPECT_EQ(find(p, "flange_stiffness"), nullptr);
  EXPECT_TRUE(noted(p, "the contact method is kec"));
  EXPECT_EQ(rb::stress::normalForceCouplings(spec), std::vector<std::string>{"contact."});
}

TEST(StressPlan, ATurnoutsCurveIsNotScaledUnderItsRails) {
  // The turnout's stock rail and blade are laid by slices for its 190 m radius: the curve_radius
  // axis would scale the track and leave the rails where they were. Speed and friction stay.
  const auto spec = load("scenarios/turnout/diverging_r190.lua");
  const auto p = rb::stress::planAxes(spec, {{}, {}, true});
  EXPECT_EQ(find(p, "curve_radius"), nullptr);
  EXPECT_TRUE(noted(p, "rails laid along the track by slices"));
  EXPECT_NE(find(p, "speed"), nullptr);
  EXPECT_NE(find(p, "friction"), nullptr);
  // The same track without slices has its curve scaled.
  const auto plain = load("scenarios/default/case3_kec_fast.lua");
  EXPECT_NE(find(rb::stress::planAxes(plain, {{}, {}, true}), "curve_radius"), nullptr);
}

TEST(StressPlan, ALoweredNoseIsLoweredFurther) {
  // The crossing's nose is lowered toward its tip (its slices' dz < 0): rail_drop scales every
  // lowered slice, and only those.
  const auto spec = load("scenarios/turnout/crossing_through.lua");
  const auto p = rb::stress::planAxes(spec, {{}, {}, true});
  const auto* drop = find(p, "rail_drop");
  ASSERT_NE(drop, nullptr);
  const auto& nose = spec.profiles.extra_rails[1].at(0).slices;
  std::size_t lowered = 0;
  for (std::size_t j = 0; j < nose.size(); ++j) {
    if (!(nose[j].dz < 0.0)) continue;
    const std::string key =
        "profiles.extra_rails.right[1].slices[" + std::to_string(j + 1) + "].dz=";
    const auto it = std::find_if(drop->overrides.begin(), drop->overrides.end(),
                                 [&](const std::string& o) { return o.rfind(key, 0) == 0; });
    ASSERT_NE(it, drop->overrides.end()) << key;
    EXPECT_NEAR(std::stod(it->substr(key.size())), 2.0 * nose[j].dz, 1e-12);
    ++lowered;
  }
  EXPECT_GT(lowered, 5U);
  EXPECT_EQ(drop->overrides.size(), lowered);
  // A scene without lowered rails notes why the axis is left out.
  const auto plain = load("scenarios/default/case3_kec_fast.lua");
  const auto q = rb::stress::planAxes(plain, {{}, {}, true});
  EXPECT_EQ(find(q, "rail_drop"), nullptr);
  EXPECT_TRUE(noted(q, "no lowered blade or nose"));
}

TEST(StressPlan, ATrainIsHardenedInEveryVehicle) {
  // Two Manchester wagons on the scenario's KEC contact{} and a two-axle wagon on its own
  // elastic contact{}.
  const auto spec = load("scenarios/train/three_wagons.lua");
  ASSERT_EQ(spec.train.size(), 3U);
  const auto p = rb::stress::planAxes(spec, {{}, {}, true});
  const auto* mu = find(p, "friction");
  ASSERT_NE(mu, nullptr);
  EXPECT_EQ(mu->overrides,
            (std::vector<std::string>{"contact.mu=0.6", "train.vehicles[3].contact.mu=0.6"}));
  // The KEC transition belongs to the scenario's contact{} only (the elastic wagon has none).
  const auto* kec = find(p, "transition");
  ASSERT_NE(kec, nullptr);
  EXPECT_EQ(kec->overrides,
            (std::vector<std::string>{"contact.dhat=0.0001", "contact.dbar=0.0001"}));
  EXPECT_EQ(find(p, "flange_stiffness"), nullptr);
  EXPECT_TRUE(noted(p, "no vehicle of the train runs on lut"));
  // A train starts at one speed: every vehicle's is scaled, none left at the old one.
  const auto* v = find(p, "speed");
  ASSERT_NE(v, nullptr);
  for (const char* k : {"train.vehicles[1]", "train.vehicles[2]", "train.vehicles[3]"})
    EXPECT_TRUE(has(v->overrides, std::string(k) + ".vehicle.speed=40")) << k;
  EXPECT_FALSE(has(v->overrides, "vehicle.speed=40"));
  // Only the constraint method couples normal forces: the elastic wagon has none to set.
  EXPECT_EQ(rb::stress::normalForceCouplings(spec), std::vector<std::string>{"contact."});
  const auto ref = rb::stress::parseSetting("bdf:1e-9", rb::stress::normalForceCouplings(spec),
                                            "--reference", 0.0);
  EXPECT_TRUE(has(ref.overrides, "contact.normal_forces=consistent"));
}

TEST(StressPlan, TheHardenedTrainLoads) {
  // Every override of every case is a key the train scenario takes (the speeds stay equal).
  const auto spec = load("scenarios/train/three_wagons.lua");
  const auto p = rb::stress::planAxes(spec, {{}, {}, true});
  for (const auto& h : p.cases) {
    rb::scenario::LoadOptions lo;
    lo.root = ".";
    lo.overrides = h.overrides;
    EXPECT_NO_THROW((void)rb::scenario::loadScenario("scenarios/train/three_wagons.lua", lo))
        << h.axis;
  }
}

}  // namespace
