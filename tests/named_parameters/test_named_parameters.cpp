// Named parameters: --set addressing of bodies and elements by name, vehicle groups (a group's key
// set in every member), their errors with the nearest name, and the study-time check at the study
// file's line.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "workbench/scenario/lua_host.hpp"
#include "workbench/scenario/override_check.hpp"
#include "workbench/scenario/overrides.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/scenario/study.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/model.hpp"

using rb::scenario::loadScenario;
using rb::scenario::ScenarioSpec;

namespace {

const std::string kDir = "tests/named_parameters/";

ScenarioSpec load(const std::string& file, const std::vector<std::string>& overrides = {}) {
  rb::scenario::LoadOptions o;
  o.root = RB_SOURCE_DIR;
  o.overrides = overrides;
  return loadScenario(file, o);
}

std::string errorOf(const std::string& file, const std::vector<std::string>& overrides = {}) {
  try {
    load(file, overrides);
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "";
}

std::string studyError(const std::string& file) {
  try {
    rb::scenario::loadStudy(file, RB_SOURCE_DIR);
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The compiled vehicle of a scenario (its parameters as the dynamics uses them).
rb::vehicle::VehicleModel compiled(const ScenarioSpec& spec) {
  return rb::vehicle::compileVehicle(spec.vehicle, rb::track::compileTrack(spec.track));
}

double springStiffness(const rb::vehicle::VehicleModel& m, const std::string& name) {
  const auto id = m.findElement(name);
  EXPECT_TRUE(id.has_value()) << name;
  if (!id) return -1;
  EXPECT_EQ(id->kind, rb::vehicle::ElementKind::SpringDamper) << name;
  return m.spring_dampers[static_cast<std::size_t>(id->index)].stiffness;
}

}  // namespace

// The group primary_longitudinal of the wagon file holds exactly its 8 prim_x springs, and
// setting its stiffness changes every one of them in the compiled model and nothing else.
TEST(NamedParameters, GroupOverrideChangesEveryMember) {
  const ScenarioSpec base = load(kDir + "wagon.lua");
  const ScenarioSpec swept =
      load(kDir + "wagon.lua", {"vehicle.groups.primary_longitudinal.stiffness=1e7"});
  const auto mb = compiled(base);
  const auto ms = compiled(swept);
  ASSERT_EQ(mb.spring_dampers.size(), ms.spring_dampers.size());
  int changed = 0;
  for (std::size_t i = 0; i < ms.spring_dampers.size(); ++i) {
    const std::string& name = ms.spring_dampers[i].g.name;
    if (name.rfind("prim_x_", 0) == 0) {
      EXPECT_EQ(ms.spring_dampers[i].stiffness, 1e7) << name;
      EXPECT_EQ(mb.spring_dampers[i].stiffness, 31391e3) << name;
      ++changed;
    } else {
      EXPECT_EQ(ms.spring_dampers[i].stiffness, mb.spring_dampers[i].stiffness) << name;
    }
    EXPECT_EQ(ms.spring_dampers[i].damping, mb.spring_dampers[i].damping) << name;
  }
  EXPECT_EQ(changed, 8);
  // A mirrored pair: the two springs of one wheelset, and no other.
  const auto mp = compiled(load(kDir + "wagon.lua", {"vehicle.groups.prim_x_ws2.stiffness=2e7"}));
  EXPECT_EQ(springStiffness(mp, "prim_x_ws2_l"), 2e7);
  EXPECT_EQ(springStiffness(mp, "prim_x_ws2_r"), 2e7);
  EXPECT_EQ(springStiffness(mp, "prim_x_ws1_l"), 31391e3);
  EXPECT_EQ(springStiffness(mp, "prim_x_ws3_r"), 31391e3);
}

// Groups name elements only: the wagon's spec is the same as without them (same elements, same
// values), so results stay as they were.
TEST(NamedParameters, GroupsDoNotChangeTheModel) {
  const ScenarioSpec spec = load(kDir + "wagon.lua");
  EXPECT_EQ(spec.vehicle.elements.size(), 50u);
  EXPECT_EQ(spec.vehicle.bodies.size(), 7u);
}

// By name and by list position set the same value in the same element / body.
TEST(NamedParameters, ByNameEqualsByIndex) {
  const ScenarioSpec base = load(kDir + "wagon.lua");
  std::size_t element = 0, body = 0;
  for (std::size_t i = 0; i < base.vehicle.elements.size(); ++i)
    if (base.vehicle.elements[i].name == "prim_x_ws3_r") element = i + 1;
  for (std::size_t i = 0; i < base.vehicle.bodies.size(); ++i)
    if (base.vehicle.bodies[i].name == "bogie2") body = i + 1;
  ASSERT_GT(element, 0u);
  ASSERT_GT(body, 0u);
  const ScenarioSpec byName =
      load(kDir + "wagon.lua",
           {"vehicle.elements.prim_x_ws3_r.stiffness=1e7", "vehicle.bodies.bogie2.mass=3000"});
  const ScenarioSpec byIndex =
      load(kDir + "wagon.lua", {"vehicle.elements[" + std::to_string(element) + "].stiffness=1e7",
                                "vehicle.bodies." + std::to_string(body) + ".mass=3000"});
  ASSERT_EQ(byName.vehicle.elements.size(), byIndex.vehicle.elements.size());
  for (std::size_t i = 0; i < byName.vehicle.elements.size(); ++i)
    EXPECT_EQ(byName.vehicle.elements[i].stiffness, byIndex.vehicle.elements[i].stiffness) << i;
  EXPECT_EQ(byName.vehicle.elements[element - 1].stiffness, 1e7);
  EXPECT_NE(base.vehicle.elements[element - 1].stiffness, 1e7);
  for (std::size_t i = 0; i < byName.vehicle.bodies.size(); ++i)
    EXPECT_EQ(byName.vehicle.bodies[i].mass, byIndex.vehicle.bodies[i].mass) << i;
  EXPECT_EQ(byName.vehicle.bodies[body - 1].mass, 3000.0);
}

// A typo in a group, element or body name is an error naming the path with the nearest name.
TEST(NamedParameters, TypoIsAnErrorWithASuggestion) {
  const std::string what =
      errorOf(kDir + "wagon.lua",
              {"vehicle.groups.primary_longitudnal.stiffness=1e7",
               "vehicle.elements.prim_x_ws1_q.stiffness=1e7", "vehicle.bodies.cat.mass=1"});
  EXPECT_TRUE(contains(what,
                       "<command line>: --set vehicle.groups.primary_longitudnal.stiffness=1e7: "
                       "vehicle.groups: no group named 'primary_longitudnal' (did you mean "
                       "'primary_longitudinal'?)"))
      << what;
  EXPECT_TRUE(contains(what,
                       "--set vehicle.elements.prim_x_ws1_q.stiffness=1e7: vehicle.elements: no "
                       "element named 'prim_x_ws1_q' (did you mean 'prim_x_ws1_"))
      << what;
  EXPECT_TRUE(contains(what,
                       "--set vehicle.bodies.cat.mass=1: vehicle.bodies: no body named 'cat' (did "
                       "you mean 'car'?)"))
      << what;
}

// A key a member's kind does not have is an error naming the member, and no member is changed.
TEST(NamedParameters, MemberWithoutTheKeyIsAnError) {
  const std::string what = errorOf(kDir + "wagon.lua", {"vehicle.groups.bumpstops.stiffness=1e7"});
  EXPECT_TRUE(contains(what,
                       "vehicle.groups.bumpstops: element 'bump_y_bogie1' (bumpstop) has "
                       "no key 'stiffness'"))
      << what;
  // series_stiffness: the primary vertical dampers have it, the plain dampers of
  // series_dampers = false would not; the wagon's default has it in all 8.
  const ScenarioSpec s =
      load(kDir + "wagon.lua", {"vehicle.groups.primary_vertical.series_stiffness=2e6"});
  int n = 0;
  for (const auto& e : s.vehicle.elements)
    if (e.name.rfind("prim_z_", 0) == 0) {
      EXPECT_EQ(e.series_stiffness, 2e6) << e.name;
      ++n;
    }
  EXPECT_EQ(n, 8);
  // A group naming no key, and a whole element set to a value, are refused.
  EXPECT_TRUE(contains(errorOf(kDir + "wagon.lua", {"vehicle.groups.primary_lateral=1"}),
                       "vehicle.groups.primary_lateral is a group; name the key"));
  EXPECT_TRUE(contains(errorOf(kDir + "wagon.lua", {"vehicle.elements.prim_y_ws1_l=1"}),
                       "vehicle.elements.prim_y_ws1_l is a whole element"));
}

// Group patterns that match nothing are reported at their line in the vehicle file.
TEST(NamedParameters, UnmatchedGroupPatternAtTheVehicleFileLine) {
  const std::string what = errorOf(kDir + "tiny_bad.lua");
  const std::string file = kDir + "vehicles/tiny_bad.lua:";
  EXPECT_TRUE(contains(what, file +
                                 "16: vehicle: groups.typo: no element named 'sprung_r' (did you "
                                 "mean 'spring_r'?)"))
      << what;
  EXPECT_TRUE(contains(what, file + "17: vehicle: groups.nothing: pattern 'damper_*' matches no "
                                    "element"))
      << what;
  EXPECT_TRUE(contains(what, file + "18: vehicle: groups.empty: lists no elements")) << what;
  EXPECT_FALSE(contains(what, "groups.good")) << what;
}

// Hostile groups: an empty name, a body, a dotted group name, a number are errors; '*' alone is
// every element (and a key not every element has is refused, naming one); a dotted element name
// works inside a group but cannot be a --set path token.
TEST(NamedParameters, HostileGroups) {
  const std::string what = errorOf(kDir + "hostile.lua");
  EXPECT_TRUE(contains(what,
                       "groups.empty_name: entries must be element names or patterns, got an "
                       "empty name"))
      << what;
  EXPECT_TRUE(contains(what,
                       "groups.body_member: 'ws' names a body ('ws'); a group holds "
                       "suspension elements"))
      << what;
  EXPECT_TRUE(contains(what, "group name 'a.b' must be letters, digits and _")) << what;
  EXPECT_TRUE(contains(what,
                       "groups.not_a_name: entries must be element names or patterns, got "
                       "number 42"))
      << what;
  EXPECT_FALSE(contains(what, "groups.everything")) << what;
  EXPECT_FALSE(contains(what, "groups.dotted")) << what;
  // Reported at the scenario's lines, where they are written.
  EXPECT_TRUE(contains(what, kDir + "hostile.lua:4: vehicle: groups.empty_name")) << what;
  EXPECT_TRUE(contains(what, kDir + "hostile.lua:5: vehicle: groups.body_member")) << what;

  const ScenarioSpec all = load(kDir + "tiny.lua", {"vehicle.groups.springs.damping=7"});
  for (const auto& e : all.vehicle.elements)
    EXPECT_EQ(e.damping, e.name.rfind("spring_", 0) == 0 ? 7.0 : (e.name == "damper" ? 4e3 : 0.0))
        << e.name;
  const std::string star = errorOf(
      kDir + "tiny.lua", {"vehicle.groups.pair.table=1", "vehicle.elements..stiffness=1",
                          "vehicle.elements.dotted.name.stiffness=1", "vehicle.groups..x=1"});
  EXPECT_TRUE(contains(star, "element 'spring_l' (spring_damper) has no key 'table'")) << star;
  // An empty name between two dots is a malformed path, never read as if the dot were single.
  EXPECT_TRUE(contains(star, "'vehicle.elements..stiffness' is not a key path")) << star;
  EXPECT_TRUE(contains(star, "vehicle.elements: no element named 'dotted'")) << star;
  EXPECT_TRUE(contains(star, "'vehicle.groups..x' is not a key path")) << star;
  // '*' alone: every element; a key one of them lacks is refused, naming it, and changes nothing.
  EXPECT_TRUE(contains(errorOf(kDir + "tiny.lua", {"vehicle.groups.all.stiffness=1"}),
                       "vehicle.groups.all: element 'stop' (bumpstop) has no key 'stiffness'"));
  const ScenarioSpec y = load(kDir + "tiny.lua", {"vehicle.groups.all.direction=y"});
  ASSERT_EQ(y.vehicle.elements.size(), 5u);
  for (const auto& e : y.vehicle.elements)
    EXPECT_EQ(e.direction, rb::vehicle::Direction::Y) << e.name;
}

TEST(NamedParameters, GlobMatch) {
  using rb::scenario::globMatch;
  EXPECT_TRUE(globMatch("*", ""));
  EXPECT_TRUE(globMatch("*", "prim_x_ws1_l"));
  EXPECT_TRUE(globMatch("prim_x_*", "prim_x_ws1_l"));
  EXPECT_FALSE(globMatch("prim_x_*", "prim_y_ws1_l"));
  EXPECT_TRUE(globMatch("prim_*_ws1_*", "prim_z_ws1_r"));
  EXPECT_FALSE(globMatch("prim_*_ws1_*", "prim_z_ws2_r"));
  EXPECT_TRUE(globMatch("*_l", "sec_z_bogie1_l"));
  EXPECT_FALSE(globMatch("*_l", "sec_z_bogie1_r"));
  EXPECT_FALSE(globMatch("sec_x_*", "sec_shear_x_bogie1_l"));
  EXPECT_TRUE(globMatch("a**b", "ab"));
  EXPECT_FALSE(globMatch("ab", "abc"));
}

// In a study, a key naming nothing is an error at the study file's line of that key, with the
// nearest name, when the study is loaded (before anything runs); good names load.
TEST(NamedParameters, StudyTypoAtTheStudyLine) {
  const std::string file = kDir + "study_typo.lua";
  const std::string what = studyError(file);
  EXPECT_TRUE(contains(what, file + ":6: study: \"vehicle.groups.primary_longitudnal.stiffness\": "
                                    "vehicle.groups: no group named 'primary_longitudnal' (did you "
                                    "mean 'primary_longitudinal'?)"))
      << what;
  EXPECT_TRUE(contains(what, file + ":10: study: \"vehicle.elements.prim_x_ws1_q.stiffness\": "
                                    "vehicle.elements: no element named 'prim_x_ws1_q'"))
      << what;
  EXPECT_TRUE(contains(what, file + ":11: study: \"vehicle.bodies.cat.mass\": vehicle.bodies: no "
                                    "body named 'cat' (did you mean 'car'?)"))
      << what;
  EXPECT_FALSE(contains(what, "vehicle.speed")) << what;
  const auto st = rb::scenario::loadStudy(kDir + "study_good.lua", RB_SOURCE_DIR);
  EXPECT_EQ(st.cases.size(), 4u);
}

// Every case repeats the study's override keys: the check tries each distinct key once (the
// first value), and finding them is not quadratic in the number of overrides (found by
// tests/fuzz: 100 cases of 2000 overrides each took a minute to load). Quadratic, the 200 cases
// of 10000 keys here would take minutes; linear, well under a second.
TEST(NamedParameters, StudyOverrideCheckScalesWithManyOverrides) {
  rb::scenario::StudySpec st;
  st.file = kDir + "study_good.lua";
  st.root = RB_SOURCE_DIR;
  const std::string base = kDir + "wagon.lua";
  for (int c = 0; c < 200; ++c) {
    rb::scenario::StudyCase sc;
    sc.base = base;
    for (int k = 0; k < 10000; ++k)
      sc.overrides.push_back("run.k" + std::to_string(k) + "=" + std::to_string(c));
    st.cases.push_back(sc);
  }
  st.cases[7].overrides.push_back("vehicle.bodies.cat.mass=1");
  const auto start = std::chrono::steady_clock::now();
  std::string what;
  try {
    rb::scenario::checkStudyOverrides(st, "", RB_SOURCE_DIR);
  } catch (const rb::InputError& e) {
    what = e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);
  EXPECT_TRUE(contains(what, "\"vehicle.bodies.cat.mass\": vehicle.bodies: no body named 'cat'"))
      << what;
}

// `workbench help vehicle SCENARIO.lua`: bodies, elements with kind and keys, groups with members
// and the keys every member has.
TEST(NamedParameters, HelpListsTheNamedParameters) {
  const std::string text = rb::scenario::vehicleParametersText(kDir + "wagon.lua", RB_SOURCE_DIR);
  EXPECT_TRUE(contains(text, "  car (car): mass=32000\n")) << text;
  EXPECT_TRUE(contains(text, "  prim_x_ws1_l (spring_damper): stiffness=3.1391e+07 damping=15000"))
      << text;
  EXPECT_TRUE(contains(text, "  bump_y_bogie1 (bumpstop): table\n")) << text;
  EXPECT_TRUE(contains(text,
                       "  primary_longitudinal (8): prim_x_ws1_l prim_x_ws1_r prim_x_ws2_l "
                       "prim_x_ws2_r prim_x_ws3_l prim_x_ws3_r prim_x_ws4_l prim_x_ws4_r\n"
                       "      keys: stiffness damping length0 preload\n"))
      << text;
  EXPECT_TRUE(contains(text, "  prim_z_ws1 (2): prim_z_ws1_l prim_z_ws1_r\n")) << text;
  std::string noVehicle;
  try {
    rb::scenario::vehicleParametersText("scenarios/tracks/manchester_r500.lua", RB_SOURCE_DIR);
  } catch (const rb::InputError& e) {
    noVehicle = e.what();
  }
  EXPECT_TRUE(contains(noVehicle, "no vehicle{} or train{} block")) << noVehicle;
  // The command line prints the same listing.
  const std::string cmd = std::string(RB_BINARY_DIR) + "/workbench/app/workbench --root " +
                          RB_SOURCE_DIR + " help vehicle " + kDir + "wagon.lua";
  FILE* p = popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string out;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, p) != nullptr) out += buf;
  EXPECT_EQ(pclose(p), 0);
  EXPECT_EQ(out, text);
}

namespace {

// A --set path as an axis label: words and the schema's SI unit, an element's or a group's key by
// its members' kind (a bending spring's stiffness is N m/rad, a spring's N/m).
TEST(NamedParameters, LabelsWithUnitsFromTheSchema) {
  rb::scenario::HostOptions ho;
  ho.root = RB_SOURCE_DIR;
  rb::scenario::LuaHost host(ho);
  const rb::scenario::Node tree = host.runFile(kDir + "wagon.lua");
  auto label = [&](const std::string& path) {
    const auto l = rb::scenario::parameterLabel(tree, path);
    return l.label + " [" + l.unit + "]";
  };
  EXPECT_EQ(label("vehicle.groups.primary_longitudinal.stiffness"),
            "primary longitudinal stiffness [N/m]");
  EXPECT_EQ(label("vehicle.elements.sec_bend_bogie1_l.stiffness"),
            "sec bend bogie1 l stiffness [N m/rad]");
  EXPECT_EQ(label("vehicle.speed"), "vehicle speed [m/s]");
  EXPECT_EQ(label("vehicle.bodies.car.mass"), "car mass [kg]");
  EXPECT_EQ(label("track.segments[1].length"), "track segments 1 length [m]");
  EXPECT_EQ(label("run.duration"), "run duration [s]");
  EXPECT_EQ(label("vehicle.initial.ws1.y"), "initial ws1 y [m]");
  // A path that names nothing keeps its text, without a unit.
  EXPECT_EQ(label("vehicle.groups.nothing.stiffness"), "vehicle.groups.nothing.stiffness []");
}

}  // namespace
