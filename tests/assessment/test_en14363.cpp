// EN 14363 quantities (workbench/assessment/en14363.hpp): Nadal's limit at hand values, the track
// shift limit for known axle loads, Y/Q, sum Y, wheel unloading and quasi-static values of
// synthetic signals, and the stability criterion on growing and decaying oscillations.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "workbench/assessment/en14363.hpp"

namespace {

using namespace rb::assessment;
using namespace rb::assessment::en14363;

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(Nadal, HandValues) {
  // (tan g - mu) / (1 + mu tan g), by hand:
  // g = 70 deg, mu = 0.36: tan = 2.747477; (2.387477) / (1.989092) = 1.200285
  EXPECT_NEAR(nadalLimit(70.0 * kDeg, 0.36), 1.200285, 1e-6);
  // g = 60 deg, mu = 0.30: tan = 1.732051; (1.432051) / (1.519615) = 0.942377
  EXPECT_NEAR(nadalLimit(60.0 * kDeg, 0.30), 0.942377, 1e-6);
  // g = 75 deg, mu = 0.25: tan = 3.732051; (3.482051) / (1.933013) = 1.801360
  EXPECT_NEAR(nadalLimit(75.0 * kDeg, 0.25), 1.801360, 1e-6);
  // Frictionless flange: tan(gamma).
  EXPECT_NEAR(nadalLimit(70.0 * kDeg, 0.0), std::tan(70.0 * kDeg), 1e-12);
  EXPECT_DOUBLE_EQ(kDerailmentQuotientLimit, 0.8);
}

TEST(TrackShift, LimitForKnownAxleLoads) {
  // Axle load P = 200 kN (Q0 = 100 kN): 10 + 200/3 = 76.667 kN.
  EXPECT_NEAR(trackShiftLimit(100e3), 76666.6667, 1e-3);
  // Freight wagon, alpha = 0.85, P = 225 kN (Q0 = 112.5 kN): 0.85 (10 + 75) = 72.25 kN.
  EXPECT_NEAR(trackShiftLimit(112.5e3, kTrackShiftAlphaFreight), 72250.0, 1e-6);
}

struct Track {
  double dt = 1e-3, speed = 20.0;
  std::vector<double> s;
  explicit Track(std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) s.push_back(speed * dt * static_cast<double>(i));
  }
};

TEST(TrackShift, ConstantForcesOfAWheelset) {
  const Track t(1000);  // 20 m
  const std::vector<double> yl(t.s.size(), 30e3), yr(t.s.size(), 20e3);
  const SlidingAssessment a = trackShiftForce(yl, yr, t.s, t.dt, 100e3);
  EXPECT_NEAR(a.check.value, 50e3, 1e-6);
  EXPECT_NEAR(a.check.limit, 76666.6667, 1e-3);
  EXPECT_NEAR(a.check.margin, 26666.6667, 1e-3);
  EXPECT_TRUE(a.check.ok());
  EXPECT_EQ(a.stats.count, 36U);  // last sample at 19.98 m: window ends 2, 2.5, ..., 19.5 m
}

TEST(DerailmentQuotient, ConstantRatioAndLiftedWheel) {
  const Track t(1000);
  std::vector<double> q(t.s.size(), 60e3), y(t.s.size(), 30e3);
  const SlidingAssessment a = derailmentQuotient(y, q, t.s, t.dt);
  EXPECT_NEAR(a.check.value, 0.5, 1e-9);
  EXPECT_NEAR(a.check.margin, 0.3, 1e-9);
  // A negative quotient (flange on the other side) is assessed by magnitude.
  for (double& v : y) v = -54e3;
  EXPECT_NEAR(derailmentQuotient(y, q, t.s, t.dt).check.value, 0.9, 1e-9);
  EXPECT_FALSE(derailmentQuotient(y, q, t.s, t.dt).check.ok());
}

TEST(WheelUnloading, DipAgainstStaticLoad) {
  const Track t(2000);
  std::vector<double> q(t.s.size(), 50e3);
  // A slow dip to 30 kN (half-sine over 1 s, well below the 20 Hz cut-off).
  for (std::size_t i = 500; i < 1500; ++i) {
    q[i] = 50e3 - 20e3 * std::sin(std::numbers::pi * static_cast<double>(i - 500) / 1000.0);
  }
  const Check c = wheelUnloading(q, t.dt, 50e3);
  EXPECT_NEAR(c.value, 0.4, 1e-4);  // (50 - 30) / 50
  EXPECT_NEAR(c.limit, 0.6, 1e-12);
  EXPECT_TRUE(c.ok());
}

