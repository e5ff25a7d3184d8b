// The answer of `workbench precision` computed in the engine (workbench/precision/answer.hpp):
// the error rule on result files of known content (a diverged run is infinitely wrong), the
// recommendation rule with its notes (a level below the table error cannot be reached with those
// tables, a level below the reference bound cannot be verified), and the plan's checks before any
// run (quantities, fixed steps against the output interval).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/precision/answer.hpp"
#include "workbench/precision/plan.hpp"

namespace fs = std::filesystem;
namespace pr = rb::precision;

namespace {

const std::string kRoot = RB_SOURCE_DIR;
const std::string kSmall = kRoot + "/scenarios/validation/case1_R300_kec.lua";

fs::path dir() {
  const fs::path p = fs::path(RB_BINARY_DIR) / "precision_answer_tests";
  fs::create_directories(p);
  return p;
}

// A result file with one wheelset whose lateral displacement is y(t) on t = 0, 0.01, ...
std::string resultFile(const std::string& name, const std::vector<double>& y) {
  const std::string path = (dir() / name).string();
  rb::io::ResultFile f(path);
  std::vector<double> t;
  for (std::size_t i = 0; i < y.size(); ++i) t.push_back(0.01 * static_cast<double>(i));
  f.dataset("/time", t, "s");
  f.attr("/bodies", "names", std::string("ws1"));
  f.attr("/bodies/ws1", "kind", std::string("wheelset"));
  f.dataset("/bodies/ws1/y", y, "m");
  f.attr("/contact", "method", std::string("kec"));
  f.finalize();
  return path;
}

pr::Quantity lateral() {
  return pr::parseQuantities({"y"}, {"ws1"}, true).front();
}

TEST(PrecisionAnswer, ErrorIsMaxAndRmsInDisplayUnits) {
  const std::string ref = resultFile("ref.h5", {0, 0, 0, 0});
  const std::string run = resultFile("run.h5", {0, 1e-3, -2e-3, 0});
  const rb::io::ResultReader a(run), b(ref);
  const pr::Error e = pr::runError(a, b, lateral());
  ASSERT_TRUE(e.have);
  EXPECT_DOUBLE_EQ(e.max, 2.0);  // mm
  EXPECT_NEAR(e.rms, std::sqrt((1.0 + 4.0) / 4.0), 1e-12);
}

TEST(PrecisionAnswer, DivergedRunIsInfinitelyWrong) {
  // A NaN in the run: its error is infinite (one rule: never left out of the comparison).
  const std::string ref = resultFile("ref2.h5", {0, 0, 0, 0});
  const std::string run =
      resultFile("nan.h5", {0, 1e-6, std::numeric_limits<double>::quiet_NaN(), 1e-6});
  const rb::io::ResultReader a(run), b(ref);
  const pr::Error e = pr::runError(a, b, lateral());
  ASSERT_TRUE(e.have);
  EXPECT_TRUE(std::isinf(e.max));
}

pr::ReferenceAnswer reference(double bound, double table, bool verified = true) {
  pr::ReferenceAnswer r;
  r.model = "KEC";
  r.verified = verified;
  r.why = verified ? "" : "a reference run failed (reference failed: wheel lift)";
  pr::Error b, t;
  b.have = t.have = true;
  b.max = b.rms = bound;
  t.max = t.rms = table;
  r.bound = {b};
  r.table = {t};
  return r;
}

std::vector<pr::CaseAnswer> cases() {
  std::vector<pr::CaseAnswer> out;
  auto add = [&](const std::string& label, double err, double cpu, bool ok = true) {
    pr::CaseAnswer c;
    c.model = "KEC";
    c.label = label;
    c.ok = ok;
    c.cpu = cpu;
    c.rhs = cpu * 1e5;
    c.integration.have = true;
    c.integration.max = err;
    out.push_back(c);
  };
  add("abm h=1ms", 0.035, 0.04);
  add("abm h=0.5ms", 5e-5, 0.05);
  add("dopri5 diverged", std::numeric_limits<double>::infinity(), 0.01);
  add("rk4 failed", 1e-9, 0.001, false);
  return out;
}

TEST(PrecisionAnswer, CheapestOkSettingReachingTheLevel) {
  const auto cs = cases();
  const auto ref = reference(1e-8, 1e-3);
  const pr::Recommendation r = pr::recommend("KEC", 0.1, cs, &ref, false, "mm");
  ASSERT_TRUE(r.reached);
  EXPECT_EQ(cs[static_cast<std::size_t>(r.best)].label, "abm h=1ms");  // not the diverged one
  EXPECT_TRUE(r.verified);
  EXPECT_EQ(r.note, "");
  const pr::Recommendation none = pr::recommend("KEC", 1e-6, cs, &ref, false, "mm");
  EXPECT_FALSE(none.reached);  // the failed rk4 run does not count
  EXPECT_NE(none.note.find("none reaches it"), std::string::npos);
}

TEST(PrecisionAnswer, LevelBelowTheTableErrorIsSaidToBeUnreachable) {
  // 0.01 mm against a 0.24 mm table error: the integration error reaches it, the total cannot.
  const auto cs = cases();
  const auto ref = reference(1e-8, 0.24);
  const pr::Recommendation r = pr::recommend("KEC", 0.01, cs, &ref, false, "mm");
  EXPECT_TRUE(r.table_limited);
  EXPECT_NE(r.note.find("cannot be reached with these tables"), std::string::npos) << r.note;
  EXPECT_NE(r.note.find("0.24"), std::string::npos) << r.note;
  // On the refined tables there is no table error to exceed.
  EXPECT_FALSE(pr::recommend("KEC", 0.01, cs, &ref, true, "mm").table_limited);
}

TEST(PrecisionAnswer, UnverifiedOrUnresolvableLevelIsSaid) {
  const auto cs = cases();
  const auto bad = reference(1e-8, 1e-3, false);
  const pr::Recommendation r = pr::recommend("KEC", 0.1, cs, &bad, false, "mm");
  EXPECT_FALSE(r.verified);
  EXPECT_NE(r.note.find("UNVERIFIED"), std::string::npos) << r.note;
  EXPECT_NE(r.note.find("wheel lift"), std::string::npos) << r.note;
  const auto wide = reference(0.05, 1e-3);
  const pr::Recommendation u = pr::recommend("KEC", 0.01, cs, &wide, false, "mm");
  EXPECT_FALSE(u.verified);
  EXPECT_NE(u.note.find("cannot be verified"), std::string::npos) << u.note;
}

TEST(PrecisionAnswer, QuantitiesAreCheckedBeforeAnyRun) {
  rb::precision::PrecisionOptions o;
  o.scenario = kSmall;
  o.root = kRoot;
  o.quick = true;
  o.quantities = "y,Ymax";
  try {
    (void)pr::makePlan(o);
    FAIL() << "an unknown quantity must be refused by the plan";
  } catch (const rb::InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--quantities"), std::string::npos) << m;
    EXPECT_NE(m.find("Ymax"), std::string::npos) << m;
  }
  o.quantities = "y,bogie9.yaw";
  EXPECT_THROW((void)pr::makePlan(o), rb::InputError);
  o.quantities = "y,YQ,ws.roll";
  EXPECT_NO_THROW((void)pr::makePlan(o));
}

TEST(PrecisionAnswer, EveryOptionIsNamedBeforeAnyRun) {
  auto refused = [](const std::function<void(rb::precision::PrecisionOptions&)>& set,
                    const std::string& option) {
    rb::precision::PrecisionOptions o;
    o.scenario = kSmall;
    o.root = kRoot;
    o.quick = true;
    set(o);
    try {
      (void)pr::makePlan(o);
    } catch (const rb::InputError& e) {
      return std::string(e.what()).find(option) != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(refused([](auto& o) { o.jobs = -2; }, "--jobs"));
  EXPECT_TRUE(refused([](auto& o) { o.repeats = 0; }, "--repeats"));
  EXPECT_TRUE(refused([](auto& o) { o.levels = "0.1,x"; }, "--levels"));
  EXPECT_TRUE(refused([](auto& o) { o.tolerances = "1e-3,,1e-5"; }, "--tolerances"));
  EXPECT_TRUE(refused([](auto& o) { o.reference_methods = "bdf"; }, "--reference-methods"));
  EXPECT_TRUE(refused([](auto& o) { o.methods = "kec,wrong"; }, "--methods"));
}

TEST(PrecisionAnswer, FixedStepsFitTheOutputInterval) {
  // 5 ms output interval: the default 2 ms step cannot reach every output time; the ladder moves
  // it to 5/3 ms and says so, every setting still runs.
  rb::precision::PrecisionOptions o;
  o.scenario = kSmall;
  o.root = kRoot;
  o.overrides = {"run.output.every=0.005"};
  o.integrators = "abm";
  o.methods = "kec";
  const pr::Plan p = pr::makePlan(o);
  ASSERT_EQ(p.ladders.size(), 1u);
  std::vector<double> steps;
  for (const auto& r : p.ladders[0].rungs) steps.push_back(r.value);
  ASSERT_EQ(steps.size(), 5u);
  for (double h : steps) {
    const double n = 0.005 / h;
    EXPECT_NEAR(n, std::round(n), 1e-6) << h;
  }
  EXPECT_NEAR(steps.front(), 0.005 / 3, 1e-12);
  ASSERT_FALSE(p.adaptations.empty());
  EXPECT_NE(p.adaptations.front().find("0.002"), std::string::npos) << p.adaptations.front();
  EXPECT_NE(pr::planCsv(p).find("adapted"), std::string::npos);
  // A step the user names that does not fit is refused before any run, naming --steps.
  o.steps = "2e-3,1e-3";
  try {
    (void)pr::makePlan(o);
    FAIL() << "--steps 2e-3 with a 5 ms output interval must be refused";
  } catch (const rb::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--steps"), std::string::npos) << e.what();
  }
}

}  // namespace
