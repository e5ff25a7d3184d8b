// Hertz ellipse (workbench/creep/hertz.hpp): circular closed forms, the derived m, n table of
// tests/data/creep/derived_hertz_m_n_table.txt, N = K_H delta^1.5, and the flange stiffness
// table of docs/creep.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "workbench/creep/elliptic.hpp"
#include "workbench/creep/hertz.hpp"

namespace {

using namespace rb::creep;

constexpr double kPi = std::numbers::pi;
const Material kSteel{};  // E = 2.1e11 Pa, nu = 0.28 (paper section 5.3)

double rel(double x, double ref) {
  return std::fabs(x - ref) / std::fabs(ref);
}

TEST(Hertz, MaterialConstants) {
  EXPECT_DOUBLE_EQ(shearModulus(kSteel), 2.1e11 / 2.56);
  EXPECT_DOUBLE_EQ(contactModulus(kSteel), 2.1e11 / (2.0 * (1.0 - 0.28 * 0.28)));
}

TEST(Hertz, RelativeCurvaturesConvention) {
  // Wheel r = 0.46 m on a straight rail; wheel profile concave R 0.32 m, rail crown convex R 0.3 m.
  const auto k = relativeCurvatures(1.0 / 0.46, -1.0 / 0.32, 0.0, 1.0 / 0.3);
  EXPECT_DOUBLE_EQ(k.A, 0.5 / 0.46);
  EXPECT_DOUBLE_EQ(k.B, 0.5 * (1.0 / 0.3 - 1.0 / 0.32));
  EXPECT_TRUE(isHertzian(k));
  // A concave wheel profile tighter than the rail head: no Hertz contact.
  EXPECT_FALSE(isHertzian(relativeCurvatures(1.0 / 0.46, -1.0 / 0.012, 0.0, 1.0 / 0.013)));
  EXPECT_THROW(hertzShape(1.0, 0.0), std::logic_error);
  EXPECT_THROW(hertzShape(-1.0, 1.0), std::logic_error);
}

TEST(Hertz, CircularContactClassicalFormulas) {
  const double R = 0.3;  // effective radius: A = B = 1/(2R)
  const RelativeCurvatures k{0.5 / R, 0.5 / R};
  const double N = 1.0e5;
  const HertzContact c = hertz(kSteel, k, N);
  const double nu = kSteel.nu, E = kSteel.E;
  const double a3 = 3.0 * N * R * (1.0 - nu * nu) / (2.0 * E);  // = 3 N R / (4 E*)
  EXPECT_NEAR(c.a, std::cbrt(a3), 1e-15);
  EXPECT_NEAR(c.b, c.a, 1e-15);
  // The brief's a^3 = 3 N R_s (1 - nu^2)/(4 E) is the same with R_s = 2R (two equal spheres).
  EXPECT_NEAR(c.a, std::cbrt(3.0 * N * (2.0 * R) * (1.0 - nu * nu) / (4.0 * E)), 1e-15);
  EXPECT_LT(rel(c.delta, c.a * c.a / R), 1e-14);
  EXPECT_LT(rel(c.p0, 3.0 * N / (2.0 * kPi * c.a * c.a)), 1e-14);
  EXPECT_LT(rel(c.k_hertz, 4.0 / 3.0 * contactModulus(kSteel) * std::sqrt(R)), 1e-14);
  EXPECT_EQ(c.shape.g, 1.0);
}

// Columns: theta_deg A/B g=b/a m n K E (A <= B, a along the smaller curvature A).
struct MnRow {
  double theta, ab, g, m, n, K, E;
};

std::vector<MnRow> readMnTable() {
  const std::string path =
      std::string(RB_SOURCE_DIR) + "/tests/data/creep/derived_hertz_m_n_table.txt";
  std::ifstream in(path);
  std::vector<MnRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    MnRow r{};
    if (s >> r.theta >> r.ab >> r.g >> r.m >> r.n >> r.K >> r.E) rows.push_back(r);
  }
  return rows;
}

