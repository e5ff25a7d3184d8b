// EN 12299 weightings and comfort indices (workbench/assessment/en12299.hpp): the digital
// weighting filters against the continuous transfer functions, hand values of the continuous
// weightings, N_MV and N_c of synthetic sines.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "workbench/assessment/en12299.hpp"

namespace {

using namespace rb::assessment;
using namespace rb::assessment::en12299;

std::vector<double> sine(double amplitude, double f, double dt, double duration) {
  std::vector<double> a(static_cast<std::size_t>(std::lround(duration / dt)));
  for (std::size_t i = 0; i < a.size(); ++i) {
    a[i] = amplitude * std::sin(2.0 * std::numbers::pi * f * dt * static_cast<double>(i));
  }
  return a;
}

class WeightingGain : public ::testing::TestWithParam<Weighting> {};

TEST_P(WeightingGain, DigitalMatchesContinuousBelowTenthOfSampling) {
  const Weighting w = GetParam();
  const double dt = 1e-3;  // fs = 1000 Hz; test frequencies up to fs / 20
  for (const double f : {0.3, 1.0, 4.0, 12.0, 50.0}) {
    const double analog = std::abs(response(w, f));
    const double digital = std::abs(digitalResponse(weightingFilter(w, dt), f, dt));
    EXPECT_NEAR(digital / analog, 1.0, 0.01) << "f = " << f << " Hz";
  }
  // At fs = 200 Hz (the band-limiting low-pass left out): within 1 % up to fs / 20; at fs / 10
  // the bilinear transform's frequency warping (tan(pi / 10) / (pi / 10) = 1.034) costs up to
  // 3.5 % on the transition's falling slope.
  for (const double f : {0.5, 2.0, 5.0, 10.0}) {
    const double analog = std::abs(response(w, f));
    const double digital = std::abs(digitalResponse(weightingFilter(w, 5e-3), f, 5e-3));
    EXPECT_NEAR(digital / analog, 1.0, 0.01) << "f = " << f << " Hz at 200 Hz";
  }
  const double at_tenth = std::abs(digitalResponse(weightingFilter(w, 5e-3), 20.0, 5e-3));
  EXPECT_NEAR(at_tenth / std::abs(response(w, 20.0)), 1.0, 0.035);
}

INSTANTIATE_TEST_SUITE_P(EN12299, WeightingGain,
                         ::testing::Values(Weighting::Wb, Weighting::Wc, Weighting::Wd));

TEST(Weighting, HandValuesOfTheContinuousWeightings) {
  // Wd at 1 Hz: |H_h| = 1/sqrt(1 + 0.4^4) = 0.987358 (Butterworth), |H_l| = 1.000000,
  // |H_t| = |1 + 0.5 j| / |1 - 0.25 + j 0.5/0.63| = 1.118034 / 1.091537 = 1.024275:
  // 0.987358 * 1.024275 = 1.011328 (to 1e-4: H_l at 1 Hz is 1 - 5e-9).
  EXPECT_NEAR(std::abs(response(Weighting::Wd, 1.0)), 1.0110, 2e-4);
  // Wb: static gain of the step K = 0.4, high-frequency gain K (f6/f5)^2 = 1.024; at 1 Hz
  // 0.391077 (|H_s(1 Hz)| = 0.4 * 0.98 and the transition still near 1).
  EXPECT_NEAR(std::abs(response(Weighting::Wb, 1.0)), 0.391077, 1e-5);
  EXPECT_NEAR(std::abs(response(Weighting::Wb, 4.0)), 0.821789, 1e-5);
  EXPECT_NEAR(std::abs(response(Weighting::Wc, 4.0)), 1.023824, 1e-5);
}

TEST(MeanComfort, LateralSineAgainstHandValue) {
  const double dt = 1e-3;
  const std::vector<double> zero(300000, 0.0);
  const std::vector<double> ay = sine(1.0, 1.0, dt, 300.0);  // 5 minutes: 60 blocks
  const MeanComfort m = meanComfort(zero, ay, zero, dt);
  // 5 s rms of the weighted sine = |Wd(1 Hz)| / sqrt(2) = 1.011017 / 1.414214 = 0.714897;
  // N_MV = 6 * 0.714897 = 4.289381.
  EXPECT_EQ(m.blocks, 60U);
  EXPECT_NEAR(m.a_y95, 0.714897, 2e-3);
  EXPECT_NEAR(m.check.value, 4.289381, 1e-2);
  EXPECT_FALSE(m.check.ok());  // above the "comfortable" bound 2
  EXPECT_STREQ(comfortClass(m.check.value), "uncomfortable");
}

TEST(MeanComfort, TwoAxesCombine) {
  const double dt = 2e-3;
  const std::vector<double> zero(150000, 0.0);
  const std::vector<double> ay = sine(1.0, 1.0, dt, 300.0);
  const std::vector<double> az = sine(0.5, 4.0, dt, 300.0);
  const MeanComfort m = meanComfort(zero, ay, az, dt);
  // a_z95 = 0.5 |Wb(4 Hz)| / sqrt(2) = 0.5 * 0.821789 / 1.414214 = 0.290546;
  // N_MV = 6 sqrt(0.714897^2 + 0.290546^2) = 4.630098.
  EXPECT_NEAR(m.a_z95, 0.290546, 2e-3);
  EXPECT_NEAR(m.check.value, 4.630098, 1.5e-2);
}

TEST(ContinuousComfort, SteadySine) {
  const double dt = 1e-3;
  const std::vector<double> ay = sine(0.2, 1.0, dt, 20.0);
  const std::vector<double> n = continuousComfort(ay, Axis::Y, dt);
  // 4 * 0.2 * 0.714897 = 0.571918 once 5 s of steady signal are in the window.
  EXPECT_NEAR(n.back(), 0.571918, 2e-3);
}

TEST(ComfortScale, Classes) {
  EXPECT_STREQ(comfortClass(0.5), "very comfortable");
  EXPECT_STREQ(comfortClass(1.5), "comfortable");
  EXPECT_STREQ(comfortClass(3.0), "medium");
  EXPECT_STREQ(comfortClass(5.0), "very uncomfortable");
}

}  // namespace
