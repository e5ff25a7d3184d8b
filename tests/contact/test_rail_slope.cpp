// The elastic search over a rail that rises or moves sideways along the track (rail_slope.hpp),
// against a brute-force minimisation of the exact 3-D gap between the wheel (a surface of
// revolution) and the rail as it lies: its slices translated by (y_s, z_s) x per unit x along the
// track. docs/sliced_rails.md, "Slope along the track".
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "workbench/contact/elastic_search.hpp"
#include "workbench/contact/rail_slope.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/profile_io.hpp"

namespace {

using namespace rb::contact;
using rb::profiles::Profile;

std::string sourceFile(const std::string& rel) {
  return std::string(RB_SOURCE_DIR) + "/" + rel;
}

// The Manchester benchmark's S1002 (r0 = 460 mm) and UIC60 (drawn canted: beta = 0), right wheel.
WheelRailPair rightPair() {
  rb::profiles::ProfileReadOptions wo;
  wo.r0 = 0.46;
  auto wheel = std::make_shared<const Profile>(
      rb::profiles::readSimpackProfile(sourceFile("profiles/MBench_S1002_v3.prw"), wo));
  auto rail = std::make_shared<const Profile>(
      rb::profiles::readSimpackProfile(sourceFile("profiles/MBench_UIC60_v3.prr")));
  WheelRailPair p;
  p.side = Side::Right;
  p.wheel = std::make_shared<const Profile>(wheel->mirrored());
  p.rail = std::make_shared<const Profile>(rail->mirrored());
  p.wheel_lw = 0.750;
  // Gauge 1435 mm measured 14 mm below the rail top, as in the benchmark.
  p.rail_lr = 0.5 * 1.435 +
              std::abs(rb::profiles::gaugePoint(*rail, rb::profiles::Side::Left, 0.0, 0.014).y);
  p.beta = 0.0;
  return p;
}

const ElasticContactSearch& search() {
  static const ElasticContactSearch s(rightPair());
  return s;
}

using Vec3 = std::array<double, 3>;

// Wheel point at (s_w, theta) of the pose (EulerOrder::RollYaw), track frame.
Vec3 wheelPoint(const ElasticContactSearch& s, const ElasticPose& p, double s_w, double theta) {
  const double h = s.pair().wheel->at(s_w).h;
  const double L = s.sigma() * s.pair().wheel_lw + s_w;
  const Vec3 X{h * std::sin(theta), L, -h * std::cos(theta)};
  const double cps = std::cos(p.psi), sps = std::sin(p.psi);
  const double cph = std::cos(p.phi), sph = std::sin(p.phi);
  const double R[3][3] = {
      {cps, -sps, 0.0}, {cph * sps, cph * cps, -sph}, {sph * sps, sph * cps, cph}};
  Vec3 w{0.0, p.y, p.z};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      w[static_cast<std::size_t>(i)] += R[i][j] * X[static_cast<std::size_t>(j)];
  return w;
}

// Height of the rail as it lies below track point (x, y): its slice (beta = 0: y = sigma Lr + u,
// z = h(u)) translated by (y_s x, z_s x).
double railHeight(const ElasticContactSearch& s, const RailSlope& sl, double x, double y) {
  const double u = y - s.sigma() * s.pair().rail_lr - sl.y_s * x;
  return s.pair().rail->at(u).h + sl.z_s * x;
}

// Golden-section minimum of f over [a, b].
double golden(const std::function<double(double)>& f, double a, double b, double& xmin) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(c), fd = f(d);
  for (int i = 0; i < 80; ++i) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = f(d);
    }
  }
  xmin = 0.5 * (a + b);
  return f(xmin);
}

// The lowest point of wheel circle s_w relative to the rail below it (over theta): its vertical
// penetration (> 0) and the wheel point.
double circlePenetration(const ElasticContactSearch& s, const ElasticPose& p, const RailSlope& sl,
                         double s_w, Vec3& at) {
  double th = 0.0;
  const double e = golden(
      [&](double theta) {
        const Vec3 w = wheelPoint(s, p, s_w, theta);
        return w[2] - railHeight(s, sl, w[0], w[1]);
      },
      -0.6, 0.6, th);
  at = wheelPoint(s, p, s_w, th);
  return -e;
}

