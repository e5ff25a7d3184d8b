// Signal processing of workbench/assessment/signal.hpp: the 2 m sliding mean against hand-computed
// windows, percentiles, block and trailing rms, and the Butterworth filters' corner gains.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "workbench/assessment/signal.hpp"

namespace {

using namespace rb::assessment;

// s_i = 0.1 i m, x_i = i for i = 0..100 (10 m of track).
struct Ramp {
  std::vector<double> s, x;
  Ramp() {
    for (int i = 0; i <= 100; ++i) {
      s.push_back(0.1 * i);
      x.push_back(i);
    }
  }
};

TEST(SlidingMean, RampAgainstHandWindows) {
  const Ramp r;
  const DistanceSeries m = slidingMean(r.x, r.s, 2.0, 0.5);
  // Window ends p = 2, 2.5, ..., 10 m: 17 windows.
  ASSERT_EQ(m.value.size(), 17U);
  // The window ending at p holds the 20 samples i = 10 (p - 2) + 1 .. 10 p: mean = 10 p - 9.5.
  EXPECT_NEAR(m.position[0], 2.0, 1e-12);
  EXPECT_NEAR(m.value[0], 10.5, 1e-12);   // mean of 1..20
  EXPECT_NEAR(m.value[1], 15.5, 1e-12);   // mean of 6..25
  EXPECT_NEAR(m.value[16], 90.5, 1e-12);  // mean of 81..100
  for (std::size_t k = 0; k < m.value.size(); ++k) {
    EXPECT_NEAR(m.value[k], 10.0 * m.position[k] - 9.5, 1e-9);
  }
}

TEST(SlidingMean, StepAgainstHandWindow) {
  const Ramp r;
  std::vector<double> x(r.s.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = r.s[i] >= 5.0 - 1e-12 ? 1.0 : 0.0;
  const DistanceSeries m = slidingMean(x, r.s, 2.0, 0.5);
  // Window ending at 6 m: samples 4.1..6.0 m (20), of which 5.0..6.0 m (11) are 1: 0.55.
  EXPECT_NEAR(m.value[8], 0.55, 1e-12);
  EXPECT_NEAR(m.value[0], 0.0, 1e-12);   // 0.1..2.0 m
  EXPECT_NEAR(m.value[16], 1.0, 1e-12);  // 8.1..10 m
}

TEST(SlidingRms, ConstantAndAlternating) {
  const Ramp r;
  std::vector<double> x(r.s.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = (i % 2 == 0) ? 3.0 : -3.0;
  const DistanceSeries m = slidingRms(x, r.s, 2.0, 1.0);
  for (const double v : m.value) EXPECT_NEAR(v, 3.0, 1e-12);
}

TEST(Percentile, LinearInterpolationDefinition7) {
  const std::vector<double> x{5.0, 1.0, 4.0, 2.0, 3.0};
  EXPECT_DOUBLE_EQ(percentile(x, 50.0), 3.0);
  EXPECT_DOUBLE_EQ(percentile(x, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(percentile(x, 100.0), 5.0);
  EXPECT_NEAR(percentile(x, 95.0), 4.8, 1e-12);     // h = 4 * 0.95 = 3.8
  EXPECT_NEAR(percentile(x, 99.85), 4.994, 1e-12);  // h = 3.994
  EXPECT_NEAR(percentile(x, 0.15), 1.006, 1e-12);   // h = 0.006
  EXPECT_DOUBLE_EQ(maxAbs(std::vector<double>{-7.0, 2.0}), 7.0);
}

// The percentile selects its two order statistics instead of sorting: the same values, bit for
// bit, as interpolating in the sorted series (ties and repeated values included).
TEST(Percentile, SelectionEqualsTheSortedSeries) {
  std::vector<double> x(997);
  std::uint64_t state = 12345;
  for (double& v : x) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    v = static_cast<double>(state >> 40) * 1e-3 - 8000.0;
  }
  for (std::size_t i = 0; i < x.size(); i += 7) x[i] = x[(i * 13) % x.size()];  // repeats
  std::vector<double> sorted = x;
  std::sort(sorted.begin(), sorted.end());
  for (const double p : {0.0, 0.15, 1.0, 50.0, 95.0, 99.85, 100.0}) {
    const double h = static_cast<double>(sorted.size() - 1) * p / 100.0;
    const auto i = static_cast<std::size_t>(std::floor(h));
    const double expected = i + 1 >= sorted.size() ? sorted.back()
                                                   : sorted[i] + (h - static_cast<double>(i)) *
                                                                     (sorted[i + 1] - sorted[i]);
    EXPECT_EQ(percentile(x, p), expected) << "p = " << p;
  }
}

TEST(BlockRms, SineBlocksAndTrailing) {
  const double dt = 1e-3;
  std::vector<double> x(12000);  // 12 s of a 1 Hz sine, amplitude 2
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = 2.0 * std::sin(2.0 * std::numbers::pi * static_cast<double>(i) * dt);
  const std::vector<double> b = blockRms(x, dt, 5.0);
  ASSERT_EQ(b.size(), 2U);  // the incomplete third block is dropped
  for (const double v : b) EXPECT_NEAR(v, std::numbers::sqrt2, 1e-9);
  const std::vector<double> t = trailingRms(x, dt, 5.0);
  EXPECT_NEAR(t.back(), std::numbers::sqrt2, 1e-9);
}

TEST(Butterworth, CornerGainsAndSteadyStart) {
  const double dt = 1e-3;
  const Cascade lp = butterworthLowPass4(20.0, dt);
  EXPECT_NEAR(std::abs(digitalResponse(lp, 20.0, dt)), std::numbers::sqrt2 / 2.0, 1e-12);
  EXPECT_NEAR(std::abs(digitalResponse(lp, 0.0, dt)), 1.0, 1e-12);
  // 4th order: |H(2 fc)| = 1 / sqrt(1 + 2^8) in the continuous filter; the prewarped digital one
  // is below it (the bilinear transform compresses frequencies above the corner).
  EXPECT_LT(std::abs(digitalResponse(lp, 40.0, dt)), 1.0 / std::sqrt(257.0));
  const Cascade bp = butterworthBandPass(3.0, 7.0, dt);
  EXPECT_NEAR(std::abs(digitalResponse(bp, 3.0, dt)), std::numbers::sqrt2 / 2.0, 0.02);
  EXPECT_NEAR(std::abs(digitalResponse(bp, 7.0, dt)), std::numbers::sqrt2 / 2.0, 0.02);
  EXPECT_LT(std::abs(digitalResponse(bp, 0.5, dt)), 0.05);
  // The stability criterion's band-pass: unit gain at the centre, -3 dB at the band edges
  // sqrt(f0^2 + (B/2)^2) -+ B/2 = 3.385 and 7.385 Hz for f0 = 5 Hz, B = 4 Hz.
  const Cascade rb = resonatorBandPass(5.0, 4.0, dt);
  EXPECT_NEAR(std::abs(digitalResponse(rb, 5.0, dt)), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(digitalResponse(rb, std::sqrt(29.0) - 2.0, dt)), std::numbers::sqrt2 / 2.0,
              5e-3);
  EXPECT_NEAR(std::abs(digitalResponse(rb, std::sqrt(29.0) + 2.0, dt)), std::numbers::sqrt2 / 2.0,
              5e-3);
  // A constant wheel load passes the low-pass without a start transient.
  std::vector<double> q(500, 5e4);
  applyCascade(lp, q, q);
  for (const double v : q) EXPECT_NEAR(v, 5e4, 1e-6);
}

TEST(Bilinear, PrewarpedFrequencyIsExact) {
  // A 2nd-order low-pass at 100 Hz sampled at 400 Hz: the digital gain at 100 Hz equals the
  // continuous one (1 / (2 zeta) = Q) only with prewarping.
  const double w = 2.0 * std::numbers::pi * 100.0;
  const AnalogSection h{w * w, 0.0, 0.0, w * w, w / 0.63, 1.0};
  Cascade c;
  c.push(bilinear(h, 1.0 / 400.0, 100.0));
  EXPECT_NEAR(std::abs(digitalResponse(c, 100.0, 1.0 / 400.0)), 0.63, 1e-12);
  EXPECT_NEAR(std::abs(analogResponse(h, 100.0)), 0.63, 1e-12);
}

}  // namespace
