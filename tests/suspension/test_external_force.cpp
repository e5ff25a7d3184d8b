// The laws of the external force element (suspension/external_force.hpp): constant, ramp (by
// duration or rate, with and without a hold), tables over time and over distance, their ends, and
// the checks of a law.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "workbench/suspension/external_force.hpp"

namespace rb::suspension {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

ForceLaw ramp(double initial, double value, double start, double duration,
              double hold = std::numeric_limits<double>::infinity()) {
  ForceLaw l;
  l.kind = ForceLawKind::Ramp;
  l.initial = initial;
  l.value = value;
  l.start = start;
  l.duration = duration;
  l.hold = hold;
  return l;
}

ForceLaw table(ForceAbscissa over, std::vector<double> at, std::vector<double> force) {
  ForceLaw l;
  l.kind = ForceLawKind::Table;
  l.over = over;
  l.at = std::move(at);
  l.force = std::move(force);
  return l;
}

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  for (const auto& p : problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

TEST(ExternalForceLaw, ConstantAtEveryTimeAndPlace) {
  ForceLaw l;
  l.value = -12.5e3;
  for (double t : {0.0, 1e-9, 3.0, 1e6})
    for (double s : {-5.0, 0.0, 250.0}) EXPECT_EQ(forceAt(l, t, s), -12.5e3);
  EXPECT_TRUE(checkForceLaw(l).empty());
}

TEST(ExternalForceLaw, RampByDurationRisesLinearlyAndStays) {
  // The flange-climb validation's push (docs/elastic_contact.md): 80 kN/s from 0 at t = 0.5 s to
  // 160 kN, that is over 2 s.
  const ForceLaw l = ramp(0.0, 160e3, 0.5, 2.0);
  EXPECT_TRUE(checkForceLaw(l).empty());
  EXPECT_EQ(forceAt(l, 0.0, 0.0), 0.0);
  EXPECT_EQ(forceAt(l, 0.5, 0.0), 0.0);  // the ramp leaves `initial` at start
  for (double t : {0.6, 1.0, 1.75, 2.4}) EXPECT_NEAR(forceAt(l, t, 0.0), 80e3 * (t - 0.5), 1e-9);
  EXPECT_EQ(forceAt(l, 2.5, 0.0), 160e3);    // reaches value at start + duration
  EXPECT_EQ(forceAt(l, 1e4, 123.0), 160e3);  // an infinite hold: to the end
}

TEST(ExternalForceLaw, RampWithHoldIsATrapezoidBackToInitial) {
  // From 2 kN up to -8 kN (a decreasing ramp) over 0.5 s from t = 1, held 1 s, back over 0.5 s.
  const ForceLaw l = ramp(2e3, -8e3, 1.0, 0.5, 1.0);
  EXPECT_TRUE(checkForceLaw(l).empty());
  EXPECT_EQ(forceAt(l, 0.9, 0.0), 2e3);
  EXPECT_NEAR(forceAt(l, 1.25, 0.0), -3e3, 1e-9);  // half way down
  EXPECT_EQ(forceAt(l, 1.5, 0.0), -8e3);
  EXPECT_EQ(forceAt(l, 2.0, 0.0), -8e3);
  EXPECT_EQ(forceAt(l, 2.5, 0.0), -8e3);           // end of the hold
  EXPECT_NEAR(forceAt(l, 2.75, 0.0), -3e3, 1e-9);  // half way back
  EXPECT_NEAR(forceAt(l, 3.0, 0.0), 2e3, 1e-9);
  EXPECT_EQ(forceAt(l, 10.0, 0.0), 2e3);
  // Continuous: no step anywhere (the largest change over 1 us is the rate's 20 kN/s x 1 us).
  for (double t = 0.0; t < 4.0; t += 1e-3)
    EXPECT_LE(std::abs(forceAt(l, t + 1e-6, 0.0) - forceAt(l, t, 0.0)), 20e3 * 1e-6 * 1.0001) << t;
  // A zero hold is a triangle.
  const ForceLaw tri = ramp(0.0, 10e3, 0.0, 1.0, 0.0);
  EXPECT_EQ(forceAt(tri, 1.0, 0.0), 10e3);
  EXPECT_NEAR(forceAt(tri, 1.5, 0.0), 5e3, 1e-9);
  EXPECT_EQ(forceAt(tri, 2.0, 0.0), 0.0);
}

TEST(ExternalForceLaw, RampOfZeroDurationOnlyWithoutChange) {
  // A rate over a zero difference gives a zero duration: the force never changes.
  const ForceLaw flat = ramp(5e3, 5e3, 1.0, 0.0, 1.0);
  EXPECT_TRUE(checkForceLaw(flat).empty());
  for (double t : {0.0, 1.0, 1.5, 2.0, 3.0}) EXPECT_EQ(forceAt(flat, t, 0.0), 5e3);
  EXPECT_TRUE(mentions(checkForceLaw(ramp(0.0, 5e3, 1.0, 0.0)), "duration must be > 0 s"));
}

TEST(ExternalForceLaw, TableOverTimeIsLinearAndHeldBeyondTheEnds) {
  const ForceLaw l = table(ForceAbscissa::Time, {1.0, 2.0, 4.0}, {0.0, 10e3, -2e3});
  EXPECT_TRUE(checkForceLaw(l).empty());
  EXPECT_EQ(forceAt(l, -1.0, 500.0), 0.0);  // before the first point: its value
  EXPECT_EQ(forceAt(l, 1.0, 500.0), 0.0);
  EXPECT_NEAR(forceAt(l, 1.5, 500.0), 5e3, 1e-9);
  EXPECT_EQ(forceAt(l, 2.0, 500.0), 10e3);
  EXPECT_NEAR(forceAt(l, 3.0, 500.0), 4e3, 1e-9);
  EXPECT_EQ(forceAt(l, 4.0, 500.0), -2e3);
  EXPECT_EQ(forceAt(l, 40.0, 500.0), -2e3);  // after the last: its value
}

TEST(ExternalForceLaw, TableOverDistanceFollowsTheBodyNotTheClock) {
  // A gust zone on the line: 0 before s = 100 m, 30 kN from 110 to 130 m, 0 after 140 m.
  const ForceLaw l =
      table(ForceAbscissa::Distance, {100.0, 110.0, 130.0, 140.0}, {0.0, 30e3, 30e3, 0.0});
  EXPECT_TRUE(checkForceLaw(l).empty());
  for (double t : {0.0, 5.0, 100.0}) {
    EXPECT_EQ(forceAt(l, t, 50.0), 0.0);
    EXPECT_NEAR(forceAt(l, t, 105.0), 15e3, 1e-9);
    EXPECT_EQ(forceAt(l, t, 120.0), 30e3);
    EXPECT_NEAR(forceAt(l, t, 137.5), 7.5e3, 1e-9);
    EXPECT_EQ(forceAt(l, t, 1e4), 0.0);
  }
}

TEST(ExternalForceLaw, ChecksNameEveryProblem) {
  ForceLaw c;
  c.value = kNaN;
  EXPECT_TRUE(mentions(checkForceLaw(c), "value must be in [-1e+08, 1e+08] N, got nan"));
  c.value = 2e8;
  EXPECT_TRUE(mentions(checkForceLaw(c), "value must be in"));

  ForceLaw r = ramp(0.0, 1e3, -1.0, kNaN, -2.0);
  const auto rp = checkForceLaw(r);
  EXPECT_TRUE(mentions(rp, "start must be in [0, inf) s, got -1"));
  EXPECT_TRUE(mentions(rp, "duration must be > 0 s, got nan"));
  EXPECT_TRUE(mentions(rp, "hold must be >= 0 s, got -2"));

  EXPECT_TRUE(
      mentions(checkForceLaw(table(ForceAbscissa::Time, {1.0}, {0.0})), "needs at least 2 points"));
  const auto tp = checkForceLaw(
      table(ForceAbscissa::Time, {0.0, 1.0, 1.0, kNaN, 3.0}, {0.0, kNaN, 1.0, 2.0, 1e9}));
  EXPECT_TRUE(mentions(tp, "table: t must be strictly increasing (t[3] = 1 after t[2] = 1)"));
  EXPECT_TRUE(mentions(tp, "table: t[4] must be finite, got nan"));
  EXPECT_TRUE(mentions(tp, "table: F[2] must be in [-1e+08, 1e+08] N, got nan"));
  EXPECT_TRUE(mentions(tp, "table: F[5] must be in"));
  EXPECT_TRUE(mentions(checkForceLaw(table(ForceAbscissa::Distance, {5.0, 4.0}, {0.0, 1.0})),
                       "table: s must be strictly increasing (s[2] = 4 after s[1] = 5)"));
}

}  // namespace
}  // namespace rb::suspension
