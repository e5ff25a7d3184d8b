// Study files: expansion of matrix x cases, the study keys of a case (label, base, role), the
// labels made from overrides, stable case ids, and every bad study key reported at once.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "workbench/scenario/scenario.hpp"
#include "workbench/scenario/study.hpp"

using rb::scenario::caseLabel;
using rb::scenario::loadStudy;

namespace {
const std::string kDir = "tests/scenario/study/";
}

TEST(Study, CaseLabels) {
  EXPECT_EQ(
      caseLabel({"contact.method=lut", "contact.flange_stiffness=7.075e+13", "solver.method=bdf",
                 "solver.rtol=1e-06", "solver.atol=1e-06", "solver.max_step=0.001"}),
      "LUT K=7.075e13 bdf tol=1e-6 hmax=1ms");
  EXPECT_EQ(caseLabel({"solver.step=0.00025", "solver.method=rk4", "contact.method=kec"}),
            "KEC rk4 h=0.25ms");
  EXPECT_EQ(caseLabel({"solver.rtol=1e-09", "solver.atol=1e-10", "profiles.refined_tables=true",
                       "run.distance=50"}),
            "refined rtol=1e-9 atol=1e-10 run.distance=50");
  EXPECT_EQ(caseLabel({}), "base");
}

TEST(Study, CaseKeysLabelBaseRole) {
  auto st = loadStudy(kDir + "labels.lua", RB_SOURCE_DIR);
  ASSERT_EQ(st.cases.size(), 6u);
  EXPECT_EQ(st.base, kDir + "base_a.lua");
  // Matrix first (slowest), then the cases.
  EXPECT_EQ(st.cases[0].label, "LUT K=1e10 rk4");
  EXPECT_EQ(st.cases[0].base, kDir + "base_a.lua");
  EXPECT_EQ(st.cases[0].role, "");
  EXPECT_EQ(st.cases[1].label, "rk4 KEC");
  EXPECT_EQ(st.cases[1].role, "reference");
  EXPECT_EQ(st.cases[2].label, "rk4 other base");
  EXPECT_EQ(st.cases[2].base, kDir + "base_b.lua");
  ASSERT_EQ(st.cases[2].overrides.size(), 1u);  // label, base, role are not --set overrides
  EXPECT_EQ(st.cases[2].overrides[0], "solver.method=rk4");
  EXPECT_EQ(st.cases[5].label, "bdf other base");
  // Ids depend on the overrides and the case's own base, not on labels or roles.
  EXPECT_NE(st.cases[2].id, st.cases[5].id);
  EXPECT_EQ(st.cases[0].id, loadStudy(kDir + "labels.lua", RB_SOURCE_DIR).cases[0].id);
  for (std::size_t i = 0; i < st.cases.size(); ++i)
    for (std::size_t k = 0; k < i; ++k) EXPECT_NE(st.cases[i].id, st.cases[k].id);
}

TEST(Study, BadCaseKeysAllReported) {
  std::string what;
  try {
    loadStudy(kDir + "bad_keys.lua", RB_SOURCE_DIR);
  } catch (const rb::InputError& e) {
    what = e.what();
  }
  EXPECT_NE(what.find("cases[1]: unknown key 'lable' (did you mean 'label'?)"), std::string::npos)
      << what;
  EXPECT_NE(what.find("cases[2]: role must be one of reference, reference_check, "
                      "reference_same_tables, baseline, got 'referense'"),
            std::string::npos)
      << what;
  EXPECT_NE(what.find("cases[3]: base scenario 'missing.lua' not found"), std::string::npos)
      << what;
}

TEST(Study, DuplicateCases) {
  std::string what;
  try {
    loadStudy(kDir + "duplicate.lua", RB_SOURCE_DIR);
  } catch (const rb::InputError& e) {
    what = e.what();
  }
  EXPECT_NE(what.find("two cases have the same overrides and base (b)"), std::string::npos) << what;
}

// Every shipped study loads, and every case of it (base + overrides) passes the scenario
// validator, so a long study never stops on a typo in its 40th case.
TEST(Study, ShippedStudiesValidate) {
  const std::map<std::string, std::size_t> expected = {
      {"efficiency_case3.lua", 66},  {"refinement.lua", 80},
      {"work_precision.lua", 99},    {"speed.lua", 9},
      {"paper_settings.lua", 20},    {"paper_settings_flange.lua", 20},
      {"flange_stiffness.lua", 90},  {"effects.lua", 20},
      {"guided_integrators.lua", 4}, {"primary_yaw.lua", 24}};
  for (const auto& [name, count] : expected) {
    auto st = loadStudy("scenarios/studies/" + name, RB_SOURCE_DIR);
    EXPECT_EQ(st.cases.size(), count) << name;
    for (const auto& c : st.cases) {
      rb::scenario::LoadOptions o;
      o.root = RB_SOURCE_DIR;
      o.overrides = c.overrides;
      try {
        rb::scenario::loadScenario(c.base, o);
      } catch (const rb::InputError& e) {
        ADD_FAILURE() << name << ": case " << c.label << ": " << e.what();
      }
    }
  }
}

namespace {
std::string loadError(const std::string& file) {
  try {
    loadStudy(kDir + file, RB_SOURCE_DIR);
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

// Case ids are 64-bit (16 hex digits): with 32 bits, two of a few ten thousand cases share a
// file name with a probability of several percent.
TEST(Study, CaseIdsAre64Bit) {
  auto st = loadStudy(kDir + "labels.lua", RB_SOURCE_DIR);
  for (const auto& c : st.cases) {
    ASSERT_EQ(c.id.size(), 5u + 16u) << c.id;
    EXPECT_EQ(c.id.substr(0, 5), "case_");
    EXPECT_EQ(c.id.find_first_not_of("0123456789abcdef", 5), std::string::npos) << c.id;
  }
}

// A 1e8-case matrix is refused at its study{} line before anything is expanded (this test would
// otherwise need gigabytes and minutes), naming the sizes and the key that raises the limit.
TEST(Study, HugeMatrixRefusedWithTheLimit) {
  const std::string what = loadError("huge.lua");
  EXPECT_NE(what.find(kDir + "huge.lua:6: study: 100000000 cases (100 x 100 x 100 x 100 x 1) "
                             "exceed max_cases = 10000; raise study.max_cases"),
            std::string::npos)
      << what;
}

TEST(Study, MaxCasesIsTheLimit) {
  const std::string what = loadError("max_cases.lua");
  EXPECT_NE(what.find("study: 3 cases (3 x 1) exceed max_cases = 2"), std::string::npos) << what;
  EXPECT_NE(loadError("max_cases_bad.lua").find("max_cases must be a whole number in [1, "),
            std::string::npos);
  EXPECT_EQ(loadStudy(kDir + "labels.lua", RB_SOURCE_DIR).max_cases, 10000);
}
