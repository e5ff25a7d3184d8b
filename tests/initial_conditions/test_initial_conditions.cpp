// vehicle.initial (initial conditions of a run): the Lua syntax and --set, every hostile input as
// file:line naming the key, the check against the compiled model's states (workbench check
// refuses before anything runs), runs that start from the given state (first output sample) and
// record it in /initial_conditions, and an empty table that changes nothing.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "workbench/io/result_file.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/vehicle_run.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/scenario/schema.hpp"
#include "workbench/vehicle/initial_conditions.hpp"
#include "workbench/vehicle/kinematics.hpp"

namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() /
             ("rb_initial_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary | std::ios::trunc) << text;
    return (path / name).string();
  }
};

// The Manchester wagon on a 200 m tangent without irregularities, KEC contact (or guided when
// `contact` is false); `initial` is Lua put after `local v = wagon{...}` (line 6).
std::string wagonScenario(const std::string& initial, bool contact = true,
                          const std::string& run = "duration = 0.05") {
  return std::string("local hard = require \"hard.lib\"\n") +                 // 1
         "track { segments = { tangent { length = 200 } }, step = 0.5 }\n" +  // 2
         (contact ? "hard.profiles()\n" : "\n") +                             // 3
         (contact ? "contact { method = \"kec\", creep = \"polach\", mu = hard.MU_PAPER }\n"
                  : "contact { method = \"guided\" }\n") +                      // 4
         "local v = require \"vehicles.manchester_wagon1\" { speed = 20 }\n" +  // 5
         initial +
         "\n" +                                               // 6
         "vehicle (v)\n" +                                    // 7
         "solver { method = \"dopri5\" }\n" +                 // 8
         "run { " + run + ", output = { every = 0.01 } }\n";  // 9
}

rb::scenario::LoadOptions loadOptions(std::vector<std::string> overrides = {}) {
  rb::scenario::LoadOptions o;
  o.root = RB_SOURCE_DIR;
  o.overrides = std::move(overrides);
  return o;
}

