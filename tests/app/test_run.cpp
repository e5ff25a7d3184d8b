// workbench run/check on shipped and bad scenarios: the result layout, and compile-stage
// (physical) problems reported with file:line together with schema problems.
#include <gtest/gtest.h>

#include <filesystem>

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
// length at the last output.
TEST(Run, FailureDistanceIsThatOfTheLeadingWheelset) {
  fs::path d = fs::temp_directory_path() / "rb_test_run";
  fs::create_directories(d);
  std::string out = (d / "fail_distance.h5").string();
  rb::app::RunOptions o = options("scenarios/hard/lut_stiff_flange.lua", out);
  o.overrides = {"solver.method=rk4", "solver.step=1e-3", "run.duration=2"};
  o.quiet = true;
  ASSERT_EQ(rb::app::runScenario(o), 2);  // the stiff flange impact: a clean failure
  hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const std::string msg = h5test::stringAttr(f, "/stats", "message");
  const auto s_ws1 = h5test::dataset(f, "/bodies/ws1/s");
  const auto s_car = h5test::dataset(f, "/bodies/car/s");
  H5Fclose(f);
  ASSERT_FALSE(s_ws1.empty());
  const auto at = msg.find("(distance ");
  ASSERT_NE(at, std::string::npos) << msg;
  const double reported = std::stod(msg.substr(at + 10));
  EXPECT_NEAR(reported, s_ws1.back(), 1e-3) << msg;
  EXPECT_GT(std::abs(reported - s_car.back()), 5.0) << msg;
}
