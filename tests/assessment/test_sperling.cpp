// Sperling's Wz (workbench/assessment/sperling.hpp): the weighting's hand values, the digital
// weighting filter against it, and Wz of pure sines against the harmonic formula.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "workbench/assessment/sperling.hpp"

namespace {

using namespace rb::assessment;
using namespace rb::assessment::sperling;

TEST(Sperling, WeightingHandValues) {
  // f = 1 Hz: num = 1.911 + 0.0625 = 1.9735; den = 0.723^2 + 1.5262^2 = 0.522729 + 2.329286
  // = 2.852015; B = 0.588 sqrt(0.691969) = 0.489125.
  EXPECT_NEAR(weighting(1.0, Direction::Vertical), 0.489125, 1e-6);
  // f = 2 Hz: num = 7.644 + 1 = 8.644; den = 0.108^2 + 2.8316^2 = 0.011664 + 8.017959
  // = 8.029623; B = 0.588 sqrt(1.076512) = 0.610080.
  EXPECT_NEAR(weighting(2.0, Direction::Vertical), 0.610080, 1e-6);
  EXPECT_NEAR(weighting(2.0, Direction::Lateral), 1.25 * 0.610080, 1e-6);
}

TEST(Sperling, DigitalFilterFollowsTheWeighting) {
  const double dt = 1e-3;
  for (const double f : {0.5, 1.0, 3.0, 6.0, 15.0, 40.0}) {
    const double digital =
        std::abs(digitalResponse(weightingFilter(Direction::Vertical, dt), f, dt));
    EXPECT_NEAR(digital / weighting(f, Direction::Vertical), 1.0, 0.01) << "f = " << f;
  }
}

TEST(Sperling, PureSineAgainstHandValue) {
  // 0.5 m/s^2 = 50 cm/s^2 at 2 Hz, vertical: Wz = (50 * 0.610080)^0.3 = 30.504^0.3 = 2.788092.
  EXPECT_NEAR(indexOfHarmonic(0.5, 2.0, Direction::Vertical), 2.788092, 1e-5);
  const double dt = 1e-3;
  std::vector<double> a(60000);  // 60 s, a whole number of periods
  for (std::size_t i = 0; i < a.size(); ++i) {
    a[i] = 0.5 * std::sin(2.0 * std::numbers::pi * 2.0 * dt * static_cast<double>(i));
  }
  const Check wz = index(a, dt, Direction::Vertical);
  EXPECT_NEAR(wz.value, 2.788092, 0.01);
  EXPECT_FALSE(wz.ok());  // above the customary 2.5
  // Lateral: (62.5 * 0.610080)^0.3 = 2.981125.
  EXPECT_NEAR(index(a, dt, Direction::Lateral).value, 2.981125, 0.01);
}

}  // namespace
