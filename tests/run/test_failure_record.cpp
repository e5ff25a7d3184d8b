// A failed run says what ended it as a record a reader can branch on (/stats failure_kind,
// failure_reason, failure_body, failure_t, failure_s; run/simulate.hpp), set where the failure is
// found: the integrator's kind, the contact model's reason and wheelset, the run's time and the
// leading wheelset's distance. An ok run records failure_kind "none" and no time or distance (no
// NaN is written).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include "tests/run/run_files.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/integrators/integrator.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/vehicle_run.hpp"

namespace {

namespace fs = std::filesystem;

std::string runInto(const std::string& scenario, const std::string& name,
                    std::vector<std::string> sets = {}) {
  return rb::test::runInto(rb::test::compiled(scenario, std::move(sets)), "rb_test_failure_record",
                           name)
      .path;
}

TEST(FailureRecord, WheelLiftIsTheModelsReasonWithItsWheelsetTimeAndDistance) {
  const std::string file =
      runInto(std::string(RB_SOURCE_DIR) + "/tests/app/data/wheel_lift/my_wheelset.lua", "wl.h5");
  const rb::io::ResultReader r(file);
  EXPECT_EQ(r.text("/stats", "status").value_or(""), "failed");
  EXPECT_EQ(r.text("/stats", "failure_kind").value_or(""), "model");
  EXPECT_EQ(r.text("/stats", "failure_reason").value_or(""), "wheel_lift");
  EXPECT_EQ(r.text("/stats", "failure_body").value_or(""), "ws");
  const double t = r.number("/stats", "failure_t").value_or(-1.0);
  const double s = r.number("/stats", "failure_s").value_or(-1.0);
  EXPECT_GT(t, 0.0);
  EXPECT_DOUBLE_EQ(t, r.number("/stats", "t_reached").value_or(-2.0));
  EXPECT_GT(s, 0.0);
  // The names a reader may meet are in the file's /schema/enums.
  const std::string kinds = r.text("/schema/enums", "failure_kind").value_or("");
  const std::string reasons = r.text("/schema/enums", "failure_reason").value_or("");
  EXPECT_NE(kinds.find("=model"), std::string::npos) << kinds;
  EXPECT_NE(reasons.find("=wheel_lift"), std::string::npos) << reasons;
}

TEST(FailureRecord, TheSolversStepLimitIsTooMuchWork) {
  // dopri5 allowed 5 internal steps per output interval: the kind follows the SUNDIALS-style flag,
  // no model reason, the time and distance where it stopped.
  const std::string file =
      runInto("scenarios/default/case3_kec_fast.lua", "work.h5",
              {"run.duration=0.02", "solver.method=dopri5", "solver.max_steps=5"});
  const rb::io::ResultReader r(file);
  EXPECT_EQ(r.text("/stats", "status").value_or(""), "failed");
  EXPECT_EQ(r.text("/stats", "failure_kind").value_or(""), "too_much_work");
  EXPECT_EQ(r.text("/stats", "failure_reason").value_or("?"), "");
  EXPECT_TRUE(r.number("/stats", "failure_t"));
  EXPECT_TRUE(r.number("/stats", "failure_s"));
}

TEST(FailureRecord, AnOkRunRecordsNoFailure) {
  const std::string file =
      runInto("scenarios/default/case3_kec_fast.lua", "ok.h5", {"run.duration=0.02"});
  const rb::io::ResultReader r(file);
  EXPECT_EQ(r.text("/stats", "failure_kind").value_or("?"), "none");
  EXPECT_EQ(r.text("/stats", "failure_reason").value_or("?"), "");
  EXPECT_FALSE(r.number("/stats", "failure_t"));
  EXPECT_FALSE(r.number("/stats", "failure_s"));
}

TEST(FailureRecord, NameTablesHaveOneNameEach) {
  std::set<std::string> names;
  for (const auto& e : rb::integ::kFailureKindNames)
    EXPECT_TRUE(names.insert(std::string(e.name)).second);
  EXPECT_EQ(std::string(rb::nameOf(rb::integ::FailureKind::TooMuchWork)), "too_much_work");
  names.clear();
  for (const auto& e : rb::dynamics::kContactFailureNames)
    EXPECT_TRUE(names.insert(std::string(e.name)).second);
  EXPECT_EQ(std::string(rb::nameOf(rb::dynamics::ContactFailure::Derailment)), "derailment");
}

}  // namespace
