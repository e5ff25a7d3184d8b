// A rail that changes along the track (sliced_rail.hpp): the search on the blend of two slices is
// the search on the profile made of the blended heights (the not-a-knot spline is linear in its
// data, so the two are the same surface to rounding); identical slices are the prismatic rail bit
// for bit; the rail's rise per unit of blend is the derivative of the approach; the pieces along
// the track. docs/sliced_rails.md.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "contact_test_util.hpp"
#include "workbench/contact/sliced_rail.hpp"
#include "workbench/core/error.hpp"

namespace {

using rb::contact::ElasticContactSearch;
using rb::contact::ElasticPose;
using rb::contact::ElasticSearchWorkspace;
using rb::contact::ElasticWheelGeometry;
using rb::contact::RailSlice;
using rb::contact::SlicedRailSearch;
using rb::contact::WheelRailPair;
using rb::profiles::Profile;
using rb::profiles::ProfileKind;

// The 60E1 head with its heights changed by f(u), on the same grid.
std::shared_ptr<const Profile> changed(const Profile& a, double (*f)(double)) {
  std::vector<double> h;
  for (double u : a.knots()) h.push_back(a.at(u).h + f(u));
  return std::make_shared<const Profile>("changed", ProfileKind::Rail, a.sMin(), a.step(), h);
}

// Lowered by 1 mm, tilted by 1:50 and with its crown radius changed (h'' - 16 1/m): a rail whose
// height, cant and curvature all differ from 60E1's.
double ground(double u) {
  return -1e-3 + 0.02 * u - 8.0 * u * u;
}

// The left wheel over the left rail of S1002 on 60E1 at 1:40.
WheelRailPair leftPair() {
  return rb::contact::wheelRailPairs(rbtest::s1002On60E1())[0];
}

// Lateral positions, yaw angles and sinks below the first touch (in z, touchHeight adds it).
std::vector<ElasticPose> poses() {
  std::vector<ElasticPose> out;
  for (double y : {-6e-3, -2e-3, 0.0, 3e-3, 6.5e-3, 8e-3})
    for (double psi : {0.0, 4e-3})
      for (double dz : {-2e-4, -5e-5}) out.push_back({y, dz, 0.0, psi});  // z: the sink
  return out;
}

// The axle height at which the wheel first touches the rail at the pose's y, angles and blend.
// (min_gap is the normal gap: a few steps down to it.)
double touchHeight(const ElasticContactSearch& s, ElasticPose p) {
  p.z = 0.46;
  for (int it = 0; it < 6; ++it) {
    const double m = s.search(p).min_gap;
    if (std::isfinite(m)) p.z -= m;
  }
  return p.z;
}

TEST(SlicedRail, TheBlendIsTheRailOfTheBlendedHeights) {
  const WheelRailPair base = leftPair();
  const auto a = base.rail;
  const auto b = changed(*a, ground);
  WheelRailPair blended = base;
  blended.rail_next = b;
  const ElasticContactSearch sb(blended);
  for (double w : {0.0, 0.3, 0.7, 1.0}) {
    std::vector<double> h;
    for (double u : a->knots()) h.push_back(a->at(u).h + w * (b->at(u).h - a->at(u).h));
    WheelRailPair explicit_pair = base;
    explicit_pair.rail =
        std::make_shared<const Profile>("blend", ProfileKind::Rail, a->sMin(), a->step(), h);
    const ElasticContactSearch se(explicit_pair);
    ElasticSearchWorkspace ws;  // one workspace along the poses: certificates must not leak
    int patches = 0;
    for (ElasticPose p : poses()) {
      p.z += touchHeight(se, p);
      ElasticPose q = p;
      q.blend = w;
      ElasticWheelGeometry g;
      sb.search(q, g, ws);
      const ElasticWheelGeometry e = se.search(p);
      ASSERT_EQ(g.count, e.count) << "w = " << w << ", y = " << p.y;
      for (int k = 0; k < g.count; ++k) {
        const auto& x = g.patch[static_cast<std::size_t>(k)];
        const auto& r = e.patch[static_cast<std::size_t>(k)];
        EXPECT_NEAR(x.s_w, r.s_w, 1e-9);
        EXPECT_NEAR(x.s_r, r.s_r, 1e-9);
        EXPECT_NEAR(x.approach, r.approach, 1e-11);
        EXPECT_NEAR(x.gamma, r.gamma, 1e-8);
        EXPECT_NEAR(x.B, r.B, 1e-6 * std::abs(r.B) + 1e-6);
        ++patches;
      }
    }
    EXPECT_GT(patches, 12);
  }
}

TEST(SlicedRail, IdenticalSlicesAreThePrismaticRailBitForBit) {
  const WheelRailPair base = leftPair();
  const auto copy = std::make_shared<const Profile>(*base.rail);  // same content, another object
  const std::vector<RailSlice> slices = {{10.0, base.rail}, {20.0, copy}, {25.0, base.rail}};
  const SlicedRailSearch sliced(base, slices, {});
  const ElasticContactSearch plain(base);
  const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  for (double s : {5.0, 10.0, 13.7, 20.0, 22.2, 26.0}) {
    const SlicedRailSearch::Place at = sliced.at(s);
    for (ElasticPose p : poses()) {
      p.z += touchHeight(plain, p);
      const ElasticWheelGeometry e = plain.search(p);
      p.blend = at.blend;
      const ElasticWheelGeometry g = at.search->search(p);
      ASSERT_EQ(g.count, e.count);
      ASSERT_GE(g.count, 1);
      EXPECT_EQ(bits(g.min_gap), bits(e.min_gap));
      for (int k = 0; k < g.count; ++k) {
        const auto& x = g.patch[static_cast<std::size_t>(k)];
        const auto& r = e.patch[static_cast<std::size_t>(k)];
        EXPECT_EQ(bits(x.approach), bits(r.approach));
        EXPECT_EQ(bits(x.s_r), bits(r.s_r));
        EXPECT_EQ(bits(x.B_span), bits(r.B_span));
        EXPECT_EQ(x.rail_rise, 0.0);
      }
    }
  }
}

TEST(SlicedRail, TheRailRiseIsTheApproachPerUnitOfBlend) {
  WheelRailPair pair = leftPair();
  pair.rail_next = changed(*pair.rail, ground);
  const ElasticContactSearch s(pair);
  for (ElasticPose p : poses()) {
    p.blend = 0.4;
    p.z += touchHeight(s, p);
    const ElasticWheelGeometry g = s.search(p);
    ASSERT_GE(g.count, 1);
    const auto& c = g.patch[0];
    // d(gap depth)/d(blend) at the fixed contact parameters: the rail surface moves along n.
    constexpr double kH = 1e-6;
    ElasticPose lo = p, hi = p;
    lo.blend -= kH;
    hi.blend += kH;
    const double d =
        (s.describe(hi, c.s_w, c.s_r).gap_depth - s.describe(lo, c.s_w, c.s_r).gap_depth) /
        (2.0 * kH);
    EXPECT_NEAR(c.rail_rise, d, 1e-3 * std::abs(d) + 1e-9) << "y = " << p.y;
    // Lowered by about 1 mm where the wheel runs.
    EXPECT_LT(c.rail_rise, -0.8e-3);
    EXPECT_GT(c.rail_rise, -1.3e-3);
  }
}

TEST(SlicedRail, PiecesAlongTheTrack) {
  const WheelRailPair base = leftPair();
  const auto b = changed(*base.rail, ground);
  const SlicedRailSearch r(base, {{100.0, base.rail}, {110.0, b}, {140.0, base.rail}}, {});
  EXPECT_EQ(r.pieces(), 4U);
  const auto before = r.at(50.0);
  EXPECT_EQ(before.piece, 0);
  EXPECT_EQ(before.blend, 0.0);
  EXPECT_EQ(before.blend_ds, 0.0);
  const auto first = r.at(102.5);
  EXPECT_EQ(first.piece, 1);
  EXPECT_DOUBLE_EQ(first.blend, 0.25);
  EXPECT_DOUBLE_EQ(first.blend_ds, 0.1);
  const auto second = r.at(110.0);  // at a slice: the piece that starts there, blend 0
  EXPECT_EQ(second.piece, 2);
  EXPECT_EQ(second.blend, 0.0);
  EXPECT_DOUBLE_EQ(r.at(125.0).blend, 0.5);
  const auto after = r.at(140.0);
  EXPECT_EQ(after.piece, 3);
  EXPECT_EQ(after.blend, 0.0);
  EXPECT_EQ(after.search->pair().rail, base.rail);
  EXPECT_EQ(after.search->pair().rail_next, nullptr);
  EXPECT_EQ(first.search->pair().rail_next, b);
}

TEST(SlicedRail, ABoundedRailExistsBetweenItsSlicesAndItsOffsetsInterpolate) {
  const WheelRailPair base = leftPair();
  RailSlice a{100.0, base.rail, 0.0, -0.01};
  RailSlice b{104.0, base.rail, 0.008, 0.0};
  const SlicedRailSearch r(base, {a, b}, {}, true);
  EXPECT_TRUE(r.bounded());
  EXPECT_EQ(r.at(99.99).search, nullptr);
  EXPECT_EQ(r.at(104.01).search, nullptr);
  const auto first = r.at(100.0);
  ASSERT_NE(first.search, nullptr);
  EXPECT_EQ(first.dz, -0.01);
  const auto mid = r.at(101.0);
  EXPECT_DOUBLE_EQ(mid.dy, 0.002);
  EXPECT_DOUBLE_EQ(mid.dz, -0.0075);
  EXPECT_DOUBLE_EQ(mid.dy_ds, 0.002);
  EXPECT_DOUBLE_EQ(mid.dz_ds, 0.0025);
  const auto last = r.at(104.0);  // the last slice still belongs to the rail
  ASSERT_NE(last.search, nullptr);
  EXPECT_EQ(last.dy, 0.008);
  EXPECT_EQ(last.dy_ds, 0.0);
  // Unbounded, the ends run on at the end slices' offsets.
  const SlicedRailSearch u(base, {a, b}, {});
  EXPECT_EQ(u.at(50.0).dz, -0.01);
  EXPECT_EQ(u.at(500.0).dy, 0.008);
  EXPECT_NE(u.at(500.0).search, nullptr);
}

TEST(SlicedRail, RefusesSlicesWithoutCommonProfileOrOrder) {
  const WheelRailPair base = leftPair();
  std::vector<double> h(200, 0.0);
  const auto far = std::make_shared<const Profile>("far", ProfileKind::Rail, 0.2, 1e-4, h);
  EXPECT_THROW(SlicedRailSearch(base, {{0.0, base.rail}, {10.0, far}}, {}), rb::InputError);
  EXPECT_THROW(SlicedRailSearch(base, {{10.0, base.rail}, {10.0, base.rail}}, {}), rb::InputError);
  EXPECT_THROW(SlicedRailSearch(base, {}, {}), rb::InputError);
}

}  // namespace
