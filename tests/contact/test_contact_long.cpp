// Refined tables (paper Tables 9-10 "after refinement"): build times and sizes, and the KEC/LUT
// consistency on the refined grids. Labelled "long" (ctest -L long); not part of the default run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact_test_util.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"

namespace {

using namespace rb::contact;

TEST(ContactLong, RefinedTablesS1002) {
  ContactGeometryConfig cfg = rbtest::s1002On60E1();
  cfg.useRefinedGrids();
  const LutTable lut = buildLut(cfg);
  const KecTable kec = buildKec(cfg);
  std::printf(
      "    refined LUT %zu x %zu: %.3f s, %.2f MB; refined KEC %zu points: %.3f s, %.3f MB\n",
      lut.ny(), lut.ng(), lut.stats().build_seconds, static_cast<double>(lut.stats().bytes) / 1e6,
      kec.grid().count(), kec.stats().build_seconds, static_cast<double>(kec.stats().bytes) / 1e6);
  for (const auto& w : kec.stats().warnings) std::printf("    warning: %s\n", w.c_str());
  EXPECT_EQ(lut.ny(), 721u);
  EXPECT_EQ(kec.grid().count(), 5001u);
  EXPECT_EQ(lut.stats().failures, 0u);
  EXPECT_TRUE(lut.stats().warnings.empty());
  EXPECT_TRUE(kec.stats().warnings.empty());
  const std::size_t ig = 5;
  double worst = 0.0;
  int compared = 0;
  for (int dir : {+1, -1}) {
    KecSolution s = solveKec(kec, KecInput{});
    for (std::size_t k = 1; k <= lut.ny() / 2; ++k) {
      const std::size_t iy = dir > 0 ? lut.ny() / 2 + k : lut.ny() / 2 - k;
      const double y = lut.yGrid().at(iy);
      if (std::abs(y) > 6e-3) break;
      s = solveKec(kec, KecInput{y, 0, 0, 0, 0}, &s);
      ASSERT_EQ(s.status, KecStatus::Ok);
      if (kec.inTransition(Side::Left, s.s_lk) || kec.inTransition(Side::Right, s.s_rk)) continue;
      ++compared;
      worst = std::max({worst, std::abs(s.z - lut.node(kLutZ, iy, ig)),
                        std::abs(s.phi - lut.node(kLutPhi, iy, ig))});
    }
  }
  std::printf("    refined KEC vs LUT at %d nodes: worst %.2e\n", compared, worst);
  EXPECT_LT(worst, 1e-6);
  // Information: the KEC profiles are built without irregularity (section 2.4); with a gauge
  // variation (y_lir = -y_rir = xi_g / 2) they approximate the LUT, which solves it exactly.
  for (std::size_t jg : {3u, 7u}) {
    const double xi = lut.gaugeGrid().at(jg);
    double dz = 0.0, dphi = 0.0;
    KecSolution s = solveKec(kec, KecInput{0.0, 0.5 * xi, -0.5 * xi, 0, 0});
    for (std::size_t iy = lut.ny() / 2; iy < lut.ny(); ++iy) {
      const double y = lut.yGrid().at(iy);
      if (y > 4e-3) break;
      s = solveKec(kec, KecInput{y, 0.5 * xi, -0.5 * xi, 0, 0}, &s);
      if (kec.inTransition(Side::Left, s.s_lk) || kec.inTransition(Side::Right, s.s_rk)) continue;
      dz = std::max(dz, std::abs(s.z - lut.node(kLutZ, iy, jg)));
      dphi = std::max(dphi, std::abs(s.phi - lut.node(kLutPhi, iy, jg)));
    }
    std::printf(
        "    xi_g = %+.0f mm: KEC (built at xi_g = 0) vs LUT for 0 <= y <= 4 mm outside the "
        "bands: |dz| <= %.2e m, |dphi| <= %.2e rad\n",
        xi * 1e3, dz, dphi);
  }
}

}  // namespace
