// Conformance suite run against every integrator of the registry, plus method-specific tests.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "test_systems.hpp"
#include "workbench/core/error.hpp"
#include "workbench/integrators/fixed_step.hpp"
#include "workbench/integrators/registry.hpp"

namespace rb::integ {
namespace {

using test::Faulty;

// Output times k * dt, k = 1..round(t_end / dt) (no accumulated rounding).
std::vector<double> grid(double dt, double t_end) {
  std::vector<double> out;
  const long n = std::lround(t_end / dt);
  for (long k = 1; k <= n; ++k) out.push_back(static_cast<double>(k) * dt);
  return out;
}

struct Recorded {
  RunResult result;
  std::vector<double> t;
  std::vector<Eigen::VectorXd> y;
};

Recorded run(OdeSystem& sys, const SolverSpec& spec, const Eigen::VectorXd& y0,
             const std::vector<double>& out, double stop_after = 1e300) {
  auto integ = makeIntegrator(spec);
  Recorded r;
  r.result = integrate(sys, *integ, 0.0, y0, out, [&](double t, const Eigen::VectorXd& y) {
    r.t.push_back(t);
    r.y.push_back(y);
    return t < stop_after;
  });
  return r;
}

bool isFixed(const std::string& m) {
  return m == "rk4" || m == "abm";
}
bool isImplicit(const std::string& m) {
  return m == "bdf" || m == "ida";
}

SolverSpec specFor(const std::string& method) {
  SolverSpec s;
  s.method = method;
  s.loc = {"test.lua", 7};
  if (isFixed(method)) {
    s.step = 0.01;
  } else {
    s.step = 0.0;
    s.rtol = 1e-8;
    s.atol = 1e-10;
  }
  return s;
}

class Conformance : public ::testing::TestWithParam<std::string> {};

TEST(ConformanceSuite, CoversEveryRegisteredMethod) {
  EXPECT_EQ(methodNames(), "rk4, abm, dopri5, bdf, ida");
}

TEST_P(Conformance, HarmonicOscillatorAccuracy) {
  const std::string m = GetParam();
  test::Oscillator sys;
  const double t_end = 10.0;
  const auto error = [&](const SolverSpec& s) {
    const Recorded r = run(sys, s, test::Oscillator::exact(0.0), grid(1.0, t_end));
    EXPECT_TRUE(r.result.ok) << r.result.message;
    EXPECT_EQ(r.t.size(), 11u);
    return (r.y.back() - test::Oscillator::exact(t_end)).norm();
  };
  SolverSpec s = specFor(m);
  if (isFixed(m)) {
    s.step = 0.02;
    const double e1 = error(s);
    s.step = 0.01;
    const double e2 = error(s);
    const double order = std::log2(e1 / e2);
    EXPECT_NEAR(order, 4.0, 0.2) << m << ": errors " << e1 << ", " << e2;
  } else {
    std::vector<double> errs;
    for (double tol : {1e-4, 1e-6, 1e-8}) {
      s.rtol = tol;
      s.atol = tol;
      errs.push_back(error(s));
    }
    EXPECT_LT(errs[1], errs[0]) << m;
    EXPECT_LT(errs[2], errs[1]) << m;
    EXPECT_LT(errs[2], 1e-5) << m;
    EXPECT_LT(errs[2], errs[0] / 100.0) << m;
  }
}

TEST_P(Conformance, StiffProtheroRobinson) {
  const std::string m = GetParam();
  const double lambda = -1e4;
  const double t_end = 10.0;
  const auto out = grid(0.5, t_end);
  SolverSpec ref = specFor("bdf");
  ref.rtol = 1e-6;
  ref.atol = 1e-8;
  test::ProtheroRobinson bdf_sys(lambda);
  const Recorded bdf = run(bdf_sys, ref, Eigen::VectorXd::Zero(1), out);
  ASSERT_TRUE(bdf.result.ok) << bdf.result.message;
  const long bdf_evals = bdf.result.stats.rhs_evals + bdf.result.stats.rhs_evals_jac;

  SolverSpec s = specFor(m);
  if (isFixed(m)) {
    s.step = 1e-3;  // h lambda = -10: outside the stability region of RK4 and ABM
  } else {
    s.rtol = 1e-6;
    s.atol = 1e-8;
  }
  test::ProtheroRobinson sys(lambda);
  const Recorded r = run(sys, s, Eigen::VectorXd::Zero(1), out);
  const Stats& st = r.result.stats;
  if (isImplicit(m)) {
    ASSERT_TRUE(r.result.ok) << r.result.message;
    EXPECT_LT(st.steps, 400) << m;
    EXPECT_LT(st.rhs_evals + st.rhs_evals_jac, 1000) << m;
    EXPECT_NEAR(r.y.back()(0), std::sin(t_end), 1e-4) << m;
  } else if (r.result.ok) {
    EXPECT_GT(st.rhs_evals, 20 * bdf_evals) << m;
  } else {
    EXPECT_FALSE(r.result.message.empty());
    EXPECT_NE(r.result.message.find(m + ": failed at t = "), std::string::npos) << r.result.message;
    EXPECT_GT(r.t.size(), 0u);  // t0 at least
  }
  std::cout << "[ stiff    ] " << m << ": ok=" << r.result.ok << " steps=" << st.steps
            << " rhs=" << st.rhs_evals << " rhs_jac=" << st.rhs_evals_jac
            << " (bdf reference: steps=" << bdf.result.stats.steps << " rhs+jac=" << bdf_evals
            << ")" << (r.result.ok ? "" : "\n             " + r.result.message) << "\n";
}

TEST_P(Conformance, RecoverableRhsFailureOnce) {
  const std::string m = GetParam();
  Faulty sys(Faulty::Fault::RecoverableOnce, 0.55);
  const Recorded r = run(sys, specFor(m), Faulty::exact(0.0), grid(0.1, 2.0));
  ASSERT_TRUE(r.result.ok) << r.result.message;
  EXPECT_TRUE(sys.fired);
  EXPECT_GE(r.result.stats.recoverable_rhs_failures, 1);
  EXPECT_GE(r.result.stats.rejected_steps, 1) << m;
  ASSERT_EQ(r.t.size(), 21u);
  EXPECT_LT((r.y.back() - Faulty::exact(2.0)).norm(), 1e-6) << m;
}

TEST_P(Conformance, FatalRhsFailure) {
  const std::string m = GetParam();
  Faulty sys(Faulty::Fault::Fatal, 0.55);
  const auto out = grid(0.1, 2.0);
  const Recorded r = run(sys, specFor(m), Faulty::exact(0.0), out);
  ASSERT_FALSE(r.result.ok);
  const RunResult& res = r.result;
  EXPECT_EQ(res.t_fail, res.t_reached);
  EXPECT_LE(res.t_fail, 0.55);
  EXPECT_GT(res.t_fail, 0.3);
  EXPECT_NE(res.message.find(m + ": failed at t = "), std::string::npos) << res.message;
  EXPECT_NE(res.message.find("returned -1"), std::string::npos) << res.message;
  EXPECT_NE(res.message.find("injected fatal failure"), std::string::npos) << res.message;
  // Partial output: t0 and every output time up to the failure, nothing after it.
  ASSERT_GE(r.t.size(), 4u);
  EXPECT_EQ(r.t.front(), 0.0);
  for (std::size_t k = 1; k < r.t.size(); ++k) EXPECT_EQ(r.t[k], out[k - 1]);
  EXPECT_LE(r.t.back(), res.t_fail);
  EXPECT_GT(out[r.t.size() - 1], res.t_fail);  // the next output was not reached
  std::cout << "[ fatal    ] " << res.message << "\n";
}

TEST_P(Conformance, NonFiniteDerivativeNamesComponent) {
  const std::string m = GetParam();
  Faulty sys(Faulty::Fault::NaN, 0.55);
  const Recorded r = run(sys, specFor(m), Faulty::exact(0.0), grid(0.1, 2.0));
  ASSERT_FALSE(r.result.ok);
  const std::string& msg = r.result.message;
  EXPECT_NE(msg.find("NaN/Inf"), std::string::npos) << msg;
  EXPECT_NE(msg.find("x2"), std::string::npos) << msg;
  EXPECT_EQ(r.result.offending_components, std::vector<int>{2}) << msg;
  EXPECT_LE(r.result.t_fail, 0.55);
  EXPECT_GT(r.result.t_fail, 0.3);
  for (const auto& y : r.y) EXPECT_TRUE(y.allFinite());  // the observer never saw NaN
  std::cout << "[ nan      ] " << msg << "\n";
}

TEST_P(Conformance, ObserverStopsEarly) {
  const std::string m = GetParam();
  test::Oscillator sys;
  const Recorded r = run(sys, specFor(m), test::Oscillator::exact(0.0), grid(0.1, 2.0), 0.25);
  EXPECT_TRUE(r.result.ok);
  EXPECT_TRUE(r.result.stopped_by_observer);
  ASSERT_EQ(r.t.size(), 4u);  // 0, 0.1, 0.2, 0.3
  EXPECT_DOUBLE_EQ(r.result.t_reached, 0.3);
  EXPECT_TRUE(std::isnan(r.result.t_fail));
}

TEST_P(Conformance, ModelExceptionPropagates) {
  const std::string m = GetParam();
  Faulty sys(Faulty::Fault::Throw, 0.55);
  EXPECT_THROW(run(sys, specFor(m), Faulty::exact(0.0), grid(0.1, 2.0)), std::runtime_error);
}

TEST_P(Conformance, NonFiniteInitialState) {
  test::Oscillator sys;
  Eigen::VectorXd y0 = test::Oscillator::exact(0.0);
  y0(1) = std::nan("");
  const Recorded r = run(sys, specFor(GetParam()), y0, grid(0.1, 1.0));
  EXPECT_FALSE(r.result.ok);
  EXPECT_NE(r.result.message.find("NaN/Inf in the initial state y[1]"), std::string::npos)
      << r.result.message;
  EXPECT_TRUE(r.t.empty());
}

TEST_P(Conformance, ProgressAndStats) {
  const std::string m = GetParam();
  test::Oscillator sys;
  auto integ = makeIntegrator(specFor(m));
  int calls = 0;
  double last_t = 0.0;
  const RunResult r = integrate(
      sys, *integ, 0.0, test::Oscillator::exact(0.0), grid(0.5, 2.0),
      [](double, const Eigen::VectorXd&) { return true; },
      [&](double t, const Stats& s) {
        ++calls;
        last_t = t;
        EXPECT_GT(s.steps, 0);
        EXPECT_GE(s.cpu_time_s, 0.0);
      });
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(last_t, 2.0);
  EXPECT_GT(r.stats.rhs_evals, 0);
  EXPECT_GT(r.stats.steps, 0);
  EXPECT_GE(r.stats.wall_time_s, 0.0);
  EXPECT_EQ(integ->name(), m);
  EXPECT_EQ(integ->isFixedStep(), isFixed(m));
}

std::string paramName(const ::testing::TestParamInfo<std::string>& p) {
  return p.param;
}
INSTANTIATE_TEST_SUITE_P(AllMethods, Conformance,
                         ::testing::Values("rk4", "abm", "dopri5", "bdf", "ida"), paramName);

// --- fixed-step methods -------------------------------------------------------------------------

SolverSpec fixedSpec(const std::string& m, double step) {
  SolverSpec s;
  s.method = m;
  s.step = step;
  return s;
}

// The paper's setting: 1 ms steps over 25 s. RK4: 100 000 evaluations (= paper); ABM: 2N + 6 =
// 50 006 (paper: 50 011, see fixed_step.hpp).
TEST(FixedStep, PaperEvaluationCounts) {
  test::Oscillator sys;
  const auto out = grid(0.01, 25.0);
  for (const std::string m : {"rk4", "abm"}) {
    auto integ = makeIntegrator(fixedSpec(m, 1e-3));
    long observed = 0;
    const RunResult r = integrate(sys, *integ, 0.0, test::Oscillator::exact(0.0), out,
                                  [&](double, const Eigen::VectorXd&) { return ++observed > 0; });
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_EQ(observed, 2501);
    EXPECT_EQ(r.stats.steps, 25000);
    EXPECT_EQ(r.stats.rejected_steps, 0);
    EXPECT_EQ(r.stats.rhs_evals, m == "rk4" ? 100000 : 50006) << m;
  }
  static_assert(rk4RhsEvals(25000) == 100000);
  static_assert(abmRhsEvals(25000) == 50006);
}

TEST(FixedStep, EvaluationCountFormulas) {
  for (const std::string m : {"rk4", "abm"}) {
    for (long n : {1L, 2L, 3L, 4L, 5L, 10L, 137L}) {
      test::Oscillator sys;
      auto integ = makeIntegrator(fixedSpec(m, 0.01));
      const RunResult r =
          integrate(sys, *integ, 0.0, test::Oscillator::exact(0.0), {0.01 * static_cast<double>(n)},
                    [](double, const Eigen::VectorXd&) { return true; });
      ASSERT_TRUE(r.ok) << r.message;
      EXPECT_EQ(r.stats.steps, n);
      EXPECT_EQ(r.stats.rhs_evals, m == "rk4" ? rk4RhsEvals(n) : abmRhsEvals(n)) << m << " n=" << n;
    }
  }
}

// Output times do not change the counts (no evaluation for output).
TEST(FixedStep, OutputDoesNotCostEvaluations) {
  test::Oscillator sys;
  auto integ = makeIntegrator(fixedSpec("abm", 0.01));
  const RunResult r = integrate(sys, *integ, 0.0, test::Oscillator::exact(0.0), grid(0.01, 1.0),
                                [](double, const Eigen::VectorXd&) { return true; });
  EXPECT_EQ(r.stats.rhs_evals, abmRhsEvals(100));
}

// A recoverable failure splits the step in halves (RK4) and ABM restarts with 3 RK4 steps:
// exact counts for a failure in the second evaluation of step 11 (t = 0.10 .. 0.11).
TEST(FixedStep, RecoverableFailurePolicyCounts) {
  for (const std::string m : {"rk4", "abm"}) {
    Faulty sys(Faulty::Fault::RecoverableOnce, 0.104);
    auto integ = makeIntegrator(fixedSpec(m, 0.01));
    const RunResult r = integrate(sys, *integ, 0.0, Faulty::exact(0.0), {0.2},
                                  [](double, const Eigen::VectorXd&) { return true; });
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_EQ(r.stats.rejected_steps, 1);
    EXPECT_EQ(r.stats.recoverable_rhs_failures, 1);
    EXPECT_EQ(r.stats.steps, 21);  // 19 full steps + 2 half steps
    if (m == "rk4") {
      // steps 1-10: 40; failed attempt (k1 ok, k2 fails): 2; two half steps: 8; steps 12-20: 36
      EXPECT_EQ(r.stats.rhs_evals, 40 + 2 + 8 + 36);
    } else {
      // steps 1-10: 2*10+6 = 26; failed attempt (f_n ok, f* fails): 2; two RK4 half steps: 8;
      // restart: steps 12-14 RK4: 12; steps 15-20 ABM: 12
      EXPECT_EQ(r.stats.rhs_evals, 26 + 2 + 8 + 12 + 12);
    }
  }
}

TEST(FixedStep, PersistentRecoverableFailureGivesUp) {
  // Recoverable from t = 0.55 on, every time: splitting cannot help.
  class Stubborn : public test::Oscillator {
   public:
    int rhs(double t, const double* y, double* yd) override {
      if (t >= 0.55) return 2;
      return Oscillator::rhs(t, y, yd);
    }
    std::string lastError() const override { return "wheel lifted"; }
  } sys;
  auto integ = makeIntegrator(fixedSpec("rk4", 0.01));
  const RunResult r = integrate(sys, *integ, 0.0, test::Oscillator::exact(0.0), grid(0.1, 1.0),
                                [](double, const Eigen::VectorXd&) { return true; });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("kept failing recoverably"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("wheel lifted"), std::string::npos) << r.message;
}

TEST(FixedStep, OutputTimesMustLieOnTheGrid) {
  test::Oscillator sys;
  SolverSpec s = fixedSpec("rk4", 1e-3);
  s.loc = {"scen.lua", 4};
  auto integ = makeIntegrator(s);
  try {
    (void)integrate(sys, *integ, 0.0, test::Oscillator::exact(0.0), {0.01, 0.0105, 0.02},
                    [](double, const Eigen::VectorXd&) { return true; });
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("scen.lua:4: solver.step: output time 0.0105 s is not on the rk4 step grid"),
              std::string::npos)
        << w;
  }
}

TEST(FixedStep, StiffBlowUpIsCaughtAtTheStep) {
  test::ProtheroRobinson sys(-1e4);
  auto integ = makeIntegrator(fixedSpec("rk4", 1e-3));
  const RunResult r = integrate(sys, *integ, 0.0, Eigen::VectorXd::Zero(1), grid(0.5, 10.0),
                                [](double, const Eigen::VectorXd&) { return true; });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("NaN/Inf"), std::string::npos) << r.message;
  EXPECT_LT(r.t_fail, 0.5);
}

