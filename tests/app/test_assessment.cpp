// The assessment of a run (run.assessment -> /assessment, ASSESSMENT_LAYOUT): nothing asked costs
// nothing and writes nothing; a short case 2 run writes every group of the layout with finite
// values, limits and ok flags, its values are those of the written series (2 m sliding means:
// the larger of |F1|, |F2|; dQ/Q, stability, T gamma: the maximum) and its summary is the largest
// over wheels, bogies and floor points; samples at output times share the outputs' model
// evaluations; the static tangent gives no wheel unloading and no track shift force; a guided
// vehicle refuses safety at check; `workbench assess` reproduces a run's /assessment, applies new
// parameters and leaves a file it cannot assess untouched.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "h5read.hpp"
#include "scenario_run.hpp"
#include "workbench/app/assess.hpp"
#include "workbench/app/run.hpp"
#include "workbench/core/error.hpp"

namespace {

constexpr const char* kWheelsets[] = {"ws1", "ws2", "ws3", "ws4"};
constexpr const char* kSides[] = {"left", "right"};
constexpr const char* kAllOn[] = {"run.assessment.safety=true", "run.assessment.stability=true",
                                  "run.assessment.comfort=true", "run.assessment.wear=true"};

rb::app::RunOptions options(const std::string& scenario, const std::string& name,
                            const std::vector<std::string>& overrides) {
  return h5test::quietRun(scenario, h5test::freshResult("rb_test_assessment", name), overrides);
}

hid_t run(const std::string& scenario, const std::string& name,
          const std::vector<std::string>& overrides) {
  return h5test::runAndOpen(options(scenario, name, overrides));
}

double attr(hid_t f, const std::string& g, const std::string& n) {
  return h5test::numAttr<double>(f, g, n);
}

double maxAbs(const std::vector<double>& v) {
  double m = 0.0;
  for (const double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Percentile p of x, linear interpolation between order statistics (numpy's default).
double percentile(std::vector<double> x, double p) {
  std::sort(x.begin(), x.end());
  const double h = (static_cast<double>(x.size()) - 1.0) * p / 100.0;
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, x.size() - 1);
  return x[lo] + (h - static_cast<double>(lo)) * (x[hi] - x[lo]);
}

// The assessed value of a 2 m sliding-mean quantity: the larger magnitude of F1 (0.15 %) and F2
// (99.85 %) of the written series.
double slidingValue(const std::vector<double>& v) {
  return std::max(std::abs(percentile(v, 99.85)), std::abs(percentile(v, 0.15)));
}

bool allFinite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// The attributes every quantity's group carries.
void expectQuantity(hid_t f, const std::string& g) {
  SCOPED_TRACE(g);
  ASSERT_TRUE(h5test::exists(f, g));
  EXPECT_TRUE(std::isfinite(attr(f, g, "value")));
  EXPECT_FALSE(std::isnan(attr(f, g, "limit")));
  EXPECT_EQ(attr(f, g, "margin"), attr(f, g, "limit") - attr(f, g, "value"));
  EXPECT_EQ(h5test::numAttr<long long>(f, g, "ok"), attr(f, g, "margin") >= 0 ? 1 : 0);
  EXPECT_FALSE(h5test::stringAttr(f, g, "unit").empty());
  EXPECT_FALSE(h5test::stringAttr(f, g, "clause").empty());
}

}  // namespace

TEST(Assessment, NothingAskedWritesNothingAndCostsNothing) {
  const std::string scen = "scenarios/validation/case2_kec.lua";
  // The shipped case asks for the assessment; switch every group off, and compare with a run
  // whose table asks for nothing.
  const std::vector<std::string> off = {
      "run.distance=20", "run.assessment.safety=false", "run.assessment.stability=false",
      "run.assessment.comfort=false", "run.assessment.wear=false"};
  hid_t a = run(scen, "off.h5", off);
  ASSERT_GE(a, 0);
  std::vector<std::string> on = {"run.distance=20"};
  on.insert(on.end(), std::begin(kAllOn), std::end(kAllOn));
  hid_t b = run(scen, "on.h5", on);
  ASSERT_GE(b, 0);
  EXPECT_FALSE(h5test::exists(a, "/assessment"));
  EXPECT_TRUE(h5test::exists(b, "/assessment"));
  // The integration is the same. The assessment's samples are step ends of the fixed-step ABM:
  // each sampled state's evaluation is the integrator's next right-hand side, so they cost no
  // model evaluation of their own (ContactVehicleOde::shareOutputEvaluations).
  EXPECT_EQ(attr(a, "/stats", "rhs_evals"), attr(b, "/stats", "rhs_evals"));
  EXPECT_EQ(attr(a, "/stats", "steps"), attr(b, "/stats", "steps"));
  EXPECT_EQ(attr(b, "/stats", "model_evaluations"), attr(a, "/stats", "model_evaluations"));
  EXPECT_GT(attr(b, "/stats", "shared_evaluations"), attr(a, "/stats", "shared_evaluations"));
  EXPECT_GT(attr(b, "/stats", "assessment_samples"), 0.0);
  // The outputs do not depend on whether the assessment samples in between.
  for (const char* ds : {"/bodies/ws1/y", "/contact/ws1/left/Q", "/contact/ws2/right/Y"})
    EXPECT_EQ(h5test::dataset(a, ds), h5test::dataset(b, ds)) << ds;
  H5Fclose(a);
  H5Fclose(b);
}

TEST(Assessment, SamplesAtOutputTimesShareTheOutputsEvaluations) {
  // Outputs with body accelerations and element values, and the assessment sampled at the output
  // times: per output time one evaluation gives the wheels, the element values, the accelerations
  // and the assessment's wheel, bogie and floor signals (ContactVehicleOde::outputs), so as many
  // evaluations as the wheels and elements alone.
  const std::string scen = "tests/app/data/wheel_forces/all_outputs.lua";
  hid_t plain = run(scen, "plain.h5",
                    {"run.output.body_accelerations=false", "run.assessment.safety=false",
                     "run.assessment.stability=false", "run.assessment.comfort=false",
                     "run.assessment.wear=false"});
  ASSERT_GE(plain, 0);
  hid_t shared = run(scen, "shared.h5", {});
  ASSERT_GE(shared, 0);
  const std::size_t outputs = h5test::dataset(shared, "/time").size();
  EXPECT_FALSE(h5test::exists(plain, "/assessment"));
  EXPECT_GT(attr(shared, "/stats", "assessment_samples"), 0.0);
  EXPECT_EQ(attr(shared, "/stats", "rhs_evals"), attr(plain, "/stats", "rhs_evals"));
  EXPECT_EQ(attr(shared, "/stats", "model_evaluations"),
            attr(plain, "/stats", "model_evaluations"));
  EXPECT_GT(outputs, 0U);
  for (const char* ds : {"/bodies/ws1/y", "/contact/ws1/left/Q", "/contact/ws2/right/patch0/fy",
                         "/elements/sec_z_bogie1_l/force", "/elements/sec_bend_bogie1_l/force"})
    EXPECT_EQ(h5test::dataset(plain, ds), h5test::dataset(shared, ds)) << ds;
  H5Fclose(plain);
  H5Fclose(shared);
}

TEST(Assessment, NoKeyEqualsNothingAsked) {
  // A scenario without run.assessment and the same with an empty table: same evaluations.
  const std::string scen = "tests/app/data/wheel_forces/tangent.lua";
  hid_t a = run(scen, "nokey.h5", {});
  ASSERT_GE(a, 0);
  hid_t b = run(scen, "empty.h5", {"run.assessment.wear=false"});
  ASSERT_GE(b, 0);
  EXPECT_FALSE(h5test::exists(a, "/assessment"));
  EXPECT_FALSE(h5test::exists(b, "/assessment"));
  EXPECT_EQ(attr(a, "/stats", "model_evaluations"), attr(b, "/stats", "model_evaluations"));
  EXPECT_EQ(attr(a, "/stats", "rhs_evals"), attr(b, "/stats", "rhs_evals"));
  H5Fclose(a);
  H5Fclose(b);
}

// The largest value of a quantity over the sections of /assessment/sections.
double sectionMax(hid_t f, const std::string& key) {
  const std::string names = h5test::stringAttr(f, "/assessment/sections", "names");
  double best = -1e300;
  std::size_t from = 0;
  while (from < names.size()) {
    const std::size_t end = std::min(names.find('\n', from), names.size());
    const std::string g = "/assessment/sections/" + names.substr(from, end - from);
    from = end + 1;
    if (H5Aexists_by_name(f, g.c_str(), key.c_str(), H5P_DEFAULT) > 0)
      best = std::max(best, attr(f, g, key));
  }
  return best;
}

TEST(Assessment, Case2WritesEveryGroupOfTheLayout) {
  std::vector<std::string> sets = {"run.distance=120"};
  sets.insert(sets.end(), std::begin(kAllOn), std::end(kAllOn));
  hid_t f = run("scenarios/validation/case2_kec.lua", "case2.h5", sets);
  ASSERT_GE(f, 0);
  const std::string A = "/assessment";
  const auto time = h5test::dataset(f, A + "/time");
  ASSERT_GT(time.size(), 100u);
  EXPECT_EQ(h5test::dataset(f, A + "/distance").size(), time.size());
  EXPECT_GT(attr(f, A, "sample_every"), 0.0);
  EXPECT_FALSE(h5test::stringAttr(f, A, "standards").empty());
  EXPECT_FALSE(h5test::stringAttr(f, A, "assumptions").empty());
  const std::string S = A + "/summary";

  double yq = 0, sy = 0, dq = -1e300, tg = 0, st = 0;
  for (const char* ws : kWheelsets) {
    for (const char* side : kSides) {
      const std::string w = A + "/safety/" + ws + "/" + side + "/";
      expectQuantity(f, w + "y_over_q");
      const auto v = h5test::dataset(f, w + "y_over_q/value");
      EXPECT_EQ(v.size(), h5test::dataset(f, w + "y_over_q/s").size());
      ASSERT_FALSE(v.empty());
      EXPECT_TRUE(allFinite(v));
      EXPECT_NEAR(attr(f, w + "y_over_q", "value"), slidingValue(v), 1e-12);
      EXPECT_TRUE(std::isfinite(attr(f, w + "y_over_q", "nadal_limit")));
      yq = std::max(yq, attr(f, w + "y_over_q", "value"));
      expectQuantity(f, w + "dq_over_q");
      const auto d = h5test::dataset(f, w + "dq_over_q/value");
      EXPECT_EQ(d.size(), time.size());
      dq = std::max(dq, *std::max_element(d.begin(), d.end()));
      const std::string wear = A + "/wear/" + ws + "/" + side;
      const auto t = h5test::dataset(f, wear + "/t_gamma");
      EXPECT_EQ(t.size(), time.size());
      EXPECT_EQ(h5test::dataset(f, wear + "/power").size(), time.size());
      EXPECT_DOUBLE_EQ(attr(f, wear, "max"), maxAbs(t));
      EXPECT_TRUE(std::isfinite(attr(f, wear + "/patch0", "energy")));
      tg = std::max(tg, maxAbs(t));
    }
    const std::string g = A + "/safety/" + ws + "/sum_y";
    expectQuantity(f, g);
    const auto v = h5test::dataset(f, g + "/value");
    EXPECT_NEAR(attr(f, g, "value"), slidingValue(v), 1e-9);
    sy = std::max(sy, attr(f, g, "value"));
  }
  for (const auto& [bogie, ws] : {std::pair{"bogie1", "ws1"}, std::pair{"bogie1", "ws2"},
                                  std::pair{"bogie2", "ws3"}, std::pair{"bogie2", "ws4"}}) {
    const std::string g = A + "/stability/" + bogie + "/" + ws;
    expectQuantity(f, g);
    const auto rms = h5test::dataset(f, g + "/rms");
    ASSERT_FALSE(rms.empty());
    EXPECT_EQ(h5test::dataset(f, g + "/s").size(), rms.size());
    EXPECT_EQ(h5test::dataset(f, g + "/acceleration").size(), time.size());
    st = std::max(st, maxAbs(rms));
  }
  double nmv = 0;
  for (const char* p : {"front", "centre", "rear"}) {
    const std::string g = A + "/comfort/" + p;
    expectQuantity(f, g);
    for (const char* d : {"a_x", "a_y", "a_z", "nc_x", "nc_y", "nc_z"}) {
      const auto v = h5test::dataset(f, g + "/" + d);
      EXPECT_EQ(v.size(), time.size()) << g << d;
      EXPECT_TRUE(allFinite(v)) << g << d;
    }
    EXPECT_TRUE(std::isfinite(attr(f, g, "wz_lateral")));
    nmv = std::max(nmv, attr(f, g, "n_mv"));
  }
  // Running safety per track section (EN 14363): the summary is the worst section; every sample
  // lies in one section, so the largest dQ/Q0 is that of the whole run, and a sliding window of
  // a section lies in the whole run's.
  EXPECT_DOUBLE_EQ(attr(f, S, "y_over_q"), sectionMax(f, "y_over_q"));
  EXPECT_DOUBLE_EQ(attr(f, S, "sum_y"), sectionMax(f, "sum_y"));
  EXPECT_LE(attr(f, S, "y_over_q"), yq * (1 + 1e-12) + 0.05);
  EXPECT_GT(attr(f, S, "sum_y"), 0.0);
  EXPECT_LE(sy, 1e9);
  EXPECT_DOUBLE_EQ(attr(f, S, "dq_over_q"), dq);
  EXPECT_DOUBLE_EQ(attr(f, S, "t_gamma_max"), tg);
  EXPECT_DOUBLE_EQ(attr(f, S, "stability_rms"), st);
  EXPECT_DOUBLE_EQ(attr(f, S, "n_mv"), nmv);
  EXPECT_EQ(attr(f, S, "y_over_q_limit"), 0.8);
  EXPECT_EQ(h5test::numAttr<long long>(f, S, "y_over_q_ok"), 1);
  for (const char* q : {"y_qst", "q_qst", "q_max", "wz_lateral", "wz_vertical"})
    EXPECT_TRUE(std::isfinite(attr(f, S, q))) << q;
  H5Fclose(f);
}

TEST(Assessment, AnExceededLimitIsAResultWithAWarning) {
  hid_t f = run("scenarios/validation/case2_kec.lua", "exceeded.h5",
                {"run.distance=20", "run.assessment.yq_limit=1e-6"});
  ASSERT_GE(f, 0);  // the run ends ok
  EXPECT_EQ(h5test::stringAttr(f, "/stats", "status"), "ok");
  EXPECT_NE(h5test::stringAttr(f, "/stats", "warnings").find("assessment: y_over_q"),
            std::string::npos);
  EXPECT_EQ(h5test::numAttr<long long>(f, "/assessment/summary", "y_over_q_ok"), 0);
  EXPECT_EQ(h5test::numAttr<long long>(f, "/assessment/summary", "all_ok"), 0);
  // T gamma has no limit: no t_gamma_max_limit (never a non-finite attribute).
  EXPECT_FALSE(H5Aexists_by_name(f, "/assessment/summary", "t_gamma_max_limit", H5P_DEFAULT) > 0);
  H5Fclose(f);
}

TEST(Assessment, StaticTangentHasNoUnloadingAndNoTrackShift) {
  hid_t f = run("tests/app/data/wheel_forces/tangent.lua", "tangent.h5",
                {"run.assessment.safety=true", "run.assessment.wear=true"});
  ASSERT_GE(f, 0);
  const std::string S = "/assessment/safety/";
  for (const char* ws : kWheelsets) {
    for (const char* side : kSides) {
      const auto d = h5test::dataset(f, S + ws + "/" + side + "/dq_over_q/value");
      ASSERT_FALSE(d.empty());
      EXPECT_LT(maxAbs(d), 1e-9) << ws << side;
    }
    const auto l = h5test::dataset(f, S + ws + "/left/y_over_q/value");
    const auto r = h5test::dataset(f, S + ws + "/right/y_over_q/value");
    ASSERT_EQ(l.size(), r.size());
    for (std::size_t k = 0; k < l.size(); ++k) EXPECT_NEAR(l[k], r[k], 1e-9) << ws << k;
    EXPECT_LT(maxAbs(h5test::dataset(f, S + ws + "/sum_y/value")), 1e-6) << ws;
  }
  H5Fclose(f);
}

TEST(Assessment, GuidedVehicleRefusesSafetyAtCheck) {
  const auto o = options("scenarios/vehicle/manchester_guided_r500.lua", "guided.h5",
                         {"run.assessment.safety=true"});
  try {
    rb::app::checkScenario(o);
    FAIL() << "no error";
  } catch (const rb::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("manchester_guided_r500.lua:15: run.assessment: safety "
                                         "needs wheel/rail contact"),
              std::string::npos)
        << e.what();
  }
}

namespace {

std::vector<char> bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(AssessCommand, ReproducesTheRunsAssessmentAndAppliesNewParameters) {
  std::vector<std::string> sets = {"run.distance=120"};
  sets.insert(sets.end(), std::begin(kAllOn), std::end(kAllOn));
  const auto o = options("scenarios/validation/case2_kec.lua", "assess.h5", sets);
  ASSERT_EQ(rb::app::runScenario(o), 0);
  const char* keys[] = {"y_over_q", "sum_y",         "dq_over_q", "y_qst",      "q_qst",
                        "q_max",    "stability_rms", "n_mv",      "wz_lateral", "t_gamma_max"};
  std::vector<double> before;
  std::vector<double> sum_y_before;
  {
    hid_t f = H5Fopen(o.out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    for (const char* k : keys) before.push_back(attr(f, "/assessment/summary", k));
    sum_y_before = h5test::dataset(f, "/assessment/safety/ws1/sum_y/value");
    H5Fclose(f);
  }
  rb::app::AssessOptions a;
  a.file = o.out;
  a.quiet = true;
  ASSERT_EQ(rb::app::assessFile(a), 0);
  {
    hid_t f = H5Fopen(o.out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    for (std::size_t k = 0; k < std::size(keys); ++k)
      EXPECT_EQ(attr(f, "/assessment/summary", keys[k]), before[k]) << keys[k];
    EXPECT_EQ(h5test::dataset(f, "/assessment/safety/ws1/sum_y/value"), sum_y_before);
    EXPECT_TRUE(h5test::exists(f, "/contact/ws1/left/Q"));  // the rest of the file is kept
    H5Fclose(f);
  }
  a.overrides = {"run.assessment.alpha=0.85", "run.assessment.comfort=false"};
  ASSERT_EQ(rb::app::assessFile(a), 0);
  hid_t f = H5Fopen(o.out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_NEAR(attr(f, "/assessment/safety/ws1/sum_y", "limit"),
              0.85 * (10e3 + 2.0 * attr(f, "/assessment/safety/ws1/sum_y", "q0") / 3.0), 1e-6);
  EXPECT_FALSE(h5test::exists(f, "/assessment/comfort"));
  EXPECT_TRUE(h5test::exists(f, "/assessment/stability"));
  H5Fclose(f);
}

TEST(AssessCommand, SaysWhatIsMissingAndLeavesTheFileAlone) {
  const auto o = options("tests/app/data/wheel_forces/tangent.lua", "coarse.h5", {});
  ASSERT_EQ(rb::app::runScenario(o), 0);  // outputs every 10 ms, no assessment
  const auto bytes = bytesOf(o.out);
  rb::app::AssessOptions a;
  a.file = o.out;
  a.quiet = true;
  try {
    rb::app::assessFile(a);
    FAIL() << "no error";
  } catch (const rb::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("too coarse"), std::string::npos) << e.what();
  }
  a.overrides = {"run.assessment.comfort=true"};
  try {
    rb::app::assessFile(a);
    FAIL() << "no error";
  } catch (const rb::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("comfort: the floor accelerations are sampled only by "
                                         "run.assessment"),
              std::string::npos)
        << e.what();
  }
  a.overrides = {"run.assessment.alpha=3"};
  EXPECT_THROW(rb::app::assessFile(a), rb::InputError);
  EXPECT_EQ(bytesOf(o.out), bytes);
  // With a fine output interval the outputs suffice for safety and wear.
  const auto fine =
      options("tests/app/data/wheel_forces/tangent.lua", "fine.h5", {"run.output.every=2.5e-3"});
  ASSERT_EQ(rb::app::runScenario(fine), 0);
  a.file = fine.out;
  a.overrides.clear();
  ASSERT_EQ(rb::app::assessFile(a), 0);
  hid_t f = H5Fopen(fine.out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_LT(attr(f, "/assessment/summary", "dq_over_q"), 1e-9);
  EXPECT_TRUE(h5test::exists(f, "/assessment/wear/ws1/left/t_gamma"));
  H5Fclose(f);
}
