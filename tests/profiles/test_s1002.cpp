// S1002 wheel: analytic sections, smoothing, Profile accuracy against the benchmark file, nominal
// dimensions, left/right mirror.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "test_util.hpp"
#include "workbench/profiles/dimensions.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/profile_io.hpp"
#include "workbench/profiles/s1002.hpp"

namespace {

using namespace rb::profiles;
using rb::profiles::test::projectFile;

constexpr double kR0 = 0.46;

TEST(S1002, SectionsAndPublishedValues) {
  EXPECT_NEAR(s1002F(0.0), 0.0, 1e-12);
  EXPECT_NEAR(s1002F(-55.0), 28.0, 1e-9);  // flange tip
  EXPECT_NEAR(s1002F(-70.0), 9.519259302, 1e-9);
  EXPECT_EQ(s1002Section(40.0), S1002Section::A);
  EXPECT_EQ(s1002Section(0.0), S1002Section::B);
  EXPECT_EQ(s1002Section(-30.0), S1002Section::C);
  EXPECT_EQ(s1002Section(-36.0), S1002Section::D);
  EXPECT_EQ(s1002Section(-39.0), S1002Section::E);
  EXPECT_EQ(s1002Section(-45.0), S1002Section::F);
  EXPECT_EQ(s1002Section(-55.0), S1002Section::G);
  EXPECT_EQ(s1002Section(-65.0), S1002Section::H);
  // The published joints (reference continuity table): value jumps only at D/C and C/B.
  const S1002Section order[] = {S1002Section::A, S1002Section::B, S1002Section::C, S1002Section::D,
                                S1002Section::E, S1002Section::F, S1002Section::G, S1002Section::H};
  for (int j = 0; j < 7; ++j) {
    const double S = kS1002BreaksMm[j];
    const double jump = s1002SectionF(order[j + 1], S) - s1002SectionF(order[j], S);
    const double slopeJump = s1002SectionDF(order[j + 1], S) - s1002SectionDF(order[j], S);
    const double tol = (j == 1 || j == 2) ? 1.3e-4 : 1e-6;
    EXPECT_LT(std::abs(jump), tol) << "joint at S = " << S;
    EXPECT_LT(std::abs(slopeJump), 5e-5) << "joint at S = " << S;
  }
  EXPECT_NEAR(s1002SectionF(S1002Section::D, -35.0) - s1002SectionF(S1002Section::C, -35.0),
              6.867504 - 6.867385, 2e-6);
  // Derivative against central differences away from the joints.
  for (double S = -69.0; S <= 59.0; S += 0.37) {
    const double h = 1e-5;
    const double fd = (s1002F(S + h) - s1002F(S - h)) / (2 * h);
    EXPECT_NEAR(s1002dF(S), fd, 1e-5 * (1.0 + std::abs(fd))) << S;
  }
}

TEST(S1002, SmoothingStaysWithinThePublishedJumps) {
  double maxDev = 0.0;
  for (double S = -69.6; S <= 60.0; S += 0.001)
    maxDev = std::max(maxDev, std::abs(s1002FSmooth(S) - s1002F(S)));
  EXPECT_LT(maxDev, 1.3e-4);
  // Continuous value and slope across the former jumps.
  for (const double Sj : {-35.0, -26.0}) {
    const double e = 1e-9;
    EXPECT_NEAR(s1002FSmooth(Sj - e), s1002FSmooth(Sj + e), 1e-8);
    EXPECT_NEAR(s1002dFSmooth(Sj - e), s1002dFSmooth(Sj + e), 1e-7);
  }
  std::printf("S1002 smoothing: max |F_smooth - F| = %.2e mm\n", maxDev);
}

TEST(S1002, ProfileMatchesBenchmarkFile) {
  const Profile p = s1002Wheel(kR0, WheelSide::Left);
  EXPECT_EQ(p.kind(), ProfileKind::Wheel);
  EXPECT_NEAR(p.sMin(), kS1002ProfileSMin, 1e-12);
  EXPECT_NEAR(p.sMax(), kS1002ProfileSMax, 1e-12);
  // The file's points: y_prw = -S (mirror.y = 1 makes the reader return s = S), z = F.
  const ProfilePoints pts = readSimpackPoints(projectFile("profiles/MBench_S1002_v3.prw"));
  ASSERT_EQ(pts.kind, ProfileKind::Wheel);
  ASSERT_EQ(pts.y.size(), 399u);
  double maxProfile = 0.0, maxExact = 0.0;
  for (std::size_t i = 0; i < pts.y.size(); ++i) {
    const double s = pts.y[i];
    ASSERT_TRUE(p.inside(s)) << s;
    maxProfile = std::max(maxProfile, std::abs(p.at(s).h - kR0 - pts.z[i]));
    maxExact = std::max(maxExact, std::abs(1e-3 * s1002F(1e3 * s) - pts.z[i]));
  }
  EXPECT_LT(maxProfile, 1e-6);  // 1e-3 mm
  EXPECT_LT(maxExact, 1e-8);
  std::printf("S1002 vs MBench_S1002_v3.prw (399 points): Profile %.2e mm, exact formula %.2e mm\n",
              maxProfile * 1e3, maxExact * 1e3);
}

TEST(S1002, ProfileSplineFollowsTheFunction) {
  const Profile p = s1002Wheel(kR0, WheelSide::Left);
  double maxH = 0.0, maxSlope = 0.0, maxCurv = 0.0;
  for (double S = -69.62; S <= 60.0; S += 0.0031) {
    const ProfilePoint q = p.at(S * 1e-3);
    maxH = std::max(maxH, std::abs((q.h - kR0) * 1e3 - s1002FSmooth(S)));
    maxSlope = std::max(maxSlope, std::abs(q.dh - s1002dFSmooth(S)));
    maxCurv = std::max(maxCurv, std::abs(p.curvature(S * 1e-3)));
  }
  EXPECT_LT(maxH, 1e-4);      // mm
  EXPECT_LT(maxSlope, 5e-3);  // largest at the curvature jumps (arc/line joints)
  // Curvature bounded by the tightest arc (R12 flange tip, 83 1/m) plus spline overshoot at the
  // designed curvature jumps.
  EXPECT_LT(maxCurv, 1.3 / 0.012);
  std::printf(
      "S1002 Profile (ds %.3f mm): |h - F| %.1e mm, |h' - F'| %.1e, max curvature %.1f 1/m\n",
      p.step() * 1e3, maxH, maxSlope, maxCurv);
}

TEST(S1002, NominalDimensionsFromTheProfile) {
  for (const WheelSide side : {WheelSide::Left, WheelSide::Right}) {
    const Profile p = s1002Wheel(kR0, side);
    const WheelDimensions d = wheelDimensions(p, kS1002FlangeBackDistance);
    EXPECT_NEAR(d.flangeHeight, 0.028, 0.05e-3);
    EXPECT_NEAR(d.flangeThickness, 0.0325, 0.05e-3);
    EXPECT_NEAR(d.qR, 0.0108, 0.05e-3);
    EXPECT_NEAR(std::abs(d.flangeTipS), 0.055, 1e-6);
    EXPECT_EQ(d.flangeTipS < 0.0, side == WheelSide::Left);
    EXPECT_NEAR(flangeHeight(p), d.flangeHeight, 1e-15);
    EXPECT_NEAR(flangeThickness(p), d.flangeThickness, 1e-15);
    EXPECT_NEAR(flangeQR(p), d.qR, 1e-15);
    if (side == WheelSide::Left) {
      std::printf("S1002: Sh %.4f mm, Sd %.4f mm, qR %.4f mm\n", d.flangeHeight * 1e3,
                  d.flangeThickness * 1e3, d.qR * 1e3);
    }
  }
}

TEST(S1002, RightWheelIsTheExactMirror) {
  const Profile l = s1002Wheel(kR0, WheelSide::Left);
  const Profile r = s1002Wheel(kR0, WheelSide::Right);
  EXPECT_EQ(r.sMin(), -l.sMax());
  EXPECT_EQ(r.sMax(), -l.sMin());
  for (double s = l.sMin(); s <= l.sMax(); s += 1.234567e-5) {
    const ProfilePoint a = l.at(s), b = r.at(-s);
    EXPECT_EQ(a.h, b.h);
    EXPECT_EQ(a.dh, -b.dh);
    EXPECT_EQ(a.d2h, b.d2h);
  }
  const auto kl = l.knots(), kr = r.knots();
  const auto vl = l.values(), vr = r.values();
  ASSERT_EQ(kl.size(), kr.size());
  for (std::size_t i = 0; i < kl.size(); ++i) {
    EXPECT_EQ(kr[i], -kl[kl.size() - 1 - i]);
    EXPECT_EQ(vr[i], vl[vl.size() - 1 - i]);
  }
  EXPECT_EQ(r.mirrored().at(0.01).h, l.at(0.01).h);
  EXPECT_EQ(r.name(), "S1002 right wheel");
}

// Profile::at takes h, h', h'' from one interval lookup: exactly the values of a CubicSpline on
// the same samples (and the exact mirror image), also outside the grid.
TEST(Profile, AtEqualsTheCubicSplineBitForBit) {
  std::vector<double> h;
  const double s0 = -0.07, ds = 1e-4;
  for (int i = 0; i < 1401; ++i) {
    const double s = s0 + ds * i;
    h.push_back(0.46 + 0.02 * std::sin(40.0 * s) + 3.0 * s * s);
  }
  const Profile p("test", ProfileKind::Wheel, s0, ds, h);
  const Profile m = p.mirrored();
  const rb::CubicSpline ref(rb::SplineGrid::uniform(s0, ds, h.size()), h);
  for (int i = -20; i <= 1420; ++i) {
    const double s = s0 + ds * (i + 0.37);
    const ProfilePoint a = p.at(s);
    EXPECT_EQ(a.h, ref.value(s));
    EXPECT_EQ(a.dh, ref.deriv1(s));
    EXPECT_EQ(a.d2h, ref.deriv2(s));
    const ProfilePoint b = m.at(-s);
    EXPECT_EQ(b.h, a.h);
    EXPECT_EQ(b.dh, -a.dh);
    EXPECT_EQ(b.d2h, a.d2h);
  }
  EXPECT_EQ(p.values().front(), h.front());
}

}  // namespace
