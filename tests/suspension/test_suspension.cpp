// Suspension element laws (paper Appendix A, Table 4) as pure functions.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "workbench/core/spline.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/suspension/bumpstop.hpp"
#include "workbench/suspension/laws.hpp"

namespace rb::suspension {
namespace {

// Table 4 bumpstop: deformation [m], force [N].
const std::vector<double> kD = {0, 0.025, 0.030, 0.035, 0.040, 0.045, 0.050, 0.055, 0.060, 0.065};
const std::vector<double> kF = {0, 0, 600, 1760, 3730, 6870, 11580, 17170, 29200, 230000};

TEST(Bumpstop, ZeroInsideClearanceAndThroughTheTable) {
  const BumpstopLaw law(kD, kF);
  EXPECT_DOUBLE_EQ(law.clearance(), 0.025);
  for (double d : {0.0, 0.01, 0.0249999, 0.025, -0.02}) EXPECT_EQ(law.force(d), 0.0) << d;
  for (std::size_t k = 1; k < kD.size(); ++k) {
    EXPECT_NEAR(law.force(kD[k]), kF[k], 1e-9 * kF.back()) << k;
    EXPECT_NEAR(law.force(-kD[k]), -kF[k], 1e-9 * kF.back()) << k;  // odd in d
  }
}

TEST(Bumpstop, ExactlyOddForceAndEvenStiffnessAndEnergy) {
  // Mirror symmetry of a vehicle (left vs right curve) needs F(-d) == -F(d) to the last bit, not
  // just to a tolerance: the law works on |d| and applies the sign afterwards.
  const BumpstopLaw law(kD, kF);
  for (double d = 0.0; d < 0.08; d += 1.7e-5) {
    EXPECT_EQ(law.force(-d), -law.force(d)) << d;
    EXPECT_EQ(law.stiffness(-d), law.stiffness(d)) << d;
    EXPECT_EQ(law.energy(-d), law.energy(d)) << d;
  }
  for (double d : kD) EXPECT_EQ(law.force(-d), -law.force(d)) << d;  // at the knots
}

TEST(Deformation, DirectionalIsOddInTheRelativeDisplacement) {
  // Mirrored relative displacement (y -> -y) gives the mirrored lateral deformation, exactly.
  const Eigen::Vector3d nominal(0.0, 1.0, 0.2275), nominal_m(0.0, -1.0, 0.2275);
  const Eigen::Vector3d delta(0.01, 1.0 + 0.0371, 0.2275 - 0.003), rate(0.2, -0.37, 0.05);
  const Eigen::Vector3d delta_m(delta.x(), -delta.y(), delta.z()),
      rate_m(rate.x(), -rate.y(), rate.z());
  const Deformation a = directionalDeformation(delta, rate, nominal, 1);
  const Deformation b = directionalDeformation(delta_m, rate_m, nominal_m, 1);
  EXPECT_EQ(a.d, -b.d);
  EXPECT_EQ(a.d_dot, -b.d_dot);
  const Deformation c = directionalDeformation(delta, rate, nominal, 2);
  const Deformation e = directionalDeformation(delta_m, rate_m, nominal_m, 2);
  EXPECT_EQ(c.d, e.d);
  EXPECT_EQ(c.d_dot, e.d_dot);
}

TEST(Bumpstop, MonotoneC1AndEnergyIsTheIntegral) {
  const BumpstopLaw law(kD, kF);
  double prev = 0.0;
  for (double d = 0.0; d < 0.07; d += 1e-5) {
    const double f = law.force(d);
    EXPECT_GE(f, prev - 1e-9) << d;
    prev = f;
    // Stiffness is the derivative of the force.
    const double h = 1e-7;
    bool near_knot = false;
    for (double k : kD) near_knot = near_knot || std::abs(d - k) < 2 * h;
    if (!near_knot) {
      EXPECT_NEAR(law.stiffness(d), (law.force(d + h) - law.force(d - h)) / (2 * h),
                  1e-4 * (1.0 + law.stiffness(d)))
          << d;
    }
  }
  // C1 at the clearance: slope 0 on both sides.
  EXPECT_NEAR(law.stiffness(0.025 + 1e-9), 0.0, 1.0);
  // Beyond the table: linear continuation with the end slope.
  EXPECT_NEAR(law.force(0.066) - law.force(0.065), law.stiffness(0.065) * 0.001, 1e-6 * 230000);
  // energy = integral of the force (trapezoid, fine grid).
  double e = 0.0;
  const double h = 1e-6;
  for (double d = 0.0; d < 0.0655 - h / 2; d += h) e += 0.5 * h * (law.force(d) + law.force(d + h));
  EXPECT_NEAR(law.energy(0.0655), e, 1e-6 * e);
  EXPECT_NEAR(law.energy(-0.0655), e, 1e-6 * e);
}

TEST(Bumpstop, AC2SplineThroughTable4WouldNotBeMonotone) {
  // Why PCHIP: the not-a-knot C2 spline through the same points decreases somewhere, i.e. the stop
  // would push back less when compressed more.
  const CubicSpline c2(std::vector<double>(kD.begin() + 1, kD.end()),
                       std::vector<double>(kF.begin() + 1, kF.end()));
  double min_slope = 1e300, at = 0.0;
  for (double d = 0.025; d <= 0.065; d += 1e-5) {
    if (c2.deriv1(d) < min_slope) {
      min_slope = c2.deriv1(d);
      at = d;
    }
  }
  std::printf("not-a-knot spline through Table 4: slope %.0f N/m at d = %.4f m\n", min_slope, at);
  EXPECT_LT(min_slope, 0.0);
}

TEST(Bumpstop, CheckReportsEveryProblem) {
  EXPECT_TRUE(BumpstopLaw::check(kD, kF).empty());
  EXPECT_EQ(BumpstopLaw::check({}, {}).size(), 1u);
  EXPECT_EQ(BumpstopLaw::check({0.0, 0.1}, {0.0}).size(), 1u);
  const auto m = BumpstopLaw::check({0.01, 0.02, 0.015}, {10.0, 5.0, 20.0});
  // first force not 0, d not increasing, F decreasing
  EXPECT_EQ(m.size(), 3u);
  EXPECT_EQ(BumpstopLaw::check({0.0, 0.1}, {0.0, 0.0}).size(), 1u);  // does nothing
  EXPECT_EQ(BumpstopLaw::check({-0.1, 0.1}, {0.0, 1.0}).size(), 1u);
}

TEST(Deformation, AxialAndDirectional) {
  const Eigen::Vector3d delta(3.0, 4.0, 0.0), dd(1.0, 2.0, 3.0);
  const Deformation a = axialDeformation(delta, dd, 4.0);
  EXPECT_DOUBLE_EQ(a.d, 1.0);
  EXPECT_NEAR(a.d_dot, (3.0 * 1.0 + 4.0 * 2.0) / 5.0, 1e-15);
  const Deformation z = directionalDeformation(delta, dd, Eigen::Vector3d(0.0, 3.5, 0.0), 1);
  EXPECT_DOUBLE_EQ(z.d, 0.5);
  EXPECT_DOUBLE_EQ(z.d_dot, 2.0);
  EXPECT_EQ(z.grad, Eigen::Vector3d::UnitY());
}

Eigen::Matrix3d expSkew(const Eigen::Vector3d& w) {
  return Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
}

TEST(Deformation, RelativeRotationRateMatchesFiniteDifference) {
  // R(t) = Bj(t) Bi(t)^T with Bdot = skew(omega) B: theta_dot = T1 a - T2 b.
  const Eigen::Vector3d a(0.3, -0.2, 0.5), b(-0.1, 0.4, 0.2);
  const Eigen::Matrix3d Bj0 = expSkew({0.2, 0.1, -0.3}), Bi0 = expSkew({-0.1, 0.25, 0.15});
  // Explicit return type: a deduced Eigen product expression would refer to temporaries that are
  // gone when it is evaluated (found by AddressSanitizer).
  const auto R = [&](double t) -> Eigen::Matrix3d {
    return (expSkew(a * t) * Bj0) * (expSkew(b * t) * Bi0).transpose();
  };
  const double h = 1e-6;
  const Eigen::Vector3d fd =
      (relativeRotation(R(h)).theta - relativeRotation(R(-h)).theta) / (2 * h);
  const RelativeRotation rr = relativeRotation(R(0.0));
  EXPECT_LT((rr.T1 * a - rr.T2 * b - fd).norm(), 1e-8);
  // Small angles: theta is the rotation vector.
  const RelativeRotation small = relativeRotation(expSkew({1e-4, -2e-4, 3e-4}));
  EXPECT_LT((small.theta - Eigen::Vector3d(1e-4, -2e-4, 3e-4)).norm(), 1e-11);
}

// The Appendix A series spring-damper ODE integrated by the project's integrators for a
// prescribed deformation d(t), against its analytic solutions.
class MaxwellOde : public integ::OdeSystem {
 public:
  MaxwellOde(double Ks, double D, double v) : Ks_(Ks), D_(D), v_(v) {}
  int size() const override { return 1; }
  int rhs(double, const double* y, double* yd) override {
    yd[0] = seriesDamperRate(Ks_, D_, y[0], v_);
    return 0;
  }

