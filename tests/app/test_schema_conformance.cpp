// The schema is the one source of truth of every range (workbench/scenario/schema.cpp): what
// `check` enforces and what `help` prints. This test sweeps every numeric key of every block at
// its bounds and just beyond, each value written in a scenario file on a line of its own, and
// compiles the scene as `check` does (run::compile):
//   - a value outside the key's valid set is refused at the key's file:line, naming the key;
//   - a value inside is never refused by a range of the key's own (no problem at the key's line
//     naming the key): the code takes the whole range the schema states. Other problems of a
//     scene at a bound (a physical check elsewhere) may refuse it, at their own place;
//   - no value ends in an internal error (an exception that is not an InputError: exit 3).
// A key whose valid set is not an interval states its extra values as sentinels (derailment_lift
// = -1); they are swept as inside values. A block without a scene here fails the test, so a new
// block cannot escape the sweep.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/scenario/schema.hpp"
#include "workbench/scenario/study.hpp"

namespace fs = std::filesystem;
using rb::scenario::KeySpec;
using rb::scenario::ValueType;

namespace {

// A scene with the block's fields at "@F@": text before and after, and the fields the block
// needs besides the swept one (required keys, a method the key applies to).
struct Scene {
  std::string text;                            // the scenario, "@F@" where the fields go
  std::map<std::string, std::string> context;  // key = Lua value, unless it is the swept key
};

const std::string kTrack = "track { segments = { tangent { length = 200 } } }\n";
const std::string kContact = "contact { method = \"elastic\", creep = \"polach\" }\n";
const std::string kWheelset =
    "vehicle (require \"vehicles.single_wheelset\" { speed = 10, start = 20 })\n";
const std::string kSolverRun =
    "solver { method = \"abm\", step = 2e-4 }\nrun { duration = 0.01 }\n";
const std::string kWagons =
    "local wagon = require \"vehicles.two_axle_wagon\"\n"
    "contact { method = \"elastic\", creep = \"polach\" }\n";

// A vehicle made in the scene with one more element or body, or initial offsets.
std::string withVehicle(const std::string& edit) {
  return kTrack + kContact +
         "local v = require \"vehicles.single_wheelset\" { speed = 10, "
         "start = 20 }\n" +
         edit + "vehicle (v)\n" + kSolverRun;
}

// Two two-axle wagons joined by one connection (train.connection and its blocks).
std::string withTrain(const std::string& connection, const std::string& train_extra = "") {
  return kTrack + kWagons +
         "train { vehicles = { { name = \"a\", vehicle = wagon { speed = 10, start = 60 } },\n"
         "                     { name = \"b\", vehicle = wagon { speed = 10, start = 46 } } },\n"
         "  connections = { " +
         connection + " },\n" + train_extra + "}\n" + kSolverRun;
}

std::string element(const std::string& kind) {
  return withVehicle("v.elements[#v.elements + 1] = " + kind +
                     " { name = \"swept\", from = \"frame\", to = \"ws\",\n@F@ }\n");
}

const std::string kBuffers =
    "buffers = { loading = { { 0, 0 }, { 0.1, 1e5 } }, unloading = "
    "{ { 0, 0 }, { 0.1, 5e4 } }, spacing = 1.75, height = 1.06 }";
const std::string kDrawGear = "draw_gear = { stiffness = 1e7, height = 1.06 }";
const std::string kConnection = "front = \"a\", rear = \"b\", front_end = -7, rear_end = 7";

std::map<std::string, Scene> scenes() {
  std::map<std::string, Scene> s;
  const std::string rest = kContact + kWheelset + kSolverRun;
  s["track"] = {"track { segments = { tangent { length = 200 } },\n@F@ }\n" + rest, {}};
  s["tangent"] = {"track { segments = { tangent {\n@F@ } } }\n" + rest, {{"length", "200"}}};
  s["transition"] = {
      "track { segments = { tangent { length = 100 }, transition {\n@F@ } } }\n" + rest,
      {{"length", "100"}}};
  s["curve"] = {"track { segments = { tangent { length = 100 }, curve {\n@F@ } } }\n" + rest,
                {{"length", "100"}, {"radius", "1000"}}};
  s["psd"] = {
      "track { segments = { tangent { length = 200 } }, irregularities = psd {\n@F@ } }\n" + rest,
      {{"spectrum", "\"ore_b176_low\""}}};
  s["measured"] = {
      "track { segments = { tangent { length = 200 } }, irregularities = measured {\n@F@ } }\n" +
          rest,
      {{"file", "\"irr.csv\""}}};
  s["profiles"] = {kTrack + "profiles {\n@F@ }\n" + rest, {}};
  s["contact"] = {kTrack + "contact {\n@F@ }\n" + kWheelset + kSolverRun,
                  {{"method", "\"elastic\""}}};
  s["contact.elastic"] = {
      kTrack + "contact { method = \"elastic\", elastic = {\n@F@ } }\n" + kWheelset + kSolverRun,
      {}};
  s["contact.fastsim"] = {kTrack +
                              "contact { method = \"elastic\", creep = \"fastsim\", fastsim = "
                              "{\n@F@ } }\n" +
                              kWheelset + kSolverRun,
                          {}};
  s["contact.elastic.rail_support"] = {
      kTrack + "contact { method = \"elastic\", elastic = { rail_support = {\n@F@ } } }\n" +
          kWheelset + kSolverRun,
      {{"mass", "50"}, {"k_z", "1e8"}, {"k_y", "5e7"}}};
  s["contact.elastic.rail_support.along"] = {
      kTrack +
          "contact { method = \"elastic\", elastic = { rail_support = { mass = 50, k_z = 1e8, "
          "k_y = 5e7, along = { {\n@F@ } } } } }\n" +
          kWheelset + kSolverRun,
      {{"s", "100"}}};  // one point: the support is the same everywhere
  // vehicle{} itself: the wheelset's bodies and elements, its own keys written here.
  s["vehicle"] = {kTrack + kContact +
                      "local v = require \"vehicles.single_wheelset\" { speed = 10 }\n"
                      "vehicle { name = v.name, bodies = v.bodies, elements = v.elements,\n"
                      "@F@ }\n" +
                      kSolverRun,
                  {{"speed", "10"}, {"start", "20"}}};
  // Written in the vehicle's constructor call: a table assigned in code has no line of its own.
  s["vehicle.initial.<body>"] = {
      kTrack + kContact +
          "local v = require \"vehicles.two_axle_wagon\" { speed = 10, start = 20 }\n"
          "vehicle { name = v.name, bodies = v.bodies, elements = v.elements, speed = 10,\n"
          "  start = 20, initial = { car = {\n@F@ } } }\n" +
          kSolverRun,
      {}};
  s["body"] = {withVehicle("v.bodies[#v.bodies + 1] = body { name = \"swept\", kind = \"frame\", "
                           "inertia = { 1, 1, 1 },\n@F@ }\n"),
               {{"mass", "100"}}};
  s["spring_damper"] = {element("spring_damper"), {}};
  s["series_damper"] = {element("series_damper"),
                        {{"damping", "1e4"}, {"series_stiffness", "1e7"}}};
  s["shear_spring"] = {element("shear_spring"), {{"stiffness", "1e5"}}};
  s["bending_spring"] = {element("bending_spring"), {{"stiffness", "1e5"}}};
  // A ramp without rate or duration is refused at the block's line, not at a swept key's.
  s["external_force"] = {
      withVehicle("v.elements[#v.elements + 1] = external_force { name = "
                  "\"swept\", body = \"frame\", direction = { 0, 1, 0 },\n@F@ }\n"),
      {{"law", "\"ramp\""}, {"value", "1e3"}}};
  s["train"] = {withTrain("{ " + kConnection + ", " + kBuffers + ", " + kDrawGear + " }"), {}};
  s["train.connection"] = {
      withTrain("{ front = \"a\", rear = \"b\", " + kBuffers + ", " + kDrawGear + ",\n@F@ }"),
      {{"front_end", "-7"}, {"rear_end", "7"}}};
  s["train.buffers"] = {
      withTrain("{ " + kConnection + ", " + kDrawGear +
                ", buffers = { loading = { { 0, 0 }, { 0.1, 1e5 } }, unloading = { { 0, 0 }, { "
                "0.1, 5e4 } },\n@F@ } }"),
      {{"spacing", "1.75"}, {"height", "1.06"}}};
  s["train.draw_gear"] = {
      withTrain("{ " + kConnection + ", " + kBuffers + ", draw_gear = {\n@F@ } }"),
      {{"stiffness", "1e7"}, {"height", "1.06"}}};
  s["train.coupler"] = {
      withTrain("{ " + kConnection + ", " + kBuffers + ", coupler = {\n@F@ } }"),
      {{"stiffness", "1e7"}, {"height", "1.06"}, {"pivot", "1"}, {"angle_stop", "0.1"}}};
  s["train.longitudinal"] = {
      withTrain("{ " + kConnection + ", " + kBuffers + ", " + kDrawGear + " }",
                "  longitudinal = {\n@F@ },\n"),
      {}};
  s["train.resistance"] = {
      kTrack + kWagons +
          "train { vehicles = { { name = \"a\", vehicle = wagon { speed = 10, start = 60 } },\n"
          "  { name = \"b\", vehicle = wagon { speed = 10, start = 46 }, resistance = {\n@F@ } } "
          "},\n"
          "  connections = { { " +
          kConnection + ", " + kBuffers + ", " + kDrawGear +
          " } },\n"
          "  longitudinal = {} }\n"
          "solver { method = \"abm\", step = 2e-4 }\nrun { duration = 0.01 }\n",
      {}};
  s["train.vehicle"] = {s["train"].text, {}};
  s["solver"] = {kTrack + kContact + kWheelset + "solver {\n@F@ }\nrun { duration = 0.01 }\n",
                 {{"method", "\"abm\""}, {"step", "2e-4"}}};
  s["run"] = {
      kTrack + kContact + kWheelset + "solver { method = \"abm\", step = 2e-4 }\nrun {\n@F@ }\n",
      {}};
  s["run.output"] = {kTrack + kContact + kWheelset +
                         "solver { method = \"abm\", step = 2e-4 }\nrun { duration = 0.01, output "
                         "= {\n@F@ } }\n",
                     {}};
  // An adaptive solver: a fixed step bounds sample_every from below by the step (a refusal at
  // the key's line that depends on solver.step, not on the key's range).
  s["run.assessment"] = {kTrack + kContact + kWheelset +
                             "solver { method = \"dopri5\" }\nrun { duration = 0.01, "
                             "assessment = { safety = true,\n@F@ } }\n",
                         {}};
  s["run.effects"] = {s["run"].text, {}};
  return s;
}

// Keys that take a value only with another one of the block (the scene sets it).
std::map<std::string, std::string> neededFor(const std::string& block, const std::string& key) {
  if (block == "contact") {
    if (key == "dhat" || key == "dbar" || key == "min_normal_force") return {{"method", "\"kec\""}};
    if (key == "flange_stiffness" || key == "flange_damping") return {{"method", "\"lut\""}};
  }
  if (block == "solver" && (key == "rtol" || key == "atol" || key == "max_step" ||
                            key == "max_order" || key == "max_steps"))
    return {{"method", "\"bdf\""}, {"step", "nil"}};
  if (block == "run.assessment" && key == "instability_frequency") return {{"stability", "false"}};
  return {};
}

std::string lua(double x) {
  return rb::formatNumberExact(x);
}

// The test points of a key: (value, inside?). A bound and the nearest value beyond it (an integer
// key: the next whole number; a real one: a relative step of 1e-6, at least 1e-9).
std::vector<std::pair<double, bool>> points(const KeySpec& k) {
  std::vector<std::pair<double, bool>> out;
  const auto beyond = [&](double b, double dir) {
    // Beyond 2^53 the next whole number may be the bound itself: the next double then.
    if (k.type == ValueType::Integer)
      return b + dir != b ? b + dir : std::nextafter(b, dir * HUGE_VAL);
    return b + dir * std::max(1e-9, std::abs(b) * 1e-6);
  };
  if (std::isfinite(k.min)) {
    out.emplace_back(k.min, !k.min_exclusive);
    out.emplace_back(k.min_exclusive ? beyond(k.min, +1) : beyond(k.min, -1), k.min_exclusive);
  }
  if (std::isfinite(k.max)) {
    out.emplace_back(k.max, !k.max_exclusive);
    out.emplace_back(k.max_exclusive ? beyond(k.max, -1) : beyond(k.max, +1), k.max_exclusive);
  }
  for (const double s : k.sentinels) {
    out.emplace_back(s, true);
    // Just beside the sentinel, unless that is inside the interval.
    for (const double dir : {-1.0, 1.0}) {
      const double x = beyond(s, dir);
      if (!(x >= k.min && x <= k.max)) out.emplace_back(x, false);
    }
  }
  // A value beside a sentinel inside the interval (derailment_lift's -0.5 between -1 and 1e-3).
  for (const double s : k.sentinels)
    if (std::isfinite(k.min) && s < k.min) out.emplace_back(0.5 * (s + k.min), false);
  return out;
}

struct Outcome {
  bool internal = false;  // an exception that is not an InputError
  std::vector<rb::Diagnostic> problems;
  std::string what;
};

Outcome compileScene(const std::string& file) {
  Outcome o;
  rb::run::CompileOptions co;
  co.scenario = file;
  co.root = RB_SOURCE_DIR;
  try {
    (void)rb::run::compile(co);
  } catch (const rb::InputError& e) {
    o.problems = e.diagnostics();
    o.what = e.what();
  } catch (const std::exception& e) {
    o.internal = true;
    o.what = e.what();
  }
  return o;
}

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("rb_conformance_" + std::to_string(::getpid()));
  TempDir() {
    fs::remove_all(path);
    fs::create_directories(path);
    std::ofstream(path / "irr.csv") << "s,alignment\n0,0\n100,0.001\n300,0\n";
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// The scene of `block` with `key = value` on a line of its own; `line` is set to that line.
std::string sceneText(const Scene& sc, const std::string& block, const std::string& key,
                      const std::string& value, int& line) {
  std::map<std::string, std::string> fields = sc.context;
  for (const auto& [k, v] : neededFor(block, key)) fields[k] = v;
  fields.erase(key);
  std::string f;
  for (const auto& [k, v] : fields) f += "  " + k + " = " + v + ",\n";
  f += "  " + key + " = " + value + "\n";
  std::string text = sc.text;
  const std::size_t at = text.find("@F@");
  text.replace(at, 3, f);
  line = 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n')) +
         static_cast<int>(fields.size());
  return text;
}

bool mentions(const rb::Diagnostic& d, const std::string& file, int line, const std::string& key) {
  return d.loc.file == file && d.loc.line == line && d.message.find(key) != std::string::npos;
}

}  // namespace

TEST(SchemaConformance, EveryNumericKeyAtItsBoundsAndBeyond) {
  const TempDir dir;
  const auto all = scenes();
  std::vector<std::string> findings;
  int swept = 0;
  for (const auto& b : rb::scenario::schema()) {
    if (b.name == "study") continue;  // a study file: EveryStudyKey below
    for (const auto& k : b.keys) {
      if (k.type != ValueType::Number && k.type != ValueType::Integer) continue;
      const auto sc = all.find(b.name);
      if (sc == all.end()) {
        findings.push_back(b.name + "." + k.name + ": no scene for block '" + b.name + "'");
        continue;
      }
      for (const auto& [x, inside] : points(k)) {
        int line = 0;
        const std::string file = (dir.path / "scene.lua").string();
        std::ofstream(file) << sceneText(sc->second, b.name, k.name, lua(x), line);
        const Outcome o = compileScene(file);
        ++swept;
        const std::string what =
            b.name + "." + k.name + " = " + lua(x) + (inside ? " (inside)" : " (outside)") + ": ";
        if (o.internal) {
          findings.push_back(what + "internal error: " + o.what);
          continue;
        }
        bool at_key = false;
        for (const auto& d : o.problems) at_key = at_key || mentions(d, file, line, k.name);
        if (inside && at_key) findings.push_back(what + "refused at the key's line: " + o.what);
        if (!inside && !at_key)
          findings.push_back(what + "not refused at scene.lua:" + std::to_string(line) + ": " +
                             (o.what.empty() ? "<accepted>" : o.what));
      }
    }
  }
  EXPECT_GT(swept, 300);
  std::string all_findings;
  for (const auto& f : findings) all_findings += f + "\n";
  EXPECT_TRUE(findings.empty()) << findings.size() << " findings:\n" << all_findings;
}

TEST(SchemaConformance, EveryStudyKey) {
  const TempDir dir;
  std::ofstream(dir.path / "base.lua") << kTrack << kContact << kWheelset << kSolverRun;
  std::vector<std::string> findings;
  for (const auto& k : rb::scenario::block("study").keys) {
    if (k.type != ValueType::Number && k.type != ValueType::Integer) continue;
    for (const auto& [x, inside] : points(k)) {
      const std::string file = (dir.path / "study.lua").string();
      std::ofstream(file) << "study { base = \"base.lua\",\n  " << k.name << " = " << lua(x)
                          << " }\n";
      std::string what;
      bool at_key = false, internal = false;
      try {
        (void)rb::scenario::loadStudy(file, RB_SOURCE_DIR);
      } catch (const rb::InputError& e) {
        for (const auto& d : e.diagnostics()) at_key = at_key || mentions(d, file, 2, k.name);
        what = e.what();
      } catch (const std::exception& e) {
        internal = true;
        what = e.what();
      }
      const std::string label = "study." + k.name + " = " + lua(x) + ": ";
      if (internal) findings.push_back(label + "internal error: " + what);
      if (inside && at_key) findings.push_back(label + "refused inside: " + what);
      if (!inside && !at_key) findings.push_back(label + "not refused at study.lua:2: " + what);
    }
  }
  std::string all;
  for (const auto& f : findings) all += f + "\n";
  EXPECT_TRUE(findings.empty()) << all;
}

// help prints each key's valid set as check enforces it (rangeText), sentinels included.
TEST(SchemaConformance, HelpPrintsTheRangeCheckEnforces) {
  const std::string text = rb::scenario::referenceText();
  for (const auto& b : rb::scenario::schema())
    for (const auto& k : b.keys) {
      const std::string range = rb::scenario::rangeText(k);
      if (range.empty()) continue;
      EXPECT_NE(text.find("  " + k.name + " ("), std::string::npos) << b.name << "." << k.name;
      EXPECT_NE(text.find(", range " + range + "\n"), std::string::npos)
          << b.name << "." << k.name << ": help does not print range " << range;
    }
  const KeySpec* lift = rb::scenario::block("contact.elastic").key("derailment_lift");
  ASSERT_NE(lift, nullptr);
  EXPECT_EQ(rb::scenario::rangeText(*lift), "[0.001, 0.1] or -1");
  EXPECT_FALSE(rb::scenario::rangeProblem(*lift, -1.0).has_value());
  EXPECT_EQ(rb::scenario::rangeProblem(*lift, -0.5).value_or(""),
            "in [0.001, 0.1] m or -1, got -0.5");
}
