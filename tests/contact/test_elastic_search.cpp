// Elastic multi-point contact search and Hertz normal problem (elastic_search.hpp,
// elastic_normal.hpp): closed-form Hertz, symmetry, seed independence, patch birth/death, the
// two-point contact, and the Manchester contact benchmark case against CONTACT's results
// (tests/data/contact_benchmark/). docs/elastic_contact.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "contact_test_util.hpp"
#include "workbench/contact/elastic_normal.hpp"
#include "workbench/contact/elastic_search.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/profile_io.hpp"

namespace {

using namespace rb::contact;
using rb::profiles::Profile;
using rb::profiles::ProfileKind;

std::string sourceFile(const std::string& rel) {
  return std::string(RB_SOURCE_DIR) + "/" + rel;
}

// ---- Benchmark set-up: the CONTACT input of case A-2.2 ------------------------------------------
// Profiles MBench_S1002_v3.prw (r0 = 460 mm) and MBench_UIC60_v3.prr (already canted 1:40, used as
// drawn: beta = 0), no smoothing (CONTACT: SMOOTH 0); flange back distance 1360 mm with the flange
// back at S = -70 mm (Lw = 750 mm); gauge 1435 mm measured 14 mm below the top of each rail (Lr).
struct Bench {
  std::array<std::shared_ptr<ElasticContactSearch>, 2> search;
  double lw = 0.0, lr = 0.0;
};

const Bench& bench() {
  static const Bench b = [] {
    Bench r;
    rb::profiles::ProfileReadOptions wo;
    wo.r0 = 0.46;
    auto wheel = std::make_shared<const Profile>(
        rb::profiles::readSimpackProfile(sourceFile("profiles/MBench_S1002_v3.prw"), wo));
    auto rail = std::make_shared<const Profile>(
        rb::profiles::readSimpackProfile(sourceFile("profiles/MBench_UIC60_v3.prr")));
    const rb::profiles::PlanePoint gp =
        rb::profiles::gaugePoint(*rail, rb::profiles::Side::Left, 0.0, 0.014);
    r.lw = 0.680 + 0.070;
    r.lr = 0.5 * 1.435 + std::abs(gp.y);
    for (Side side : {Side::Left, Side::Right}) {
      WheelRailPair p;
      p.side = side;
      p.wheel = side == Side::Left ? wheel : std::make_shared<const Profile>(wheel->mirrored());
      p.rail = side == Side::Left ? rail : std::make_shared<const Profile>(rail->mirrored());
      p.wheel_lw = r.lw;
      p.rail_lr = r.lr;
      p.beta = 0.0;
      r.search[side == Side::Left ? 0 : 1] = std::make_shared<ElasticContactSearch>(p);
    }
    return r;
  }();
  return b;
}

// One row of tests/data/contact_benchmark/mbench_a22_contact_reference.csv (CONTACT conventions).
struct RefRow {
  std::string wheel;
  int case_no = 0;
  double y_mm = 0, yaw = 0, roll = 0, fz = 0, fn = 0, xw = 0, yw = 0, yr = 0, delta = 0;
  double approach_mm = 0, pmax = 0, len_x = 0, len_s = 0;
  int ncon = 0;
};

std::vector<RefRow> referenceRows() {
  std::ifstream in(sourceFile("tests/data/contact_benchmark/mbench_a22_contact_reference.csv"));
  std::vector<RefRow> rows;
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    for (char& c : line) {
      if (c == ',') c = ' ';
    }
    std::istringstream ss(line);
    RefRow r;
    ss >> r.wheel >> r.case_no >> r.y_mm >> r.yaw >> r.roll >> r.fz >> r.fn >> r.xw >> r.yw >>
        r.yr >> r.delta >> r.approach_mm >> r.pmax >> r.ncon >> r.len_x >> r.len_s;
    rows.push_back(r);
  }
  return rows;
}

// CONTACT (y right, z down) -> railbench (y left, z up): y = -y_ws, psi = -yaw, phi = roll (both
// mean "left side up" for > 0). Wheel and rail lateral positions: YCP(W) = -s_w, YCP(R) = -s_r on
// both sides; contact angle: left gamma = DELTCP, right gamma = -DELTCP (README of the data).
ElasticPose poseOf(const RefRow& r) {
  ElasticPose p;
  p.y = -r.y_mm * 1e-3;
  p.psi = -r.yaw;
  p.phi = r.roll;
  p.z = 0.46;
  return p;
}

struct Ours {
  int patches = 0;
  double N = 0, s_w = 0, s_r = 0, gamma = 0, x_w = 0, delta = 0, a = 0, b = 0, p0 = 0;
  double N_total = 0;
  bool converged = false;
};

