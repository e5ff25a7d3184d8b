#include "workbench/profiles/s1002.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/profiles/sampling.hpp"

namespace rb::profiles {
namespace {

// Coefficients exactly as published (s1002_analytic_EN13715.md).
constexpr double AA = 1.364323640, BA = 0.066666667;
constexpr double AB = 0.0, BB = 3.358537058e-02, CB = 1.565681624e-03, DB = 2.810427944e-05,
                 EB = 5.844240864e-08, FB = 1.562379023e-08, GB = 5.309217349e-15,
                 HB = 5.957839843e-12, IB = 2.646656573e-13;
constexpr double AC = 4.320221063e+03, BC = 1.038384026e+03, CC = 1.065501873e+02, DC = 6.051367875,
                 EC = 2.054332446e-01, FC = 4.169739389e-03, GC = 4.687195829e-05,
                 HC = 2.252755540e-07;
constexpr double AD = 16.446, BD = 13.0, CD = 26.210665;
constexpr double AE = 93.576667419, BE = 2.747477419;
constexpr double AF = 8.834924130, BF = 20.0, CF = 58.558326413;
constexpr double AG = 16.0, BG = 12.0, CG = 55.0;
constexpr double AH = 9.519259302, BH = 20.5, CH = 49.5;

// sqrt(R^2 - u^2), clamped at 0 outside the circle.
double rootOf(double R, double u) {
  return std::sqrt(std::max(0.0, R * R - u * u));
}

// d/dS of sqrt(R^2 - u^2) = -u / sqrt(R^2 - u^2) (infinite at the vertical tangent).
double rootSlope(double R, double u) {
  const double r = rootOf(R, u);
  if (r == 0.0)
    return u > 0 ? -std::numeric_limits<double>::infinity()
                 : std::numeric_limits<double>::infinity();
  return -u / r;
}

// Quintic smoothstep w(t) = 6t^5 - 15t^4 + 10t^3 on [0, 1] (C2: w', w'' vanish at both ends).
double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * t * (t * (6.0 * t - 15.0) + 10.0);
}
double smoothstepSlope(double t) {
  if (t <= 0.0 || t >= 1.0) return 0.0;
  return 30.0 * t * t * (t - 1.0) * (t - 1.0);
}

}  // namespace

S1002Section s1002Section(double S) {
  const auto& b = kS1002BreaksMm;
  if (S >= b[0]) return S1002Section::A;
  if (S >= b[1]) return S1002Section::B;
  if (S >= b[2]) return S1002Section::C;
  if (S >= b[3]) return S1002Section::D;
  if (S >= b[4]) return S1002Section::E;
  if (S >= b[5]) return S1002Section::F;
  if (S >= b[6]) return S1002Section::G;
  return S1002Section::H;
}

double s1002SectionF(S1002Section section, double S) {
  switch (section) {
    case S1002Section::A:
      return AA - BA * S;
    case S1002Section::B:
      return AB - BB * S + CB * std::pow(S, 2) - DB * std::pow(S, 3) + EB * std::pow(S, 4) -
             FB * std::pow(S, 5) + GB * std::pow(S, 6) - HB * std::pow(S, 7) + IB * std::pow(S, 8);
    case S1002Section::C:
      return -AC - BC * S - CC * std::pow(S, 2) - DC * std::pow(S, 3) - EC * std::pow(S, 4) -
             FC * std::pow(S, 5) - GC * std::pow(S, 6) - HC * std::pow(S, 7);
    case S1002Section::D:
      return AD - rootOf(BD, S + CD);
    case S1002Section::E:
      return -AE - BE * S;
    case S1002Section::F:
      return AF + rootOf(BF, S + CF);
    case S1002Section::G:
      return AG + rootOf(BG, S + CG);
    case S1002Section::H:
      return AH + rootOf(BH, S + CH);
  }
  return 0.0;
}

double s1002SectionDF(S1002Section section, double S) {
  switch (section) {
    case S1002Section::A:
      return -BA;
    case S1002Section::B:
      return -BB + 2.0 * CB * S - 3.0 * DB * std::pow(S, 2) + 4.0 * EB * std::pow(S, 3) -
             5.0 * FB * std::pow(S, 4) + 6.0 * GB * std::pow(S, 5) - 7.0 * HB * std::pow(S, 6) +
             8.0 * IB * std::pow(S, 7);
    case S1002Section::C:
      return -BC - 2.0 * CC * S - 3.0 * DC * std::pow(S, 2) - 4.0 * EC * std::pow(S, 3) -
             5.0 * FC * std::pow(S, 4) - 6.0 * GC * std::pow(S, 5) - 7.0 * HC * std::pow(S, 6);
    case S1002Section::D:
      return -rootSlope(BD, S + CD);
    case S1002Section::E:
      return -BE;
    case S1002Section::F:
      return rootSlope(BF, S + CF);
    case S1002Section::G:
      return rootSlope(BG, S + CG);
    case S1002Section::H:
      return rootSlope(BH, S + CH);
  }
  return 0.0;
}

double s1002F(double S) {
  return s1002SectionF(s1002Section(std::max(S, kS1002SMinMm)), std::max(S, kS1002SMinMm));
}

double s1002dF(double S) {
  if (S <= kS1002SMinMm) return std::numeric_limits<double>::infinity();
  return s1002SectionDF(s1002Section(S), S);
}

namespace {

// The blending window around joint S_j between section `left` (S < S_j) and `right` (S > S_j):
// returns true and the blended value/slope when S is inside it.
bool blended(double S, double Sj, S1002Section left, S1002Section right, double& F, double& dF) {
  const double a = Sj - kS1002BlendHalfWidthMm;
  const double L = 2.0 * kS1002BlendHalfWidthMm;
  if (S <= a || S >= a + L) return false;
  const double t = (S - a) / L;
  const double w = smoothstep(t);
  const double dw = smoothstepSlope(t) / L;
  const double Fl = s1002SectionF(left, S), Fr = s1002SectionF(right, S);
  F = (1.0 - w) * Fl + w * Fr;
  dF = (1.0 - w) * s1002SectionDF(left, S) + w * s1002SectionDF(right, S) + dw * (Fr - Fl);
  return true;
}

void smoothEval(double S, double& F, double& dF) {
  if (blended(S, kS1002BreaksMm[2], S1002Section::D, S1002Section::C, F, dF)) return;
  if (blended(S, kS1002BreaksMm[1], S1002Section::C, S1002Section::B, F, dF)) return;
  F = s1002F(S);
  dF = s1002dF(S);
}

}  // namespace

double s1002FSmooth(double S) {
  double F = 0.0, dF = 0.0;
  smoothEval(S, F, dF);
  return F;
}

double s1002dFSmooth(double S) {
  double F = 0.0, dF = 0.0;
  smoothEval(S, F, dF);
  return dF;
}

Profile s1002Wheel(double r0, WheelSide side, double ds) {
  RB_CHECK(r0 > 0.0 && ds > 0.0, "s1002Wheel needs r0 > 0 and ds > 0");
  const UniformGrid g = alignedGrid(kS1002ProfileSMin, kS1002ProfileSMax, ds);
  std::vector<double> h(g.n);
  for (std::size_t i = 0; i < g.n; ++i) {
    const double s = g.at(i);
    h[i] = r0 + 1e-3 * s1002FSmooth(1e3 * s);
  }
  Profile left("S1002 left wheel", ProfileKind::Wheel, g.s0, g.ds, h);
  if (side == WheelSide::Left) return left;
  return left.mirrored("S1002 right wheel");
}

}  // namespace rb::profiles