std::string loadErrors(const std::string& file, std::vector<std::string> overrides = {}) {
  try {
    rb::scenario::loadScenario(file, loadOptions(std::move(overrides)));
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "<no error>";
}

rb::run::CompileOptions compileOptions(const std::string& file,
                                       std::vector<std::string> overrides = {}) {
  rb::run::CompileOptions o;
  o.scenario = file;
  o.root = RB_SOURCE_DIR;
  o.overrides = std::move(overrides);
  return o;
}

std::string compileErrors(const std::string& file, std::vector<std::string> overrides = {}) {
  try {
    rb::run::compile(compileOptions(file, std::move(overrides)));
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "<no error>";
}

// Runs a scenario in-process into `out` (as `workbench run` does).
void runInto(const std::string& file, const std::string& out,
             std::vector<std::string> overrides = {}) {
  const rb::run::Model m = rb::run::compile(compileOptions(file, std::move(overrides)));
  rb::io::ResultFile f(out);
  rb::run::writeProvenance(m, f, "test");
  const rb::run::VehicleRunResult res = rb::run::runVehicle(m, f, {});
  f.finalize();
  ASSERT_TRUE(res.result.ok) << res.result.message;
}

std::vector<double> series(const std::string& file, const std::string& path) {
  rb::io::ResultReader r(file);
  EXPECT_TRUE(r.ok()) << file;
  auto d = r.dataset(path);
  EXPECT_TRUE(d.has_value()) << file << " " << path;
  return d.value_or(std::vector<double>{});
}

}  // namespace

TEST(InitialConditionsSchema, KeysAgreeWithTheVehicleNamesAndAreListed) {
  const rb::scenario::BlockSpec& b = rb::scenario::block("vehicle.initial.<body>");
  std::vector<std::string> keys;
  for (const bool rate : {false, true})
    for (int c = rb::vehicle::kY; c <= rb::vehicle::kYaw; ++c)
      keys.push_back(rb::vehicle::initialConditionKey(c, rate));
  EXPECT_EQ(b.keyNames(), keys);
  ASSERT_NE(rb::scenario::block("vehicle").key("initial"), nullptr);
  const std::string help = rb::scenario::referenceText();
  EXPECT_NE(help.find("vehicle.initial.<body> = { ... }"), std::string::npos);
  EXPECT_NE(help.find("  yaw_dot (number, rad/s) default 0, range [-5, 5]\n"), std::string::npos);
  EXPECT_NE(help.find("  initial (table)"), std::string::npos);
}

TEST(InitialConditionsParse, LuaTableGivesOneConditionPerKey) {
  TempDir t("parse");
  const std::string f = t.write(
      "s.lua", wagonScenario("v.initial = { ws1 = { y = 3e-3 }, car = { roll = 1e-3, y_dot = "
                             "0.01 }, bogie2 = { yaw_dot = -0.02, pitch = 0 } }"));
  const auto spec = rb::scenario::loadScenario(f, loadOptions());
  const auto& ic = spec.vehicle.initial;
  ASSERT_EQ(ic.size(), 5U);
  // Bodies in name order, keys in coordinate order, positions before rates.
  EXPECT_EQ(ic[0].body, "bogie2");
  EXPECT_EQ(ic[0].coord, rb::vehicle::kPitch);
  EXPECT_FALSE(ic[0].rate);
  EXPECT_EQ(ic[0].value, 0.0);
  EXPECT_EQ(ic[1].body, "bogie2");
  EXPECT_EQ(ic[1].coord, rb::vehicle::kYaw);
  EXPECT_TRUE(ic[1].rate);
  EXPECT_EQ(ic[1].value, -0.02);
  EXPECT_EQ(ic[2].body, "car");
  EXPECT_EQ(ic[2].coord, rb::vehicle::kRoll);
  EXPECT_EQ(ic[2].value, 1e-3);
  EXPECT_EQ(ic[3].body, "car");
  EXPECT_EQ(ic[3].coord, rb::vehicle::kY);
  EXPECT_TRUE(ic[3].rate);
  EXPECT_EQ(ic[3].value, 0.01);
  EXPECT_EQ(ic[4].body, "ws1");
  EXPECT_EQ(ic[4].coord, rb::vehicle::kY);
  EXPECT_FALSE(ic[4].rate);
  EXPECT_EQ(ic[4].value, 3e-3);
  EXPECT_EQ(ic[4].loc.file, f);
  EXPECT_EQ(ic[4].loc.line, 7);  // the vehicle (v) call
}

TEST(InitialConditionsParse, SetCreatesTheTableOnAScenarioWithoutOne) {
  TempDir t("set");
  const std::string f = t.write("s.lua", wagonScenario(""));
  const auto spec = rb::scenario::loadScenario(
      f, loadOptions({"vehicle.initial.ws1.y=0.003", "vehicle.initial.car.yaw_dot=-1e-3"}));
  const auto& ic = spec.vehicle.initial;
  ASSERT_EQ(ic.size(), 2U);
  EXPECT_EQ(ic[0].body, "car");
  EXPECT_EQ(ic[0].coord, rb::vehicle::kYaw);
  EXPECT_TRUE(ic[0].rate);
  EXPECT_EQ(ic[0].value, -1e-3);
  EXPECT_EQ(ic[1].body, "ws1");
  EXPECT_EQ(ic[1].value, 0.003);
  EXPECT_EQ(ic[1].loc.file, "<command line>");
  // --set also replaces a value the file gives.
  const std::string g = t.write("g.lua", wagonScenario("v.initial = { ws1 = { y = 1e-3 } }"));
  const auto spec2 = rb::scenario::loadScenario(g, loadOptions({"vehicle.initial.ws1.y=2e-3"}));
  ASSERT_EQ(spec2.vehicle.initial.size(), 1U);
  EXPECT_EQ(spec2.vehicle.initial[0].value, 2e-3);
}

TEST(InitialConditionsParse, EveryHostileInputIsNamedAtItsLine) {
  TempDir t("hostile");
  auto errors = [&](const std::string& initial) {
    return loadErrors(t.write("h.lua", wagonScenario(initial)));
  };
  const std::string at = (t.path / "h.lua").string() + ":7: ";
  EXPECT_EQ(errors("v.initial = { ws7 = { y = 1e-3 } }"),
            at + "vehicle: initial: no body named 'ws7' (did you mean 'ws1'?)");
  EXPECT_EQ(errors("v.initial = { locomotive = { y = 1e-3 } }"),
            at + "vehicle: initial: no body named 'locomotive' (bodies: car, bogie1, ws1, ws2, "
                 "bogie2, ws3, ws4)");
  EXPECT_EQ(errors("v.initial = { ws1 = { yaww = 1e-3 } }"),
            at + "vehicle.initial.ws1: unknown key 'yaww' (did you mean 'yaw'?)");
  EXPECT_EQ(errors("v.initial = { ws1 = { y = 'three' } }"),
            at + "vehicle.initial.ws1: y must be a number [m], got string \"three\"");
  EXPECT_EQ(errors("v.initial = { ws1 = { y = 1/0 } }"),
            at + "vehicle.initial.ws1: y must be finite, got inf");
  EXPECT_EQ(errors("v.initial = { car = { roll_dot = 0/0 } }")
                .rfind(at + "vehicle.initial.car: roll_dot must be finite, got ", 0),
            0U);  // nan or -nan
  EXPECT_EQ(errors("v.initial = 3"),
            at + "vehicle: initial must be a table keyed by body name, e.g. { ws1 = { y = 3e-3 } "
                 "}, got number 3");
  EXPECT_EQ(errors("v.initial = { { y = 1 } }"),
            at + "vehicle: initial must be a table keyed by body name, e.g. { ws1 = { y = 3e-3 } "
                 "}, got table");
  EXPECT_EQ(errors("v.initial = { ws1 = 0.003 }"),
            at + "vehicle: initial.ws1 must be a table of offsets, e.g. { y = 3e-3, yaw_dot = "
                 "0.01 }, got number 0.003");
  // Every problem at once.
  EXPECT_EQ(errors("v.initial = { ws1 = { y = 'a', pich = 1 }, cr = { y = 1 } }"),
            at + "vehicle: initial: no body named 'cr' (did you mean 'car'?)\n" + at +
                "vehicle.initial.ws1: unknown key 'pich' (did you mean 'pitch'?)\n" + at +
                "vehicle.initial.ws1: y must be a number [m], got string \"a\"");
  // From the command line.
  const std::string plain = t.write("p.lua", wagonScenario(""));
  EXPECT_EQ(loadErrors(plain, {"vehicle.initial.wsl.y=1e-3"}),
            "<command line>: vehicle: initial: no body named 'wsl' (did you mean 'ws1'?)");
  EXPECT_EQ(loadErrors(plain, {"vehicle.initial.ws1.lateral=1e-3"}),
            "<command line>: vehicle.initial.ws1: unknown key 'lateral' (valid keys: y, z, roll, "
            "pitch, yaw, y_dot, z_dot, roll_dot, pitch_dot, yaw_dot)");
  EXPECT_EQ(loadErrors(plain, {"vehicle.initial.ws1.y=inf"}),
            "<command line>: vehicle.initial.ws1: y must be finite, got inf");
}

TEST(InitialConditionsCheck, ACoordinateThatIsNotAStateIsRefusedByCheck) {
  TempDir t("states");
  const std::string contact = t.write("c.lua", wagonScenario(""));
  const std::string guided = t.write("g.lua", wagonScenario("", false));
  const std::string cl = "<command line>: vehicle.initial.";
  EXPECT_EQ(compileErrors(contact, {"vehicle.initial.ws2.z=1e-3"}),
            cl + "ws2.z: not a state of this model: the height z and roll of wheelset 'ws2' on "
                 "wheel/rail contact are given by the contact constraints (KEC Eq. 22, LUT Eq. "
                 "17-18); its states are y, yaw and, with a free spin, pitch");
  EXPECT_NE(compileErrors(contact, {"vehicle.initial.ws1.roll_dot=1e-3"})
                .find("ws1.roll_dot: not a state"),
            std::string::npos);
  EXPECT_EQ(compileErrors(contact,
                          {"vehicle.initial.ws1.pitch=1e-3", "contact.wheelset_spin=prescribed"}),
            cl + "ws1.pitch: not a state of this model: the spin of wheelset 'ws1' is prescribed "
                 "(contact.wheelset_spin = prescribed: pitch_dot = V / r0)");
  EXPECT_EQ(compileErrors(guided, {"vehicle.initial.ws3.y=1e-3"}),
            cl + "ws3.y: not a state of this model: the wheelsets are guided: they follow the "
                 "track kinematically (contact.method = guided), so 'ws3' has no state");
  // The single wheelset's guided frame.
  const std::string frame =
      t.write("f.lua", "local common = require 'validation.common'\ncommon.case1(300, 'kec')\n");
  EXPECT_EQ(compileErrors(frame, {"vehicle.initial.frame.y=1e-3", "run.duration=0.01"}),
            cl + "frame.y: not a state of this model: 'frame' is a frame, fixed in its track "
                 "frame (it has no state)");
  // States of the model pass: a free spin's pitch rate, car-body and wheelset coordinates.
  EXPECT_EQ(compileErrors(contact, {"vehicle.initial.ws1.pitch_dot=0.1",
                                    "vehicle.initial.car.z=1e-3", "vehicle.initial.ws4.yaw=1e-3"}),
            "<no error>");
  EXPECT_EQ(compileErrors(guided, {"vehicle.initial.car.y=1e-2"}), "<no error>");
}

TEST(InitialConditionsCheck, AWheelsetKickedOntoItsFlangeIsRefusedBeforeTheRun) {
  TempDir t("far");
  const std::string f = t.write("c.lua", wagonScenario(""));
  // 6 mm: on the tread (the run test kicks 3 mm); 7 and 9 mm: on the flange at rest (7 mm lifts
  // the wheel at t = 0, 9 mm within 5 ms); 50 mm: outside the contact tables.
  EXPECT_EQ(compileErrors(f, {"vehicle.initial.ws1.y=6e-3"}), "<no error>");
  for (const char* y : {"7e-3", "9e-3", "-9e-3", "0.05"}) {
    const std::string e = compileErrors(f, {std::string("vehicle.initial.ws1.y=") + y});
    const std::string side = y[0] == '-' ? "right" : "left";
    EXPECT_EQ(e.rfind("<command line>: vehicle.initial: the offsets put the " + side +
                          " wheel of wheelset 'ws1' beyond its flangeway at the start",
                      0),
              0U)
        << e;
    // The bound is stated: between 6 and 7 mm.
    const std::size_t at = e.find("(here ");
    ASSERT_NE(at, std::string::npos) << e;
    const double bound = std::stod(e.substr(at + 6));
    EXPECT_GT(bound, 6e-3) << e;
    EXPECT_LT(bound, 7e-3) << e;
  }
  // A car-body kick is not limited by the flangeway.
  EXPECT_EQ(compileErrors(f, {"vehicle.initial.car.y=0.02"}), "<no error>");
}

TEST(InitialConditionsCli, CheckAndRunRefuseWithExitOneAndWriteNothing) {
  TempDir t("cli");
  const std::string f = t.write("c.lua", wagonScenario("v.initial = { ws1 = { z = 1e-3 } }"));
  const std::string bin = std::string(RB_BINARY_DIR) + "/workbench/app/workbench";
  const std::string out = (t.path / "r.h5").string();
  const std::string err = (t.path / "err.txt").string();
  auto rc = [&](const std::string& args) {
    const int s = std::system((bin + " " + args + " > /dev/null 2> " + err).c_str());
    return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  };
  const std::string root = std::string("--root ") + RB_SOURCE_DIR + " ";
  EXPECT_EQ(rc(root + "check " + f), 1);
  std::ifstream in(err);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("c.lua:7: vehicle.initial.ws1.z: not a state of this model"),
            std::string::npos)
      << text;
  EXPECT_EQ(rc(root + "run " + f + " --quiet --out " + out), 1);
  EXPECT_FALSE(fs::exists(out));
  for (const auto& entry : fs::directory_iterator(t.path))
    EXPECT_EQ(entry.path().extension() == ".h5" ||
                  entry.path().string().find(".tmp.") != std::string::npos,
              false)
        << entry.path();
}