Ours solveRow(const RefRow& r, WheelLoad mode, const ElasticNormalSpec& spec = {}) {
  const ElasticContactSearch& s = *bench().search[r.wheel == "left" ? 0 : 1];
  const double target = mode == WheelLoad::Vertical ? r.fz : r.fn;
  const WheelLoadSolution sol = solveWheelLoad(s, poseOf(r), spec, target, mode);
  Ours o;
  o.converged = sol.converged;
  const ElasticWheelContact& c = sol.contact;
  o.patches = c.geometry.count;
  o.N_total = c.normal_sum;
  if (c.geometry.count > 0) {
    // The patch carrying the largest force (CONTACT reports one patch per wheel in ).
    std::size_t k = 0;
    for (std::size_t i = 1; i < static_cast<std::size_t>(c.geometry.count); ++i) {
      if (c.normal[i].N > c.normal[k].N) k = i;
    }
    const ElasticPatchGeometry& g = c.geometry.patch[k];
    o.N = c.normal[k].N;
    o.s_w = g.s_w;
    o.s_r = g.s_r;
    o.gamma = g.gamma;
    o.x_w = g.x_w;
    o.delta = g.approach;
    o.a = c.normal[k].a;
    o.b = c.normal[k].b;
    o.p0 = c.normal[k].p0;
  }
  return o;
}

// ---- Closed-form Hertz ----------------------------------------------------------------------

// A cylindrical wheel (constant radius r) crossing a rail crown of the same radius R = r, beta =
// 0: crossed cylinders of equal radii have the gap of a sphere of radius r on a flat, A = B =
// 1/(2r), a circular Hertz contact with effective radius R_e = r: a^3 = 3 N R_e / (4 E*), delta =
// a^2 / R_e, N = (4/3) E* sqrt(R_e) delta^1.5 (hertz.hpp, "Circular check"); the penetration is
// r - z exactly.
TEST(ElasticSearch, CylinderOnCrownIsExactlyHertz) {
  const double r = 0.46;
  auto wheel =
      rbtest::sampled("cylinder", ProfileKind::Wheel, -0.04, 0.04, 1e-4, [&](double) { return r; });
  auto rail = rbtest::arcRail(r, 0.03, 1e-5);
  WheelRailPair p;
  p.wheel = wheel;
  p.rail = rail;
  p.wheel_lw = 0.75;
  p.rail_lr = 0.75;
  p.beta = 0.0;
  const ElasticContactSearch s(p);
  const double delta = 50e-6;
  const ElasticPose pose{0.0, r - delta, 0.0, 0.0};
  const ElasticWheelGeometry g = s.search(pose);
  ASSERT_EQ(g.count, 1);
  const ElasticPatchGeometry& pg = g.patch[0];
  EXPECT_NEAR(pg.gap_depth, delta, 1e-12);
  EXPECT_NEAR(pg.s_w, 0.0, 1e-9);
  EXPECT_NEAR(pg.A, 0.5 / r, 1e-9);
  EXPECT_NEAR(pg.B, 0.5 / r, 2e-6);  // spline of the sampled rail circle
  const ElasticNormalSpec spec;
  const ElasticPatchNormal n = elasticNormal(pg, spec);
  EXPECT_FALSE(n.B_floored);
  const double Es = rb::creep::contactModulus(spec.material);
  const double Re = r;
  const double N = 4.0 / 3.0 * Es * std::sqrt(Re) * std::pow(delta, 1.5);
  EXPECT_NEAR(n.N / N, 1.0, 1e-5);
  const double a = std::cbrt(3.0 * N * Re / (4.0 * Es));
  EXPECT_NEAR(n.a / a, 1.0, 1e-5);
  EXPECT_NEAR(n.b / a, 1.0, 1e-5);
  EXPECT_NEAR(n.p0 / (3.0 * N / (2.0 * M_PI * a * a)), 1.0, 2e-5);
  // A yawed and rolled cylinder on the crown: still one patch, the locus point leads by
  // x_w = h sin(theta) with theta = 0 for a cylinder (h' = 0): no shift.
  const ElasticWheelGeometry gy = s.search({0.0, r - delta, 0.0, 0.02});
  ASSERT_EQ(gy.count, 1);
  EXPECT_NEAR(gy.patch[0].x_w, 0.0, 1e-12);
}

