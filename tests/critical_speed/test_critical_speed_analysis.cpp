// The signal processing of `workbench critical-speed` on signals of known content: the window
// amplitude of a harmonic motion, the verdict on decaying, sustained and shrinking-onto-a-cycle
// motions, and the speed where a ramp's limit cycle dies.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/critical_speed/analysis.hpp"
#include "workbench/critical_speed/critical_speed.hpp"

namespace cs = rb::critical_speed;

namespace {

struct Signal {
  std::vector<double> t, v;
  std::vector<std::vector<double>> y;
};

// Two wheelsets at f = 4 Hz; the second with amplitude amp(t), the first with half of it.
template <class Amp, class Speed>
Signal harmonic(double duration, Amp amp, Speed speed) {
  Signal s;
  s.y.resize(2);
  for (double t = 0.0; t <= duration + 1e-9; t += 0.005) {
    s.t.push_back(t);
    s.v.push_back(speed(t));
    const double phase = std::sin(2.0 * std::numbers::pi * 4.0 * t);
    s.y[0].push_back(0.5 * amp(t) * phase);
    s.y[1].push_back(amp(t) * phase);
  }
  return s;
}

TEST(CriticalSpeedAnalysis, WindowAmplitudeOfAHarmonicIsItsAmplitude) {
  const Signal s = harmonic(
      5.0, [](double) { return 4e-3; }, [](double) { return 80.0; });
  const auto w = cs::windowAmplitudes(s.t, s.y, s.v, 1.0, 1.0);
  ASSERT_EQ(w.size(), 4u);
  for (const auto& x : w) {
    EXPECT_NEAR(x.amplitude, 4e-3, 2e-5);  // 200 samples per period: peak within 0.5 %
    EXPECT_EQ(x.wheelset, 1);
    EXPECT_DOUBLE_EQ(x.speed, 80.0);
  }
  EXPECT_NEAR(w.front().t0, 1.0, 1e-9);
}

TEST(CriticalSpeedAnalysis, DecayingMotionIsStable) {
  const Signal s = harmonic(
      10.0, [](double t) { return 5e-3 * std::exp(-0.5 * t); }, [](double) { return 60.0; });
  const auto v = cs::judgeKickedRun(cs::windowAmplitudes(s.t, s.y, s.v, 1.0, 1.0), 1e-3, 0.8);
  ASSERT_TRUE(v.valid);
  EXPECT_FALSE(v.unstable) << v.why;
}

TEST(CriticalSpeedAnalysis, SlowDecayAboveTheThresholdIsStable) {
  // 6 mm decaying by 10 % per second: still above 1 mm at the end, but decaying.
  const Signal s = harmonic(
      10.0, [](double t) { return 6e-3 * std::exp(-0.105 * t); }, [](double) { return 70.0; });
  const auto v = cs::judgeKickedRun(cs::windowAmplitudes(s.t, s.y, s.v, 1.0, 1.0), 1e-3, 0.8);
  EXPECT_GT(v.a_last, 1e-3);
  EXPECT_FALSE(v.unstable) << v.why;
}

TEST(CriticalSpeedAnalysis, KickShrinkingOntoALimitCycleIsHunting) {
  // 8 mm kick settling onto a 3 mm cycle within 2 s.
  const Signal s = harmonic(
      10.0, [](double t) { return 3e-3 + 5e-3 * std::exp(-2.0 * t); }, [](double) { return 80.0; });
  const auto v = cs::judgeKickedRun(cs::windowAmplitudes(s.t, s.y, s.v, 1.0, 1.0), 1e-3, 0.8);
  EXPECT_TRUE(v.unstable) << v.why;
}

TEST(CriticalSpeedAnalysis, ShortLastWindowDoesNotTurnHuntingIntoDecay) {
  // A sustained 3 mm cycle at 1 Hz over 10.5 s: the last window [10, 10.5] s holds half a period,
  // whose half peak-to-peak is half the amplitude. The verdict is on full windows only.
  Signal s;
  s.y.resize(1);
  for (double t = 0.0; t <= 10.5 + 1e-9; t += 0.005) {
    s.t.push_back(t);
    s.v.push_back(60.0);
    s.y[0].push_back(3e-3 * std::sin(2.0 * std::numbers::pi * t));
  }
  const auto w = cs::windowAmplitudes(s.t, s.y, s.v, 1.0, 1.0);
  ASSERT_LT(w.back().amplitude, 0.6 * 3e-3);  // the short window is there, and reads low
  const auto v = cs::judgeKickedRun(w, 1e-3, 0.8);
  EXPECT_TRUE(v.unstable) << v.why;
  EXPECT_NEAR(v.a_last, 3e-3, 3e-5);
}

TEST(CriticalSpeedAnalysis, SustainedCycleJustBelowTheThresholdIsNotStable) {
  // A limit cycle of 0.097 mm that neither grows nor decays, judged against 0.1 mm: the amplitude
  // is below the threshold, but the motion is sustained, so the run is no proof of stability.
  const Signal s = harmonic(
      10.0, [](double) { return 0.097e-3; }, [](double) { return 45.0; });
  const auto v = cs::judgeKickedRun(cs::windowAmplitudes(s.t, s.y, s.v, 1.0, 1.0), 1e-4, 0.8);
  ASSERT_TRUE(v.valid);
  EXPECT_FALSE(v.unstable) << v.why;  // not hunting by the threshold criterion
  EXPECT_TRUE(v.small_cycle) << v.why;
  EXPECT_EQ(v.state(), "sustained small-amplitude oscillation");
  EXPECT_NE(v.why.find("sustained small-amplitude oscillation of 0.09"), std::string::npos)
      << v.why;
  EXPECT_EQ(v.why.find("(stable)"), std::string::npos) << v.why;
  EXPECT_NEAR(v.trend, 1.0, 0.01);
  EXPECT_DOUBLE_EQ(v.threshold, 1e-4);
}

TEST(CriticalSpeedAnalysis, MotionDecayedToNoiseIsStable) {
  // A kick decaying at 3 1/s to 1e-11 m: died out, stable (not a small cycle).
  const Signal s = harmonic(
      10.0, [](double t) { return 5e-3 * std::exp(-3.0 * t); }, [](double) { return 45.0; });
  const auto v = cs::judgeKickedRun(cs::windowAmplitudes(s.t, s.y, s.v, 1.0, 1.0), 1e-4, 0.8);
  EXPECT_FALSE(v.unstable) << v.why;
  EXPECT_FALSE(v.small_cycle) << v.why;
  EXPECT_EQ(v.state(), "stable");
}

TEST(CriticalSpeedAnalysis, SlowlyDecayingSmallMotionIsStable) {
  // 0.09 mm decaying by 30 % per second: below the threshold and decaying, stable.
  const Signal s = harmonic(
      10.0, [](double t) { return 0.09e-3 * std::exp(-0.36 * t); }, [](double) { return 45.0; });
  const auto v = cs::judgeKickedRun(cs::windowAmplitudes(s.t, s.y, s.v, 1.0, 1.0), 1e-4, 0.8);
  EXPECT_FALSE(v.small_cycle) << v.why;
  EXPECT_EQ(v.state(), "stable");
}

TEST(CriticalSpeedAnalysis, TooFewWindowsAreNoVerdict) {
  const Signal s = harmonic(
      2.5, [](double) { return 3e-3; }, [](double) { return 80.0; });
  const auto v = cs::judgeKickedRun(cs::windowAmplitudes(s.t, s.y, s.v, 1.0, 1.0), 1e-3, 0.8);
  EXPECT_FALSE(v.valid);
}

TEST(CriticalSpeedAnalysis, RampLimitCycleDiesWhereTheAmplitudeFallsBelowTheThreshold) {
  // Speed 90 - t; a 4 mm cycle down to 70 m/s, then decaying quickly.
  auto speed = [](double t) { return 90.0 - t; };
  auto amp = [&](double t) {
    const double v = speed(t);
    return v >= 70.0 ? 4e-3 : 4e-3 * std::exp(-3.0 * (70.0 - v));
  };
  const Signal s = harmonic(40.0, amp, speed);
  const auto r = cs::rampCriticalSpeed(cs::windowAmplitudes(s.t, s.y, s.v, 0.5, 0.5), 1e-3);
  ASSERT_TRUE(r.found);
  EXPECT_TRUE(r.hunting_at_start);
  EXPECT_FALSE(r.hunting_at_end);
  EXPECT_NEAR(r.critical_speed, 70.0, 1.0);
}

TEST(CriticalSpeedAnalysis, RampWithoutDeathOrWithoutCycleFindsNothing) {
  const Signal alive = harmonic(
      10.0, [](double) { return 4e-3; }, [](double t) { return 90 - t; });
  const auto a = cs::rampCriticalSpeed(cs::windowAmplitudes(alive.t, alive.y, alive.v, 1, 1), 1e-3);
  EXPECT_FALSE(a.found);
  EXPECT_TRUE(a.hunting_at_end);
  const Signal none = harmonic(
      10.0, [](double) { return 1e-4; }, [](double t) { return 90 - t; });
  const auto n = cs::rampCriticalSpeed(cs::windowAmplitudes(none.t, none.y, none.v, 1, 1), 1e-3);
  EXPECT_FALSE(n.found);
  EXPECT_FALSE(n.hunting_at_start);
}

}  // namespace