 private:
  double Ks_, D_, v_;
};

TEST(SeriesDamper, StepAndRampResponsesMatchAppendixAOde) {
  const double Ks = 1000e3, D = 4e3;  // Table 4 primary vertical damper: tau = 4 ms
  const double tau = D / Ks;
  for (const char* method : {"rk4", "bdf"}) {
    integ::SolverSpec s;
    s.method = method;
    s.step = 1e-5;
    s.rtol = 1e-10;
    s.atol = 1e-8;
    // Step of 2 mm at t = 0: f(0+) = Ks h, then f = Ks h exp(-t/tau) with d_dot = 0.
    const double h = 2e-3;
    MaxwellOde step(Ks, D, 0.0);
    std::vector<double> out;
    for (int k = 1; k <= 20; ++k) out.push_back(k * 1e-3);
    double worst = 0.0;
    auto integ1 = integ::makeIntegrator(s);
    Eigen::VectorXd y0(1);
    y0[0] = seriesDamperStep(Ks, D, 0.0, h, 0.0);
    EXPECT_DOUBLE_EQ(y0[0], Ks * h);
    auto r = integ::integrate(step, *integ1, 0.0, y0, out, [&](double t, const Eigen::VectorXd& y) {
      worst = std::max(worst, std::abs(y[0] - seriesDamperStep(Ks, D, 0.0, h, t)));
      return true;
    });
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_LT(worst, 1e-6 * Ks * h) << method;
    // Constant rate 0.1 m/s from rest: f -> D v with time constant tau.
    MaxwellOde ramp(Ks, D, 0.1);
    worst = 0.0;
    y0[0] = 0.0;
    auto integ2 = integ::makeIntegrator(s);
    r = integ::integrate(ramp, *integ2, 0.0, y0, out, [&](double t, const Eigen::VectorXd& y) {
      worst = std::max(worst, std::abs(y[0] - seriesDamperConstantRate(Ks, D, 0.0, 0.1, t)));
      return true;
    });
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_LT(worst, 1e-6 * D * 0.1) << method;
    EXPECT_NEAR(seriesDamperConstantRate(Ks, D, 0.0, 0.1, 10 * tau), D * 0.1, 1e-4 * D * 0.1);
  }
}

}  // namespace
}  // namespace rb::suspension