// A cone (conicity lambda) yawed by psi: the contact point leads by x_w = -r h' psi to first
// order (Wickens' shift; h' = -lambda on the left wheel), exactly r sin(theta) with the locus
// equation cos(psi) sin(theta) = -sin(psi) h' at zero roll.
TEST(ElasticSearch, YawShiftOfAConeFollowsTheLocusEquation) {
  const double r0 = 0.46, lambda = 0.05, psi = 0.01;
  WheelRailPair p;
  p.wheel = rbtest::coneWheel(r0, lambda);
  p.rail = rbtest::arcRail(0.3);
  p.wheel_lw = 0.75;
  p.rail_lr = 0.75;
  p.beta = 0.0;
  const ElasticContactSearch s(p);
  const ElasticWheelGeometry g = s.search({0.0, r0 - 30e-6, 0.0, psi});
  ASSERT_EQ(g.count, 1);
  const ElasticPatchGeometry& pg = g.patch[0];
  const double st = std::sin(psi) * lambda / std::cos(psi);
  EXPECT_NEAR(pg.x_w, pg.radius * st, 1e-12);
  EXPECT_NEAR(pg.x_w, r0 * lambda * psi, 1e-6);
}

// ---- Curvature policy -----------------------------------------------------------------------

TEST(ElasticNormal, CurvatureFloorIsC1AndOnlyActsBelowTwiceTheFloor) {
  const double m = 0.2;
  EXPECT_EQ(smoothCurvatureFloor(1.0, m), 1.0);
  EXPECT_EQ(smoothCurvatureFloor(2 * m, m), 2 * m);
  EXPECT_EQ(smoothCurvatureFloor(-5.0, m), m);
  EXPECT_EQ(smoothCurvatureFloor(0.0, m), m);
  const double h = 1e-7;
  for (double x : {0.0, 2 * m}) {  // slopes match at both joints
    const double left = (smoothCurvatureFloor(x, m) - smoothCurvatureFloor(x - h, m)) / h;
    const double right = (smoothCurvatureFloor(x + h, m) - smoothCurvatureFloor(x, m)) / h;
    EXPECT_NEAR(left, right, 1e-5);
  }
  ElasticPatchGeometry g;
  g.A = 1.0;
  g.B = -3.0;  // a conformal flange root
  g.approach = 20e-6;
  const ElasticPatchNormal n = elasticNormal(g, {});
  EXPECT_TRUE(n.B_floored);
  EXPECT_DOUBLE_EQ(n.B, 0.1);
  EXPECT_GT(n.N, 0.0);
  EXPECT_NEAR(n.p0, 3.0 * n.N / (2.0 * M_PI * n.a * n.b), 1e-6 * n.p0);
  g.approach = 0.0;
  EXPECT_EQ(elasticNormal(g, {}).N, 0.0);
}

// ---- S1002 on UIC60 (benchmark profiles) ----------------------------------------------------

TEST(ElasticSearch, CentredSymmetricWheelsetGivesMirroredPatches) {
  const Bench& b = bench();
  const ElasticPose pose{0.0, 0.46 - 0.2e-3, 0.0, 0.0};
  const ElasticWheelGeometry l = b.search[0]->search(pose);
  const ElasticWheelGeometry r = b.search[1]->search(pose);
  ASSERT_GE(l.count, 1);
  ASSERT_EQ(l.count, r.count);
  for (std::size_t k = 0; k < static_cast<std::size_t>(l.count); ++k) {
    EXPECT_NEAR(l.patch[k].s_w, -r.patch[k].s_w, 1e-12);
    EXPECT_NEAR(l.patch[k].s_r, -r.patch[k].s_r, 1e-12);
    EXPECT_NEAR(l.patch[k].gap_depth, r.patch[k].gap_depth, 1e-15);
    EXPECT_NEAR(l.patch[k].gamma, r.patch[k].gamma, 1e-12);
    EXPECT_NEAR(l.patch[k].y, -r.patch[k].y, 1e-12);
  }
}

