// Equivalent conicity (EN 15302) against a cone, a cone with rolling-radius jumps (closed form),
// and the EN 15302 Annex E benchmark cases E1-E9 (tests/data/en15302: reference tan(gamma_e) with
// the Annex F tolerance band).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "workbench/profiles/conicity.hpp"

namespace {

using rb::profiles::DrJump;
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

// A cone dr = 2 g y with a step D at y = +yj (and at -yj, by -D, when `both`): dr = 2 g y + D for
// y > yj. Closed form of EN 15302's J: for |y| < yj, C - I = C - g y^2; beyond the step,
// C - I = K - D y - g y^2 (K = C + D yj) = g (R^2 - (y + D / 2g)^2); both integrate to arcsines.
struct SteppedCone {
  double g = 0.1, D = 0.4, yj = 4.95;
  bool both = true;

  double dr(double y) const {
    double v = 2.0 * g * y;
    if (y > yj) v += D;
    if (both && y < -yj) v -= D;
    return v;
  }
  // Turning point beyond +yj (or inside) for level C.
  double rightTurn(double C) const {
    if (C <= g * yj * yj) return std::sqrt(C / g);
    const double K = C + D * yj;
    return (-D + std::sqrt(D * D + 4.0 * g * K)) / (2.0 * g);
  }
  double leftTurn(double C) const { return both ? -rightTurn(C) : -std::sqrt(C / g); }
  // integral_0^{y2} dy / sqrt(C - I(y)) on the side with the step.
  double halfJ(double C, double y2) const {
    const double sg = std::sqrt(g);
    auto asinClamped = [](double u) { return std::asin(std::clamp(u, -1.0, 1.0)); };
    if (y2 <= yj) return std::numbers::pi / (2.0 * sg);
    const double cone = asinClamped(yj * std::sqrt(g / C)) / sg;
    const double K = C + D * yj, c = D / (2.0 * g);
    const double R = std::sqrt((K + D * D / (4.0 * g)) / g);
    return cone + (asinClamped((y2 + c) / R) - asinClamped((yj + c) / R)) / sg;
  }
  double tanGammaE(double yhat) const {
    // Level C with y2 - y1 = 2 yhat, by bisection (y2 - y1 increases with C).
    double lo = 0.0, hi = g * 4.0 * yhat * yhat + 2.0 * D * yhat;
    for (int it = 0; it < 200; ++it) {
      const double m = 0.5 * (lo + hi);
      (rightTurn(m) - leftTurn(m) < 2.0 * yhat ? lo : hi) = m;
    }
    const double C = 0.5 * (lo + hi);
    const double right = halfJ(C, rightTurn(C));
    const double left = both ? right : std::numbers::pi / (2.0 * std::sqrt(g));
    return std::pow(std::numbers::pi / (left + right), 2);
  }
};

// Samples of a stepped cone on a 0.1 mm grid (-10..10 mm), its jumps, and the same with every
// jump written as a repeated y.
struct SteppedSamples {
  std::vector<double> y, dr, y_repeated, dr_repeated;
  std::vector<DrJump> jumps;
};

SteppedSamples sample(const SteppedCone& sc) {
  SteppedSamples out;
  const double inner = 2.0 * sc.g * sc.yj;
  if (sc.both) out.jumps.push_back({-sc.yj, -inner - sc.D, -inner});
  out.jumps.push_back({sc.yj, inner, inner + sc.D});
  std::size_t next = 0;
  for (int i = -100; i <= 100; ++i) {
    const double yi = 0.1 * i;
    for (; next < out.jumps.size() && out.jumps[next].y < yi; ++next) {
      out.y_repeated.insert(out.y_repeated.end(), {out.jumps[next].y, out.jumps[next].y});
      out.dr_repeated.insert(out.dr_repeated.end(), {out.jumps[next].left, out.jumps[next].right});
    }
    out.y.push_back(yi);
    out.dr.push_back(sc.dr(yi));
    out.y_repeated.push_back(yi);
    out.dr_repeated.push_back(sc.dr(yi));
  }
  return out;
}

// tan(gamma_e) with the turning point `above` beyond the step: closed form, exact jumps (both
// inputs), and (printed) the samples interpolated across the step.
void checkBeyondStep(const SteppedCone& sc, const RollingRadiusDifference& exact,
                     const RollingRadiusDifference& repeated,
                     const RollingRadiusDifference& smeared, double above) {
  const double a = sc.yj + above, ref = sc.tanGammaE(a);
  const double t = exact.tanGammaE(a), ts = smeared.tanGammaE(a);
  EXPECT_NEAR(t, ref, 1e-6 * ref) << "both " << sc.both << " a " << a;
  EXPECT_EQ(repeated.tanGammaE(a), t) << "both " << sc.both << " a " << a;
  std::printf(
      "stepped cone (%s): y-hat = yj + %.2f mm: closed form %.8f, exact jumps %.8f (%+.1e), "
      "interpolated across the step %.8f (%+.2f %%)\n",
      sc.both ? "both sides" : "one side", above, ref, t, t / ref - 1.0, ts,
      100.0 * (ts / ref - 1.0));
  RollingRadiusDifference::Oscillation o;
  ASSERT_TRUE(exact.oscillation(a, o));
  EXPECT_NEAR(o.y2, sc.rightTurn(o.level), 1e-9);
  EXPECT_NEAR(o.y2 - o.y1, 2.0 * a, 1e-9);
}

// The conicity of a cone with rolling-radius steps just beyond a step (the turning point 0.01,
// 0.1, 0.5 mm past it): exact to 1e-6 with the steps given as jumps, both as an explicit jump list
// and as a repeated y; interpolating the same 0.1 mm samples across the step is biased.
void checkSteppedCone(bool both) {
  SteppedCone sc;
  sc.both = both;
  const SteppedSamples sm = sample(sc);
  const RollingRadiusDifference exact(sm.y, sm.dr, sm.jumps),
      repeated(sm.y_repeated, sm.dr_repeated), smeared(sm.y, sm.dr);
  ASSERT_EQ(exact.jumps().size(), sm.jumps.size());
  EXPECT_NEAR(exact.centre(), 0.0, 1e-12);
  EXPECT_EQ(exact.dr(sc.yj), sm.jumps.back().right);
  EXPECT_NEAR(exact.dr(sc.yj - 1e-9), sm.jumps.back().left, 1e-9);
  for (const double above : {0.01, 0.1, 0.5}) checkBeyondStep(sc, exact, repeated, smeared, above);
  // Below the step the jumps play no part: the cone.
  EXPECT_NEAR(exact.tanGammaE(3.0), sc.g, 1e-6 * sc.g);
}

TEST(EquivalentConicity, JumpsAreExact) {
  checkSteppedCone(true);
  checkSteppedCone(false);
}

// A step through zero at the centre (given at a sample position, which it replaces).
TEST(EquivalentConicity, JumpThroughZero) {
  std::vector<double> y, dr;
  for (int i = -50; i <= 50; ++i) {
    y.push_back(0.1 * i);
    dr.push_back(0.02 * i + 0.1 * ((i > 0) - (i < 0)));
  }
  const RollingRadiusDifference f(y, dr, {{0.0, -0.1, 0.1}});
  EXPECT_NEAR(f.centre(), 0.0, 1e-12);
  EXPECT_TRUE(std::isfinite(f.tanGammaE(1.0)));
}

bool rejected(const std::vector<double>& y, const std::vector<double>& dr,
              const std::vector<DrJump>& jumps) {
  try {
    const RollingRadiusDifference f(y, dr, jumps);
  } catch (const std::exception&) {
    return true;
  }
  return false;
}

// Jumps outside the data or at its ends, and a y given three times, are rejected.
TEST(EquivalentConicity, JumpInputChecks) {
  std::vector<double> y, dr;
  for (int i = -50; i <= 50; ++i) {
    y.push_back(0.1 * i);
    dr.push_back(0.02 * i);
  }
  EXPECT_FALSE(rejected(y, dr, {{1.05, 0.2, 0.3}}));
  EXPECT_TRUE(rejected(y, dr, {{-5.0, 0.0, 0.0}}));
  EXPECT_TRUE(rejected(y, dr, {{5.5, 0.0, 0.0}}));
  std::vector<double> y3 = y, dr3 = dr;
  y3.insert(y3.begin() + 10, {y[10], y[10]});
  dr3.insert(dr3.begin() + 10, {0.0, 0.0});
  EXPECT_THROW(RollingRadiusDifference(y3, dr3), std::exception);
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