TEST(InitialConditionsRun, KickedWheelsetStartsThereDecaysAndIsRecorded) {
  TempDir t("kick");
  const std::string f =
      t.write("k.lua", wagonScenario("v.initial = { ws1 = { y = 3e-3 } }", true, "duration = 3"));
  const std::string out = (t.path / "k.h5").string();
  runInto(f, out);
  const std::vector<double> y = series(out, "/bodies/ws1/y");
  ASSERT_GT(y.size(), 200U);
  EXPECT_NEAR(y.front(), 3e-3, 1e-12);  // the first output is the start state
  // At 20 m/s (well below the wagon's critical speed) the kinematic oscillation decays: the
  // largest |y| over the last second is a fraction of the kick.
  double late = 0.0;
  for (std::size_t i = y.size() - 100; i < y.size(); ++i) late = std::max(late, std::abs(y[i]));
  EXPECT_LT(late, 0.3e-3);
  // It moved (the kick is not held): the wheelset crosses the centre line.
  double lowest = 1.0;
  for (const double v : y) lowest = std::min(lowest, v);
  EXPECT_LT(lowest, 0.0);

  rb::io::ResultReader r(out);
  ASSERT_TRUE(r.has("/initial_conditions"));
  EXPECT_EQ(r.number("/initial_conditions", "count"), 1.0);
  // The file states the group's layout: one /schema row per dataset, each naming a dataset.
  const auto rows = r.strings("/schema/initial_conditions/path");
  ASSERT_TRUE(rows);
  EXPECT_EQ(r.members("/initial_conditions").size(), rows->size());
  for (const auto& p : *rows) EXPECT_TRUE(r.has(p)) << p;
  EXPECT_EQ(series(out, "/initial_conditions/value"), std::vector<double>{3e-3});
  const std::vector<double> eq = series(out, "/initial_conditions/equilibrium");
  const std::vector<double> st = series(out, "/initial_conditions/state");
  ASSERT_EQ(eq.size(), st.size());
  // ws1.y differs by the kick, held exactly; the rest of the equilibrium settles around it (the
  // bogie and car body follow the wheelset on the primary and secondary lateral springs by a
  // fraction of the kick), and no rate moves.
  const auto names = r.strings("/initial_conditions/state_names");
  ASSERT_TRUE(names);
  ASSERT_EQ(names->size(), st.size());
  int kicked = 0;
  for (std::size_t i = 0; i < st.size(); ++i) {
    const std::string& name = (*names)[i];
    if (name == "ws1.y") {
      ++kicked;
      EXPECT_NEAR(st[i] - eq[i], 3e-3, 1e-15);
    } else if (name.find("_dot") != std::string::npos) {
      EXPECT_EQ(st[i], eq[i]) << name;
    } else {
      EXPECT_LT(std::abs(st[i] - eq[i]), 3e-3) << name;
    }
  }
  EXPECT_EQ(kicked, 1);
}