TEST(ElasticSearch, ResultDoesNotDependOnSeedOrSampling) {
  const Bench& b = bench();
  const ElasticContactSearch& s = *b.search[1];
  for (double y : {0.0, -3e-3, -5e-3, -6e-3, -7e-3, -8e-3}) {
    // The height at which the wheel carries 10 kN, with a roll and a yaw.
    ElasticPose pose{y, 0.46, -0.004 * (y / -0.007), -0.01};
    const WheelLoadSolution load = solveWheelLoad(s, pose, {}, 1e4, WheelLoad::Vertical);
    ASSERT_TRUE(load.converged);
    pose.z = load.z;
    const ElasticWheelGeometry ref = s.search(pose);
    // An unrelated seed (a pose 2 mm away) and the result itself as a seed.
    const ElasticWheelGeometry other = s.search({y + 2e-3, pose.z, 0.0, 0.0});
    for (const ElasticWheelGeometry* seed : {&other, &ref}) {
      const ElasticWheelGeometry g = s.search(pose, seed);
      ASSERT_EQ(g.count, ref.count) << "y = " << y;
      for (std::size_t k = 0; k < static_cast<std::size_t>(g.count); ++k) {
        EXPECT_NEAR(g.patch[k].s_w, ref.patch[k].s_w, 1e-10);
        EXPECT_NEAR(g.patch[k].approach, ref.patch[k].approach, 1e-13);
      }
    }
    // A finer sampling finds the same patches (the scan only seeds the refinement).
    ElasticSearchSpec fine;
    fine.sample_step = 0.05e-3;
    const ElasticContactSearch sf(s.pair(), fine);
    const ElasticWheelGeometry gf = sf.search(pose);
    ASSERT_EQ(gf.count, ref.count) << "y = " << y;
    for (std::size_t k = 0; k < static_cast<std::size_t>(gf.count); ++k) {
      EXPECT_NEAR(gf.patch[k].s_w, ref.patch[k].s_w, 1e-9) << "y = " << y;
      EXPECT_NEAR(gf.patch[k].gap_depth, ref.patch[k].gap_depth, 1e-12) << "y = " << y;
    }
  }
}

