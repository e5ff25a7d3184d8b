// summary_errors.csv (workbench/study/reference_errors.hpp): which case is measured against which
// (the reference of the same physical model, its own checks, the full scene of effects) and the
// values, by the one error rule, on result files of known content.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "workbench/core/strings.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/study/reference_errors.hpp"

namespace fs = std::filesystem;

namespace {

// One wheelset whose lateral displacement is `y` on t = 0, 0.1, ..., 1 s; normal forces 50 kN.
std::string resultFile(const std::string& name, double y) {
  const fs::path d = fs::path(RB_BINARY_DIR) / "reference_errors_tests";
  fs::create_directories(d);
  const std::string path = (d / name).string();
  rb::io::ResultFile f(path);
  std::vector<double> t;
  for (int i = 0; i <= 10; ++i) t.push_back(0.1 * i);
  f.dataset("/time", t, "s");
  f.attr("/bodies", "names", std::string("ws1"));
  f.attr("/bodies/ws1", "kind", std::string("wheelset"));
  f.dataset("/bodies/ws1/y", std::vector<double>(t.size(), y), "m");
  f.dataset("/bodies/ws1/yaw", std::vector<double>(t.size(), 0.0), "rad");
  f.attr("/contact", "method", std::string("kec"));
  for (const char* side : {"left", "right"}) {
    const std::string g = std::string("/contact/ws1/") + side + "/";
    f.dataset(g + "normal_force", std::vector<double>(t.size(), 5e4), "N");
    f.dataset(g + "creep_force_y", std::vector<double>(t.size(), 0.0), "N");
  }
  f.finalize();
  return path;
}

rb::scenario::StudyCase makeCase(const std::string& id, const std::string& role,
                                 const std::vector<std::string>& overrides) {
  rb::scenario::StudyCase c;
  c.id = id;
  c.role = role;
  c.base = "base.lua";
  c.overrides = overrides;
  return c;
}

TEST(ReferenceErrors, PairsByRoleAndPhysicalModel) {
  const std::vector<rb::scenario::StudyCase> cases = {
      makeCase("full", "baseline", {"contact.method=kec", "solver.method=abm"}),
      makeCase("bdf", "", {"contact.method=kec", "solver.method=bdf", "solver.rtol=1e-6"}),
      makeCase("lut", "", {"contact.method=lut", "solver.method=abm"}),
      makeCase("ref", "reference",
               {"contact.method=kec", "profiles.refined_tables=true", "solver.rtol=1e-9"}),
      makeCase("check", "reference_check",
               {"contact.method=kec", "profiles.refined_tables=true", "solver.rtol=1e-10"}),
      makeCase("same", "reference_same_tables", {"contact.method=kec", "solver.rtol=1e-9"}),
  };
  EXPECT_EQ(rb::study::physicalKey(cases[1]), rb::study::physicalKey(cases[3]));
  EXPECT_NE(rb::study::physicalKey(cases[1]), rb::study::physicalKey(cases[2]));
  const std::map<std::string, double> y = {{"full", 0.0}, {"bdf", 1e-4},   {"lut", 1e-3},
                                           {"ref", 0.0},  {"check", 1e-6}, {"same", 2e-5}};
  std::vector<rb::study::CaseResult> results;
  for (const auto& c : cases) results.push_back({&c, resultFile(c.id + ".h5", y.at(c.id))});
  const auto table = rb::parseCsv(rb::study::referenceErrorsCsv(results));
  ASSERT_FALSE(table.empty());
  EXPECT_EQ(table[0], (std::vector<std::string>{"case", "against", "reference", "quantity", "unit",
                                                "max", "rms"}));
  // {case against reference: y max} of every row of quantity y.
  std::map<std::string, double> ymax;
  for (std::size_t i = 1; i < table.size(); ++i)
    if (table[i][3] == "y")
      ymax[table[i][0] + " " + table[i][1] + " " + table[i][2]] = std::stod(table[i][5]);
  const std::map<std::string, double> want = {
      {"full baseline full", 0.0},
      {"full reference ref", 0.0},  // the full scene is a KEC case too
      {"full reference_same_tables same", 0.02},
      {"bdf reference ref", 0.1},                // mm
      {"bdf reference_same_tables same", 0.08},  // 0.1 - 0.02 mm
      {"bdf baseline full", 0.1},
      {"lut baseline full", 1.0},     // no reference of its model
      {"check reference ref", 1e-3},  // the reference's own error
      {"same reference ref", 0.02},   // the error of the default tables
      {"ref baseline full", 0.0},
      {"check baseline full", 1e-3},
      {"same baseline full", 0.02}};
  ASSERT_EQ(ymax.size(), want.size());
  for (const auto& [k, v] : want) {
    ASSERT_TRUE(ymax.count(k)) << k;
    EXPECT_NEAR(ymax.at(k), v, 1e-9) << k;
  }
  // Every pair has its four quantities; Q equal in both files: 0 kN.
  EXPECT_EQ(table.size(), 1 + 4 * want.size());
}

TEST(ReferenceErrors, NoReferenceNoBaselineNoRows) {
  const auto c = makeCase("a", "", {"solver.method=abm"});
  const std::string table = rb::study::referenceErrorsCsv({{&c, resultFile("lonely.h5", 0.0)}});
  EXPECT_EQ(table, "case,against,reference,quantity,unit,max,rms\n");
}

}  // namespace
