// Stability limit of fixed-step runs: the stability regions of RK4 and ABM PECE, the eigenvalue
// analysis of a finite-difference Jacobian, and the wheelset spin creep mode of the wagon.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/integrators/integrator.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/step_limit.hpp"

using rb::run::FixedStepMethod;

namespace {

// Growth per step of ABM PECE on y' = lambda y, by running the method itself (independent of the
// characteristic polynomial in step_limit.cpp): the geometric mean of |y_n+1 / y_n| over the last
// 2000 of 4000 steps (the dominant roots may be a complex pair, so single ratios oscillate).
double abmGrowthBySimulation(std::complex<double> z) {
  std::complex<double> y3 = 0.75, y2 = 0.8, y1 = 0.9, y0 = 1.0;  // y_n-3 .. y_n, arbitrary
  double log_growth = 0.0;
  constexpr int kSteps = 4000, kCounted = 2000;
  for (int n = 0; n < kSteps; ++n) {
    const auto ys = y0 + z / 24.0 * (55.0 * y0 - 59.0 * y1 + 37.0 * y2 - 9.0 * y3);
    const auto ynew = y0 + z / 24.0 * (9.0 * ys + 19.0 * y0 - 5.0 * y1 + y2);
    const double scale = std::abs(ynew);  // renormalise: only ratios matter
    if (n >= kSteps - kCounted) log_growth += std::log(scale / std::abs(y0));
    y3 = y2 / scale;
    y2 = y1 / scale;
    y1 = y0 / scale;
    y0 = ynew / scale;
  }
  return std::exp(log_growth / kCounted);
}

class LinearOde : public rb::integ::OdeSystem {
 public:
  explicit LinearOde(Eigen::MatrixXd a) : a_(std::move(a)) {}
  int size() const override { return static_cast<int>(a_.rows()); }
  int rhs(double, const double* y, double* ydot) override {
    Eigen::Map<Eigen::VectorXd>(ydot, size()) = a_ * Eigen::Map<const Eigen::VectorXd>(y, size());
    return 0;
  }

 private:
  Eigen::MatrixXd a_;
};

}  // namespace

TEST(StepLimit, Rk4RealAxisLimitIsTheKnownValue) {
  // The real stability interval of classical RK4 is (-2.7853, 0).
  const double h = rb::run::stableStep(FixedStepMethod::Rk4, {-1.0, 0.0});
  EXPECT_NEAR(h, 2.7853, 2e-3);
  EXPECT_LE(rb::run::amplification(FixedStepMethod::Rk4, {-2.7, 0.0}), 1.0);
  EXPECT_GT(rb::run::amplification(FixedStepMethod::Rk4, {-2.9, 0.0}), 1.0);
}

TEST(StepLimit, AbmRealAxisLimitAgreesWithRunningTheMethod) {
  const double h = rb::run::stableStep(FixedStepMethod::Abm, {-1.0, 0.0});
  EXPECT_GT(h, 1.0);
  EXPECT_LT(h, 1.6);
  for (double zr : {0.5 * h, 0.95 * h, 1.05 * h, 1.5 * h}) {
    const double g = abmGrowthBySimulation({-zr, 0.0});
    const double a = rb::run::amplification(FixedStepMethod::Abm, {-zr, 0.0});
    EXPECT_NEAR(g, a, 2e-3) << "z = " << -zr;
    EXPECT_EQ(g > 1.0 + rb::run::kGrowthTolerance, zr > h) << "z = " << -zr;
  }
}

TEST(StepLimit, OscillatoryModeUsesTheRegionOffTheRealAxis) {
  // A lightly damped mode (damping ratio 0.05): its ray limit differs from the real-axis one,
  // and the amplification along the ray crosses 1 exactly there.
  const std::complex<double> lam = std::polar(1.0, M_PI - std::acos(0.05));
  for (auto m : {FixedStepMethod::Rk4, FixedStepMethod::Abm}) {
    const double h = rb::run::stableStep(m, lam);
    ASSERT_TRUE(std::isfinite(h));
    EXPECT_LE(rb::run::amplification(m, 0.99 * h * lam), 1.0 + rb::run::kGrowthTolerance);
    EXPECT_GT(rb::run::amplification(m, 1.01 * h * lam), 1.0 + rb::run::kGrowthTolerance);
  }
  // A growing mode never limits the step.
  EXPECT_TRUE(std::isinf(rb::run::stableStep(FixedStepMethod::Abm, {0.1, 5.0})));
}