// The pruned scan (ElasticSearchSpec::prune_scan, the default) skips wheel samples by a rigorous
// bound but must give the full scan's result bit for bit: poses across both wheels, lateral
// positions from the flange back to the flange, yaw and roll, from 1 mm clear (min_gap must
// still be exact) to 0.2 mm deep, also with an inclined, offset rail.
TEST(ElasticSearch, PrunedScanEqualsTheFullScan) {
  const Bench& b = bench();
  int compared = 0, with_patches = 0;
  for (int variant = 0; variant < 3; ++variant) {
    for (std::size_t side = 0; side < 2; ++side) {
      WheelRailPair pair = b.search[side]->pair();
      if (variant == 2) {
        pair.beta = 0.025;
        pair.rail_dy = 0.4e-3;
        pair.rail_dz = -0.3e-3;
      }
      ElasticSearchSpec pruned, full;
      full.prune_scan = false;
      if (variant == 1) pruned.sample_step = full.sample_step = 0.1e-3;
      const ElasticContactSearch sp(pair, pruned), sf(pair, full);
      ASSERT_TRUE(sp.spec().prune_scan);
      const double sigma = sp.sigma();
      for (double y = -4.13e-3; y <= 10.0e-3; y += variant == 0 ? 0.37e-3 : 1.1e-3) {
        for (double psi : {-0.012, 0.0, 0.007}) {
          for (double phi : {0.0, 0.004}) {
            ElasticPose pose{-sigma * y, 0.46, phi, psi};
            const double m = sf.search(pose).min_gap;
            if (!std::isfinite(m)) continue;
            for (double d : {1e-3, 1e-5, -1e-5, -5e-5, -2e-4}) {
              pose.z = 0.46 - m + d;
              const ElasticWheelGeometry gp = sp.search(pose), gf = sf.search(pose);
              ++compared;
              SCOPED_TRACE(testing::Message()
                           << "variant " << variant << " side " << side << " y " << y << " psi "
                           << psi << " phi " << phi << " d " << d);
              ASSERT_EQ(gp.count, gf.count);
              EXPECT_EQ(gp.min_gap, gf.min_gap);
              EXPECT_EQ(gp.truncated, gf.truncated);
              EXPECT_EQ(gp.newton_iterations, gf.newton_iterations);
              with_patches += gp.count > 0;
              for (std::size_t k = 0; k < static_cast<std::size_t>(gp.count); ++k) {
                EXPECT_EQ(gp.patch[k].s_w, gf.patch[k].s_w);
                EXPECT_EQ(gp.patch[k].s_r, gf.patch[k].s_r);
                EXPECT_EQ(gp.patch[k].x, gf.patch[k].x);
                EXPECT_EQ(gp.patch[k].gap_depth, gf.patch[k].gap_depth);
                EXPECT_EQ(gp.patch[k].approach, gf.patch[k].approach);
                EXPECT_EQ(gp.patch[k].B_span, gf.patch[k].B_span);
                EXPECT_EQ(gp.patch[k].refined, gf.patch[k].refined);
              }
            }
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 1500);
  EXPECT_GT(with_patches, 1000);
  std::printf("pruned scan = full scan at %d poses (%d with patches)\n", compared, with_patches);
}

// Bit-for-bit equality of two search results (every field of every patch, min_gap, truncated,
// the iteration count); the first difference is reported.
::testing::AssertionResult sameBits(const ElasticWheelGeometry& a, const ElasticWheelGeometry& b) {
  auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  if (a.count != b.count || a.truncated != b.truncated || bits(a.min_gap) != bits(b.min_gap) ||
      a.newton_iterations != b.newton_iterations) {
    return ::testing::AssertionFailure()
           << "count " << a.count << " / " << b.count << ", min_gap " << a.min_gap << " / "
           << b.min_gap << ", iterations " << a.newton_iterations << " / " << b.newton_iterations;
  }
  for (std::size_t k = 0; k < static_cast<std::size_t>(a.count); ++k) {
    const ElasticPatchGeometry &p = a.patch[k], &q = b.patch[k];
    const std::array<std::pair<double, double>, 19> f{{{p.s_w, q.s_w},
                                                       {p.s_r, q.s_r},
                                                       {p.x, q.x},
                                                       {p.y, q.y},
                                                       {p.z, q.z},
                                                       {p.x_w, q.x_w},
                                                       {p.theta, q.theta},
                                                       {p.n_y, q.n_y},
                                                       {p.n_z, q.n_z},
                                                       {p.gamma, q.gamma},
                                                       {p.radius, q.radius},
                                                       {p.gap_depth, q.gap_depth},
                                                       {p.approach, q.approach},
                                                       {p.k_wheel_trans, q.k_wheel_trans},
                                                       {p.k_wheel_rolling, q.k_wheel_rolling},
                                                       {p.k_rail_trans, q.k_rail_trans},
                                                       {p.A, q.A},
                                                       {p.B, q.B},
                                                       {p.B_span, q.B_span}}};
    for (std::size_t j = 0; j < f.size(); ++j) {
      if (bits(f[j].first) != bits(f[j].second)) {
        return ::testing::AssertionFailure()
               << "patch " << k << " field " << j << ": " << f[j].first << " / " << f[j].second;
      }
    }
    if (p.refined != q.refined) return ::testing::AssertionFailure() << "patch " << k << " refined";
  }
  return ::testing::AssertionSuccess();
}

// A workspace kept from one search to the next, as the dynamic method keeps one per wheel, must
// not change any result: a random walk of poses (steps from 1e-15 m to 10 um, exact repeats,
// occasional jumps to a new lateral position, yaw, roll and depth: tread, two-point and flange
// contact, lift-off; now and then a seed, or the other wheel's search in the same workspace),
// every result bit for bit equal to a fresh workspace's full scan at the same pose. On the
// benchmark profiles (rail upright) and on S1002/60E1 at 1:40 (the dynamics' set-up).
TEST(ElasticSearch, SearchesInSequenceEqualFreshFullScans) {
  const auto incl = wheelRailPairs(rbtest::s1002On60E1());
  const std::array<std::array<WheelRailPair, 2>, 2> sets{
      {{bench().search[0]->pair(), bench().search[1]->pair()}, {incl[0], incl[1]}}};
  std::mt19937_64 rng(20261204);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  int compared = 0, repeats = 0, lifted = 0, two_point = 0, flange = 0, seeded = 0, shared = 0;
  for (const auto& pairs : sets) {
    ElasticSearchSpec full;
    full.prune_scan = false;
    const std::array<ElasticContactSearch, 2> sp{ElasticContactSearch(pairs[0]),
                                                 ElasticContactSearch(pairs[1])};
    const std::array<ElasticContactSearch, 2> sf{ElasticContactSearch(pairs[0], full),
                                                 ElasticContactSearch(pairs[1], full)};
    for (std::size_t side = 0; side < 2; ++side) {
      const double sigma = sp[side].sigma();
      ElasticSearchWorkspace ws;
      ElasticWheelGeometry g, prev;
      ElasticPose pose;
      double z_touch = 0.46;
      for (int step = 0; step < 2500; ++step) {
        const double r = uni(rng);
        if (step % 150 == 0 || r < 0.01) {
          // A jump: lateral position from the flange back to the flange, yaw, roll, depth from
          // 1 mm clear to 0.25 mm deep.
          pose.y = sigma * (-4e-3 + 14e-3 * uni(rng));
          pose.psi = 0.024 * (uni(rng) - 0.5);
          pose.phi = 0.01 * (uni(rng) - 0.5);
          // The height of first touch (min_gap is the normal gap: a few steps down to it).
          pose.z = 0.46;
          for (int it = 0; it < 6; ++it) {
            const double m = sf[side].search(pose).min_gap;
            if (std::isfinite(m)) pose.z -= m;
          }
          z_touch = pose.z;
          pose.z = z_touch + (uni(rng) < 0.1 ? 1e-3 : 2e-5 - 2.7e-4 * uni(rng));
        } else if (r < 0.1) {
          ++repeats;  // the same pose again
        } else {
          // A step of 10^-15 to 10^-5 m (rad for the angles) in each coordinate.
          auto d = [&] { return (uni(rng) - 0.5) * std::pow(10.0, -15.0 + 10.0 * uni(rng)); };
          pose.y += d();
          pose.z = std::clamp(pose.z + d(), z_touch - 3e-4, z_touch + 1.2e-3);
          pose.phi += 0.1 * d();
          pose.psi += 0.1 * d();
        }
        const ElasticWheelGeometry* seed = nullptr;
        if (uni(rng) < 0.03) {
          seed = &prev;
          ++seeded;
        }
        if (uni(rng) < 0.02) {  // the other wheel's model in this workspace
          ElasticWheelGeometry other;
          sp[1 - side].search(pose, other, ws);
          ++shared;
        }
        sp[side].search(pose, g, ws, seed);
        const ElasticWheelGeometry ref = sf[side].search(pose, seed);
        ++compared;
        ASSERT_TRUE(sameBits(g, ref))
            << "set " << (&pairs - sets.data()) << " side " << side << " step " << step << " pose "
            << pose.y << " " << pose.z << " " << pose.phi << " " << pose.psi;
        lifted += g.count == 0;
        two_point += g.count >= 2;
        for (int k = 0; k < g.count; ++k) {
          flange += std::abs(g.patch[static_cast<std::size_t>(k)].gamma) > 0.5;
        }
        prev = g;
      }
    }
  }
  std::printf(
      "%d searches in sequence = fresh full scans (%d repeated poses, %d lifted, %d two-point, "
      "%d flange patches, %d seeded, %d with the other wheel's search in between)\n",
      compared, repeats, lifted, two_point, flange, seeded, shared);
  EXPECT_GT(compared, 9500);
  EXPECT_GT(repeats, 600);
  EXPECT_GT(lifted, 600);
  EXPECT_GT(two_point, 600);
  EXPECT_GT(flange, 1000);  // patches with a contact angle above 0.5 rad
  EXPECT_GT(seeded, 150);
  EXPECT_GT(shared, 100);
}

// ---- Patch birth and death, two-point contact ------------------------------------------------

// The right wheel moved toward its flange at zero yaw, its height solved for 10 kN (each wheel
// alone, roll 0), in steps of 5 um from the centre to the flange root: two tread minima hand over
// (y < 0.5 mm), then the tread/root two-point contact. Patches are born and die with zero approach
// and little force, and neither the lateral force nor the sum of the normal forces jumps anywhere
// (the largest changes per 5 um step are 34 N and 7 N).
TEST(ElasticSearch, PatchesAreBornAndDieWithZeroForce) {
  const ElasticContactSearch& s = *bench().search[1];
  int prev = 0;
  ElasticWheelContact last;
  double y_born = 0.0, y_died = 0.0, max_dfy = 0.0, max_dn = 0.0;
  for (double y = 0.0; y <= 5.5e-3 + 1e-12; y += 5e-6) {
    const WheelLoadSolution sol =
        solveWheelLoad(s, {-y, 0.46, 0.0, 0.0}, {}, 1e4, WheelLoad::Vertical);
    ASSERT_TRUE(sol.converged) << "y = " << y;
    const ElasticWheelContact& c = sol.contact;
    const int n = c.geometry.count;
    ASSERT_GE(n, 1);
    ASSERT_LE(n, 2);
    if (prev != 0) {
      max_dfy = std::max(max_dfy, std::abs(c.force_y - last.force_y));
      max_dn = std::max(max_dn, std::abs(c.normal_sum - last.normal_sum));
      if (n != prev) {
        // The patch that appears (or the one that disappears) carries little force.
        const ElasticWheelContact& two = n == 2 ? c : last;
        const std::size_t k = two.normal[0].N < two.normal[1].N ? 0 : 1;
        EXPECT_LT(two.normal[k].N, 60.0) << "y = " << y;
        EXPECT_LT(two.geometry.patch[k].approach, 1e-6) << "y = " << y;
        if (y > 1e-3) (n == 2 ? y_born : y_died) = y;
      }
    }
    prev = n;
    last = c;
  }
  // S1002 on UIC60 1:40, G = 1435 mm, B = 1360 mm: the flange root (s_w ~ 28 mm from the tape
  // circle) starts to touch at y = 4.89 mm beside the tread, and takes the whole load at
  // y = 5.22 mm.
  EXPECT_NEAR(y_born, 4.89e-3, 0.02e-3);
  EXPECT_NEAR(y_died, 5.22e-3, 0.02e-3);
  EXPECT_LT(max_dfy, 60.0);
  EXPECT_LT(max_dn, 20.0);
}

// A hollow wheel of almost the rail crown's radius (B -> 0+, a conformal contact; at a gap minimum
// B cannot be negative, the gap's second derivative is 2 B): the policy floors B, so N stays
// finite and the ellipse stays within b / a ~ 4.6.
TEST(ElasticSearch, ConformalPatchIsFlooredByThePolicy) {
  WheelRailPair p;
  p.wheel = rbtest::arcWheel(0.46, -0.3005, 0.0);  // hollow tread, R = 300.5 mm
  p.rail = rbtest::arcRail(0.3);                   // crown R = 300 mm
  p.wheel_lw = 0.75;
  p.rail_lr = 0.75;
  p.beta = 0.0;
  ElasticSearchSpec spec;
  spec.curvature_span = 0.0;  // the pointwise B
  const ElasticContactSearch s(p, spec);
  const ElasticWheelGeometry g = s.search({0.0, 0.46 - 20e-6, 0.0, 0.0});
  ASSERT_EQ(g.count, 1);
  EXPECT_NEAR(g.patch[0].B, 0.5 * (-1.0 / 0.3005 + 1.0 / 0.3), 1e-3);
  EXPECT_NEAR(g.patch[0].gap_depth, 20e-6, 1e-10);
  const ElasticPatchNormal n = elasticNormal(g.patch[0], {});
  EXPECT_TRUE(n.B_floored);
  EXPECT_NEAR(n.B, smoothCurvatureFloor(g.patch[0].B, 0.1 * g.patch[0].A), 1e-12);
  EXPECT_NEAR(n.B, 0.1 * g.patch[0].A, 1e-4);
  EXPECT_GT(n.N, 0.0);
  EXPECT_GT(n.b, 4.0 * n.a);
  EXPECT_LT(n.b, 5.0 * n.a);
}

// ---- Manchester contact benchmark A-2.2 ----------------------------------------------------
//
// Each wheel alone (as CONTACT solves it) at the benchmark's y, yaw and roll, its height solved for
// the benchmark's vertical load Fz = 10 kN (frictionless: sum of N n_z), compared with CONTACT's
// results (README of tests/data/contact_benchmark). A second solve at CONTACT's own normal force
// FN compares the normal problem alone (CONTACT's Fz also carries the vertical component of the
// friction force, which at the flange is a third of it). Tolerances (docs/elastic_contact.md):
//   positions on wheel and rail   0.5 mm (tread), 0.6 mm (root, flange)
//   contact angle                 0.006 rad (tread), 0.01 rad (root, flange)
//   longitudinal shift x_w        0.01 mm + 3 % (it follows the contact angle)
//   approach (tread, Fz)          4 %
//   2a                            0.3 mm (CONTACT's grid: 0.2 mm cells) + 4 % (flange, at FN)
//   2b                            0.3 mm + 5 % (tread), one 0.2 mm cell (flange, at FN)
//   p0                            6 % (at FN)
// except the near-conformal positions y = 0 (both wheels) and the right wheel at y = 0.5 mm and
// y = 1.0 mm, where CONTACT's one patch spans 14-16 mm laterally over two of our minima or a
// conformal zone (there: p0 within 20 %, the CONTACT reference point between our patches or within
// 3 mm of ours), and 2b at the tread/root two-point contact (right, y = 5 mm), which CONTACT
// reports as one combined patch 12.2 mm wide.
struct Row {
  RefRow ref;
  Ours fz, fn;
};

bool conformal(const RefRow& r) {
  return r.case_no == 1 || (r.wheel == "right" && (r.case_no == 2 || r.case_no == 3));
}
bool flangeSide(const RefRow& r) {
  return r.wheel == "right" && r.case_no >= 11;
}

void writeTable(const std::vector<Row>& rows) {
  const std::string path = std::string(RB_BINARY_DIR) + "/elastic_mbench_a22.md";
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return;
  std::fprintf(
      f,
      "| wheel | y [mm] | patches ours/CONTACT | y_w ours / ref [mm] | y_r ours / ref [mm] "
      "| gamma ours / ref [rad] | x_w ours / ref [mm] | approach ours / ref [um] | N main "
      "patch ours (Fz) / FN ref [kN] | 2a ours(FN) / ref [mm] | 2b ours(FN) / ref [mm] | p0 "
      "ours(FN) / ref [MPa] |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& w : rows) {
    const RefRow& r = w.ref;
    const double sgn = r.wheel == "left" ? 1.0 : -1.0;
    std::fprintf(f,
                 "| %s | %.1f | %d / 1 | %.2f / %.2f | %.2f / %.2f | %.4f / %.4f | %.3f / %.3f | "
                 "%.1f / %.1f | %.2f / %.2f | %.2f / %.1f | %.2f / %.1f | %.0f / %.0f |\n",
                 r.wheel.c_str(), r.y_mm, w.fz.patches, -w.fz.s_w * 1e3, r.yw, -w.fz.s_r * 1e3,
                 r.yr, w.fz.gamma, sgn * r.delta, w.fz.x_w * 1e3, r.xw, w.fz.delta * 1e6,
                 r.approach_mm * 1e3, w.fz.N * 1e-3, r.fn * 1e-3, 2e3 * w.fn.a, r.len_x,
                 2e3 * w.fn.b, r.len_s, w.fn.p0 * 1e-6, r.pmax);
  }
  std::fclose(f);
}

TEST(ElasticBenchmark, MBenchA22AgainstContact) {
  const std::vector<RefRow> refs = referenceRows();
  ASSERT_EQ(refs.size(), 42u);
  std::vector<Row> rows;
  for (const RefRow& r : refs) {
    Row w{r, solveRow(r, WheelLoad::Vertical), solveRow(r, WheelLoad::Normal)};
    rows.push_back(w);
    SCOPED_TRACE(r.wheel + " wheel, y = " + std::to_string(r.y_mm) + " mm");
    ASSERT_TRUE(w.fz.converged && w.fn.converged);
    const double sgn = r.wheel == "left" ? 1.0 : -1.0;
    const Ours& v = w.fz;
    const Ours& n = w.fn;
    const bool fl = flangeSide(r);
    EXPECT_NEAR(v.x_w * 1e3, r.xw, 0.01 + 0.03 * std::abs(r.xw));
    if (conformal(r)) {
      EXPECT_NEAR(n.p0 * 1e-6, r.pmax, 0.2 * r.pmax);
      EXPECT_NEAR(-v.s_w * 1e3, r.yw, 3.0);
      continue;
    }
    EXPECT_EQ(v.patches, r.wheel == "right" && r.case_no == 11 ? 2 : 1);
    EXPECT_NEAR(-v.s_w * 1e3, r.yw, fl ? 0.6 : 0.5);
    EXPECT_NEAR(-v.s_r * 1e3, r.yr, fl ? 0.6 : 0.5);
    EXPECT_NEAR(v.gamma, sgn * r.delta, fl ? 0.01 : 0.006);
    EXPECT_NEAR(n.p0 * 1e-6, r.pmax, 0.06 * r.pmax);
    if (fl) {
      EXPECT_NEAR(2e3 * n.a, r.len_x, 0.3 + 0.04 * r.len_x);
      if (r.case_no != 11) {
        EXPECT_NEAR(2e3 * n.b, r.len_s, 0.2 + 1e-9);
      }
    } else {
      EXPECT_NEAR(v.delta * 1e3, r.approach_mm, 0.04 * r.approach_mm);
      EXPECT_NEAR(2e3 * v.a, r.len_x, 0.3);
      EXPECT_NEAR(2e3 * v.b, r.len_s, 0.3 + 0.05 * r.len_s);
    }
  }
  writeTable(rows);
}

// Our own roll for the benchmark positions: both wheels at 10 kN (solveWheelsetLoad, the
// benchmark's iteration) gives the roll CONTACT's inputs prescribe to within 2 % from y = 1 mm
// on (at y = 0.5 mm, 2e-5 rad, within 5e-6 rad).
TEST(ElasticBenchmark, WheelsetRollMatchesTheBenchmarkInputs) {
  const Bench& b = bench();
  for (const RefRow& r : referenceRows()) {
    if (r.wheel != "left" || r.case_no == 1) continue;
    const WheelsetLoadSolution w = solveWheelsetLoad(*b.search[0], *b.search[1], poseOf(r), {},
                                                     r.fz, r.fz, WheelLoad::Vertical);
    ASSERT_TRUE(w.converged) << "y = " << r.y_mm;
    EXPECT_NEAR(w.phi, r.roll, std::max(5e-6, 0.02 * std::abs(r.roll))) << "y = " << r.y_mm;
  }
}

}  // namespace
