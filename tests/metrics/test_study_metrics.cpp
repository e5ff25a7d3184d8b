// A small study end to end: its summaries carry the metric columns, with values equal to the
// last bit to an independent computation from the result files; the function metric, the error
// against the reference (exactly 0 for a case that equals the reference) and a metric that
// cannot be computed (empty field, NaN, reason in the message). Also /metrics stored by the
// runner's call and read back by the summary.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "tests/app/h5read.hpp"
#include "workbench/io/metrics_output.hpp"
#include "workbench/stability/stability.hpp"
#include "workbench/study/metrics.hpp"
#include "workbench/study/runner.hpp"

namespace fs = std::filesystem;

namespace {

// CSV rows as maps column -> text (quoted fields with commas handled).
std::vector<std::map<std::string, std::string>> readCsv(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> f(1);
    bool q = false;
    for (char c : line) {
      if (c == '"')
        q = !q;
      else if (c == ',' && !q)
        f.emplace_back();
      else
        f.back() += c;
    }
    rows.push_back(f);
  }
  std::vector<std::map<std::string, std::string>> out;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    std::map<std::string, std::string> m;
    for (std::size_t c = 0; c < rows[0].size() && c < rows[r].size(); ++c)
      m[rows[0][c]] = rows[r][c];
    out.push_back(m);
  }
  return out;
}

double num(const std::string& s) {
  return std::strtod(s.c_str(), nullptr);
}

struct Expected {
  double y_max = 0, y_mean = 0, q_fn = 0;
};

// The metrics recomputed here from the file with plain loops.
Expected recompute(const std::string& h5) {
  hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const auto y = h5test::dataset(f, "/bodies/ws1/y");
  const auto s = h5test::dataset(f, "/bodies/ws1/s");
  const auto q = h5test::dataset(f, "/contact/ws1/left/Q");
  H5Fclose(f);
  Expected e;
  double sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    e.y_max = std::max(e.y_max, std::fabs(y[k]));
    if (s[k] >= 11.0 && s[k] <= 13.0) {
      sum += y[k];
      ++n;
    }
  }
  e.y_mean = sum / n;
  e.q_fn = q.at(0);
  for (double v : q) e.q_fn = std::max(e.q_fn, v);
  return e;
}

const char* kMetrics = R"(
  metrics = {
    { name = "y_max", signal = "/bodies/ws1/y", stat = "max_abs" },
    { name = "y_mean", signal = "/bodies/ws1/y", stat = "mean", from = 11, to = 13 },
    { name = "y_err", kind = "error", signal = "/bodies/ws1/y" },
    { name = "q_fn", signals = { q = "/contact/ws1/left/Q" },
      fn = function(s)
        local m = s.q[1]
        for i = 2, #s.q do m = math.max(m, s.q[i]) end
        assert(#s.distance == #s.q and #s.time == #s.q)
        return m
      end },
    { name = "late", signal = "/bodies/ws1/y", stat = "max", from = 100, to = 200 },
  },
)";

}  // namespace

