// KEC equivalent profiles (Eq. 22-23) and the online KEC solver.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact_tables.hpp"
#include "workbench/contact/geometry.hpp"

namespace {

using namespace rb::contact;

// KEC solution at y (zero irregularity) followed from y = 0.
KecSolution kecAt(const KecTable& kec, double y, int steps = 20) {
  KecSolution s = solveKec(kec, KecInput{0.0, 0, 0, 0, 0});
  for (int i = 1; i <= steps; ++i) s = solveKec(kec, KecInput{y * i / steps, 0, 0, 0, 0}, &s);
  return s;
}

TEST(Kec, ConeOnArcReproducesTheLut) {
  // No contact-point jumps, no transitions: the equivalent profiles reproduce the contact
  // kinematics to interpolation accuracy everywhere.
  const LutTable& lut = rbtest::coneLut();
  const KecTable& kec = rbtest::coneKec();
  EXPECT_TRUE(kec.transitions(Side::Left).empty());
  EXPECT_TRUE(kec.stats().warnings.empty());
  const std::size_t ig = 2;  // xi_g = 0
  ASSERT_EQ(lut.gaugeGrid().at(ig), 0.0);
  double worst = 0.0;
  KecSolution s;
  bool have = false;
  for (std::size_t iy = lut.ny() / 2; iy < lut.ny(); ++iy) {
    s = solveKec(kec, KecInput{lut.yGrid().at(iy), 0, 0, 0, 0}, have ? &s : nullptr);
    ASSERT_EQ(s.status, KecStatus::Ok);
    have = true;
    worst = std::max({worst, std::abs(s.z - lut.node(kLutZ, iy, ig)),
                      std::abs(s.phi - lut.node(kLutPhi, iy, ig)) * 0.75});
  }
  std::printf("    cone/arc: KEC vs LUT worst |dz|, |dphi| Lw = %.2e m\n", worst);
  EXPECT_LT(worst, 1e-9);
}

TEST(Kec, S1002ReproducesTheLutOutsideTheRegularisedBands) {
  const LutTable& lut = rbtest::s1002Lut();
  const KecTable& kec = rbtest::s1002Kec();
  const std::size_t ig = 5;
  ASSERT_EQ(lut.gaugeGrid().at(ig), 0.0);
  // Where the tread constraint of the LUT is the rigid contact: up to the first two-point contact.
  double y_two_point = 1.0;
  for (const TwoPointContact& p : lut.twoPointContacts()) {
    if (p.xi_g == 0.0) y_two_point = std::min(y_two_point, std::abs(p.y));
  }
  double worst_z = 0.0, worst_phi = 0.0;
  int compared = 0;
  for (int dir : {+1, -1}) {
    KecSolution s = solveKec(kec, KecInput{});
    for (std::size_t k = 1; k <= lut.ny() / 2; ++k) {
      const std::size_t iy = dir > 0 ? lut.ny() / 2 + k : lut.ny() / 2 - k;
      const double y = lut.yGrid().at(iy);
      s = solveKec(kec, KecInput{y, 0, 0, 0, 0}, &s);
      ASSERT_EQ(s.status, KecStatus::Ok) << y;
      if (std::abs(y) >= y_two_point) break;
      if (kec.inTransition(Side::Left, s.s_lk) || kec.inTransition(Side::Right, s.s_rk)) continue;
      ++compared;
      worst_z = std::max(worst_z, std::abs(s.z - lut.node(kLutZ, iy, ig)));
      worst_phi = std::max(worst_phi, std::abs(s.phi - lut.node(kLutPhi, iy, ig)));
    }
  }
  std::printf(
      "    S1002/60E1: KEC vs LUT at %d nodes outside the bands: |dz| <= %.2e m, "
      "|dphi| <= %.2e rad\n",
      compared, worst_z, worst_phi);
  EXPECT_GT(compared, 40);
  EXPECT_LT(worst_z, 1e-6);
  EXPECT_LT(worst_phi, 1e-6);
}

TEST(Kec, S1002EquivalentProfiles) {
  const KecTable& kec = rbtest::s1002Kec();
  const TableBuildStats& st = kec.stats();
  std::printf(
      "    S1002/60E1 KEC %zu points: build %.3f s, %zu bytes, %zu branch samples, %ld "
      "Newton iterations, %zu warnings\n",
      kec.grid().count(), st.build_seconds, st.bytes, st.nodes, st.newton_iterations,
      st.warnings.size());
  for (const auto& n : st.notes) std::printf("      %s\n", n.c_str());
  EXPECT_EQ(kec.grid().count(), 465u);
  EXPECT_TRUE(st.warnings.empty());
  EXPECT_LT(st.build_seconds, 10.0);
  // The wheel climbs to the flange tip beyond the two-point contact (section 2.4 step 2): the
  // equivalent profiles cover the Table 9 range.
  EXPECT_LT(kec.validMin(Side::Left), -40e-3);
  EXPECT_GT(kec.validMax(Side::Right), 40e-3);
  // Mirror symmetry of the two equivalent profiles.
  for (double s = -0.04; s <= 0.04; s += 0.00137) {
    KecPoint l, r;
    kec.eval(Side::Left, s, l);
    kec.eval(Side::Right, -s, r);
    EXPECT_NEAR(l.value[0], r.value[0], 1e-9) << s;
    EXPECT_NEAR(l.value[static_cast<std::size_t>(KecQuantity::Sw)],
                -r.value[static_cast<std::size_t>(KecQuantity::Sw)], 1e-7)
        << s;
  }
  // One tread-flange transition per wheel: the contact jumps from the tread side (A) to the flange
  // flank (B, ~70 deg) near y = 6.3 mm.
  int flange = 0;
  for (const KecTransition& t : kec.transitions(Side::Left)) {
    std::printf(
        "      left transition at s_k = %+.3f mm [%+.3f, %+.3f]: %s, y = %+.4f mm, "
        "A s_w = %+.3f mm, B s_w = %+.3f mm\n",
        t.s_jump * 1e3, t.lo * 1e3, t.hi * 1e3,
        t.flange ? "tread-flange" : (t.own ? "tread jump" : "other wheel"), t.y * 1e3,
        t.s_w_field * 1e3, t.s_w_flange * 1e3);
    if (!t.flange) continue;
    ++flange;
    EXPECT_NEAR(t.y, 6.26e-3, 0.05e-3);
    EXPECT_LT(t.s_w_flange, -38e-3);
    EXPECT_GT(t.s_w_field, -36e-3);
    // d_hat + d_bar = 1.5 mm, shortened slightly where it meets the transition of the flange-root
    // jump 1.47 mm away.
    EXPECT_NEAR(t.hi - t.lo, 1.5e-3, 0.05e-3);
  }
  EXPECT_EQ(flange, 1);
}

TEST(Kec, RegularisationIsSmoothAndSplitsBetweenAAndB) {
  const KecTable& kec = rbtest::s1002Kec();
  for (const KecTransition& t : kec.transitions(Side::Left)) {
    if (!t.flange) continue;
    // f is C2 through the transition: compare derivatives just inside and outside its ends.
    for (double e : {t.lo, t.hi}) {
      double d1a, d2a, d1b, d2b;
      kec.f(Side::Left, e - 1e-9, &d1a, &d2a);
      kec.f(Side::Left, e + 1e-9, &d1b, &d2b);
      EXPECT_NEAR(d1a, d1b, 1e-5);
      EXPECT_NEAR(d2a, d2b, 1.0);
    }
    // In the transition the contact point C is (1 - w) A + w B with w the weight of B (the flange
    // side: low s_k on the left wheel), ramping linearly from 0 to 1 (checked at the grid nodes).
    const GridSpec& g = kec.grid();
    int inside = 0;
    for (std::size_t i = 0; i < g.count(); ++i) {
      const double s = g.at(i);
      if (s <= t.lo || s >= t.hi) continue;
      ++inside;
      const auto q = [&](KecQuantity k) { return kec.node(Side::Left, k, i); };
      EXPECT_NEAR(q(KecQuantity::Weight), (t.hi - s) / (t.hi - t.lo), 1e-12);
      EXPECT_NEAR(q(KecQuantity::Sw),
                  (1 - q(KecQuantity::Weight)) * q(KecQuantity::SwA) +
                      q(KecQuantity::Weight) * q(KecQuantity::SwB),
                  1e-12);
    }
    EXPECT_GE(inside, 6);
    // Slope of f at the ends: the contact angles of the two branches (f' = tan gamma, to roll).
    double dlo, dhi;
    kec.f(Side::Left, t.lo, &dlo);
    kec.f(Side::Left, t.hi, &dhi);
    EXPECT_GT(std::abs(dlo), 2.0);  // flange side, ~ tan 70 deg
    EXPECT_LT(std::abs(dhi), 1.2);  // tread side
  }
}

TEST(Kec, ShortTransitionIsWarnedAtBuildTime) {
  rb::contact::ContactGeometryConfig cfg = rbtest::s1002On60E1();
  cfg.kec_dhat = 0.02e-3;
  cfg.kec_dbar = 0.03e-3;
  const KecTable kec = buildKec(cfg);
  const auto& w = kec.stats().warnings;
  ASSERT_FALSE(w.empty());
  bool below = false, steep = false, unresolved = false;
  for (const auto& m : w) {
    below = below || m.find("below") != std::string::npos;
    steep = steep || m.find("|f''|") != std::string::npos;
    unresolved = unresolved || m.find("grid") != std::string::npos;
  }
  EXPECT_TRUE(below);
  EXPECT_TRUE(steep);
  EXPECT_TRUE(unresolved);
  for (const auto& m : w) std::printf("    warning: %s\n", m.c_str());
}

TEST(Kec, SolutionJacobianMatchesFiniteDifferences) {
  const KecTable& kec = rbtest::s1002Kec();
  KecInput in{2.7e-3, 0.4e-3, -0.3e-3, 0.2e-3, -0.1e-3};
  const KecSolution s = solveKec(kec, in, nullptr);
  ASSERT_EQ(s.status, KecStatus::Ok);
  EXPECT_LT(s.residual, 1e-12);
  const double h = 1e-7;
  double* p[5] = {&in.y, &in.y_lir, &in.y_rir, &in.z_lir, &in.z_rir};
  for (int j = 0; j < 5; ++j) {
    const double v = *p[j];
    *p[j] = v + h;
    const KecSolution a = solveKec(kec, in, &s);
    *p[j] = v - h;
    const KecSolution b = solveKec(kec, in, &s);
    *p[j] = v;
    const Eigen::Vector4d fd((a.z - b.z) / (2 * h), (a.phi - b.phi) / (2 * h),
                             (a.s_lk - b.s_lk) / (2 * h), (a.s_rk - b.s_rk) / (2 * h));
    EXPECT_LT((fd - s.dx_dp.col(j)).cwiseAbs().maxCoeff(), 1e-6) << "column " << j;
  }
  // Vertical irregularity of both rails lifts the wheelset by the same amount.
  const KecSolution u =
      solveKec(kec, KecInput{in.y, in.y_lir, in.y_rir, in.z_lir + 1e-3, in.z_rir + 1e-3}, &s);
  EXPECT_NEAR(u.z - s.z, 1e-3, 1e-12);
  EXPECT_NEAR(u.phi, s.phi, 1e-13);
}

TEST(Kec, AccelerationLevelTerm) {
  // Along a path p(t), x(t) solves Eq. (22); xddot = dx_dp pddot + quadratic(xdot).
  const KecTable& kec = rbtest::s1002Kec();
  auto input = [](double t) {
    return KecInput{3e-3 + 2e-3 * std::sin(3 * t), 0.3e-3 * std::cos(2 * t), -0.2e-3 * t,
                    0.1e-3 * t * t, 0.05e-3 * std::sin(t)};
  };
  auto pdot = [](double t) {
    return Eigen::Matrix<double, 5, 1>(6e-3 * std::cos(3 * t), -0.6e-3 * std::sin(2 * t), -0.2e-3,
                                       0.2e-3 * t, 0.05e-3 * std::cos(t));
  };
  auto pddot = [](double t) {
    return Eigen::Matrix<double, 5, 1>(-18e-3 * std::sin(3 * t), -1.2e-3 * std::cos(2 * t), 0.0,
                                       0.2e-3, -0.05e-3 * std::sin(t));
  };
  auto state = [&](double t, const KecSolution* w) {
    const KecSolution s = solveKec(kec, input(t), w);
    return Eigen::Vector4d(s.z, s.phi, s.s_lk, s.s_rk);
  };
  const double t = 0.4, h = 1e-4;
  const KecSolution s = solveKec(kec, input(t), nullptr);
  ASSERT_EQ(s.status, KecStatus::Ok);
  const Eigen::Vector4d xdot = s.dx_dp * pdot(t);
  const Eigen::Vector4d xddot = s.dx_dp * pddot(t) + kecQuadraticTerm(s, xdot);
  const Eigen::Vector4d fd = (state(t + h, &s) - 2 * state(t, &s) + state(t - h, &s)) / (h * h);
  const Eigen::Vector4d fd1 = (state(t + h, &s) - state(t - h, &s)) / (2 * h);
  EXPECT_LT((fd1 - xdot).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT((fd - xddot).cwiseAbs().maxCoeff(), 1e-4 * (1 + xddot.cwiseAbs().maxCoeff()));
}

TEST(Kec, FailuresAreRecoverableCodes) {
  const KecTable& kec = rbtest::coneKec();
  // Far outside the computed equivalent profiles: recoverable code, not an exception.
  const KecSolution s = solveKec(kec, KecInput{0.05, 0, 0, 0, 0}, nullptr);
  EXPECT_GT(s.code(), 0);
  const KecSolution n = solveKec(kec, KecInput{std::nan(""), 0, 0, 0, 0}, nullptr);
  EXPECT_EQ(n.status, KecStatus::NotConverged);
  EXPECT_EQ(n.code(), 1);
  const KecSolution ok = kecAt(kec, 2e-3);
  EXPECT_EQ(ok.code(), 0);
}

// The dynamics' values-only lookup: the same values as eval() (bit for bit for the maps; the
// transition end points A, B exact on constant intervals, otherwise also bit for bit).
TEST(Kec, EvalValuesEqualsEval) {
  const KecTable& kec = rbtest::s1002Kec();
  int checked = 0;
  for (const Side side : {Side::Left, Side::Right}) {
    const double lo = kec.validMin(side), hi = kec.validMax(side);
    for (int i = 0; i <= 4000; ++i) {
      const double s = lo + (hi - lo) * i / 4000.0;
      KecPoint full, vals;
      kec.eval(side, s, full);
      kec.evalValues(side, s, vals);
      EXPECT_EQ(vals.inside, full.inside);
      for (std::size_t q = 1; q < kKecQuantities; ++q) {
        if (q < static_cast<std::size_t>(KecQuantity::SwA)) {
          EXPECT_EQ(vals.value[q], full.value[q]) << q << " " << s;
        } else {
          EXPECT_NEAR(vals.value[q], full.value[q], 4e-16 * std::abs(full.value[q]) + 1e-20)
              << q << " " << s;
        }
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, 8002);
}

// kecQuadraticTerm takes g_x^-1 from dx_dp for a solved system; the pivoted LU (the path of an
// unsolved one) gives the same to round-off.
TEST(Kec, QuadraticTermFromDxDpEqualsTheLuSolve) {
  const KecTable& kec = rbtest::s1002Kec();
  for (const double y : {-6e-3, -1e-3, 0.0, 2.5e-3, 6.5e-3}) {
    KecSolution s = kecAt(kec, y);
    s = solveKec(kec, KecInput{y, 1e-3, 0.5e-3, -0.4e-3, 0.7e-3}, &s);
    ASSERT_EQ(s.status, KecStatus::Ok) << y;
    const Eigen::Vector4d xd(0.01, 0.02, -0.03, 0.05);
    const Eigen::Vector4d fast = kecQuadraticTerm(s, xd);
    KecSolution unsolved = s;
    unsolved.status = KecStatus::NotConverged;
    const Eigen::Vector4d lu = kecQuadraticTerm(unsolved, xd);
    EXPECT_LE((fast - lu).cwiseAbs().maxCoeff(), 1e-12 * (lu.cwiseAbs().maxCoeff() + 1e-12)) << y;
  }
}

}  // namespace
