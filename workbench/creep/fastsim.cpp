#include "workbench/creep/fastsim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace rb::creep {

namespace {

constexpr double kPi = std::numbers::pi;
// Dimensionless creepages beyond this are full slip to far below rounding; clamping them keeps the
// squares of the tractions finite (|tau| <= 4e2 kHuge).
constexpr double kHuge = 1e100;
constexpr int kMaxStrips = static_cast<int>(kFastsimStripsRange.max);
constexpr int kMaxElements = static_cast<int>(kFastsimElementsRange.max);

double clampHuge(double x) {
  return std::clamp(x, -kHuge, kHuge);
}

// The direction of a creepage component whose magnitude is infinite (others count as zero).
double infiniteDirection(double x) {
  if (!std::isinf(x)) return 0.0;
  return x > 0.0 ? 1.0 : -1.0;
}

bool positiveFinite(double x) {
  return x > 0.0 && std::isfinite(x);
}

// The creepages as a unit direction (ux, uy, uphi) and the magnitude k = max(|s_x|, |s_y|,
// |phi| sqrt(a b)); infinite components give their direction and k = kHuge.
struct UnitCreepage {
  double ux = 0.0, uy = 0.0, uphi = 0.0, k = 0.0;
};

UnitCreepage unitCreepage(const Creepages& s, double c) {
  UnitCreepage u;
  const double phi_c = s.phi * c;
  const double k = std::max({std::fabs(s.sx), std::fabs(s.sy), std::fabs(phi_c)});
  if (std::isinf(k)) {
    u.ux = infiniteDirection(s.sx);
    u.uy = infiniteDirection(s.sy);
    u.uphi = infiniteDirection(phi_c);
    u.k = kHuge;
    return u;
  }
  u.ux = s.sx / k;
  u.uy = s.sy / k;
  u.uphi = phi_c / k;
  u.k = k;
  return u;
}

}  // namespace

FastsimFlexibilities fastsimFlexibilities(double G, const ContactPatch& patch) {
  const double a = patch.a, b = patch.b;
  return {8.0 * a / (3.0 * patch.c11 * G), 8.0 * a / (3.0 * patch.c22 * G),
          kPi * a * std::sqrt(a / b) / (4.0 * patch.c23 * G)};
}

// Dimensionless form (x = a xi, y = b eta, p = (mu Q / (a b)) tau): along a strip the traction
// grows per element d xi by -(Sx - Sphx eta, Sy + Sphy xi_m) d xi, with
//   Sx = a^2 b s_x / (mu Q L1) = 3 C11 G a b s_x / (8 mu Q),   Sy = 3 C22 G a b s_y / (8 mu Q),
//   Sphy = a^3 b phi / (mu Q L3) = 4 C23 G (a b)^(3/2) phi / (pi mu Q),   Sphx = Sphy b / a,
// and F = mu Q integral(tau) d xi d eta, M_z = mu Q integral(a xi tau_y - b eta tau_x): no
// quantity of the loop depends on the units or the size of the patch.
FastsimForce fastsimForce(const CreepParams& p, const ContactPatch& patch, const Creepages& s,
                          const FastsimGrid& grid) {
  FastsimForce out;
  const double Q = patch.Q, a = patch.a, b = patch.b;
  if (!(positiveFinite(Q) && positiveFinite(a) && positiveFinite(b) && positiveFinite(p.mu) &&
        positiveFinite(p.G)))
    return out;
  if (std::isnan(s.sx) || std::isnan(s.sy) || std::isnan(s.phi)) {
    out.fx = out.fy = out.mz = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  const double c = std::sqrt(a * b);
  const UnitCreepage u = unitCreepage(s, c);
  if (u.k == 0.0) return out;
  const double muQ = p.mu * Q;
  // F = G a b k / (mu Q), clamped: an overflow means full slip.
  double F = (p.G / muQ) * a * b * u.k;
  if (!(F <= kHuge)) F = kHuge;
  const double Sx = clampHuge(0.375 * patch.c11 * F * u.ux);
  const double Sy = clampHuge(0.375 * patch.c22 * F * u.uy);
  const double Sphy = clampHuge(4.0 / kPi * patch.c23 * F * u.uphi);
  const double Sphx = u.uphi == 0.0 ? 0.0 : clampHuge(Sphy * (b / a));

  const int m = std::clamp(grid.strips, 1, kMaxStrips);
  const int n = std::clamp(grid.elements, 2, kMaxElements);
  const bool parabolic = grid.bound == FastsimBound::Parabolic;
  // Shape of the bound along a strip at the middle of element i (xi_i = s (1 - (2 i - 1) / n),
  // i = 1..n): 1 - (xi_i / s)^2 or its root.
  std::array<double, kMaxElements + 1> h{};
  double h_sum = 0.0;
  const double inv_n = 1.0 / n;
  for (int i = 1; i <= n; ++i) {
    const double q = (2.0 * i - 1.0) * (2.0 * (n - i) + 1.0) * inv_n * inv_n;
    h[static_cast<std::size_t>(i)] = parabolic ? q : std::sqrt(q);
    h_sum += h[static_cast<std::size_t>(i)];
  }
  // Half-length s_j = sqrt(1 - eta_j^2) of each strip and the bound's factor f_j across y.
  std::array<double, kMaxStrips> half{};
  const double d_eta = 2.0 / m;
  double y_sum = 0.0;
  for (int j = 0; j < m; ++j) {
    const double eta = static_cast<double>(2 * j + 1 - m) / m;  // exactly odd in j
    const double sj = std::sqrt(std::max(0.0, 1.0 - eta * eta));
    half[static_cast<std::size_t>(j)] = sj;
    y_sum += d_eta * (2.0 * sj * inv_n) * (parabolic ? sj * sj : sj);
  }
  // Normalised so that the discrete integral of the bound is exactly 1 (mu Q).
  const double B = 1.0 / (y_sum * h_sum);

  double fx = 0.0, fy = 0.0, mz = 0.0;
  for (int j = 0; j < m; ++j) {
    const double eta = static_cast<double>(2 * j + 1 - m) / m;
    const double sj = half[static_cast<std::size_t>(j)];
    const double dxi = 2.0 * sj * inv_n;
    const double gj = B * (parabolic ? sj * sj : sj);
    const double rate_x = Sx - Sphx * eta;
    // From the leading edge (traction zero) half an element to the first middle, then whole
    // elements; the spin term at the middle of each step (exact for its linear rigid slip).
    double step = 0.5 * dxi, step_mid = sj - 0.25 * dxi;
    double tx = 0.0, ty = 0.0;
    double sum_x = 0.0, sum_y = 0.0, sum_xi_y = 0.0;
    for (int i = 1; i <= n; ++i) {
      tx -= rate_x * step;
      ty -= (Sy + Sphy * step_mid) * step;
      const double g = gj * h[static_cast<std::size_t>(i)];
      const double t2 = tx * tx + ty * ty;
      if (t2 > g * g) {
        const double r = g / std::sqrt(t2);
        tx *= r;
        ty *= r;
      }
      sum_x += tx;
      sum_y += ty;
      sum_xi_y += (sj - (i - 0.5) * dxi) * ty;
      step = dxi;
      step_mid = sj - i * dxi;
    }
    // Midpoint rule: every element weighs d xi d eta.
    const double w = d_eta * dxi;
    fx += w * sum_x;
    fy += w * sum_y;
    mz += w * (a * sum_xi_y - b * eta * sum_x);
  }
  out.fx = muQ * fx;
  out.fy = muQ * fy;
  out.mz = muQ * mz;
  return out;
}

}  // namespace rb::creep
