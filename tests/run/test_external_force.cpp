// A run with an external force (external_force{}, docs/vehicle.md "External forces"): the wagon
// pushed sideways on a tangent, where the rails must carry the push in the steady state, and the
// force the run writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "run_files.hpp"

namespace {

using rb::test::lastSecondMean;

constexpr const char* kScene = "tests/run/data/external_force_tangent.lua";

// The ramp of the scene: 0 until 0.5 s, 5 kN/s, then 10 kN.
double push(double t) {
  return std::clamp(5e3 * (t - 0.5), 0.0, 10e3);
}

TEST(ExternalForceRun, TheRailsCarryALateralPushOnTheCarInTheSteadyState) {
  const rb::test::RunFile f =
      rb::test::runInto(rb::test::compiled(kScene), "rb_test_external_force", "push.h5");
  ASSERT_TRUE(f.result.result.ok) << f.result.result.message;
  const rb::io::ResultReader r(f.path);
  const auto t = *r.dataset("/time");
  // The force the run writes: the law's value, and its components in the track frame.
  const auto F = *r.dataset("/elements/push/force");
  const auto Fx = *r.dataset("/elements/push/force_x");
  const auto Fy = *r.dataset("/elements/push/force_y");
  const auto Fz = *r.dataset("/elements/push/force_z");
  ASSERT_EQ(F.size(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(F[i], push(t[i]), 1e-6) << t[i];
    EXPECT_EQ(Fy[i], F[i]) << t[i];
    EXPECT_EQ(Fx[i], 0.0) << t[i];
    EXPECT_EQ(Fz[i], 0.0) << t[i];
  }
  EXPECT_EQ(r.text("/elements/push", "kind").value_or(""), "external_force");
  EXPECT_EQ(r.text("/elements/push", "frame").value_or(""), "track");
  EXPECT_EQ(r.text("/elements/push", "body").value_or(""), "car");
  // Lateral equilibrium of the whole vehicle at rest on a level tangent: the rails' lateral
  // forces on the 8 wheels (y_track, positive to the left) balance the 10 kN push.
  double rails = 0.0;
  for (const char* ws : {"ws1", "ws2", "ws3", "ws4"})
    for (const char* side : {"left", "right"})
      rails +=
          lastSecondMean(t, *r.dataset("/contact/" + std::string(ws) + "/" + side + "/y_track"));
  std::printf("[ push     ] sum of the wheels' y_track over the last second: %.1f N\n", rails);
  EXPECT_NEAR(rails, -10e3, 50.0);
  // The secondary shear springs (K = 160 kN/m, the only lateral link of car and bogies at rest)
  // each carry a quarter of it: 2.5 kN, a deflection of 15.6 mm (d = bogie point - car point).
  for (const char* e : {"sec_shear_y_bogie1_l", "sec_shear_y_bogie1_r", "sec_shear_y_bogie2_l",
                        "sec_shear_y_bogie2_r"}) {
    const std::string base = std::string("/elements/") + e;
    EXPECT_NEAR(lastSecondMean(t, *r.dataset(base + "/force")), -2.5e3, 25.0) << e;
    EXPECT_NEAR(lastSecondMean(t, *r.dataset(base + "/deflection")), -2.5e3 / 160e3, 0.16e-3) << e;
  }
  // The car moves left, off the centre line.
  EXPECT_GT(lastSecondMean(t, *r.dataset("/bodies/car/y")), 10e-3);
}

TEST(ExternalForceRun, TheRunWritesTheForceItsSchemaRowsAndItsProvenance) {
  const rb::run::Model m = rb::test::compiled(kScene, {"run.duration=0.05"});
  const rb::test::RunFile f = rb::test::runInto(m, "rb_test_external_force", "short.h5");
  ASSERT_TRUE(f.result.result.ok) << f.result.result.message;
  const rb::io::ResultReader r(f.path);
  const auto paths = *r.strings("/schema/series/path");
  const auto units = *r.strings("/schema/series/unit");
  for (const char* q : {"force", "force_x", "force_y", "force_z"}) {
    const std::string p = std::string("/elements/push/") + q;
    const auto it = std::find(paths.begin(), paths.end(), p);
    ASSERT_NE(it, paths.end()) << p;
    EXPECT_EQ(units[static_cast<std::size_t>(it - paths.begin())], "N") << p;
  }
  EXPECT_NE(r.text("/", "effects").value_or("").find("suspension:external_force"),
            std::string::npos);
}

TEST(ExternalForceRun, NamingTheForceInTheElementOutputsAsksForNothingMore) {
  // Written anyway: run.output.elements may name it (a study's list of every element) without
  // an error and without a second copy.
  const rb::run::Model m =
      rb::test::compiled(kScene, {"run.duration=0.05", "run.output.elements[1]=push"});
  EXPECT_EQ(m.lead().output_elements.size(), 3u);
}

}  // namespace

TEST(ExternalForceRun, StudyMetricsMayNameItsSignals) {
  const rb::run::Model m = rb::test::compiled(kScene, {"run.duration=0.05"});
  for (const char* q : {"force", "force_x", "force_y", "force_z"})
    EXPECT_EQ(rb::run::signalProblem(m.spec, std::string("/elements/push/") + q), "") << q;
  EXPECT_NE(rb::run::signalProblem(m.spec, "/elements/push/deflection")
                .find("no external force signal 'deflection'"),
            std::string::npos)
      << rb::run::signalProblem(m.spec, "/elements/push/deflection");
}

TEST(ExternalForceRun, ATrainWithALongitudinalMotionWarnsThatTheForceIsNotInIt) {
  // The braking rake (train.longitudinal) with a force on the leading wagon's car body.
  std::ifstream in(std::string(RB_SOURCE_DIR) + "/tests/run/data/train_braking_rake.lua");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "vehicle = wagon { speed = 20, start = 80 }";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(),
               "vehicle = (function() local v = wagon { speed = 20, start = 80 }\n"
               "  v.elements[#v.elements + 1] = external_force { name = \"wind\", body = \"car\",\n"
               "    direction = { 0, 1, 0 }, value = 1e3 }\n"
               "  return v end)()");
  const auto path = std::filesystem::temp_directory_path() / "rb_external_force_train.lua";
  std::ofstream(path) << text;
  const rb::run::Model m = rb::test::compiled(path.string());
  bool warned = false;
  for (const auto& w : m.warnings)
    warned =
        warned || w.find(
                      "warning: element 'wind' (external_force): its component along "
                      "the track is not in the vehicle's longitudinal motion") != std::string::npos;
  EXPECT_TRUE(warned);
  EXPECT_EQ(m.vehicles.front().vehicle.external_forces.size(), 1u);
}
