// The statistics of study metrics on vectors whose answers are known by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "workbench/assessment/signal_metrics.hpp"

namespace m = rb::assessment::metrics;

namespace {
const std::vector<double> kX = {0, 1, 2, 3, 4};
const std::vector<double> kY = {1, -3, 2, 0, 4};

double stat(m::Stat s, m::Window w = {}) {
  const m::Value v = m::statistic(kX, kY, w, s);
  EXPECT_TRUE(v.ok()) << v.why;
  return v.value;
}
}  // namespace

TEST(SignalMetrics, EveryStatisticOnAKnownVector) {
  EXPECT_EQ(stat(m::Stat::Max), 4.0);
  EXPECT_EQ(stat(m::Stat::Min), -3.0);
  EXPECT_EQ(stat(m::Stat::MaxAbs), 4.0);
  EXPECT_EQ(stat(m::Stat::Mean), 0.8);
  EXPECT_DOUBLE_EQ(stat(m::Stat::Rms), std::sqrt(30.0 / 5.0));
  // Population variance: mean of (y - 0.8)^2 = (0.04 + 14.44 + 1.44 + 0.64 + 10.24) / 5.
  EXPECT_DOUBLE_EQ(stat(m::Stat::Std), std::sqrt(26.8 / 5.0));
  EXPECT_EQ(stat(m::Stat::HalfPeakToPeak), 3.5);
  EXPECT_EQ(stat(m::Stat::Final), 4.0);
}

TEST(SignalMetrics, WindowEdgesAreInclusive) {
  // [1, 3] holds -3, 2, 0.
  EXPECT_EQ(stat(m::Stat::Max, {1, 3}), 2.0);
  EXPECT_EQ(stat(m::Stat::Min, {1, 3}), -3.0);
  EXPECT_EQ(stat(m::Stat::Final, {1, 3}), 0.0);
  // Between samples: [1.5, 2.5] holds only 2.
  EXPECT_EQ(stat(m::Stat::Mean, {1.5, 2.5}), 2.0);
}

TEST(SignalMetrics, WindowBeyondTheSignalIsRefused) {
  // One sample spacing of slack at the end, no more.
  EXPECT_TRUE(m::statistic(kX, kY, {0, 5}, m::Stat::Max).ok());
  const m::Value v = m::statistic(kX, kY, {0, 10}, m::Stat::Max);
  EXPECT_FALSE(v.ok());
  EXPECT_TRUE(std::isnan(v.value));
  EXPECT_NE(v.why.find("window ends at 10"), std::string::npos) << v.why;
  EXPECT_FALSE(m::statistic(kX, kY, {-5, 2}, m::Stat::Max).ok());
  const m::Value empty = m::statistic(kX, kY, {2.2, 2.8}, m::Stat::Max);
  EXPECT_NE(empty.why.find("no sample"), std::string::npos) << empty.why;
}

TEST(SignalMetrics, NaNIsRefused) {
  std::vector<double> y = kY;
  y[2] = std::nan("");
  const m::Value v = m::statistic(kX, y, {}, m::Stat::Max);
  EXPECT_FALSE(v.ok());
  EXPECT_NE(v.why.find("nan"), std::string::npos) << v.why;
  // Outside the window it does not matter.
  EXPECT_TRUE(m::statistic(kX, y, {3, 4}, m::Stat::Max).ok());
  EXPECT_FALSE(m::statistic(kX, std::vector<double>{1, 2}, {}, m::Stat::Max).ok());
}

TEST(SignalMetrics, NamesRoundTrip) {
  for (const auto& n : m::statNames()) {
    m::Stat s{};
    ASSERT_TRUE(m::statFromName(n, s));
    EXPECT_EQ(m::statNames()[static_cast<std::size_t>(s)], n);
  }
  m::Stat s{};
  EXPECT_FALSE(m::statFromName("maximum", s));
}

TEST(SignalMetrics, SteadyValueAndItsCheck) {
  std::vector<double> x, flat, osc;
  for (int k = 0; k <= 100; ++k) {
    x.push_back(k);
    flat.push_back(k < 50 ? 0.01 * k : 0.5);  // settles at 0.5
    osc.push_back(0.5 + 0.2 * ((k % 2) ? 1.0 : -1.0));
  }
  const m::Value s = m::steady(x, flat, {}, 0.0, -1.0);
  ASSERT_TRUE(s.ok()) << s.why;
  EXPECT_EQ(s.value, 0.5);  // the last 20 m: every sample 0.5
  EXPECT_TRUE(s.note.empty()) << s.note;
  const m::Value o = m::steady(x, osc, {}, 0.0, -1.0);
  ASSERT_TRUE(o.ok());
  EXPECT_NE(o.note.find("not steady"), std::string::npos);
  // The ramp part, with an explicit length, drifts.
  const m::Value r = m::steady(x, flat, {0, 50}, 20.0, 1e-3);
  EXPECT_NE(r.note.find("drift"), std::string::npos) << r.note;
  EXPECT_TRUE(m::steady(x, osc, {}, 0.0, 0.5).note.empty());
}

TEST(SignalMetrics, InterpolationIsExactAtSamples) {
  const std::vector<double> x = {0, 0.1, 0.3, 0.7}, y = {1.1, 2.3, -0.7, 5.9};
  for (std::size_t k = 0; k < x.size(); ++k) {
    double v = 0;
    ASSERT_TRUE(m::interpolate(x, y, x[k], v));
    EXPECT_EQ(v, y[k]);
  }
  double v = 0;
  ASSERT_TRUE(m::interpolate(x, y, 0.2, v));
  EXPECT_NEAR(v, 0.8, 1e-15);
  EXPECT_FALSE(m::interpolate(x, y, 0.8, v));
}

TEST(SignalMetrics, MaxAbsDifference) {
  const std::vector<double> x = {0, 1, 2, 3}, y = {0, 1, 2, 3};
  EXPECT_EQ(m::maxAbsDifference(x, y, x, y, {}).value, 0.0);
  // Reference sampled at the half points, offset by 0.25 at 1.5.
  const std::vector<double> xr = {0.5, 1.5, 2.5}, yr = {0.5, 1.75, 2.5};
  EXPECT_DOUBLE_EQ(m::maxAbsDifference(x, y, xr, yr, {}).value, 0.25);
  EXPECT_DOUBLE_EQ(m::maxAbsDifference(x, y, xr, yr, {2, 3}).value, 0.0);
  // The reference runs further than the case: refused.
  const std::vector<double> xl = {0, 4.5}, yl = {0, 4.5};
  EXPECT_FALSE(m::maxAbsDifference(x, y, xl, yl, {}).ok());
  // Within one sample spacing of the case's end: that sample is left out.
  const std::vector<double> xe = {0, 1.5, 3.5}, ye = {0, 1.5, 9};
  EXPECT_EQ(m::maxAbsDifference(x, y, xe, ye, {}).value, 0.0);
}

TEST(SignalMetrics, DivergedRunIsAnInfiniteError) {
  // The rule of every comparison of runs: a NaN in the case (or the reference) is not left out
  // and not "no value", it is an infinite error, with its place in the note.
  const std::vector<double> x = {0, 1, 2, 3}, y = {0, 1, 2, 3};
  std::vector<double> diverged = y;
  diverged[2] = std::nan("");
  for (const auto& v :
       {m::maxAbsDifference(x, diverged, x, y, {}), m::maxAbsDifference(x, y, x, diverged, {})}) {
    EXPECT_TRUE(v.ok());
    EXPECT_TRUE(std::isinf(v.value));
    EXPECT_NE(v.note.find("nan at 2"), std::string::npos) << v.note;
  }
}
