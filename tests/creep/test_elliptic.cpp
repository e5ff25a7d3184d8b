// Complete elliptic integrals K(k), E(k) (workbench/creep/elliptic.hpp) against 30-digit values
// (mpmath 1.3 at 100 digits, ellipk/ellipe at m = k^2 with k the exact double used here).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "workbench/creep/elliptic.hpp"

namespace {

using rb::creep::ellipticE;
using rb::creep::ellipticK;
using rb::creep::ellipticKE;
using rb::creep::ellipticKEComplementary;

struct Ref {
  double k, K, E;
};

double rel(double x, double ref) {
  return std::fabs(x - ref) / std::fabs(ref);
}

TEST(Elliptic, CircularLimit) {
  EXPECT_DOUBLE_EQ(ellipticK(0.0), std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(ellipticE(0.0), std::numbers::pi / 2);
  EXPECT_EQ(ellipticKE(0.0).S, 0.0);
}

TEST(Elliptic, BriefValuesAtOneOverSqrt2) {
  const double k = 1.0 / std::sqrt(2.0);
  EXPECT_LT(rel(ellipticK(k), 1.854074677301372), 1e-14);
  EXPECT_LT(rel(ellipticE(k), 1.350643881047675), 1e-14);
}

TEST(Elliptic, AgainstHighPrecision) {
  const Ref refs[] = {
      {0.1, 1.57474556151735595, 1.56686194202166829},
      {0.5, 1.68575035481259604, 1.46746220933942716},
      {0.7071067811865476, 1.85407467730137198, 1.35064388104767547},
      {0.9, 2.2805491384227703, 1.17169705278161411},
      {0.99, 3.35660052336119194, 1.02847580902880402},
      {0.999999, 7.94747977354796703, 1.00000744747772439},
  };
  double worst = 0.0;
  for (const Ref& r : refs) {
    const auto ke = ellipticKE(r.k);
    worst = std::max({worst, rel(ke.K, r.K), rel(ke.E, r.E)});
    EXPECT_LT(rel(ke.K, r.K), 1e-14) << "k = " << r.k;
    EXPECT_LT(rel(ke.E, r.E), 1e-14) << "k = " << r.k;
    EXPECT_NEAR(ke.S, 1.0 - r.E / r.K, 1e-15);
    // Negative modulus: even functions.
    EXPECT_EQ(ellipticK(-r.k), ke.K);
  }
  std::printf("elliptic K, E (modulus form): worst relative error %.2e\n", worst);
}

TEST(Elliptic, ComplementaryModulusNearOne) {
  // {k', K, E}
  const Ref refs[] = {
      {1e-3, 8.29405146361543996, 1.00000389702617206},
      {1e-8, 19.8069751050722565, 1.00000000000000097},
      {1e-15, 35.9250707560305758, 1.0},
      {1e-12, 29.0173154770484388, 1.0},
      {1e-5, 12.8992198263875995, 1.00000000061996099},
      {1e-4, 10.5966347570876603, 1.00000005048317384},
      {3e-4, 9.49802263563347824, 1.00000040491102278},
      {1e-2, 5.99158934050699638, 1.00027458243066297},
      {0.02119, 5.24099639882802066, 1.00106444215790842},
      {0.1, 3.69563736298987462, 1.01599354502522394},
      {0.5, 2.15651564749964324, 1.21105602756845952},
  };
  double worst = 0.0;
  for (const Ref& r : refs) {
    const auto ke = ellipticKEComplementary(r.k);
    worst = std::max({worst, rel(ke.K, r.K), rel(ke.E, r.E)});
    EXPECT_LT(rel(ke.K, r.K), 1e-14) << "k' = " << r.k;
    EXPECT_LT(rel(ke.E, r.E), 1e-14) << "k' = " << r.k;
  }
  std::printf("elliptic K, E (complementary form): worst relative error %.2e\n", worst);
  // Both entry points agree where both are accurate.
  const auto a = ellipticKE(0.6);
  const auto b = ellipticKEComplementary(0.8);
  EXPECT_NEAR(a.K, b.K, 4e-16 * a.K);
  EXPECT_NEAR(a.E, b.E, 4e-16 * a.E);
}

TEST(Elliptic, EndPoint) {
  const auto ke = ellipticKE(1.0);
  EXPECT_EQ(ke.K, std::numeric_limits<double>::infinity());
  EXPECT_EQ(ke.E, 1.0);
  const auto kc = ellipticKEComplementary(0.0);
  EXPECT_EQ(kc.K, std::numeric_limits<double>::infinity());
  EXPECT_EQ(kc.E, 1.0);
}

TEST(Elliptic, LegendreRelation) {
  // E K' + E' K - K K' = pi/2 (DLMF 19.7.1), a check independent of tabulated values.
  for (double k = 0.05; k < 1.0; k += 0.05) {
    const double kp = std::sqrt(1.0 - k * k);
    const auto a = ellipticKE(k);
    const auto b = ellipticKE(kp);
    EXPECT_NEAR(a.E * b.K + b.E * a.K - a.K * b.K, std::numbers::pi / 2, 2e-15) << k;
  }
}

}  // namespace
