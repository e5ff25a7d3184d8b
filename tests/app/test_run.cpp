// workbench run/check on shipped and bad scenarios: the result layout, and compile-stage
// (physical) problems reported with file:line together with schema problems.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "h5read.hpp"
#include "workbench/app/run.hpp"
#include "workbench/core/error.hpp"

namespace fs = std::filesystem;

namespace {
rb::app::RunOptions options(const std::string& scenario, const std::string& out = {}) {
  rb::app::RunOptions o;
  o.scenario = scenario;
  o.root = RB_SOURCE_DIR;
  o.out = out;
  return o;
}
std::string checkErrors(const std::string& scenario) {
  try {
    rb::app::checkScenario(options(scenario));
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "<no error>";
}
}  // namespace

TEST(Run, IrregularManchesterTrackWritesTrackAndProvenance) {
  fs::path d = fs::temp_directory_path() / "rb_test_run";
  fs::create_directories(d);
  std::string out = (d / "m.h5").string();
  fs::remove(out);
  ASSERT_EQ(rb::app::runScenario(options("scenarios/tracks/manchester_r500_irregular.lua", out)),
            0);
  hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  auto s = h5test::dataset(f, "/track/centreline/s");
  ASSERT_FALSE(s.empty());
  EXPECT_NEAR(s.back(), 500.0, 1e-9);
  EXPECT_NEAR(h5test::dataset(f, "/track/centreline/heading").back(), 50.0 / 1000 + 350.0 / 500,
              1e-6);
  auto irr = h5test::dataset(f, "/track/irregularities/alignment");
  EXPECT_GT(irr.size(), 4000u);
  EXPECT_EQ(h5test::stringAttr(f, "/track/irregularities", "spectrum"), "ore_b176_low");
  EXPECT_EQ(h5test::numAttr<std::int64_t>(f, "/track/irregularities", "seed"), 42);
  EXPECT_NE(h5test::stringAttr(f, "/", "scenario_text").find("ore_b176_low"), std::string::npos);
  EXPECT_EQ(h5test::stringAttr(f, "/", "seeds"), "track.irregularities.seed=42");
  // Required files are recorded with their text (provenance).
  EXPECT_NE(
      h5test::stringAttr(f, "/", "scenario_modules").find("-- file: scenarios/tracks/lib.lua\n"),
      std::string::npos);
  EXPECT_EQ(h5test::stringAttr(f, "/", "effects"), "track_geometry\nirregularities");
  EXPECT_EQ(h5test::stringAttr(f, "/stats", "status"), "ok");
  EXPECT_EQ(h5test::stringAttr(f, "/track/centreline/curvature", "units"), "1/m");
  H5Fclose(f);
}

TEST(Run, SceneWithoutIrregularitiesBuildsNone) {
  fs::path d = fs::temp_directory_path() / "rb_test_run";
  fs::create_directories(d);
  std::string out = (d / "plain.h5").string();
  ASSERT_EQ(rb::app::runScenario(options("scenarios/tracks/manchester_r500.lua", out)), 0);
  hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_FALSE(h5test::exists(f, "/track/irregularities"));
  EXPECT_EQ(h5test::stringAttr(f, "/", "effects"), "track_geometry");
  H5Fclose(f);
}

TEST(Run, NonPhysicalValuesAreReportedWithFileLine) {
  EXPECT_EQ(
      checkErrors("tests/scenario/bad/nonphysical.lua"),
      "tests/scenario/bad/nonphysical.lua:4: track.segments[2] (curve): radius must be >= 10 m "
      "(tighter curves are not railway track), got 5");
}

// A speed ramp that would stop the vehicle (V0 + a t = 0) before the run's distance is an input
// error naming the field, not a run with a negative speed.
TEST(Run, RampThatStopsTheVehicleIsAnInputError) {
  rb::app::RunOptions o = options("scenarios/studies/case3_base.lua");
  o.overrides = {"vehicle.acceleration=-5"};
  std::string what = "<no error>";
  try {
    rb::app::checkScenario(o);
  } catch (const rb::InputError& e) {
    what = e.what();
  }
  EXPECT_NE(what.find("vehicle: acceleration -5 m/s^2 stops the vehicle"), std::string::npos)
      << what;
  o.overrides = {"vehicle.acceleration=-0.1"};  // 20 m/s -> 17.5 m/s over 500 m: fine
  EXPECT_NO_THROW(rb::app::checkScenario(o));
}

// Regression (found by the hard-case suite): the distance in a failure message was that of the
// first body in the vehicle file (the car body centre, 10.9 m behind the leading wheelset),
// while the run's end is measured at the leading body. It is now the leading wheelset's arc
// length at the failure time.
TEST(Run, FailureDistanceIsThatOfTheLeadingWheelset) {
  fs::path d = fs::temp_directory_path() / "rb_test_run";
  fs::create_directories(d);
  std::string out = (d / "fail_distance.h5").string();
  rb::app::RunOptions o = options("scenarios/hard/lut_stiff_flange.lua", out);
  o.overrides = {"solver.method=rk4", "solver.step=1e-3", "run.duration=2",
                 "solver.accept_unstable_step=true"};  // the paper's step, beyond the spin limit
  o.quiet = true;
  ASSERT_EQ(rb::app::runScenario(o), 2);  // the stiff flange impact: a clean failure
  hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const std::string msg = h5test::stringAttr(f, "/stats", "message");
  const auto s_ws1 = h5test::dataset(f, "/bodies/ws1/s");
  const auto s_car = h5test::dataset(f, "/bodies/car/s");
  H5Fclose(f);
  ASSERT_FALSE(s_ws1.empty());
  const std::string key = "(leading wheelset at s = ";
  const auto at = msg.find(key);
  ASSERT_NE(at, std::string::npos) << msg;
  const double reported = std::stod(msg.substr(at + key.size()));
  // At the failure time, which lies within one output interval (0.01 s at 20 m/s) after the last
  // output.
  EXPECT_GE(reported, s_ws1.back() - 1e-9) << msg;
  EXPECT_LE(reported, s_ws1.back() + 0.2 + 1e-9) << msg;
  EXPECT_GT(std::abs(reported - s_car.back()), 5.0) << msg;
}

namespace {
std::string tmpOut(const std::string& name) {
  fs::path d = fs::temp_directory_path() / "rb_test_run";
  fs::create_directories(d);
  const std::string out = (d / name).string();
  fs::remove(out);
  return out;
}
std::string checkError(rb::app::RunOptions o) {
  try {
    rb::app::checkScenario(o);
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "<no error>";
}
std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
}  // namespace

// Element outputs and body accelerations are written by contact runs too (they used to be
// silently dropped in every run with wheel/rail contact): one vehicle-run path for all.
TEST(Run, ContactRunWritesElementsAndBodyAccelerations) {
  for (const char* method : {"kec", "lut"}) {
    const std::string out = tmpOut(std::string("elements_") + method + ".h5");
    rb::app::RunOptions o = options("scenarios/studies/bases/element_outputs.lua", out);
    o.overrides = {std::string("contact.method=") + method, "run.duration=0.2",
                   "run.output.body_accelerations=true"};
    o.quiet = true;
    ASSERT_EQ(rb::app::runScenario(o), 0) << method;
    hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const auto t = h5test::dataset(f, "/time");
    ASSERT_EQ(t.size(), 21u);
    // A primary vertical spring carries a quarter of a bogie's share of the car's weight: tens of
    // kN in compression, the same in every sample up to the irregularities.
    int elements = 0;
    for (const char* e : {"/elements", "/bodies/car/az", "/bodies/ws1/ay"})
      EXPECT_TRUE(h5test::exists(f, e)) << method << " " << e;
    const auto az = h5test::dataset(f, "/bodies/car/az");
    const auto ay = h5test::dataset(f, "/bodies/car/ay");
    ASSERT_EQ(az.size(), t.size());
    // Quasi-static curving on R = 500 m at 20 m/s is not reached in 0.2 s (the run starts on
    // the tangent): the car's accelerations are small and finite.
    for (std::size_t k = 0; k < az.size(); ++k) {
      EXPECT_TRUE(std::isfinite(az[k]) && std::abs(az[k]) < 2.0) << method << " t=" << t[k];
      EXPECT_TRUE(std::isfinite(ay[k]) && std::abs(ay[k]) < 2.0) << method << " t=" << t[k];
    }
    hid_t g = H5Gopen2(f, "/elements", H5P_DEFAULT);
    hsize_t n = 0;
    H5Gget_num_objs(g, &n);
    H5Gclose(g);
    elements = static_cast<int>(n);
    EXPECT_EQ(elements, 50) << method;
    H5Fclose(f);
  }
}

// Guided and contact runs write the same body channels for the same output keys.
TEST(Run, GuidedAndContactRunsShareTheirBodyOutputs) {
  const std::string out = tmpOut("guided_acc.h5");
  rb::app::RunOptions o = options("scenarios/vehicle/manchester_guided_r500.lua", out);
  o.overrides = {"run.duration=0.1", "run.output.body_accelerations=true"};
  o.quiet = true;
  ASSERT_EQ(rb::app::runScenario(o), 0);
  hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  for (const char* p : {"/bodies/car/ax", "/bodies/car/ay", "/bodies/car/az", "/vehicle/speed"})
    EXPECT_TRUE(h5test::exists(f, p)) << p;
  EXPECT_EQ(h5test::stringAttr(f, "/stats", "warnings"), "");
  H5Fclose(f);
}

// A user's single wheelset hunting at 80 m/s lifts a wheel (normal forces of -681 kN used to be
// written with status "ok"): the run now stops with exit 2, names the wheel and the force, and
// keeps what it wrote up to there.
TEST(Run, WheelLiftStopsTheRunWithADiagnostic) {
  const std::string out = tmpOut("wheel_lift.h5");
  rb::app::RunOptions o = options("tests/app/data/wheel_lift/my_wheelset.lua", out);
  o.quiet = true;
  ASSERT_EQ(rb::app::runScenario(o), 2);
  hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const std::string msg = h5test::stringAttr(f, "/stats", "message");
  EXPECT_EQ(h5test::stringAttr(f, "/stats", "status"), "failed");
  EXPECT_NE(msg.find("wheel lift: wheelset 'ws', "), std::string::npos) << msg;
  EXPECT_NE(msg.find(" wheel: constraint normal force -"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(leading wheelset at s = "), std::string::npos) << msg;
  // Every written normal force is a valid one (>= 0): nothing past the lift.
  for (const char* side : {"left", "right"}) {
    const auto n = h5test::dataset(f, std::string("/contact/ws/") + side + "/normal_force");
    ASSERT_FALSE(n.empty());
    for (double v : n) EXPECT_GE(v, 0.0) << side;
  }
  H5Fclose(f);
}

// A threshold above zero stops the run earlier (wheel unloading as a failure criterion).
TEST(Run, MinNormalForceThresholdIsHonoured) {
  rb::app::RunOptions o = options("tests/app/data/wheel_lift/my_wheelset.lua");
  o.overrides = {"contact.min_normal_force=1e9"};
  const std::string what = checkError(o);
  EXPECT_NE(what.find("min_normal_force"), std::string::npos) << what;  // out of range
  o.overrides = {"contact.min_normal_force=100e3", "run.duration=0.05"};
  o.out = tmpOut("min_normal.h5");
  o.quiet = true;
  // The static wheel load is about 40 kN: a 100 kN threshold is violated in the initial state,
  // which check and run report as an input error, before any result exists.
  EXPECT_NE(checkError(o).find("wheel lift"), std::string::npos) << checkError(o);
  EXPECT_THROW(rb::app::runScenario(o), rb::InputError);
  EXPECT_FALSE(fs::exists(o.out));
}

// Inputs that used to pass `check` and fail (or silently extrapolate) in `run`.
TEST(Run, CheckRefusesWhatRunCannotDo) {
  rb::app::RunOptions o = options("scenarios/validation/case3_kec.lua");
  o.overrides = {"solver.step=1.5e-4"};
  EXPECT_NE(checkError(o).find("not a multiple of the abm step"), std::string::npos)
      << checkError(o);
  o.overrides = {"run.output.every=1e-12"};
  EXPECT_NE(checkError(o).find("more than run.output.max_samples"), std::string::npos)
      << checkError(o);
  o.overrides = {"run.distance=600"};
  EXPECT_NE(checkError(o).find("beyond the end of the track"), std::string::npos) << checkError(o);
  o.overrides = {"run.duration=100"};
  EXPECT_NE(checkError(o).find("beyond the end of the track"), std::string::npos) << checkError(o);
  rb::app::RunOptions t = options("scenarios/tracks/manchester_r500.lua");
  t.overrides = {"run.output.body_accelerations=true"};
  EXPECT_NE(checkError(t).find("run.output.body_accelerations: the scene has no vehicle"),
            std::string::npos)
      << checkError(t);
}

// A run that did not run never replaces an earlier result.
TEST(Run, InputErrorLeavesAnEarlierResultUntouched) {
  const std::string out = tmpOut("keep.h5");
  ASSERT_EQ(rb::app::runScenario(options("scenarios/tracks/manchester_r500.lua", out)), 0);
  const std::string before = fileBytes(out);
  rb::app::RunOptions o = options("scenarios/validation/case3_kec.lua", out);
  o.overrides = {"solver.step=1.5e-4"};
  EXPECT_THROW(rb::app::runScenario(o), rb::InputError);
  EXPECT_EQ(fileBytes(out), before);
  for (const auto& e : fs::directory_iterator(fs::path(out).parent_path()))
    EXPECT_EQ(e.path().filename().string().find("keep.h5.tmp"), std::string::npos) << e.path();
}

// --out never overwrites the scenario, an input, or any file that is not an HDF5 result.
TEST(Run, OutputNeverReplacesANonResultFile) {
  const std::string scenario = tmpOut("copy.lua");
  fs::copy_file(std::string(RB_SOURCE_DIR) + "/scenarios/tracks/manchester_r500.lua", scenario);
  // The copy requires tracks.lib from scenarios/: it resolves through the project root.
  rb::app::RunOptions o = options(scenario, scenario);
  o.quiet = true;
  try {
    rb::app::runScenario(o);
    FAIL() << "ran";
  } catch (const rb::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is the scenario file"), std::string::npos) << e.what();
  }
  const std::string text = tmpOut("notes.txt");
  std::ofstream(text) << "my notes";
  o = options("scenarios/tracks/manchester_r500.lua", text);
  try {
    rb::app::runScenario(o);
    FAIL() << "ran";
  } catch (const rb::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not an HDF5 result"), std::string::npos) << e.what();
  }
  EXPECT_EQ(fileBytes(text), "my notes");
}

// A scenario of more than 64 KiB (the limit of an attribute in an HDF5 object header) runs and
// keeps its whole text as provenance.
TEST(Run, LargeScenarioTextIsKept) {
  const std::string scenario = tmpOut("large.lua");
  {
    std::ofstream s(scenario);
    s << "track { segments = { tangent { length = 100 } } }\n";
    for (int i = 0; i < 2000; ++i)
      s << "-- padding line " << i << " ..........................................\n";
  }
  ASSERT_GT(fs::file_size(scenario), 65536u);
  const std::string out = tmpOut("large.h5");
  ASSERT_EQ(rb::app::runScenario(options(scenario, out)), 0);
  hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(h5test::stringAttr(f, "/", "scenario_text"), fileBytes(scenario));
  H5Fclose(f);
}
