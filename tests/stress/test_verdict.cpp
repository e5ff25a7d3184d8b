// The verdict of `workbench stress` (workbench/stress/verdict.hpp) apart from running: the
// expectation file, the classification of runs that left no result, the map as text and
// stress.csv as a table a reader parses back.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/stress/verdict.hpp"

namespace {

namespace fs = std::filesystem;
using rb::stress::Outcome;
using rb::stress::StressRow;

std::string writeFile(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("rb_test_verdict_" + name);
  std::ofstream(p) << text;
  return p.string();
}

StressRow row(const std::string& axis, const std::string& value, const std::string& label,
              const std::string& integrator, Outcome o, std::optional<double> err = {}) {
  StressRow r;
  r.axis = axis;
  r.value = value;
  r.value_label = label;
  r.integrator = integrator;
  r.outcome = o;
  r.error_y_mm = err;
  return r;
}

TEST(StressVerdict, ExpectationFileErrorsNameFileAndLine) {
  const std::string path =
      writeFile("bad.csv", "# comment\nspeed, *, *, ok\nspeed, 2\n*, *, *, ok|fine\n");
  try {
    (void)rb::stress::readExpectations(path);
    FAIL() << "accepted a malformed expectation file";
  } catch (const rb::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path + ":3: expected AXIS, VALUE, INTEGRATOR, OUTCOME"), std::string::npos)
        << what;
    EXPECT_NE(what.find(path + ":4: unknown outcome 'fine'"), std::string::npos) << what;
  }
  EXPECT_THROW((void)rb::stress::readExpectations(path + ".missing"), rb::InputError);
}

TEST(StressVerdict, ExpectationsMatchByPatternAndNumber) {
  const std::string path = writeFile(
      "good.csv",
      "speed, 2, rk4*, ok|inaccurate  # the value as a number\nspeed, x2, reference*, ok\n"
      "nominal, *, *, failed cleanly\ncurve_radius, *, *, ok\n");
  const auto ex = rb::stress::readExpectations(path);
  ASSERT_EQ(ex.size(), 4u);
  const std::vector<StressRow> rows = {
      row("speed", "2.0", "x2", "reference bdf 1e-9", Outcome::Ok, 0.0),
      row("speed", "2.0", "x2", "rk4 1 ms", Outcome::FailedBadly),
      row("nominal", "1", "as given", "dopri5 1e-6", Outcome::FailedCleanly)};
  const auto mismatches = rb::stress::checkExpectations(rows, ex);
  ASSERT_EQ(mismatches.size(), 2u);
  EXPECT_NE(mismatches[0].find(":1: speed=x2 rk4 1 ms: failed badly, expected ok or inaccurate"),
            std::string::npos)
      << mismatches[0];
  EXPECT_NE(mismatches[1].find(":4: no run matches curve_radius"), std::string::npos)
      << mismatches[1];
}

TEST(StressVerdict, RunsWithoutResultAreClassifiedByTheirSummary) {
  const rb::stress::Bounds b;
  // Refused before the first step with the model's diagnostic: a clean failure.
  const auto refused = rb::stress::classifyRun(
      "error", "solver.step 2 ms is beyond the stability limit of rk4 ...", "", 1.0, b);
  EXPECT_EQ(refused.outcome, Outcome::FailedCleanly);
  ASSERT_EQ(refused.notes.size(), 1u);
  EXPECT_EQ(refused.notes[0].rfind("refused before the run: ", 0), 0u);
  // A crash, or a result file that is gone: failed badly, never ok.
  const auto crash = rb::stress::classifyRun("error", "signal 11", "", 1.0, b);
  EXPECT_EQ(crash.outcome, Outcome::FailedBadly);
  EXPECT_EQ(crash.problems.at(0), "no result: signal 11");
  const auto gone = rb::stress::classifyRun("ok", "", "/nonexistent/run.h5", 1.0, b);
  EXPECT_EQ(gone.outcome, Outcome::FailedBadly);
  // A file that is not a result: failed badly with the reason.
  const auto junk = rb::stress::classifyRun("ok", "", writeFile("junk.h5", "not hdf5"), 1.0, b);
  EXPECT_EQ(junk.outcome, Outcome::FailedBadly);
  EXPECT_NE(junk.problems.at(0).find("cannot read result"), std::string::npos);
}

TEST(StressVerdict, MapAndCsv) {
  std::vector<StressRow> rows = {row("speed", "2", "x2", "reference bdf 1e-9", Outcome::Ok, 0.0),
                                 row("speed", "2", "x2", "rk4 1 ms", Outcome::Inaccurate, 3.456),
                                 row("speed", "2", "x2", "dopri5 1e-6", Outcome::FailedCleanly)};
  rows[2].message = "a wheel rose beyond the derailment lift at t = 1 s, s = 2 m";
  const std::string map = rb::stress::textMap(rows, 1.0);
  EXPECT_NE(map.find("x2     ok                  inacc 3.5  clean-fail"), std::string::npos) << map;
  EXPECT_NE(map.find("runs: 1 ok, 1 inaccurate, 1 failed cleanly, 0 failed badly"),
            std::string::npos);
  EXPECT_NE(map.find("- speed=x2 dopri5 1e-6: failed cleanly: a wheel rose"), std::string::npos);
  const auto table = rb::parseCsv(rb::stress::stressCsv(rows));
  ASSERT_EQ(table.size(), 4u);
  EXPECT_EQ(table[0][5], "outcome");
  EXPECT_EQ(table[0][6], "error_y_mm");
  EXPECT_EQ(table[2][5], "inaccurate");
  EXPECT_EQ(table[2][6], "3.456");
  EXPECT_EQ(table[3][5], "failed cleanly");
  EXPECT_EQ(table[3][6], "");
  EXPECT_EQ(table[3][15], rows[2].message);
}

}  // namespace
