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