TEST(Hertz, DerivedMnTableReproduced) {
  const auto rows = readMnTable();
  ASSERT_EQ(rows.size(), 18u) << "table file missing or changed";
  const double es = contactModulus(kSteel);
  const double N = 5.0e4;
  for (const MnRow& r : rows) {
    // cos(theta) = (B - A)/(A + B), A <= B; scale A + B = 2 (any scale: the shape is scale-free).
    const double ct = std::cos(r.theta * kPi / 180.0);
    const double A = 1.0 - ct, B = 1.0 + ct;
    EXPECT_NEAR(A / B, r.ab, 5e-7 + 1e-6 * r.ab) << r.theta;
    const HertzShape s = hertzShape(A, B);
    // Printed precision: g 6 decimals, m n 4, K E 5 (half a unit of the last digit).
    EXPECT_NEAR(s.g, r.g, 5e-7) << r.theta;
    EXPECT_NEAR(s.m, r.m, 5e-5) << r.theta;
    EXPECT_NEAR(s.n, r.n, 5e-5) << r.theta;
    EXPECT_NEAR(s.K, r.K, 5e-6) << r.theta;
    EXPECT_NEAR(s.E, r.E, 5e-6) << r.theta;
    EXPECT_TRUE(s.rolling_major);
    // Semi-axes from the solver: a (rolling, along A) = m c0, b = n c0.
    const HertzContact c = hertz(kSteel, {A, B}, N);
    const double c0 = std::cbrt(3.0 * N / (4.0 * es * (A + B)));
    EXPECT_NEAR(c.a / c0, r.m, 5e-5) << r.theta;
    EXPECT_NEAR(c.b / c0, r.n, 5e-5) << r.theta;
    // Swapped curvatures (A > B): same ellipse turned by 90 degrees.
    const HertzContact t = hertz(kSteel, {B, A}, N);
    EXPECT_NEAR(t.b, c.a, 1e-14 * c.a);
    EXPECT_NEAR(t.a, c.b, 1e-14 * c.a);
    EXPECT_NEAR(t.delta, c.delta, 1e-14 * c.delta);
    if (r.theta != 90.0) {
      EXPECT_FALSE(t.shape.rolling_major);
    }
  }
}

TEST(Hertz, ShapeEquationResidualAndRange) {
  int max_iter = 0;
  for (double lr = -9.0; lr <= 0.0; lr += 0.25) {
    const double ratio = std::pow(10.0, lr);
    const HertzShape s = hertzShape(ratio, 1.0);
    max_iter = std::max(max_iter, s.iterations);
    if (s.g == 1.0) continue;
    const auto ke = ellipticKEComplementary(s.g);
    const double f = s.g * s.g * (ke.K - ke.E) / (ke.E - s.g * s.g * ke.K);
    EXPECT_LT(rel(f, ratio), 1e-13) << ratio;
  }
  // Nearly circular.
  for (double d : {1e-3, 1e-6, 1e-9, 1e-11, 1e-13}) {
    const HertzShape s = hertzShape(1.0 - d, 1.0);
    EXPECT_NEAR(s.g, 1.0 - 2.0 * d / 3.0, 0.2 * d * d + 1e-12) << d;  // first-order expansion
    max_iter = std::max(max_iter, s.iterations);
  }
  std::printf("Hertz shape equation: at most %d evaluations for A/B in [1e-9, 1]\n", max_iter);
  // Extreme elongation still converges (g ~ sqrt(r / (ln(4/g) - 1))).
  const HertzShape x = hertzShape(1e-30, 1.0);
  EXPECT_GT(x.g, 0.0);
  EXPECT_LT(x.g, 1e-14);
  EXPECT_TRUE(std::isfinite(x.m) && std::isfinite(x.n) && std::isfinite(x.K));
  EXPECT_LE(max_iter, 30);
}

TEST(Hertz, StiffnessConsistentWithSolver) {
  const RelativeCurvatures k = relativeCurvatures(1.0 / 0.46, -1.0 / 0.32, 0.0, 1.0 / 0.3);
  const double kh = hertzStiffness(kSteel, k);
  for (double N : {2.0e4, 1.2e5}) {
    const HertzContact c = hertz(kSteel, k, N);
    EXPECT_EQ(c.k_hertz, kh);
    EXPECT_LT(rel(kh * std::pow(c.delta, 1.5), N), 1e-13) << N;
  }
  const HertzContact c1 = hertz(kSteel, k, 2.0e4), c2 = hertz(kSteel, k, 1.2e5);
  const HertzContact c3 = hertz(kSteel, k, hertzShape(k.A, k.B), 1.2e5);  // precomputed shape
  EXPECT_EQ(c3.a, c2.a);
  EXPECT_EQ(c3.delta, c2.delta);
  EXPECT_LT(rel(c2.delta / c1.delta, std::cbrt(36.0)), 1e-13);  // delta ~ N^(2/3)
  EXPECT_LT(rel(c2.a / c1.a, std::cbrt(6.0)), 1e-13);           // a ~ N^(1/3)
}

TEST(Hertz, ZeroLoad) {
  const HertzContact c = hertz(kSteel, {1.0, 2.0}, 0.0);
  EXPECT_EQ(c.a, 0.0);
  EXPECT_EQ(c.b, 0.0);
  EXPECT_EQ(c.delta, 0.0);
  EXPECT_EQ(c.p0, 0.0);
  EXPECT_GT(c.k_hertz, 0.0);
  EXPECT_EQ(hertz(kSteel, {1.0, 2.0}, -5.0).a, 0.0);
}

