// Kalker coefficients (workbench/creep/kalker.hpp) against
// tests/data/creep/kalker_creep_coefficients_tableE3.txt.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "workbench/creep/kalker.hpp"

namespace {

using rb::creep::kalkerCoefficients;
using rb::creep::KalkerCoefficients;

struct Row {
  bool a_less_b;
  double g;
  double v[12];  // C11, C22, C23, C33 at nu = 0, 0.25, 0.5
};

std::vector<Row> readTable() {
  const std::string path =
      std::string(RB_SOURCE_DIR) + "/tests/data/creep/kalker_creep_coefficients_tableE3.txt";
  std::ifstream in(path);
  std::vector<Row> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("a<b", 0) != 0 && line.rfind("a>b", 0) != 0) continue;
    std::istringstream s(line);
    std::string tag;
    Row r{};
    s >> tag >> r.g;
    r.a_less_b = tag == "a<b";
    for (double& x : r.v) s >> x;
    if (s) rows.push_back(r);
  }
  return rows;
}

double get(const KalkerCoefficients& c, int k) {
  return k == 0 ? c.c11 : k == 1 ? c.c22 : k == 2 ? c.c23 : c.c33;
}

TEST(Kalker, TablePointsReproduced) {
  const auto rows = readTable();
  ASSERT_EQ(rows.size(), 20u) << "table file missing or changed";
  const double nus[3] = {0.0, 0.25, 0.5};
  for (const Row& r : rows) {
    const double a_over_b = r.a_less_b ? r.g : 1.0 / r.g;
    for (int j = 0; j < 3; ++j) {
      const KalkerCoefficients c = kalkerCoefficients(a_over_b, nus[j]);
      for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(get(c, k), r.v[3 * k + j], 1e-12)
            << (r.a_less_b ? "a<b" : "a>b") << " g=" << r.g << " nu=" << nus[j] << " C" << k;
    }
  }
}

TEST(Kalker, CircularValue) {
  // Circular contact, nu = 0.25: C11 4.12, C22 3.67, C23 1.47 (reference note s.5).
  const KalkerCoefficients c = kalkerCoefficients(1.0, 0.25);
  EXPECT_DOUBLE_EQ(c.c11, 4.12);
  EXPECT_DOUBLE_EQ(c.c22, 3.67);
  EXPECT_DOUBLE_EQ(c.c23, 1.47);
}

TEST(Kalker, LinearInNu) {
  // nu = 0.28: 12 % of the way from 0.25 to 0.5.
  const KalkerCoefficients c = kalkerCoefficients(1.0, 0.28);
  EXPECT_NEAR(c.c11, 4.12 + 0.12 * (5.20 - 4.12), 1e-12);
  EXPECT_NEAR(c.c22, 3.67 + 0.12 * (3.98 - 3.67), 1e-12);
  EXPECT_NEAR(c.c23, 1.47 + 0.12 * (1.63 - 1.47), 1e-12);
}

TEST(Kalker, MonotoneBetweenTablePoints) {
  // Between neighbouring table points every coefficient stays between the two end values, and
  // C11, C22, C23 increase with a/b over the whole table (both halves) at nu = 0.25 and 0.28.
  const auto rows = readTable();
  for (double nu : {0.25, 0.28}) {
    KalkerCoefficients prev = kalkerCoefficients(0.1, nu);
    const int n = 4000;
    for (int i = 1; i <= n; ++i) {
      const double ab = std::pow(10.0, -1.0 + 2.0 * i / n);  // a/b from 0.1 to 10
      const KalkerCoefficients c = kalkerCoefficients(ab, nu);
      EXPECT_GE(c.c11, prev.c11 - 1e-12) << ab;
      EXPECT_GE(c.c22, prev.c22 - 1e-12) << ab;
      EXPECT_GE(c.c23, prev.c23 - 1e-12) << ab;
      prev = c;
    }
  }
  for (const Row& lo : rows) {
    for (const Row& hi : rows) {
      if (lo.a_less_b != hi.a_less_b || std::fabs(hi.g - lo.g - 0.1) > 1e-9) continue;
      for (int j = 0; j < 3; ++j) {
        const double nu = 0.25 * j;
        for (int s = 1; s < 10; ++s) {
          const double g = lo.g + 0.01 * s;
          const KalkerCoefficients c = kalkerCoefficients(lo.a_less_b ? g : 1.0 / g, nu);
          for (int k = 0; k < 4; ++k) {
            const double v0 = lo.v[3 * k + j], v1 = hi.v[3 * k + j];
            EXPECT_GE(get(c, k), std::min(v0, v1) - 1e-12);
            EXPECT_LE(get(c, k), std::max(v0, v1) + 1e-12);
          }
        }
      }
    }
  }
}