TEST(StepLimit, JacobianEigenvaluesFindTheStiffestMode) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, 3);
  a(0, 0) = -10.0;
  a(1, 1) = -3000.0;
  a(2, 2) = 0.5;  // growing: not a step limit
  a(0, 1) = 7.0;  // coupling keeps the eigenvalues on the diagonal (triangular)
  LinearOde ode(a);
  const auto lim =
      rb::run::fixedStepLimit(ode, 0.0, Eigen::Vector3d(0.1, -0.2, 0.3), FixedStepMethod::Rk4);
  ASSERT_TRUE(lim.computed);
  EXPECT_NEAR(lim.lambda.real(), -3000.0, 1e-3);
  EXPECT_NEAR(lim.h_max, rb::run::stableStep(FixedStepMethod::Rk4, {-3000.0, 0.0}), 1e-12);
  EXPECT_EQ(lim.mode, "y[1]");
  EXPECT_NEAR(lim.stiffest, 3000.0, 1e-3);
}

// The wagon of the paper's case 3 with a free spin: the spin creep mode (about -2400 1/s at
// 20 m/s, 2 f11 r0^2 / (V I_yy)) limits ABM to about 0.5 ms; with the spin prescribed the limit
// lies well above the paper's 1 ms.
TEST(StepLimit, FreeSpinCreepModeLimitsAbmBelowTheMillisecond) {
  for (const char* spin : {"free", "prescribed"}) {
    rb::run::CompileOptions o;
    o.scenario = "scenarios/validation/case3_kec.lua";
    o.root = RB_SOURCE_DIR;
    o.overrides = {std::string("contact.wheelset_spin=") + spin, "run.distance=10"};
    const rb::run::Model model = rb::run::compile(o);
    rb::dynamics::ContactVehicleOde ode(model.lead().vehicle, *model.lead().contact, *model.track);
    const Eigen::VectorXd y0 = ode.initialState(0.0);
    const auto lim = rb::run::fixedStepLimit(ode, 0.0, y0, FixedStepMethod::Abm);
    ASSERT_TRUE(lim.computed) << lim.why_not;
    if (std::string(spin) == "free") {
      EXPECT_GT(lim.h_max, 0.3e-3);
      EXPECT_LT(lim.h_max, 0.8e-3);
      EXPECT_NE(lim.mode.find("theta_dot"), std::string::npos) << lim.mode;
      EXPECT_GT(lim.stiffest, 1500.0);
    } else {
      EXPECT_GT(lim.h_max, 1.2e-3) << lim.mode << " " << lim.lambda;
    }
  }
}