// The deepest vertical penetration over the wheel circles within 3 mm of s_w0.
double deepestPenetration(const ElasticContactSearch& s, const ElasticPose& p, const RailSlope& sl,
                          double s_w0) {
  Vec3 w{};
  double sw = 0.0;
  return -golden([&](double s_w) { return -circlePenetration(s, p, sl, s_w, w); }, s_w0 - 3e-3,
                 s_w0 + 3e-3, sw);
}

// The height at which the sloped search's deepest patch penetrates by `delta`.
ElasticPose poseAt(const ElasticPose& p0, const RailSlope& sl, double delta) {
  ElasticPose p = p0;
  ElasticWheelGeometry g;
  ElasticSearchWorkspace a;
  SlopedSearchWorkspace b;
  double lo = p0.z - 0.01, hi = p0.z + 0.01;
  for (int i = 0; i < 80; ++i) {
    p.z = 0.5 * (lo + hi);
    searchSlopedRail(search(), p, sl, g, a, b);
    ((g.count > 0 ? g.patch[0].gap_depth : -1.0) > delta ? lo : hi) = p.z;
  }
  return p;
}

TEST(RailSlope, WithoutSlopeItIsThePlainSearch) {
  ElasticSearchWorkspace a, c;
  SlopedSearchWorkspace b;
  ElasticWheelGeometry g1, g2;
  const ElasticPose p{-0.002, 0.46, 0.001, 0.004};
  searchSlopedRail(search(), p, RailSlope{}, g1, a, b);
  search().search(p, g2, c);
  ASSERT_EQ(g1.count, g2.count);
  ASSERT_GT(g1.count, 0);
  for (int k = 0; k < g1.count; ++k) {
    const auto& x = g1.patch[static_cast<std::size_t>(k)];
    const auto& y = g2.patch[static_cast<std::size_t>(k)];
    EXPECT_EQ(std::bit_cast<std::uint64_t>(x.gap_depth), std::bit_cast<std::uint64_t>(y.gap_depth));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(x.x), std::bit_cast<std::uint64_t>(y.x));
    EXPECT_EQ(x.n_x, 0.0);
  }
  EXPECT_EQ(b.second.searches, 0u);
  EXPECT_EQ(b.further.searches, 0u);
}

