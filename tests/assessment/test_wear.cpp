// Wear number and frictional power (workbench/assessment/wear.hpp) of synthetic patches.
#include <gtest/gtest.h>

#include <vector>

#include "workbench/assessment/wear.hpp"

namespace {

using namespace rb::assessment::wear;

TEST(Wear, TGammaOfASyntheticPatch) {
  // |1000 * 0.002| + |-5000 * -0.003| + |20 * 0.5| = 2 + 15 + 10 = 27 N.
  const PatchCreep p{1000.0, -5000.0, 20.0, 0.002, -0.003, 0.5};
  EXPECT_NEAR(tGamma(p), 27.0, 1e-12);
  EXPECT_NEAR(frictionalPower(p, 20.0), 540.0, 1e-9);  // 27 N * 20 m/s
  PatchCreep no_spin = p;
  no_spin.mz = 0.0;
  EXPECT_NEAR(tGamma(no_spin), 17.0, 1e-12);
}

TEST(Wear, SeriesWheelSumAndEnergy) {
  const std::vector<double> fx{1000.0, 1000.0, 1000.0}, fy{-5000.0, -5000.0, -5000.0};
  const std::vector<double> nux{0.002, 0.002, 0.002}, nuy{-0.003, -0.003, -0.003};
  const std::vector<double> mz{20.0, 20.0, 20.0}, phi{0.5, 0.5, 0.5};
  std::vector<double> tread(3), flange(3);
  tGammaSeries(fx, fy, mz, nux, nuy, phi, tread);
  tGammaSeries(fx, fy, {}, nux, nuy, {}, flange);
  EXPECT_NEAR(tread[1], 27.0, 1e-12);
  EXPECT_NEAR(flange[1], 17.0, 1e-12);
  std::vector<double> wheel(3, 0.0);
  addPatch(wheel, tread);
  addPatch(wheel, flange);
  const WearSummary w = summarize(wheel, std::vector<double>{0.0, 1.0, 3.0});
  EXPECT_NEAR(w.mean, 44.0, 1e-12);
  EXPECT_NEAR(w.max, 44.0, 1e-12);
  EXPECT_NEAR(w.energy, 44.0 * 3.0, 1e-9);  // 44 N over 3 m
}

}  // namespace
