// Exponential treatment of stiff components in RK4 (ETDRK4, Cox-Matthews) and ABM (exponential
// Adams-Bashforth-Moulton 4): phi functions, the classical weights as the limit z -> 0, stability
// far beyond the explicit limits, exactness at the fixed point of a linear stiff component, and
// convergence under step refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "test_systems.hpp"
#include "workbench/integrators/exponential.hpp"
#include "workbench/integrators/registry.hpp"

namespace rb::integ {
namespace {

// Prothero-Robinson y' = lambda (y - sin t) + cos t (exact y = sin t) whose component is declared
// stiff, so the fixed-step methods may integrate it exponentially.
class StiffPR : public test::ProtheroRobinson {
 public:
  using test::ProtheroRobinson::ProtheroRobinson;
  std::vector<int> stiffComponents() const override { return {0}; }
};

// A stiff fast component relaxing to a slow oscillator it also drives:
//   u' = -k (u - x),  x' = v,  v' = -x + 0.2 (u - x),  k = 4000.
class StiffCoupled : public OdeSystem {
 public:
  int size() const override { return 3; }
  int rhs(double, const double* y, double* yd) override {
    yd[0] = -4000.0 * (y[0] - y[1]);
    yd[1] = y[2];
    yd[2] = -y[1] + 0.2 * (y[0] - y[1]);
    return 0;
  }
  std::vector<int> stiffComponents() const override { return {0}; }
};

SolverSpec spec(const std::string& method, double h, StiffTreatment stiff) {
  SolverSpec s;
  s.method = method;
  s.step = h;
  s.stiff = stiff;
  s.loc = {"test.lua", 3};
  return s;
}

Eigen::VectorXd endState(OdeSystem& sys, const SolverSpec& s, const Eigen::VectorXd& y0,
                         double t_end, RunResult* res = nullptr) {
  auto integ = makeIntegrator(s);
  Eigen::VectorXd last = y0;
  const RunResult r =
      integrate(sys, *integ, 0.0, y0, {t_end}, [&](double, const Eigen::VectorXd& y) {
        last = y;
        return true;
      });
  if (res) *res = r;
  return last;
}

TEST(Exponential, PhiFunctionsMatchClosedFormsAndSeries) {
  for (double z : {-40.0, -3.0, -0.7, -0.49, -0.2, -1e-3, 0.0, 1e-3, 0.3}) {
    const auto p = expo::phi(z);
    EXPECT_NEAR(p[0], std::exp(z), 1e-15 * std::max(1.0, std::exp(z)));
    if (std::abs(z) > 0.1) {
      EXPECT_NEAR(p[1], (std::exp(z) - 1.0) / z, 1e-13);
      EXPECT_NEAR(p[2], (std::exp(z) - 1.0 - z) / (z * z), 1e-12);
    } else {
      EXPECT_NEAR(p[1], 1.0 + z / 2.0 + z * z / 6.0, 1e-9);
      EXPECT_NEAR(p[4], 1.0 / 24.0 + z / 120.0, 1e-7);
    }
  }
  // Continuity at the switch between series and recurrence (|z| = 0.5).
  const auto a = expo::phi(-0.4999999), b = expo::phi(-0.5000001);
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(a[k], b[k], 1e-6);  // |dz| = 2e-7
}

TEST(Exponential, WeightsReduceToTheClassicalMethodsAtZero) {
  const expo::Weights w = expo::weights(0.0);
  const double ab[4] = {55.0, -59.0, 37.0, -9.0}, am[4] = {9.0, 19.0, -5.0, 1.0};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(w.ab[k], ab[k] / 24.0, 1e-15);
    EXPECT_NEAR(w.am[k], am[k] / 24.0, 1e-15);
  }
  EXPECT_NEAR(w.f1, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(w.f2, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(w.f3, 1.0 / 6.0, 1e-15);
  // Every exponential multistep formula integrates a constant N exactly: sum of weights = phi_1.
  const expo::Weights s = expo::weights(-7.0);
  const double phi1 = (std::exp(-7.0) - 1.0) / -7.0;
  EXPECT_NEAR(s.ab[0] + s.ab[1] + s.ab[2] + s.ab[3], phi1, 1e-13);
  EXPECT_NEAR(s.am[0] + s.am[1] + s.am[2] + s.am[3], phi1, 1e-13);
  EXPECT_NEAR(s.f1 + 4.0 * s.f2 + s.f3, phi1, 1e-13);
}

// h lambda = -100: far outside both explicit stability regions (RK4 2.79, ABM 1.28). The
// explicit treatment diverges; the exponential one follows sin t.
TEST(Exponential, StableFarBeyondTheExplicitLimit) {
  for (const char* m : {"rk4", "abm"}) {
    StiffPR sys(-1e4);
    RunResult res;
    const Eigen::VectorXd y0 = Eigen::VectorXd::Zero(1);
    const Eigen::VectorXd ye =
        endState(sys, spec(m, 0.01, StiffTreatment::Exponential), y0, 2.0, &res);
    ASSERT_TRUE(res.ok) << m << ": " << res.message;
    EXPECT_NEAR(ye(0), std::sin(2.0), 1e-6) << m;
    EXPECT_GT(res.stats.jacobian_evals, 0) << m;  // the diagonal is estimated during the run
    StiffPR sys2(-1e4);
    RunResult bad;
    const Eigen::VectorXd yx =
        endState(sys2, spec(m, 0.01, StiffTreatment::Explicit), y0, 2.0, &bad);
    EXPECT_TRUE(!bad.ok || !(std::abs(yx(0) - std::sin(2.0)) < 1.0)) << m;
  }
}

TEST(Exponential, ConvergesUnderStepRefinementOnACoupledStiffSystem) {
  const Eigen::Vector3d y0(1.0, 1.0, 0.0);
  StiffCoupled ref_sys;
  const Eigen::VectorXd ref =
      endState(ref_sys, spec("rk4", 1e-5, StiffTreatment::Explicit), y0, 3.0);  // h k = 0.04
  for (const char* m : {"rk4", "abm"}) {
    double prev = 0.0;
    for (double h : {0.02, 0.01, 0.005}) {  // h k = 80, 40, 20
      StiffCoupled sys;
      const double err = (endState(sys, spec(m, h, StiffTreatment::Exponential), y0, 3.0) - ref)
                             .cwiseAbs()
                             .maxCoeff();
      EXPECT_LT(err, 1e-3) << m << " h = " << h;
      // ABM: third order or better. ETDRK4 couples its exponential stages (low stage order) into
      // the classical stages of the slow components, which costs order at h k >> 1 (here 20-80;
      // the order returns as h k falls to about 1): at least first order.
      if (prev > 0.0) {
        EXPECT_GT(prev / err, std::string(m) == "abm" ? 6.0 : 1.8) << m << " h = " << h;
      }
      prev = err;
    }
  }
}

// Without stiff components the exponential setting changes nothing: bit-identical results.
TEST(Exponential, SystemsWithoutStiffComponentsAreUnchanged) {
  for (const char* m : {"rk4", "abm"}) {
    test::Oscillator a, b;
    const Eigen::Vector2d y0(1.0, 0.0);
    const Eigen::VectorXd ya = endState(a, spec(m, 0.01, StiffTreatment::Exponential), y0, 1.0);
    const Eigen::VectorXd yb = endState(b, spec(m, 0.01, StiffTreatment::Explicit), y0, 1.0);
    EXPECT_EQ(ya(0), yb(0));
    EXPECT_EQ(ya(1), yb(1));
  }
}

}  // namespace
}  // namespace rb::integ