namespace {

// The problems checkCriticalSpeedOptions reports for `o` (empty when it accepts them).
std::vector<std::string> optionProblems(const rb::critical_speed::CriticalSpeedOptions& o) {
  try {
    rb::critical_speed::checkCriticalSpeedOptions(o);
  } catch (const rb::InputError& e) {
    std::vector<std::string> out;
    for (const auto& d : e.diagnostics()) out.push_back(d.message);
    return out;
  }
  return {};
}

}  // namespace

TEST(CriticalSpeedOptions, DefaultsAreAccepted) {
  EXPECT_TRUE(optionProblems(rb::critical_speed::CriticalSpeedOptions{}).empty());
}

TEST(CriticalSpeedOptions, UnboundedWorkIsRefusedAllAtOnceWithTheValues) {
  rb::critical_speed::CriticalSpeedOptions o;
  o.tolerance = 1e-300;  // repeated one bisection probe forever
  o.max_speed = 1e9;     // swept the linear critical speed over 1e8 speeds
  o.duration = 1e9;
  const auto p = optionProblems(o);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_NE(p[0].find("--max-speed 1e+09"), std::string::npos) << p[0];
  EXPECT_NE(p[1].find("--tolerance 1e-300"), std::string::npos) << p[1];
  EXPECT_NE(p[2].find("--duration 1e+09"), std::string::npos) << p[2];
}

TEST(CriticalSpeedOptions, ATypedZeroSpeedIsNoDefault) {
  rb::critical_speed::CriticalSpeedOptions o;
  o.from = 0.0;
  o.from_given = true;
  const auto p = optionProblems(o);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("--from 0:"), std::string::npos) << p[0];
  o.from_given = false;  // not typed: the default search start
  EXPECT_TRUE(optionProblems(o).empty());
}

TEST(CriticalSpeedOptions, ToleranceIsBoundedRelativeToTheSpeed) {
  rb::critical_speed::CriticalSpeedOptions o;
  o.from = 100.0;
  o.from_given = true;
  o.tolerance = 0.005;  // below 1e-4 x 100 m/s
  EXPECT_EQ(optionProblems(o).size(), 1u);
  o.tolerance = 0.02;
  EXPECT_TRUE(optionProblems(o).empty());
}