// --- SUNDIALS methods ---------------------------------------------------------------------------

TEST(Bdf, AnalyticJacobianUsesNoDifferenceQuotients) {
  for (const std::string m : {"bdf", "ida"}) {
    SolverSpec s = specFor(m);
    s.rtol = 1e-6;
    s.atol = 1e-8;
    test::LinearChain sys(true);
    const Recorded a = run(sys, s, Eigen::Vector3d(1.0, -1.0, 2.0), grid(0.5, 5.0));
    ASSERT_TRUE(a.result.ok) << a.result.message;
    EXPECT_EQ(a.result.stats.rhs_evals_jac, 0) << m;
    EXPECT_GT(a.result.stats.jacobian_evals, 0) << m;
    EXPECT_EQ(sys.jacobian_calls, a.result.stats.jacobian_evals) << m;

    s.jacobian = "fd";
    test::LinearChain fd_sys(true);
    const Recorded f = run(fd_sys, s, Eigen::Vector3d(1.0, -1.0, 2.0), grid(0.5, 5.0));
    ASSERT_TRUE(f.result.ok) << f.result.message;
    EXPECT_GT(f.result.stats.rhs_evals_jac, 0) << m;
    EXPECT_EQ(fd_sys.jacobian_calls, 0) << m;
    EXPECT_GT(f.result.stats.jacobian_evals, 0) << m;
    EXPECT_LT((a.y.back() - f.y.back()).norm(), 1e-5) << m;
  }
}