TEST(Hertz, AgainstIndependentHighPrecisionSolution) {
  // mpmath (30 digits, ellipk/ellipe, bisection on the shape equation), E = 2.1e11, nu = 0.28.
  double worst = 0.0;
  auto track = [&](double x, double ref) {
    worst = std::max(worst, rel(x, ref));
    return rel(x, ref);
  };
  {
    const double r = 0.49, gamma = 70.0 * kPi / 180.0;
    const auto k = relativeCurvatures(std::cos(gamma) / r, 0.0, 0.0, 1.0 / 0.013);
    const HertzContact c = hertz(kSteel, k, 5.0e4);
    EXPECT_LT(track(c.a, 0.012622933481106846), 1e-11);
    EXPECT_LT(track(c.b, 0.0006556943571130138), 1e-11);
    EXPECT_LT(track(c.delta, 7.214510723571651e-5), 1e-11);
    EXPECT_LT(track(c.k_hertz, 81594273409.38239), 1e-11);
  }
  {
    const auto k = relativeCurvatures(1.0 / 0.46, -1.0 / 0.32, 0.0, 1.0 / 0.3);
    const HertzContact c = hertz(kSteel, k, 1.0e5);
    EXPECT_LT(track(c.a, 0.0043176766992350885), 1e-11);
    EXPECT_LT(track(c.b, 0.019955261933767483), 1e-11);
    EXPECT_LT(track(c.delta, 6.174387098020576e-5), 1e-11);
    EXPECT_LT(track(c.k_hertz, 206114820003.43302), 1e-11);
  }
  std::printf("Hertz a, b, delta, K_H vs mpmath: worst relative error %.2e\n", worst);
}

// The flange-stiffness table of docs/creep.md (printed; the paper quotes Khertz = 7.075e13 N/m^1.5
// for S1002 on LB-140, section 5.3).
TEST(Hertz, FlangeStiffnessTable) {
  struct Case {
    const char* name;
    double r, gamma_deg, wheel_lat, rail_lat;
  };
  const double deg = kPi / 180.0;
  const Case cases[] = {
      // S1002 (EN 13715 sections): flank E straight at 70 deg; arc F R20 convex spans contact
      // angles 26.4-70 deg; tip G R12 convex only below 26.4 deg (flange on top of the rail);
      // throat D R13 concave. 60E1 gauge corner R13 (1:40) spans the steep rail angles.
      {"flank E (straight, 70 deg) on gauge corner R13", 0.49, 70.0, 0.0, 1.0 / 0.013},
      {"same, rolling curvature 1/r (no cos gamma)", 0.49, 0.0, 0.0, 1.0 / 0.013},
      {"arc F R20 (60 deg) on gauge corner R13", 0.49, 60.0, 1.0 / 0.020, 1.0 / 0.013},
      {"tip G R12 (20 deg, climbing) on R13", 0.49, 20.0, 1.0 / 0.012, 1.0 / 0.013},
      {"tip R12 on R13, rolling 1/r (no cos gamma)", 0.49, 0.0, 1.0 / 0.012, 1.0 / 0.013},
      {"throat D R13 concave (45 deg) on R80 rail head", 0.47, 45.0, -1.0 / 0.013, 1.0 / 0.080},
      {"tread (r 0.46, R-320 concave) on crown R300", 0.46, 0.0, -1.0 / 0.32, 1.0 / 0.3},
  };
  std::printf("%-48s %9s %9s %8s %8s %8s %11s\n", "case (N = 50 kN)", "A [1/m]", "B [1/m]",
              "a [mm]", "b [mm]", "d [um]", "K_H");
  for (const Case& cs : cases) {
    const auto k =
        relativeCurvatures(std::cos(cs.gamma_deg * deg) / cs.r, cs.wheel_lat, 0.0, cs.rail_lat);
    if (!isHertzian(k)) {
      std::printf("%-48s %9.3f %9.3f   not Hertzian (conformal/concave)\n", cs.name, k.A, k.B);
      continue;
    }
    const HertzContact c = hertz(kSteel, k, 5.0e4);
    std::printf("%-48s %9.3f %9.3f %8.3f %8.3f %8.2f %11.4e  a/b %.1f\n", cs.name, k.A, k.B,
                c.a * 1e3, c.b * 1e3, c.delta * 1e6, c.k_hertz, c.a / c.b);
    EXPECT_GT(c.k_hertz, 1e10);
    EXPECT_LT(c.k_hertz, 1e12);  // all three orders of magnitude below the paper's 7.075e13
  }
}

}  // namespace