TEST(QuasiStatic, MedianOfTheSection) {
  const Track t(4000);
  std::vector<double> y(t.s.size());
  // 40 kN with a 2 Hz, 10 kN oscillation: median 40 kN, 99.85 % close to 50 kN.
  for (std::size_t i = 0; i < y.size(); ++i) {
    y[i] = 40e3 + 10e3 * std::sin(2.0 * std::numbers::pi * 2.0 * t.dt * static_cast<double>(i));
  }
  const SectionValues v = sectionValues(y, t.dt);
  EXPECT_NEAR(v.quasi_static, 40e3, 100.0);
  EXPECT_NEAR(v.upper, 50e3, 100.0);
  EXPECT_NEAR(v.lower, 30e3, 100.0);
  EXPECT_TRUE(quasiStaticGuidingForce(y, t.dt).ok());                // 40 < 60 kN
  EXPECT_NEAR(maximumWheelForce(y, t.dt, 60e3).limit, 150e3, 1e-9);  // 90 kN + Q0
  EXPECT_FALSE(quasiStaticWheelForce(y, t.dt, 30e3).ok());
}

// Bogie-frame lateral acceleration A0 exp(sigma t) sin(2 pi f0 t) at 20 m/s over 400 m.
std::vector<double> oscillation(const Track& t, double f0, double sigma) {
  std::vector<double> a(t.s.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double time = t.dt * static_cast<double>(i);
    a[i] = std::exp(sigma * time) * std::sin(2.0 * std::numbers::pi * f0 * time);
  }
  return a;
}

TEST(Stability, LimitFormula) {
  EXPECT_NEAR(bogieAccelerationLimit(3000.0), 5.7, 1e-12);  // (12 - 3/5) / 2
  EXPECT_NEAR(bogieAccelerationLimit(5000.0), 5.5, 1e-12);
}

TEST(Stability, FiresOnGrowingNotOnDecaying) {
  const Track t(20001);  // 20 s, 400 m
  const double f0 = 5.0;
  const double sigma = std::log(20.0) / 20.0;  // amplitude 1 -> 20 m/s^2 over the run
  const StabilityAssessment grow = stability(oscillation(t, f0, sigma), t.s, t.dt, f0, 3000.0);
  EXPECT_FALSE(grow.check.ok());
  EXPECT_GT(grow.check.value, 9.0);         // last 100 m: amplitudes 9.4..20, rms about 10
  EXPECT_NEAR(grow.position, 400.0, 1e-6);  // the largest rms at the end
  const StabilityAssessment decay = stability(oscillation(t, f0, -sigma), t.s, t.dt, f0, 3000.0);
  EXPECT_TRUE(decay.check.ok());
  EXPECT_LT(decay.check.value, 1.0);  // first 100 m: rms of amplitudes 1..0.47
  EXPECT_NEAR(decay.position, 100.0, 1e-6);
  // A steady oscillation at the limit's amplitude sqrt(2) * 5.7 sits at the limit.
  std::vector<double> steady = oscillation(t, f0, 0.0);
  for (double& v : steady) v *= std::numbers::sqrt2 * 5.7;
  EXPECT_NEAR(stability(steady, t.s, t.dt, f0, 3000.0).check.value, 5.7, 0.05);
}

}  // namespace

// A wheel's forces filtered once give every quantity exactly as the raw series do.
TEST(FilteredWheelForces, SameValuesAsTheRawSeries) {
  const double dt = 2.5e-3;
  std::vector<double> Y(2000), Q(2000), s(2000);
  for (std::size_t i = 0; i < Y.size(); ++i) {
    const double t = static_cast<double>(i) * dt;
    Y[i] = 12e3 * std::sin(2.0 * std::numbers::pi * 1.7 * t) + 3e3 * std::sin(90.0 * t);
    Q[i] = 60e3 + 9e3 * std::sin(2.0 * std::numbers::pi * 2.3 * t) + 2e3 * std::sin(170.0 * t);
    s[i] = 20.0 * t;
  }
  const FilteredWheelForces f = filterWheelForces(Y, Q, dt);
  const SlidingAssessment a = derailmentQuotient(Y, Q, s, dt), b = derailmentQuotient(f, s);
  EXPECT_EQ(a.check.value, b.check.value);
  EXPECT_EQ(a.series.value, b.series.value);
  EXPECT_EQ(wheelUnloading(Q, dt, 62e3).value, wheelUnloading(f, 62e3).value);
  EXPECT_EQ(quasiStaticGuidingForce(Y, dt).value, quasiStaticGuidingForce(f).value);
  EXPECT_EQ(quasiStaticWheelForce(Q, dt).value, quasiStaticWheelForce(f).value);
  EXPECT_EQ(maximumWheelForce(Q, dt, 62e3).value, maximumWheelForce(f, 62e3).value);
  EXPECT_EQ(maximumWheelForce(Q, dt, 62e3).limit, maximumWheelForce(f, 62e3).limit);
}
