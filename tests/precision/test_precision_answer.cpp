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

// A file like resultFile's with its own output times t.
std::string resultFileAt(const std::string& name, const std::vector<double>& t,
                         const std::vector<double>& y, const std::vector<double>& car = {}) {
  const std::string path = (dir() / name).string();
  rb::io::ResultFile f(path);
  f.dataset("/time", t, "s");
  f.attr("/bodies", "names", std::string(car.empty() ? "ws1" : "ws1\ncar"));
  f.attr("/bodies/ws1", "kind", std::string("wheelset"));
  f.dataset("/bodies/ws1/y", y, "m");
  if (car.empty()) {
    f.attr("/contact", "method", std::string("kec"));
  } else {
    f.attr("/bodies/car", "kind", std::string("car_body"));
    f.dataset("/bodies/car/y", car, "m");
  }
  f.finalize();
  return path;
}

TEST(PrecisionAnswer, ErrorOfAFailedRunIsOnTheReferenceTimesInsideItsRun) {
  // The reference over 1 s at 0.1 s; the run failed at 0.5 s with outputs every 0.025 s, 0.05 mm
  // off: the error is taken at the reference's times up to 0.5 s, the run interpolated there.
  std::vector<double> tr, yr, tc, yc;
  for (int i = 0; i <= 10; ++i) {
    tr.push_back(0.1 * i);
    yr.push_back(1e-3 * tr.back());
  }
  for (int i = 0; i <= 20; ++i) {
    tc.push_back(0.025 * i);
    yc.push_back(1e-3 * tc.back() + 5e-5);
  }
  const rb::io::ResultReader a(resultFileAt("half.h5", tc, yc)), b(resultFileAt("full.h5", tr, yr));
  const pr::Error e = pr::runError(a, b, lateral());
  ASSERT_TRUE(e.have);
  EXPECT_NEAR(e.max, 0.05, 1e-9);
  EXPECT_NEAR(e.rms, 0.05, 1e-9);
}

TEST(PrecisionAnswer, GuidedVehicleErrorCoversItsOtherBodies) {
  // Guided wheelsets follow the track (no error of their own): y covers the other bodies.
  const std::vector<double> t = {0.0, 0.1, 0.2}, zero = {0, 0, 0}, off = {3e-4, 3e-4, 3e-4};
  const rb::io::ResultReader a(resultFileAt("g_run.h5", t, zero, off)),
      b(resultFileAt("g_ref.h5", t, zero, zero));
  const auto qs = pr::parseQuantities({"y", "car.y"}, {"ws1", "car"}, false);
  for (const auto& q : qs) {
    const pr::Error e = pr::runError(a, b, q);
    ASSERT_TRUE(e.have) << q.tag;
    EXPECT_NEAR(e.max, 0.3, 1e-12) << q.tag;
  }
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

TEST(PrecisionAnswer, TheTablesAreTheEnginesErrors) {
  // precision.csv and precision_references.csv are written by the engine from the same errors
  // the recommendation uses: per quantity integration and total error, max and RMS; the bound row
  // says verified or why not.
  pr::Answer a;
  a.quantities = pr::parseQuantities({"y"}, {"ws1"}, true);
  a.limit = 1e-3;
  a.references = {reference(0.02, 0.5, false)};
  a.cases = cases();
  for (auto& c : a.cases) {
    c.status = c.ok ? "ok" : "failed";
    c.integration_all = {c.integration};
    c.total_all = {pr::Error{}};
  }
  const std::string csv = pr::casesCsv(a);
  EXPECT_NE(csv.find("y_integration_max_mm,y_integration_rms_mm,y_total_max_mm"), std::string::npos)
      << csv;
  EXPECT_NE(csv.find(",0.035,"), std::string::npos) << csv;  // abm h=1ms's integration error
  EXPECT_NE(csv.find(",inf,"), std::string::npos) << csv;    // the diverged one's
  const std::string refs = pr::referencesCsv(a);
  EXPECT_NE(refs.find("UNVERIFIED: a reference run failed"), std::string::npos) << refs;
  EXPECT_NE(refs.find(",0.5,"), std::string::npos) << refs;  // the table error
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