TEST(InitialConditionsRun, GuidedCarBodyKickStartsThere) {
  TempDir t("guided");
  const std::string scen =
      std::string(RB_SOURCE_DIR) + "/scenarios/vehicle/manchester_guided_r500.lua";
  const std::string plain = (t.path / "plain.h5").string();
  const std::string kicked = (t.path / "kicked.h5").string();
  runInto(scen, plain, {"run.duration=0.3"});
  runInto(scen, kicked, {"run.duration=0.3", "vehicle.initial.car.y=0.01"});
  const std::vector<double> a = series(plain, "/bodies/car/y");
  const std::vector<double> b = series(kicked, "/bodies/car/y");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  EXPECT_NEAR(b.front() - a.front(), 0.01, 1e-12);
  EXPECT_GT(std::abs(b.back() - a.back()), 1e-4);  // the kick moves the car body
  rb::io::ResultReader r(kicked);
  EXPECT_TRUE(r.has("/initial_conditions/state_names"));
  EXPECT_FALSE(rb::io::ResultReader(plain).has("/initial_conditions"));
}

TEST(InitialConditionsRun, EmptyOrZeroTableChangesNothing) {
  TempDir t("zero");
  const std::string none = t.write("n.lua", wagonScenario("", true, "duration = 0.2"));
  const std::string empty =
      t.write("e.lua", wagonScenario("v.initial = {}", true, "duration = 0.2"));
  const std::string zero = t.write(
      "z.lua", wagonScenario("v.initial = { ws1 = { y = 0, yaw_dot = 0 }, car = { roll = 0 } }",
                             true, "duration = 0.2"));
  const std::string a = (t.path / "n.h5").string();
  const std::string b = (t.path / "e.h5").string();
  const std::string c = (t.path / "z.h5").string();
  runInto(none, a);
  runInto(empty, b);
  runInto(zero, c);
  EXPECT_FALSE(rb::io::ResultReader(b).has("/initial_conditions"));
  EXPECT_TRUE(rb::io::ResultReader(c).has("/initial_conditions"));
  const rb::io::ResultReader ra(a);
  for (const std::string& body : ra.members("/bodies"))
    for (const char* q : {"s", "y", "z", "roll", "pitch", "yaw"}) {
      const std::string p = "/bodies/" + body + "/" + q;
      const std::vector<double> x = series(a, p);
      ASSERT_FALSE(x.empty()) << p;
      EXPECT_EQ(series(b, p), x) << p;
      EXPECT_EQ(series(c, p), x) << p;
    }
  for (const char* p : {"/contact/ws1/left/normal_force", "/contact/ws4/right/creep_force_y"}) {
    const std::vector<double> x = series(a, p);
    ASSERT_FALSE(x.empty()) << p;
    EXPECT_EQ(series(b, p), x) << p;
    EXPECT_EQ(series(c, p), x) << p;
  }
}
