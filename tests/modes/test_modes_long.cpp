// The linear critical speed of the Manchester wagon (workbench/stability) against the primary
// longitudinal (yaw) stiffness, KEC and LUT: a sweep and a refinement per stiffness (long).
#include "tests/modes/modes_fixture.hpp"

using namespace rb;
using namespace rb::modes_test;

// The linear critical speed exists between 20 and 120 m/s and rises with the primary
// longitudinal (yaw) stiffness, for KEC and LUT.
class CriticalSpeedVsKpx : public ::testing::TestWithParam<std::string> {};

TEST_P(CriticalSpeedVsKpx, RisesWithStiffness) {
  double last = 0.0;
  for (const double kpx : {10e6, 31391e3, 60e6}) {
    const stability::CriticalSpeed c =
        stability::linearCriticalSpeed(wagonWithKpx(GetParam(), kpx), 20.0, 120.0, 6, {}, 0.2);
    ASSERT_TRUE(c.found) << GetParam() << " Kpx " << kpx << ": " << c.why;
    EXPECT_GT(c.speed, 20.0);
    EXPECT_LT(c.speed, 120.0);
    EXPECT_GT(c.speed, last) << GetParam() << " Kpx " << kpx;
    last = c.speed;
  }
}

INSTANTIATE_TEST_SUITE_P(Contact, CriticalSpeedVsKpx, ::testing::Values("kec", "lut"));