TEST(Kalker, OutsideTheTable) {
  EXPECT_TRUE(rb::creep::kalkerInTable(2.0, 0.28));
  EXPECT_FALSE(rb::creep::kalkerInTable(20.0, 0.28));
  EXPECT_FALSE(rb::creep::kalkerInTable(0.05, 0.28));
  EXPECT_FALSE(rb::creep::kalkerInTable(1.0, 0.6));
  // Poisson's ratio is clamped to the table's columns.
  EXPECT_EQ(kalkerCoefficients(1.0, 0.7).c11, kalkerCoefficients(1.0, 0.5).c11);
  EXPECT_EQ(kalkerCoefficients(1.0, -0.1).c11, kalkerCoefficients(1.0, 0.0).c11);
  EXPECT_THROW(kalkerCoefficients(0.0, 0.28), std::logic_error);
  EXPECT_THROW(kalkerCoefficients(std::nan(""), 0.28), std::logic_error);
}

// Beyond a/b = 10 (flange patches, a/b 15-25) and below 0.1 the coefficients follow Kalker's
// asymptotes instead of the last row: continuous at the table's edge, growing like the asymptote
// (C11, C22 ~ 1/(g ln(1/g)), C23 ~ g^-1.5 / ln(1/g) for g = b/a -> 0), and equal to it in the
// limit.
TEST(Kalker, AsymptotesBeyondTheTable) {
  for (double nu : {0.0, 0.25, 0.28, 0.5}) {
    for (double edge : {10.0, 0.1}) {
      SCOPED_TRACE("nu = " + std::to_string(nu) + ", edge a/b = " + std::to_string(edge));
      const double out = edge > 1.0 ? 1.0 + 1e-9 : 1.0 - 1e-9;  // just outside the table
      const KalkerCoefficients in = kalkerCoefficients(edge, nu);
      const KalkerCoefficients just = kalkerCoefficients(edge * out, nu);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(get(just, k), get(in, k), 1e-6 * get(in, k));
      EXPECT_EQ(just.c33, in.c33);  // C33 (UNVERIFIED) keeps the last row
      // The asymptote itself is within 7 % of the table at its last row (CONTACT's linrol
      // switches between them there).
      const KalkerCoefficients asym = rb::creep::kalkerAsymptote(edge, nu);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(get(asym, k) / get(in, k), 1.0, 0.07);
      // In the limit the coefficients are the asymptote's.
      const double far = edge > 1.0 ? 1e4 : 1e-4;
      const KalkerCoefficients lim = kalkerCoefficients(far, nu);
      const KalkerCoefficients lim_asym = rb::creep::kalkerAsymptote(far, nu);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(get(lim, k) / get(lim_asym, k), 1.0, 1e-3);
    }
    // Flange patches: the coefficients grow past the table, C23 fastest.
    const KalkerCoefficients at10 = kalkerCoefficients(10.0, nu);
    const KalkerCoefficients at20 = kalkerCoefficients(20.0, nu);
    EXPECT_GT(at20.c11, 1.3 * at10.c11);
    EXPECT_GT(at20.c22, 1.3 * at10.c22);
    EXPECT_GT(at20.c23, 2.0 * at10.c23);
    double prev = 0.0;
    for (double ab = 10.0; ab <= 40.0; ab += 0.5) {  // monotone across the edge
      const double c23 = kalkerCoefficients(ab, nu).c23;
      EXPECT_GT(c23, prev);
      prev = c23;
    }
  }
}

}  // namespace
