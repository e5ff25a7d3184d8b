// 60E1 rail head: arc construction, head width, the head inclined 1:40 against the benchmark file
// MBench_UIC60_v3.prr, gauge point and profile positioning (Table 1, positioning.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "test_util.hpp"
#include "workbench/profiles/dimensions.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/profile_io.hpp"
#include "workbench/profiles/rail60e1.hpp"

namespace {

using namespace rb::profiles;
using rb::profiles::test::projectFile;

const double kCant = std::atan(1.0 / 40.0);

TEST(Rail60E1, ArcConstruction) {
  const Rail60E1Geometry& g = rail60E1Geometry();
  // Derived centres and tangent points of rail_profiles.md.
  EXPECT_NEAR(g.z1, -0.17440, 1e-5);
  EXPECT_NEAR(g.c2y, 7.50053, 1e-5);
  EXPECT_NEAR(g.c2z, -80.12790, 1e-5);
  EXPECT_NEAR(g.z2, -2.30252, 1e-5);
  EXPECT_NEAR(g.c3y, 23.01603, 1e-5);
  EXPECT_NEAR(g.c3z, -14.94915, 1e-5);
  EXPECT_NEAR(g.y3, 35.99981, 1e-5);
  EXPECT_NEAR(g.z3, -14.29996, 1e-5);
  // Tangent continuity at the joints, symmetry.
  for (const double y : {g.y1, g.y2, g.y3}) {
    EXPECT_NEAR(rail60E1Z(y - 1e-9), rail60E1Z(y + 1e-9), 1e-7);  // slope up to 20
    EXPECT_NEAR(rail60E1dZ(y - 1e-9), rail60E1dZ(y + 1e-9), 1e-6);
    EXPECT_EQ(rail60E1Z(-y), rail60E1Z(y));
  }
  EXPECT_EQ(rail60E1Z(0.0), 0.0);
  EXPECT_NEAR(rail60E1dZ(g.y3 + 1.0), -20.0, 1e-12);
}

TEST(Rail60E1, ProfileAndHeadWidth) {
  const Profile p = rail60E1(RailSide::Left);
  EXPECT_EQ(p.kind(), ProfileKind::Rail);
  EXPECT_NEAR(p.sMax(), kRail60E1HalfWidth, 1e-12);
  EXPECT_NEAR(p.sMin(), -kRail60E1HalfWidth, 1e-12);
  EXPECT_NEAR(p.at(0.0).h, 0.0, 1e-15);
  double maxH = 0.0, maxNormal = 0.0;
  for (double y = -36.25; y <= 36.25; y += 0.0013) {
    const ProfilePoint q = p.at(y * 1e-3);
    const double e = std::abs(q.h * 1e3 - rail60E1Z(y));
    maxH = std::max(maxH, e);
    maxNormal = std::max(maxNormal, e / std::sqrt(1.0 + q.dh * q.dh));
  }
  EXPECT_LT(maxNormal, 1e-4);  // mm
  // Curvature bounded: R13 gives 77 1/m; the spline overshoots a little where the curvature jumps
  // to 0 on the 1:20 side.
  double maxCurv = 0.0;
  for (double s = p.sMin(); s <= p.sMax(); s += 1e-6)
    maxCurv = std::max(maxCurv, std::abs(p.curvature(s)));
  EXPECT_LT(maxCurv, 1.3 / 0.013);
  const double width = railHeadWidth(p);
  EXPECT_NEAR(width, 0.072, 0.05e-3);
  std::printf(
      "60E1 Profile (ds %.3f mm): max |h - z| %.1e mm (normal %.1e mm), max curvature "
      "%.1f 1/m, head width %.4f mm\n",
      p.step() * 1e3, maxH, maxNormal, maxCurv, width * 1e3);
}

TEST(Rail60E1, RightRailIsTheExactMirror) {
  const Profile l = rail60E1(RailSide::Left);
  const Profile r = rail60E1(RailSide::Right);
  for (double s = l.sMin(); s <= l.sMax(); s += 0.777e-5) {
    EXPECT_EQ(l.at(s).h, r.at(-s).h);
    EXPECT_EQ(l.at(s).dh, -r.at(-s).dh);
    EXPECT_EQ(l.at(s).d2h, r.at(-s).d2h);
  }
}

// Distance (normal to the profile) of a point given in the rotated frame from the rotated
// profile, or a negative value if the point is outside the profile domain.
double normalDistance(const Profile& p, double angle, double Y, double Z) {
  const double c = std::cos(angle), sn = std::sin(angle);
  const double s = Y * c + Z * sn, h = -Y * sn + Z * c;  // back to the profile frame
  if (!p.inside(s)) return -1.0;
  const ProfilePoint q = p.at(s);
  return std::abs(h - q.h) / std::sqrt(1.0 + q.dh * q.dh);
}

TEST(Rail60E1, InclinedMatchesBenchmarkFile) {
  const Profile p = rail60E1(RailSide::Left);
  const TopPoint top = highestPoint(p, kCant);
  EXPECT_NEAR(top.s, 0.3 * std::sin(kCant), 1e-7);  // 7.5 mm toward the field side
  // File: canted, origin at its highest point, z down (the reader returns z up), gauge side y < 0.
  const ProfilePoints pts = readSimpackPoints(projectFile("profiles/MBench_UIC60_v3.prr"));
  ASSERT_EQ(pts.kind, ProfileKind::Rail);
  double maxDist = 0.0;
  int used = 0;
  for (std::size_t i = 0; i < pts.y.size(); ++i) {
    const double d = normalDistance(p, kCant, pts.y[i] + top.p.y, pts.z[i] + top.p.z);
    if (d < 0.0) continue;
    ++used;
    maxDist = std::max(maxDist, d);
  }
  EXPECT_GT(used, 300);  // the rest lies on the flanks below the head domain
  EXPECT_LT(maxDist, 0.05e-3);
  std::printf(
      "60E1 at 1:40 vs MBench_UIC60_v3.prr: %d of %zu points in the domain, max normal "
      "distance %.4f mm\n",
      used, pts.y.size(), maxDist * 1e3);
  // Right rail at -beta is the mirror image.
  const Profile r = rail60E1(RailSide::Right);
  const TopPoint topR = highestPoint(r, railFrameAngle(RailSide::Right, kCant));
  EXPECT_NEAR(topR.s, -top.s, 1e-9);
  EXPECT_NEAR(topR.p.y, -top.p.y, 1e-9);
  EXPECT_NEAR(topR.p.z, top.p.z, 1e-12);
  const auto pl = rotatedPoints(p, kCant);
  ASSERT_EQ(pl.size(), p.knots().size());
}

TEST(Positioning, GaugePointOf60E1At1in40) {
  const Profile l = rail60E1(RailSide::Left);
  double s = 0.0;
  const PlanePoint gl = gaugePoint(l, RailSide::Left, kCant, kGaugePointDepth, &s);
  EXPECT_LT(gl.y, 0.0);
  EXPECT_NEAR(gl.y, -0.03553, 0.05e-3);
  EXPECT_NEAR(highestPoint(l, kCant).p.z - gl.z, 0.014, 1e-12);
  const Profile r = rail60E1(RailSide::Right);
  const PlanePoint gr = gaugePoint(r, RailSide::Right, -kCant);
  EXPECT_NEAR(gr.y, -gl.y, 1e-9);
  EXPECT_NEAR(rail60E1GaugePointOffset(kCant), -gl.y, 1e-15);
  std::printf(
      "60E1 1:40 gauge point: %.4f mm from the profile origin (s = %.4f mm); paper beta "
      "1/40 rad: %.4f mm\n",
      -gl.y * 1e3, s * 1e3, rail60E1GaugePointOffset(1.0 / 40.0) * 1e3);
}

TEST(Positioning, FromBackToBackAndGauge) {
  const ProfilePositioning pos = positionS1002On60E1(1.360, 1.435, 0.46, kCant);
  EXPECT_NEAR(pos.Lw, 0.750, 0.05e-3);
  EXPECT_NEAR(pos.Lr, 0.7530, 0.05e-3);
  EXPECT_EQ(pos.r0, 0.46);
  EXPECT_EQ(pos.beta, kCant);
  const WheelLandmarks wl = wheelLandmarks(pos, WheelSide::Left);
  const WheelLandmarks wr = wheelLandmarks(pos, WheelSide::Right);
  EXPECT_NEAR(wl.tapeCircleY, 0.750, 1e-12);
  EXPECT_NEAR(wl.flangeBackY, 0.680, 1e-12);
  EXPECT_NEAR(wr.tapeCircleY, -0.750, 1e-12);
  EXPECT_NEAR(wr.flangeBackY, -0.680, 1e-12);
  // The paper's Lw corresponds to B = 1363 mm.
  EXPECT_NEAR(positionS1002On60E1(1.363, 1.435, 0.457, 1.0 / 40.0).Lw, paper_table1::kLw, 1e-12);
  EXPECT_NEAR(positionProfiles(1.36, 1.435, 0.46, kCant, 0.07, 0.03553).Lr, 0.75303, 1e-12);
  std::printf("S1002 on 60E1 1:40, B 1360, G 1435: Lw %.5f m, Lr %.5f m\n", pos.Lw, pos.Lr);
}

TEST(Positioning, PaperTable1Constants) {
  EXPECT_EQ(paper_table1::kPositioning.Lw, 0.7515);
  EXPECT_EQ(paper_table1::kPositioning.Lr, 0.7555);
  EXPECT_EQ(paper_table1::kPositioning.r0, 0.457);
  EXPECT_EQ(paper_table1::kPositioning.beta, 1.0 / 40.0);
  EXPECT_EQ(kS1002FlangeBackS, -kS1002FlangeBackDistance);
  EXPECT_EQ(kS1002TapeCircleS, 0.0);
}

}  // namespace

namespace {

// The inclination a rail profile is drawn with, from the symmetry of its head: the upright 60E1
// gives 0, the benchmark file (drawn at 1:40) its 1:40, and 60E1 drawn at any cant that cant.
TEST(RailInclination, DrawnInclinationFromTheHeadSymmetry) {
  const auto upright = drawnInclination(rail60E1(RailSide::Left));
  ASSERT_TRUE(upright.has_value());
  EXPECT_NEAR(*upright, 0.0, 1e-4);
  const Profile file = readSimpackProfile(projectFile("profiles/MBench_UIC60_v3.prr"));
  const auto canted = drawnInclination(file);
  ASSERT_TRUE(canted.has_value());
  EXPECT_NEAR(*canted, kCant, 1e-3);
  std::printf("drawn inclination: 60E1 %.6f rad, MBench_UIC60_v3.prr %.6f rad (1:%.2f)\n", *upright,
              *canted, 1.0 / std::tan(*canted));
}

}  // namespace