namespace {

rb::run::Model compileCase3(std::vector<std::string> overrides) {
  rb::run::CompileOptions o;
  o.scenario = "scenarios/validation/case3_kec.lua";
  o.root = RB_SOURCE_DIR;
  o.overrides = std::move(overrides);
  return rb::run::compile(o);
}

std::string compileError(std::vector<std::string> overrides) {
  try {
    (void)compileCase3(std::move(overrides));
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return {};
}

// Lateral displacement of every wheelset at every 10 ms over the first `seconds` of case 3.
std::vector<double> wheelsetPaths(const rb::run::Model& m, double seconds) {
  rb::dynamics::ContactVehicleOde ode(m.lead().vehicle, *m.lead().contact, *m.track);
  const Eigen::VectorXd y0 = ode.initialState(0.0);
  auto integ = rb::integ::makeIntegrator(m.solver);
  std::vector<double> times;
  for (int k = 1; k <= static_cast<int>(std::lround(seconds / 0.01)); ++k)
    times.push_back(k * 0.01);
  std::vector<double> out;
  std::vector<rb::vehicle::Vector6d> q(m.lead().vehicle.bodies.size());
  const auto res =
      rb::integ::integrate(ode, *integ, 0.0, y0, times, [&](double t, const Eigen::VectorXd& y) {
        ode.bodyCoordinates(t, y.data(), q);
        for (std::size_t b = 0; b < q.size(); ++b)
          if (m.lead().vehicle.bodies[b].kind == rb::vehicle::BodyKind::Wheelset)
            out.push_back(q[b][1]);
        return true;
      });
  EXPECT_TRUE(res.ok) << res.message;
  return out;
}

double maxDifference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace

// No fast wrong answers: ABM at the paper's 1 ms with the free spin is beyond the stability limit
// of the spin creep mode. check refuses it, naming the mode and the largest stable step, unless
// the scenario accepts it; the exponential treatment of the stiff components removes the limit.
TEST(StepLimit, CheckRefusesAbmAtOneMillisecondWithTheFreeSpin) {
  const std::string err =
      compileError({"solver.step=1e-3", "solver.stiff=explicit", "run.distance=10"});
  EXPECT_NE(err.find("common.lua:"), std::string::npos) << err;
  EXPECT_NE(err.find("beyond the stability limit of abm"), std::string::npos) << err;
  EXPECT_NE(err.find("theta_dot"), std::string::npos) << err;
  EXPECT_NE(err.find("largest stable step 0.5"), std::string::npos) << err;
  EXPECT_NE(err.find("solver.stiff = \"exponential\""), std::string::npos) << err;

  const auto accepted = compileCase3({"solver.step=1e-3", "solver.stiff=explicit",
                                      "run.distance=10", "solver.accept_unstable_step=true"});
  ASSERT_EQ(accepted.run_warnings.size(), 1u);
  EXPECT_NE(accepted.run_warnings[0].find("not reliable"), std::string::npos);

  EXPECT_EQ(compileError({"solver.step=1e-3", "run.distance=10", "solver.stiff=exponential"}), "");
  EXPECT_EQ(
      compileError({"solver.step=1e-3", "run.distance=10", "contact.wheelset_spin=prescribed"}),
      "");
  EXPECT_EQ(compileError({"run.distance=10"}), "");  // the scenario's 0.25 ms
}

// ... and when it runs, it runs accurately: over the first 3 s of case 3 (60 m, tangent and
// transition with irregularities) ABM at 1 ms and RK4 at 2 ms with the exponential treatment stay
// within 0.05 mm of a tight dopri5 reference on every wheelset, as the explicit ABM at the
// scenario's 0.25 ms does.
TEST(StepLimit, ExponentialTreatmentIsAccurateAtTheLargerSteps) {
  const auto ref =
      wheelsetPaths(compileCase3({"solver.method=dopri5", "solver.rtol=1e-9", "solver.atol=1e-10",
                                  "solver.max_steps=100000", "run.distance=60"}),
                    3.0);
  const double explicit_abm = maxDifference(
      wheelsetPaths(compileCase3({"solver.stiff=explicit", "run.distance=60"}), 3.0), ref);
  const double abm = maxDifference(
      wheelsetPaths(
          compileCase3({"solver.step=1e-3", "solver.stiff=exponential", "run.distance=60"}), 3.0),
      ref);
  const double rk4 =
      maxDifference(wheelsetPaths(compileCase3({"solver.method=rk4", "solver.step=2e-3",
                                                "solver.stiff=exponential", "run.distance=60"}),
                                  3.0),
                    ref);
  EXPECT_LT(explicit_abm, 0.05e-3);
  EXPECT_LT(abm, 0.05e-3);
  EXPECT_LT(rk4, 0.05e-3);
  std::printf(
      "max |y - y_ref| over 3 s: abm 0.25 ms %.4f mm, abm-exp 1 ms %.4f mm, rk4-exp 2 ms "
      "%.4f mm\n",
      explicit_abm * 1e3, abm * 1e3, rk4 * 1e3);
}