TEST(Bdf, ModelWithoutJacobianUsesDifferenceQuotients) {
  test::LinearChain sys(false);
  SolverSpec s = specFor("bdf");
  const Recorded r = run(sys, s, Eigen::Vector3d(1.0, -1.0, 2.0), grid(0.5, 5.0));
  ASSERT_TRUE(r.result.ok) << r.result.message;
  EXPECT_GT(r.result.stats.rhs_evals_jac, 0);
  EXPECT_GT(r.result.stats.nonlinear_iters, 0);
}

TEST(Bdf, MaxStepsGivesCleanFailure) {
  test::Oscillator sys;
  SolverSpec s = specFor("bdf");
  s.max_steps = 20;
  const Recorded r = run(sys, s, test::Oscillator::exact(0.0), {10.0});
  ASSERT_FALSE(r.result.ok);
  EXPECT_NE(r.result.message.find("too much work: 20 internal steps"), std::string::npos)
      << r.result.message;
  EXPECT_NE(r.result.message.find("CV_TOO_MUCH_WORK"), std::string::npos) << r.result.message;
  EXPECT_NE(r.result.message.find("SUNDIALS: CVode: At t = "), std::string::npos)
      << r.result.message;
  EXPECT_NE(r.result.message.find("largest weighted local errors"), std::string::npos)
      << r.result.message;
  EXPECT_GT(r.result.t_fail, 0.0);
  EXPECT_LT(r.result.t_fail, 10.0);
  EXPECT_FALSE(r.result.offending_components.empty());
}