TEST(StudyMetrics, SummaryColumnsMatchAnIndependentComputation) {
  std::random_device rd;
  const fs::path dir =
      fs::temp_directory_path() / ("railbench_study_metrics_" + std::to_string(rd()));
  fs::create_directories(dir);
  const std::string study = (dir / "m.lua").string();
  std::ofstream(study)
      << "study {\n  base = \"" << RB_SOURCE_DIR
      << "/scenarios/studies/case3_base.lua\",\n"
         "  matrix = { [\"run.distance\"] = { 3 }, [\"vehicle.speed\"] = { 20, 21 } },\n"
         "  cases = { { label = \"ref\", role = \"reference\" },\n"
         "            { label = \"same\", [\"solver.accept_unstable_step\"] = true },\n"
         "            { label = \"finer\", [\"solver.step\"] = 2e-4 } },\n"
      << kMetrics << "}\n";
  setenv("RAILBENCH_STUDY_PLOTS", "0", 1);
  rb::study::StudyOptions o;
  o.file = study;
  o.out = (dir / "out").string();
  o.root = RB_SOURCE_DIR;
  o.program = std::string(RB_BINARY_DIR) + "/workbench/app/workbench";
  o.jobs = 2;
  ASSERT_EQ(rb::study::runStudy(o), 0);

  const auto runs = readCsv(dir / "out" / "summary.csv");
  const auto cases = readCsv(dir / "out" / "summary_cases.csv");
  ASSERT_EQ(runs.size(), 6u);
  ASSERT_EQ(cases.size(), 6u);
  for (const auto& rows : {runs, cases})
    for (const auto& r : rows) {
      ASSERT_EQ(r.at("status"), "ok") << r.at("message");
      const Expected e = recompute(r.at("file"));
      EXPECT_EQ(num(r.at("metric_y_max")), e.y_max);
      EXPECT_EQ(num(r.at("metric_y_mean")), e.y_mean);
      EXPECT_EQ(num(r.at("metric_q_fn")), e.q_fn);
      // The window beyond the 3 m run: no value, and why.
      EXPECT_EQ(r.at("metric_late"), "");
      EXPECT_NE(r.at("message").find("metric late: the window ends at 200"), std::string::npos)
          << r.at("message");
      const std::string lbl = r.at("label");
      // Each against the reference of its own speed (the matrix combination).
      if (lbl.find("ref") != std::string::npos || lbl.find("same") != std::string::npos)
        EXPECT_EQ(r.at("metric_y_err"), "0") << lbl;
      else
        EXPECT_GT(num(r.at("metric_y_err")), 0.0) << lbl;
    }
  // summary.h5: the same values, NaN where none.
  hid_t f = H5Fopen((dir / "out" / "summary.h5").string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const auto ymax = h5test::dataset(f, "/runs/metric_y_max");
  const auto late = h5test::dataset(f, "/runs/metric_late");
  H5Fclose(f);
  ASSERT_EQ(ymax.size(), 6u);
  ASSERT_EQ(late.size(), 6u);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(ymax[k], num(runs[k].at("metric_y_max")));
    EXPECT_TRUE(std::isnan(late[k]));
  }

  // The runner's call stores /metrics; the summary then reads them (a value changed in the file
  // under the same hash is what it reports), and recomputes when the hash differs.
  const auto st = rb::scenario::loadStudy(study, RB_SOURCE_DIR);
  const std::string h5 = runs[0].at("file");
  const rb::scenario::StudyCase* c = nullptr;
  for (const auto& sc : st.cases)
    if (sc.id == runs[0].at("case")) c = &sc;
  ASSERT_NE(c, nullptr);
  std::string why;
  ASSERT_TRUE(rb::study::detail::storeCaseMetrics(st, *c, h5, why)) << why;
  auto stored = rb::io::readMetrics(h5);
  ASSERT_TRUE(stored);
  EXPECT_EQ(stored->hash, rb::study::detail::metricsHash(st));
  ASSERT_EQ(stored->values.size(), 5u);
  EXPECT_EQ(stored->values[0].value, num(runs[0].at("metric_y_max")));
  EXPECT_NE(stored->values[2].why.find("summary"), std::string::npos);  // error: at summary time
  stored->values[0].value = 42.0;
  rb::io::writeMetrics(h5, *stored);
  rb::study::detail::MetricContext ctx(st);
  EXPECT_EQ(rb::study::detail::summaryMetrics(ctx, *c, h5, h5)[0].value, 42.0);
  EXPECT_EQ(rb::study::detail::summaryMetrics(ctx, *c, h5, h5)[2].value, 0.0);
  stored->hash = "other";
  rb::io::writeMetrics(h5, *stored);
  EXPECT_EQ(rb::study::detail::summaryMetrics(ctx, *c, h5, h5)[0].value,
            num(runs[0].at("metric_y_max")));
  fs::remove_all(dir);
}

TEST(StudyMetrics, LinearCriticalSpeedOfTheCaseScenario) {
  // The metric equals the stability library's answer on the case's scenario (base + overrides).
  std::random_device rd;
  const fs::path dir =
      fs::temp_directory_path() / ("railbench_study_vcrit_" + std::to_string(rd()));
  fs::create_directories(dir);
  const std::string study = (dir / "v.lua").string();
  std::ofstream(study) << "study { base = \"" << RB_SOURCE_DIR
                       << "/scenarios/studies/case3_base.lua\",\n"
                          "  matrix = { [\"run.distance\"] = { 1 } },\n"
                          "  metrics = { { name = \"v\", kind = \"linear_critical_speed\", "
                          "speeds = { 20, 200, 3 } },\n"
                          "              { name = \"none\", kind = \"linear_critical_speed\", "
                          "speeds = { 20, 30, 2 } } } }\n";
  setenv("RAILBENCH_STUDY_PLOTS", "0", 1);
  rb::study::StudyOptions o;
  o.file = study;
  o.out = (dir / "out").string();
  o.root = RB_SOURCE_DIR;
  o.program = std::string(RB_BINARY_DIR) + "/workbench/app/workbench";
  ASSERT_EQ(rb::study::runStudy(o), 0);
  const auto cases = readCsv(dir / "out" / "summary_cases.csv");
  ASSERT_EQ(cases.size(), 1u);
  rb::scenario::LoadOptions lo;
  lo.root = RB_SOURCE_DIR;
  lo.overrides = {"run.distance=1"};
  const auto cs = rb::stability::linearCriticalSpeed(
      rb::scenario::loadScenario(std::string(RB_SOURCE_DIR) + "/scenarios/studies/case3_base.lua",
                                 lo),
      20, 200, 3);
  ASSERT_TRUE(cs.found);
  EXPECT_EQ(num(cases[0].at("metric_v")), cs.speed);
  // None between 20 and 30 m/s: no value, and the library's reason.
  EXPECT_EQ(cases[0].at("metric_none"), "");
  EXPECT_NE(cases[0].at("message").find("metric none: no linear critical speed"), std::string::npos)
      << cases[0].at("message");
  fs::remove_all(dir);
}