// Rails rising at 1:10 (a crossing nose), moving sideways at 1:10 (a wing rail), both, with the
// wheelset displaced, rolled and yawed: the penetration equals the brute-force one within 0.2 um
// (the neglected slope would make it 2.3 mm too small at 1:10), the contact point within 0.05 mm
// along the track (it leads the wheel centre by about r z_s = 46 mm on the rising rail), and the
// wheel point of (x_w, theta) lies on the rail normal through the contact at depth delta.
TEST(RailSlope, SearchEqualsTheBruteForceGapOfTheSlopedRail) {
  const ElasticContactSearch& s = search();
  struct Case {
    RailSlope slope;
    ElasticPose pose;
  };
  const Case cases[] = {
      {{0.0, 0.1, 0.0}, {0.0, 0.46, 0.0, 0.0}},
      {{0.0, -0.1, 0.0}, {0.001, 0.46, 0.0, 0.0}},
      {{0.1, 0.0, 0.0}, {0.0, 0.46, 0.0, 0.0}},
      {{-0.05, 0.0, 0.0}, {-0.002, 0.46, 0.0, 0.003}},
      {{0.06, 0.08, 0.0}, {0.002, 0.46, 0.002, -0.006}},
      {{0.0, 0.02, 0.0}, {0.0, 0.46, -0.001, 0.002}},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE("y_s " + std::to_string(k.slope.y_s) + ", z_s " + std::to_string(k.slope.z_s));
    const double delta = 50e-6;
    const ElasticPose p = poseAt(k.pose, k.slope, delta);
    ElasticWheelGeometry g;
    ElasticSearchWorkspace a;
    SlopedSearchWorkspace b;
    searchSlopedRail(s, p, k.slope, g, a, b);
    ASSERT_GE(g.count, 1);
    const ElasticPatchGeometry& c = g.patch[0];
    EXPECT_NEAR(c.gap_depth, delta, 1e-9);
    // The normal is a unit vector perpendicular to the rail's direction (1, y_s, z_s).
    EXPECT_NEAR(std::hypot(c.n_x, c.n_y, c.n_z), 1.0, 1e-12);
    EXPECT_NEAR(c.n_x + k.slope.y_s * c.n_y + k.slope.z_s * c.n_z, 0.0, 1e-12);
    // Vertical penetration times n_z is the normal one (to first order in delta times curvature):
    // on the search's wheel circle, where the same circle's lowest point over the rail as it lies
    // is the contact point, and over the neighbouring circles (on a conformal tread the deepest
    // circle is ill-defined within tenths of a millimetre, its depth is not).
    Vec3 w{};
    const double pen = circlePenetration(s, p, k.slope, c.s_w, w);
    EXPECT_NEAR(pen * c.n_z, c.gap_depth, 0.2e-6);
    EXPECT_NEAR(deepestPenetration(s, p, k.slope, c.s_w) * c.n_z, c.gap_depth, 0.2e-6);
    EXPECT_NEAR(w[0], c.x, 0.05e-3);
    EXPECT_NEAR(w[1], c.y, 0.05e-3);
    // (x_w, theta) on the wheelset's own wheel: the wheel point is at the rail point minus delta n.
    const Vec3 wp = wheelPoint(s, p, c.s_w, c.theta);
    EXPECT_NEAR(c.x_w, c.radius * std::sin(c.theta), 1e-12);
    EXPECT_NEAR(wp[0], c.x - c.gap_depth * c.n_x, 1e-7);
    EXPECT_NEAR(wp[1], c.y - c.gap_depth * c.n_y, 1e-7);
    EXPECT_NEAR(wp[2], c.z - c.gap_depth * c.n_z, 1e-7);
    if (k.slope.z_s != 0.0 && k.slope.y_s == 0.0 && k.pose.psi == 0.0) {
      EXPECT_NEAR(c.x, c.radius * std::sin(std::atan(k.slope.z_s)), 0.5e-3);
    }
  }
}

// A rail whose heights rise along the track by blending two slices (the second 1 mm higher,
// 10 mm further: 1:10) is the same rail as the first slice rising by an offset dz at 1:10: the
// blend's own slope at the contact pitches the search as the offsets' slope does (the two first
// searches pivot at different points, so the results agree to second order in the pivots'
// distance times the slope).
TEST(RailSlope, ABlendedRiseIsTheSameRiseAsAnOffsetSlope) {
  const WheelRailPair plain = rightPair();
  const Profile left = plain.rail->mirrored();  // the file's left rail
  std::vector<double> h = left.values();
  for (double& v : h) v += 1e-3;
  WheelRailPair blended = plain;
  blended.rail_next = std::make_shared<const Profile>(
      Profile("raised", rb::profiles::ProfileKind::Rail, left.sMin(), left.step(), h).mirrored());
  const ElasticContactSearch sb(blended);
  for (const ElasticPose& p0 :
       {ElasticPose{0.0, 0.46, 0.0, 0.0}, ElasticPose{0.003, 0.46, 0.0, 0.002},
        ElasticPose{-0.004, 0.46, 0.001, -0.003}}) {
    const RailSlope offset{0.0, 0.1, 0.0};
    const ElasticPose p = poseAt(p0, offset, 50e-6);
    ElasticWheelGeometry a, b;
    ElasticSearchWorkspace w1, w3;
    SlopedSearchWorkspace w2, w4;
    searchSlopedRail(search(), p, offset, a, w1, w2);
    searchSlopedRail(sb, p, RailSlope{0.0, 0.0, 1.0 / 0.01}, b, w3, w4);
    ASSERT_GE(a.count, 1);
    ASSERT_GE(b.count, 1);
    const ElasticPatchGeometry& x = a.patch[0];
    const ElasticPatchGeometry& y = b.patch[0];
    EXPECT_NEAR(x.gap_depth, y.gap_depth, 1e-8);
    EXPECT_NEAR(x.x, y.x, 1e-6);
    EXPECT_NEAR(x.y, y.y, 1e-6);
    EXPECT_NEAR(x.z, y.z, 1e-7);
    EXPECT_NEAR(x.n_x, y.n_x, 1e-9);
  }
}

}  // namespace
