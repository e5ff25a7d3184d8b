// Equivalent conicity (EN 15302) against a cone and the EN 15302 Annex E benchmark cases E1-E9
// (tests/data/en15302: reference tan(gamma_e) with the Annex F tolerance band).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "workbench/profiles/conicity.hpp"

namespace {

using rb::profiles::RollingRadiusDifference;

const std::string kEn15302 = std::string(RB_SOURCE_DIR) + "/tests/data/en15302/";

std::vector<std::vector<double>> readColumns(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    std::vector<double> row;
    double v = 0.0;
    while (ss >> v) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

TEST(EquivalentConicity, ConeGivesItsConicity) {
  for (const double g : {0.05, 0.2, 0.4}) {
    std::vector<double> y, dr;
    for (int i = -100; i <= 100; ++i) {
      y.push_back(0.1 * i);
      dr.push_back(2.0 * g * 0.1 * i);
    }
    const RollingRadiusDifference f(y, dr);
    EXPECT_NEAR(f.centre(), 0.0, 1e-12);
    for (const double a : {0.5, 1.0, 3.0, 7.5, 9.9}) {
      EXPECT_NEAR(f.tanGammaE(a), g, 1e-6 * g) << "a " << a;
      EXPECT_NEAR(f.tanGammaHarmonic(a), g, 1e-9 * g) << "a " << a;
    }
    EXPECT_TRUE(std::isnan(f.tanGammaE(10.5)));
  }
}

// Shifted cone (unequal wheel radii): the oscillation centres on dr = 0.
TEST(EquivalentConicity, ShiftedConeCentresOnZero) {
  std::vector<double> y, dr;
  for (int i = -100; i <= 100; ++i) {
    y.push_back(0.1 * i);
    dr.push_back(0.3 * (0.1 * i - 1.7));
  }
  const RollingRadiusDifference f(y, dr);
  EXPECT_NEAR(f.centre(), 1.7, 1e-12);
  RollingRadiusDifference::Oscillation o;
  ASSERT_TRUE(f.oscillation(3.0, o));
  EXPECT_NEAR(o.y1, -1.3, 1e-9);
  EXPECT_NEAR(o.y2, 4.7, 1e-9);
  EXPECT_NEAR(f.tanGammaE(3.0), 0.15, 1e-6);
}

struct Case {
  const char* name;
  double yFirst;  // [mm] first lateral position of the dr samples (0.1 mm grid)
};

TEST(EquivalentConicity, En15302AnnexEBenchmark) {
  const Case cases[] = {{"E1", -6.8}, {"E2", -6.8}, {"E3", -6.8}, {"E4", -7.1}, {"E5", -6.8},
                        {"E6", -6.9}, {"E7", -6.8}, {"E8", -7.1}, {"E9", -6.8}};
  double worstAll = 0.0, worstHarmonic = 0.0;
  for (const Case& c : cases) {
    const auto drRows = readColumns(kEn15302 + "dr_ce_" + c.name + ".dat");
    const auto ben = readColumns(kEn15302 + "ben_" + c.name + ".dat");
    ASSERT_GT(drRows.size(), 100u);
    std::vector<double> y, dr;
    for (std::size_t i = 0; i < drRows.size(); ++i) {
      y.push_back(c.yFirst + 0.1 * static_cast<double>(i));
      dr.push_back(drRows[i][0]);
    }
    const RollingRadiusDifference f(y, dr);
    double worst = 0.0, worstH = 0.0, maxAmp = 0.0;
    int checked = 0;
    for (const auto& row : ben) {
      ASSERT_GE(row.size(), 4u);
      const double a = row[0], ref = row[1], upper = row[2], lower = row[3];
      const double t = f.tanGammaE(a);
      if (std::isnan(t)) continue;  // amplitude beyond the dr data
      ++checked;
      maxAmp = a;
      EXPECT_LE(t, upper) << c.name << " y-hat " << a;
      EXPECT_GE(t, lower) << c.name << " y-hat " << a;
      worst = std::max(worst, std::abs(t - ref));
      const double th = f.tanGammaHarmonic(a);
      if (!std::isnan(th)) worstH = std::max(worstH, std::abs(th - ref));
    }
    // The unequal-radii cases are off-centre, so their data reach less far.
    EXPECT_GE(maxAmp, 5.0) << c.name;
    std::printf(
        "%s: centre %+.3f mm, %d amplitudes 1.0..%.1f mm, max |tan ge - ref| = %.4f "
        "(harmonic linearisation %.4f)\n",
        c.name, f.centre(), checked, maxAmp, worst, worstH);
    worstAll = std::max(worstAll, worst);
    worstHarmonic = std::max(worstHarmonic, worstH);
  }
  std::printf("EN 15302 E1-E9: max deviation from the reference %.4f (harmonic %.4f)\n", worstAll,
              worstHarmonic);
}

}  // namespace
