// contact.table_interpolation: the key, its name table, a bad value reported as file:line, and
// short case-3 runs on the paper's linear tables that converge and finish with both methods and
// both kinds of integrator.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "workbench/app/run.hpp"
#include "workbench/contact/interpolation.hpp"
#include "workbench/core/error.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/scenario/schema.hpp"

namespace {

using rb::contact::TableInterpolation;
namespace fs = std::filesystem;

rb::scenario::LoadOptions opts(std::vector<std::string> overrides = {}) {
  rb::scenario::LoadOptions o;
  o.root = RB_SOURCE_DIR;
  o.overrides = std::move(overrides);
  return o;
}

const char* kCase3 = "scenarios/studies/case3_base.lua";

TEST(TableInterpolationKey, SchemaChoicesComeFromTheNameTable) {
  for (const auto& e : rb::contact::kTableInterpolationNames) {
    EXPECT_EQ(rb::parse<TableInterpolation>(e.name), e.value) << e.name;
    EXPECT_EQ(rb::nameOf(e.value), e.name);
  }
  const rb::scenario::KeySpec* k = rb::scenario::block("contact").key("table_interpolation");
  ASSERT_NE(k, nullptr);
  EXPECT_EQ(k->choices, rb::namesOf<TableInterpolation>());
  EXPECT_EQ(k->def, "cubic");
  const std::string help = rb::scenario::referenceText();
  for (const auto& e : rb::contact::kTableInterpolationNames)
    EXPECT_NE(help.find(std::string(e.name) + ": " + std::string(e.help)), std::string::npos)
        << e.name;
}

TEST(TableInterpolationKey, DefaultIsCubicAndOverrideSetsLinear) {
  EXPECT_EQ(rb::scenario::loadScenario(kCase3, opts()).contact.table_interpolation,
            TableInterpolation::Cubic);
  const auto s = rb::scenario::loadScenario(kCase3, opts({"contact.table_interpolation=linear"}));
  EXPECT_EQ(s.contact.table_interpolation, TableInterpolation::Linear);
}

TEST(TableInterpolationKey, BadValueIsReportedWithFileLine) {
  const std::string f = "tests/scenario/bad/table_interpolation.lua";
  std::string what = "<no error>";
  try {
    rb::scenario::loadScenario(f, opts());
  } catch (const rb::InputError& e) {
    what = e.what();
  }
  EXPECT_EQ(what, f + ":4: contact: table_interpolation: unknown value 'bilinear' (did you mean "
                      "'linear'?); valid: cubic, linear");
}

// Case 3 (60 m) on linear tables: Newton on the piecewise-linear KEC profile and the kinks of the
// bilinear LUT surfaces must not stop either integrator.
void expectRunFinishes(const std::string& method, const std::string& label,
                       std::vector<std::string> solver) {
  const fs::path dir = fs::temp_directory_path() / "rb_test_table_interpolation";
  fs::create_directories(dir);
  rb::app::RunOptions o;
  o.scenario = kCase3;
  o.root = RB_SOURCE_DIR;
  o.quiet = true;
  o.out = (dir / (method + "_" + label + ".h5")).string();
  o.overrides = {"contact.method=" + method, "contact.table_interpolation=linear",
                 "run.distance=60"};
  for (std::string& s : solver) o.overrides.push_back(std::move(s));
  EXPECT_EQ(rb::app::runScenario(o), 0) << method;
}

// accept_unstable_step: the start-of-run stability check linearises the right-hand side by finite
// differences at the initial state; on the bilinear LUT it reports a 0.47 ms limit (2.2 ms on the
// cubic tables), a difference quotient taken across the kinks of z, phi at the nodes (the centred
// wheelset sits on the node y = 0). The paper's 1 ms ABM run itself finishes, which is the point.
const std::vector<std::string> kAbm = {"solver.method=abm", "solver.step=1e-3",
                                       "contact.wheelset_spin=prescribed", "solver.stiff=explicit",
                                       "solver.accept_unstable_step=true"};
const std::vector<std::string> kDopri = {"solver.method=dopri5", "solver.rtol=1e-6"};

TEST(TableInterpolationRun, KecAbmPrescribedSpin) {
  expectRunFinishes("kec", "abm", kAbm);
}
TEST(TableInterpolationRun, LutAbmPrescribedSpin) {
  expectRunFinishes("lut", "abm", kAbm);
}
TEST(TableInterpolationRun, KecDopri5) {
  expectRunFinishes("kec", "dopri5", kDopri);
}
TEST(TableInterpolationRun, LutDopri5) {
  expectRunFinishes("lut", "dopri5", kDopri);
}

}  // namespace
