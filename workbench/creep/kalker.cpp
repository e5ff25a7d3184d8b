#include "workbench/creep/kalker.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "workbench/core/error.hpp"

namespace rb::creep {

namespace {

// Kalker (1990) Table E.3 via tests/data/creep/kalker_creep_coefficients_tableE3.txt (copied with
// its source). C23(a<b, g = 0.8, nu = 0.25) = 1.25 as in CONTACT m_hertz.f90 (usetab_table.f90 has
// the typo 1.15). 'a<b' rows, g = a/b = 0.1 ... 1.0; columns C11(nu = 0, .25, .5), C22(...),
// C23(...), C33(...) (C33 UNVERIFIED).
constexpr double kAlessB[10][12] = {
    {2.510, 3.310, 4.850, 2.510, 2.520, 2.530, 0.334, 0.473, 0.731, 6.420, 8.280,
     11.700},  // g = 0.1
    {2.590, 3.370, 4.810, 2.590, 2.630, 2.660, 0.483, 0.603, 0.809, 3.460, 4.270,
     5.660},  // g = 0.2
    {2.680, 3.440, 4.800, 2.680, 2.750, 2.810, 0.607, 0.715, 0.889, 2.490, 2.960,
     3.720},  // g = 0.3
    {2.780, 3.530, 4.820, 2.780, 2.880, 2.980, 0.720, 0.823, 0.977, 2.020, 2.320,
     2.770},  // g = 0.4
    {2.880, 3.620, 4.830, 2.880, 3.010, 3.140, 0.827, 0.929, 1.070, 1.740, 1.930,
     2.220},  // g = 0.5
    {2.980, 3.720, 4.910, 2.980, 3.140, 3.310, 0.930, 1.030, 1.180, 1.560, 1.680,
     1.860},  // g = 0.6
    {3.090, 3.810, 4.970, 3.090, 3.280, 3.480, 1.030, 1.140, 1.290, 1.430, 1.500,
     1.600},  // g = 0.7
    {3.190, 3.910, 5.050, 3.190, 3.410, 3.650, 1.130, 1.250, 1.400, 1.340, 1.370,
     1.420},  // g = 0.8
    {3.290, 4.010, 5.120, 3.290, 3.540, 3.820, 1.230, 1.360, 1.510, 1.270, 1.270,
     1.270},  // g = 0.9
    {3.400, 4.120, 5.200, 3.400, 3.670, 3.980, 1.330, 1.470, 1.630, 1.210, 1.190,
     1.160},  // g = 1.0
};
// 'a>b' rows, g = b/a = 0.1 ... 1.0;
// columns C11(nu = 0, .25, .5), C22(...), C23(...), C33(...) (C33 UNVERIFIED).
constexpr double kAgreaterB[10][12] = {
    {10.700, 11.700, 12.900, 10.700, 12.800, 16.000, 12.200, 14.600, 18.000, 0.795, 0.526,
     0.228},  // g = 0.1
    {6.960, 7.780, 8.820, 6.960, 8.140, 9.790, 5.720, 6.630, 7.890, 0.828, 0.601,
     0.341},  // g = 0.2
    {5.570, 6.340, 7.340, 5.570, 6.400, 7.510, 3.790, 4.320, 5.010, 0.868, 0.674,
     0.446},  // g = 0.3
    {4.840, 5.570, 6.570, 4.840, 5.480, 6.310, 2.880, 3.240, 3.700, 0.912, 0.747,
     0.549},  // g = 0.4
    {4.370, 5.100, 6.110, 4.370, 4.900, 5.560, 2.350, 2.620, 2.960, 0.958, 0.819,
     0.650},  // g = 0.5
    {4.060, 4.780, 5.800, 4.060, 4.500, 5.040, 2.010, 2.230, 2.500, 1.010, 0.892,
     0.751},  // g = 0.6
    {3.820, 4.540, 5.580, 3.820, 4.210, 4.670, 1.760, 1.950, 2.180, 1.050, 0.965,
     0.852},  // g = 0.7
    {3.650, 4.360, 5.420, 3.650, 3.990, 4.390, 1.580, 1.750, 1.940, 1.100, 1.040,
     0.954},  // g = 0.8
    {3.510, 4.220, 5.300, 3.510, 3.810, 4.160, 1.440, 1.590, 1.770, 1.160, 1.110,
     1.060},  // g = 0.9
    {3.400, 4.120, 5.200, 3.400, 3.670, 3.980, 1.330, 1.470, 1.630, 1.210, 1.190,
     1.160},  // g = 1.0
};

constexpr double kNuStep = 0.25;  // nu columns 0, 0.25, 0.5

// Linear interpolation in the table half at g in [0.1, 1] and nu in [0, 0.5].
KalkerCoefficients tableCoefficients(const double (&table)[10][12], double g, double nu) {
  // Row interval on the grid g_i = 0.1 (i + 1), i = 0..9.
  const double tg = g * 10.0 - 1.0;  // in [0, 9]
  const int i = std::min(static_cast<int>(tg), 8);
  const double wg = tg - static_cast<double>(i);
  // Column interval in nu.
  const double tn = nu / kNuStep;  // in [0, 2]
  const int j = std::min(static_cast<int>(tn), 1);
  const double wn = tn - static_cast<double>(j);
  double c[4];
  for (int k = 0; k < 4; ++k) {
    const double* r0 = table[i] + 3 * k + j;
    const double* r1 = table[i + 1] + 3 * k + j;
    const double v0 = r0[0] + wn * (r0[1] - r0[0]);
    const double v1 = r1[0] + wn * (r1[1] - r1[0]);
    c[k] = v0 + wg * (v1 - v0);
  }
  return {c[0], c[1], c[2], c[3]};
}

}  // namespace

KalkerCoefficients kalkerAsymptote(double a_over_b, double nu) {
  RB_CHECK(a_over_b > 0.0 && std::isfinite(a_over_b) && nu >= 0.0 && nu < 1.0,
           "Kalker asymptotes need a/b > 0 and 0 <= nu < 1");
  constexpr double kPi = std::numbers::pi;
  KalkerCoefficients c;
  if (a_over_b <= 1.0) {
    // Narrow ellipse across the rolling direction (g = a/b -> 0).
    const double g = a_over_b;
    c.c11 = kPi * kPi / (4.0 * (1.0 - nu));
    c.c22 = kPi * kPi / 4.0;
    c.c23 = kPi * std::sqrt(g) / (3.0 * (1.0 - nu)) * (1.0 + nu * (std::log(16.0 / g) - 5.0));
  } else {
    // Long ellipse along the rolling direction (g = b/a -> 0), the flange's patches.
    const double g = 1.0 / a_over_b;
    const double L = std::log(16.0 / (g * g));
    const double k = 3.0 - std::log(4.0);
    const double l2 = (1.0 - nu) * L + 2.0 * nu;
    c.c11 = 2.0 * kPi / ((L - 2.0 * nu) * g) * (1.0 + k / (L - 2.0 * nu));
    c.c22 = 2.0 * kPi / g * (1.0 + (1.0 - nu) * k / l2) / l2;
    c.c23 = 2.0 * kPi / (3.0 * std::pow(g, 1.5) * ((1.0 - nu) * L - 2.0 + 4.0 * nu));
  }
  return c;
}

bool kalkerInTable(double a_over_b, double nu) {
  return a_over_b >= 0.1 && a_over_b <= 10.0 && nu >= 0.0 && nu <= 0.5;
}

KalkerCoefficients kalkerCoefficients(double a_over_b, double nu) {
  RB_CHECK(a_over_b > 0.0 && std::isfinite(a_over_b),
           "Kalker coefficients need a/b > 0, got " + std::to_string(a_over_b));
  const bool a_less_b = a_over_b <= 1.0;
  const auto& table = a_less_b ? kAlessB : kAgreaterB;
  const double g = a_less_b ? a_over_b : 1.0 / a_over_b;
  const double nuc = std::clamp(nu, 0.0, 0.5);
  constexpr double kEdge = 0.1;  // the table's last row
  KalkerCoefficients c = tableCoefficients(table, std::max(g, kEdge), nuc);
  if (g >= kEdge) return c;
  // Beyond the table: Kalker's asymptotes, scaled to meet the table at its last row (they differ
  // there by up to 7 %, which the scale takes away linearly as g -> 0 where the asymptote is
  // exact). C33 (UNVERIFIED, spin moment only) has no asymptote here and keeps the last row.
  const double edge_ratio = a_less_b ? kEdge : 1.0 / kEdge;
  const KalkerCoefficients at_edge = kalkerAsymptote(edge_ratio, nuc);
  const KalkerCoefficients asym = kalkerAsymptote(a_over_b, nuc);
  const double w = g / kEdge;  // 1 at the last row, 0 in the limit
  c.c11 = asym.c11 * (1.0 + w * (c.c11 / at_edge.c11 - 1.0));
  c.c22 = asym.c22 * (1.0 + w * (c.c22 / at_edge.c22 - 1.0));
  c.c23 = asym.c23 * (1.0 + w * (c.c23 / at_edge.c23 - 1.0));
  return c;
}

}  // namespace rb::creep