TEST(Dopri5, MaxStepsGivesCleanFailure) {
  test::ProtheroRobinson sys(-1e4);
  SolverSpec s = specFor("dopri5");
  s.rtol = 1e-6;
  s.atol = 1e-8;
  const Recorded r = run(sys, s, Eigen::VectorXd::Zero(1), {10.0});
  ASSERT_FALSE(r.result.ok);
  EXPECT_NE(r.result.message.find("too much work: 500 internal steps"), std::string::npos)
      << r.result.message;
  EXPECT_EQ(r.result.stats.steps, 500);
}

TEST(Dopri5, DenseOutputDoesNotForceSteps) {
  test::Oscillator sys;
  SolverSpec s = specFor("dopri5");
  s.rtol = 1e-6;
  s.atol = 1e-6;
  s.step = 1e-3;  // the automatic initial step depends on the first output time (as in ode45)
  const Recorded coarse = run(sys, s, test::Oscillator::exact(0.0), {10.0});
  const Recorded fine = run(sys, s, test::Oscillator::exact(0.0), grid(0.001, 10.0));
  ASSERT_TRUE(coarse.result.ok && fine.result.ok);
  EXPECT_EQ(coarse.result.stats.steps, fine.result.stats.steps);
  EXPECT_EQ(coarse.result.stats.rhs_evals, fine.result.stats.rhs_evals);
  EXPECT_LT(fine.result.stats.steps, 200);
  // FSAL: 6 evaluations per step, plus f(t0); outputs cost nothing.
  EXPECT_LE(fine.result.stats.rhs_evals, 6 * fine.result.stats.steps + 3);
  for (std::size_t k = 0; k < fine.t.size(); k += 500)
    EXPECT_LT((fine.y[k] - test::Oscillator::exact(fine.t[k])).norm(), 1e-4);
}

