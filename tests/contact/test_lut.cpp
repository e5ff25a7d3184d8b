// Contact lookup table (Eq. 14): nodes, interpolation accuracy and smoothness, S1002/60E1 facts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact_tables.hpp"
#include "workbench/contact/derived.hpp"
#include "workbench/contact/geometry.hpp"
#include "workbench/profiles/conicity.hpp"

namespace {

using namespace rb::contact;

TEST(Lut, NodesAreTheSolvedGeometry) {
  const LutTable& lut = rbtest::coneLut();
  const ContactSolver solver(rbtest::coneConfig());
  for (std::size_t ig = 0; ig < lut.ng(); ++ig) {
    for (std::size_t iy = 0; iy < lut.ny(); iy += 17) {
      const double y = lut.yGrid().at(iy), xi = lut.gaugeGrid().at(ig);
      const TreadContact t = solver.solveTread(y, xi);
      ASSERT_TRUE(t.converged);
      EXPECT_NEAR(lut.node(kLutZ, iy, ig), t.z, 1e-12);
      EXPECT_NEAR(lut.node(kLutPhi, iy, ig), t.phi, 1e-12);
      EXPECT_NEAR(lut.node(lutChannel(Side::Left, TreadQuantity::Sw), iy, ig), t.s[0], 1e-10);
      // Interpolant through the nodes.
      const LutValue v = lut.evalChannel(kLutZ, y, xi);
      EXPECT_NEAR(v.v, t.z, 1e-13);
    }
  }
}

// evalValues (the dynamics' values-only path) returns exactly eval()'s values, inside and outside.
TEST(Lut, EvalValuesIsBitIdenticalToEval) {
  const LutTable& lut = rbtest::coneLut();
  LutSample full, vals;
  for (double y = -9.1e-3; y < 9.1e-3; y += 0.377e-3) {
    for (double xi = -6e-3; xi < 6e-3; xi += 0.91e-3) {
      lut.eval(y, xi, full);
      lut.evalValues(y, xi, vals);
      EXPECT_EQ(full.inside, vals.inside);
      for (std::size_t ch = 0; ch < kLutChannels; ++ch)
        ASSERT_EQ(full.value[ch], vals.value[ch]) << ch << " " << y << " " << xi;
    }
  }
}

// The channel-range evalValues gives exactly the full call's values in [first, last) and leaves
// the other channels untouched.
TEST(Lut, EvalValuesOfAChannelRange) {
  const LutTable& lut = rbtest::coneLut();
  LutSample full, part;
  const std::size_t first = lutChannel(Side::Right, FlangeQuantity::Sw);
  const std::size_t last = lutChannel(Side::Right, FlangeQuantity::DdeltaDphi) + 1;
  for (double y = -9.1e-3; y < 9.1e-3; y += 0.377e-3) {
    for (double xi = -6e-3; xi < 6e-3; xi += 0.91e-3) {
      lut.evalValues(y, xi, full);
      part.value.fill(-7.0);
      part.inside = !full.inside;
      lut.evalValues(y, xi, part, first, last);
      EXPECT_EQ(full.inside, part.inside);
      for (std::size_t ch = 0; ch < kLutChannels; ++ch)
        ASSERT_EQ(part.value[ch], ch >= first && ch < last ? full.value[ch] : -7.0)
            << ch << " " << y << " " << xi;
    }
  }
}

TEST(Lut, InterpolationAccuracyBetweenNodes) {
  // Cone on arc: smooth geometry, so the error is the interpolation error: O(h^4) in y (splines)
  // and O(h^3) in xi_g (Akima, 1 mm steps).
  const LutTable& lut = rbtest::coneLut();
  const ContactSolver solver(rbtest::coneConfig());
  double err_z = 0.0, err_phi = 0.0, err_dz = 0.0;
  for (double y = -7.93e-3; y < 7.9e-3; y += 0.731e-3) {
    for (double xi : {-1.57e-3, -0.5e-3, 0.0, 0.33e-3, 1.41e-3}) {
      const TreadContact t = solver.solveTread(y, xi);
      ASSERT_TRUE(t.converged);
      LutSample s;
      lut.eval(y, xi, s);
      EXPECT_TRUE(s.inside);
      err_z = std::max(err_z, std::abs(s.value[kLutZ] - t.z));
      err_phi = std::max(err_phi, std::abs(s.value[kLutPhi] - t.phi));
      // Derivative against a central difference of the exact solution.
      const double h = 1e-6;
      const TreadContact a = solver.solveTread(y + h, xi, &t), b = solver.solveTread(y - h, xi, &t);
      err_dz = std::max(err_dz, std::abs(s.d_dy[kLutZ] - (a.z - b.z) / (2 * h)));
    }
  }
  std::printf(
      "    cone/arc LUT interpolation: |dz| <= %.2e m, |dphi| <= %.2e rad, "
      "|d(dz/dy)| <= %.2e\n",
      err_z, err_phi, err_dz);
  EXPECT_LT(err_z, 1e-9);
  EXPECT_LT(err_phi, 1e-8);
  EXPECT_LT(err_dz, 1e-5);
}

TEST(Lut, InterpolantIsC1AcrossCells) {
  const LutTable& lut = rbtest::s1002Lut();
  const double eps = 1e-11;
  // Cell edges in y and in xi_g, away from contact-point jumps: values and first derivatives agree
  // on both sides (up to the change over 2 eps).
  for (double y : {1.0e-3, 2.3e-3, -3.1e-3}) {
    for (std::size_t c : {kLutZ, kLutPhi, lutChannel(Side::Left, TreadQuantity::Gamma)}) {
      const LutValue a = lut.evalChannel(c, y - eps, 0.37e-3),
                     b = lut.evalChannel(c, y + eps, 0.37e-3);
      EXPECT_NEAR(a.v, b.v, 4 * eps * std::abs(a.dy) + 1e-15 * (1 + std::abs(a.v)));
      EXPECT_NEAR(a.dy, b.dy, 4 * eps * std::abs(a.dyy) + 1e-9 * (1 + std::abs(a.dy)));
      EXPECT_NEAR(a.dxi, b.dxi, 4 * eps * std::abs(a.dyxi) + 1e-9 * (1 + std::abs(a.dxi)));
    }
  }
  for (double xi : {-1e-3, 2e-3}) {
    const LutValue a = lut.evalChannel(kLutZ, 1.234e-3, xi - eps);
    const LutValue b = lut.evalChannel(kLutZ, 1.234e-3, xi + eps);
    EXPECT_NEAR(a.v, b.v, 4 * eps * std::abs(a.dxi) + 1e-15);
    EXPECT_NEAR(a.dy, b.dy, 4 * eps * std::abs(a.dyxi) + 1e-9);
    EXPECT_NEAR(a.dxi, b.dxi, 4 * eps * std::abs(a.dxixi) + 1e-9);
  }
}

TEST(Lut, DerivativesAreThoseOfTheInterpolant) {
  const LutTable& lut = rbtest::s1002Lut();
  const double hy = lut.yGrid().step, hg = lut.gaugeGrid().step;
  for (double y : {-4.33e-3, 1.71e-3, 3.05e-3}) {
    for (double xi : {-2.4e-3, 0.6e-3}) {
      LutSample s;
      lut.eval(y, xi, s);
      for (std::size_t c = 0; c < kLutChannels; ++c) {
        const LutValue v = lut.evalChannel(c, y, xi);
        // Size of the terms the interpolant adds up (for the round-off of the differences).
        const double S = std::abs(v.v) + std::abs(v.dy) * hy + std::abs(v.dxi) * hg + 1e-12;
        EXPECT_NEAR(v.v, s.value[c], 1e-15 * S);
        EXPECT_NEAR(v.dy, s.d_dy[c], 1e-13 * S / hy);
        EXPECT_NEAR(v.dxi, s.d_dxi[c], 1e-13 * S / hg);
        // Within a cell the interpolant is bicubic: central differences are exact for the first
        // derivatives up to O(h^2) and for the second ones up to round-off.
        const double h = 1e-7;
        const LutValue p = lut.evalChannel(c, y + h, xi), m = lut.evalChannel(c, y - h, xi);
        EXPECT_NEAR((p.v - m.v) / (2 * h), v.dy, 1e-5 * S / hy + 1e-14 * S / h)
            << lutChannelName(c);
        EXPECT_NEAR((p.dy - m.dy) / (2 * h), v.dyy, 1e-6 * std::abs(v.dyy) + 1e-14 * S / (h * hy))
            << lutChannelName(c);
        const LutValue q = lut.evalChannel(c, y, xi + h), r = lut.evalChannel(c, y, xi - h);
        EXPECT_NEAR((q.v - r.v) / (2 * h), v.dxi, 1e-5 * S / hg + 1e-14 * S / h)
            << lutChannelName(c);
        EXPECT_NEAR((q.dy - r.dy) / (2 * h), v.dyxi, 1e-6 * std::abs(v.dyxi) + 1e-14 * S / (h * hy))
            << lutChannelName(c);
        EXPECT_NEAR((q.dxi - r.dxi) / (2 * h), v.dxixi,
                    1e-6 * std::abs(v.dxixi) + 1e-14 * S / (h * hg))
            << lutChannelName(c);
      }
    }
  }
  // Outside the grid: flagged, extrapolated from the end cells.
  EXPECT_FALSE(lut.evalChannel(kLutZ, 0.02, 0.0).inside);
  EXPECT_FALSE(lut.evalChannel(kLutZ, 0.0, 0.006).inside);
  EXPECT_TRUE(lut.evalChannel(kLutZ, 0.018, 0.005).inside);
}

TEST(Lut, S1002TableBuildAndSymmetry) {
  const LutTable& lut = rbtest::s1002Lut();
  const TableBuildStats& st = lut.stats();
  std::printf(
      "    S1002/60E1 LUT %zu x %zu: build %.3f s, %.2f MB, %ld Newton iterations, %zu "
      "restarts, %zu failures, %zu warnings\n",
      lut.ny(), lut.ng(), st.build_seconds, static_cast<double>(st.bytes) / 1e6,
      st.newton_iterations, st.restarts, st.failures, st.warnings.size());
  EXPECT_EQ(lut.ny(), 361u);
  EXPECT_EQ(lut.ng(), 11u);
  EXPECT_EQ(st.failures, 0u);
  EXPECT_TRUE(st.warnings.empty());
  EXPECT_LT(st.build_seconds, 10.0);
  EXPECT_EQ(lut.configHash(), configHash(rbtest::s1002On60E1()));
  // Mirror: node (y) against node (-y) for xi_g = 0 (the grid is symmetric).
  const std::size_t ig = 5, ny = lut.ny();
  for (std::size_t iy = 0; iy < ny; ++iy) {
    const std::size_t jy = ny - 1 - iy;
    EXPECT_NEAR(lut.node(kLutZ, iy, ig), lut.node(kLutZ, jy, ig), 1e-11);
    EXPECT_NEAR(lut.node(kLutPhi, iy, ig), -lut.node(kLutPhi, jy, ig), 1e-11);
    for (std::size_t q = 0; q < kTreadQuantities; ++q) {
      const auto tq = static_cast<TreadQuantity>(q);
      const double sign = (tq == TreadQuantity::Sw || tq == TreadQuantity::Sr) ? -1.0 : 1.0;
      EXPECT_NEAR(lut.node(lutChannel(Side::Left, tq), iy, ig),
                  sign * lut.node(lutChannel(Side::Right, tq), jy, ig),
                  1e-8 * (1 + std::abs(lut.node(lutChannel(Side::Left, tq), iy, ig))))
          << lutChannelName(lutChannel(Side::Left, tq)) << " y = " << lut.yGrid().at(iy);
    }
    EXPECT_NEAR(lut.node(lutChannel(Side::Left, FlangeQuantity::Delta), iy, ig),
                lut.node(lutChannel(Side::Right, FlangeQuantity::Delta), jy, ig), 1e-10);
  }
}

TEST(Lut, S1002JumpsAndTwoPointContact) {
  const LutTable& lut = rbtest::s1002Lut();
  // Contact-point jumps at xi_g = 0: the known S1002/60E1 1:40 tread jump near |y| = 0.2 mm and the
  // jump to the flange root near |y| = 5 mm, mirrored.
  int tread = 0, root = 0;
  for (const LutJump& j : lut.jumps()) {
    if (j.xi_g != 0.0) continue;
    const double y = std::abs(0.5 * (j.y_before + j.y_after));
    if (y < 0.5e-3) ++tread;
    if (y > 4.5e-3 && y < 5.5e-3) ++root;
    std::printf("    jump (xi_g = 0): %s wheel, y %+.2f -> %+.2f mm, s_w %+.3f -> %+.3f mm\n",
                j.side == Side::Left ? "left " : "right", j.y_before * 1e3, j.y_after * 1e3,
                j.s_w_before * 1e3, j.s_w_after * 1e3);
  }
  EXPECT_EQ(tread, 2);
  EXPECT_EQ(root, 2);
  // Two-point contact (flange touches while the tread constraint holds), both sides, all gauges.
  double y_left = 0.0, y_right = 0.0;
  for (const TwoPointContact& p : lut.twoPointContacts()) {
    if (p.xi_g == 0.0) (p.side == Side::Left ? y_left : y_right) = p.y;
    if (p.xi_g == 0.0) {
      std::printf(
          "    two-point contact (xi_g = 0): %s wheel at y = %+.4f mm: tread s_w = %.3f mm "
          "(%.1f deg%s), flange s_w = %.3f mm (%.1f deg)\n",
          p.side == Side::Left ? "left " : "right", p.y * 1e3, p.s_w_tread * 1e3,
          p.gamma_tread * 180 / M_PI, p.tread_edge ? ", at the tread/flange boundary" : "",
          p.s_w_flange * 1e3, p.gamma_flange * 180 / M_PI);
    }
  }
  EXPECT_EQ(lut.twoPointContacts().size(), 2 * lut.ng());
  EXPECT_GT(y_left, 6e-3);
  EXPECT_LT(y_left, 9e-3);
  EXPECT_NEAR(y_right, -y_left, 1e-9);
  // Wider gauge: the flange touches later (about xi_g / 2 per unit of gauge widening).
  for (const TwoPointContact& p : lut.twoPointContacts()) {
    if (p.side == Side::Left) {
      EXPECT_NEAR(p.y - y_left, 0.5 * p.xi_g, 0.1e-3) << p.xi_g;
    }
  }
}

TEST(Lut, RollingRadiusDifferenceAndConicity) {
  // Cone on a rounded rail head: delta_r is linear in y, 2 lambda_e y with lambda_e = lambda (1 +
  // R phi / y) (the roll moves the contact on the head), and the EN 15302 conicity is lambda_e.
  const RollingRadiusTable cone = rollingRadiusDifference(rbtest::coneLut());
  ASSERT_EQ(cone.y.size(), rbtest::coneLut().ny());
  const double lambda_e = 0.5 * cone.delta_r.back() / cone.y.back();
  EXPECT_NEAR(lambda_e, 1.0 / 20.0, 0.1 / 20.0);
  for (std::size_t i = 0; i < cone.y.size(); i += 20) {
    EXPECT_NEAR(cone.delta_r[i], 2.0 * lambda_e * cone.y[i], 1e-3 * std::abs(cone.y[i]) + 1e-12);
    EXPECT_NEAR(cone.delta_gamma[i], cone.gamma_left[i] - cone.gamma_right[i], 0.0);
  }
  const rb::profiles::RollingRadiusDifference rc(cone.y, cone.delta_r);
  EXPECT_NEAR(rc.tanGammaE(3e-3), lambda_e, 1e-3 * lambda_e);
  // S1002 / 60E1 1:40, G 1435, B 1360.
  const RollingRadiusTable s = rollingRadiusDifference(rbtest::s1002Lut());
  const rb::profiles::RollingRadiusDifference rs(s.y, s.delta_r);
  const double c2 = rs.tanGammaE(2e-3), c3 = rs.tanGammaE(3e-3), c4 = rs.tanGammaE(4e-3);
  std::printf("    S1002/60E1 1:40 equivalent conicity: %.3f (2 mm), %.3f (3 mm), %.3f (4 mm)\n",
              c2, c3, c4);
  EXPECT_GT(c3, 0.05);
  EXPECT_LT(c3, 0.5);
  // Interpolated gauge line equals the node line on a node.
  const RollingRadiusTable s1 = rollingRadiusDifference(rbtest::s1002Lut(), 1e-3);
  const RollingRadiusTable s1i = rollingRadiusDifference(rbtest::s1002Lut(), 1e-3 + 1e-11);
  for (std::size_t i = 0; i < s1.y.size(); i += 7)
    EXPECT_NEAR(s1.delta_r[i], s1i.delta_r[i], 1e-10);
}

}  // namespace