TEST(Ida, IndexOneDaeMatchesExactSolution) {
  test::SimpleDae sys;
  SolverSpec s = specFor("ida");
  auto integ = makeIntegrator(s);
  std::vector<double> ts;
  std::vector<Eigen::VectorXd> ys;
  // Inconsistent guesses: y1(0) = 0.3 (exact 0), y0'(0) = 0 (exact -1).
  const RunResult r =
      integrate(sys, *integ, 0.0, Eigen::Vector2d(1.0, 0.3), Eigen::Vector2d(0.0, 0.0),
                grid(0.25, 5.0), [&](double t, const Eigen::VectorXd& y) {
                  ts.push_back(t);
                  ys.push_back(y);
                  return true;
                });
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_EQ(ts.size(), 21u);
  EXPECT_NEAR(ys[0](1), 0.0, 1e-10);  // IDACalcIC made y1(0) consistent
  EXPECT_NEAR(ys[0](0), 1.0, 1e-14);  // differential component kept
  double err = 0.0;
  for (std::size_t k = 0; k < ts.size(); ++k)
    err = std::max(err, (ys[k] - test::SimpleDae::exact(ts[k])).cwiseAbs().maxCoeff());
  EXPECT_LT(err, 1e-6);
  EXPECT_GT(r.stats.steps, 0);
  EXPECT_GT(r.stats.rhs_evals, 0);
}

TEST(Ida, OtherMethodsRejectDaes) {
  test::SimpleDae sys;
  for (const std::string m : {"rk4", "abm", "dopri5", "bdf"}) {
    auto integ = makeIntegrator(specFor(m));
    EXPECT_FALSE(integ->supportsDae());
    try {
      (void)integrate(sys, *integ, 0.0, Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, 0.0), {1.0},
                      [](double, const Eigen::VectorXd&) { return true; });
      FAIL() << m;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("test.lua:7: solver.method: '" + m +
                                           "' cannot integrate a DAE model; use 'ida'"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace rb::integ
