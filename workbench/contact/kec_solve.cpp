// Hot path of the KEC method: evaluation of the KEC tables and the online solution of the
// constraints of Eq. (22) (one solveKec per wheelset and right-hand side). The table build is in
// kec_build.cpp.
#include "workbench/contact/kec.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

namespace rb::contact {
namespace {

// The interval of s_k on the uniform grid (min, step, n nodes; clamped to the end intervals) and
// the cubic Hermite basis at its local coordinate t: v = A0 v0 + A1 v1 + C0 v0' + C1 v1'. Shared
// by KecTable::eval and evalValues, so their values are the same to the bit.
struct HermiteCell {
  std::size_t i;
  double t, A0, A1, C0, C1;
};
HermiteCell hermiteCell(double min, double h, std::size_t n, double s_k) {
  double tf = std::floor((s_k - min) / h);
  tf = std::clamp(tf, 0.0, static_cast<double>(n - 2));
  const double t = (s_k - min) / h - tf;
  const double t2 = t * t, t3 = t2 * t;
  return {static_cast<std::size_t>(tf), t,
          2 * t3 - 3 * t2 + 1,          -2 * t3 + 3 * t2,
          (t3 - 2 * t2 + t) * h,        (t3 - t2) * h};
}

// The segment of s_k on the uniform grid (the same floor and clamp as hermiteCell) and the local
// coordinate t in it, for the linear tables.
struct LinearCell {
  std::size_t i;
  double t;
};
LinearCell linearCell(double min, double h, std::size_t n, double s_k) {
  double tf = std::floor((s_k - min) / h);
  tf = std::clamp(tf, 0.0, static_cast<double>(n - 2));
  return {static_cast<std::size_t>(tf), (s_k - min) / h - tf};
}

}  // namespace

std::string kecQuantityName(KecQuantity q) {
  static const char* names[kKecQuantities] = {
      "f",         "s_w",    "s_r",   "gamma", "radius", "k_w_trans", "k_w_long",
      "k_r_trans", "weight", "s_w_A", "s_r_A", "s_w_B",  "s_r_B"};
  return names[static_cast<std::size_t>(q)];
}

bool KecTable::inTransition(Side side, double s_k) const {
  for (const KecTransition& t : trans_[idx(side)]) {
    if (s_k >= t.lo && s_k <= t.hi) return true;
  }
  return false;
}

void KecTable::eval(Side side, double s_k, KecPoint& out) const {
  const std::size_t k = idx(side);
  if (interp_ == TableInterpolation::Linear) {
    evalLinear(k, s_k, out, true);
    return;
  }
  const HermiteCell c = hermiteCell(grid_.min, grid_.step, n_, s_k);
  const double A0 = c.A0, A1 = c.A1, C0 = c.C0, C1 = c.C1, t = c.t, t2 = t * t, h = grid_.step;
  const double dA0 = (6 * t2 - 6 * t) / h, dA1 = -dA0;
  const double dC0 = 3 * t2 - 4 * t + 1, dC1 = 3 * t2 - 2 * t;
  const double* p0 = &herm_[k][c.i * kKecQuantities * 2];
  const double* p1 = p0 + kKecQuantities * 2;
  for (std::size_t q = 1; q < kKecQuantities; ++q) {
    out.value[q] = A0 * p0[2 * q] + A1 * p1[2 * q] + C0 * p0[2 * q + 1] + C1 * p1[2 * q + 1];
    out.d_ds[q] = dA0 * p0[2 * q] + dA1 * p1[2 * q] + dC0 * p0[2 * q + 1] + dC1 * p1[2 * q + 1];
  }
  fspl_[k].eval(s_k, {&out.value[0], 1}, {&out.d_ds[0], 1}, {&out.d2f, 1});
  out.inside = s_k >= valid_[k][0] && s_k <= valid_[k][1];
}

void KecTable::evalValues(Side side, double s_k, KecPoint& out) const {
  // eval() without f and without derivatives (the dynamics reads values of the maps only); the
  // same expressions, so the values are bit-identical to eval()'s, except on an interval where a
  // channel is constant (equal node values, zero slopes): there the interpolant IS that constant
  // and it is returned exactly (A0 v + A1 v can be 1 ulp off). The end points A, B of a transition
  // band (SwA ... SrB, the only channels checked) are such channels, and an exact value lets the
  // dynamics reuse its last describe() of them.
  const std::size_t k = idx(side);
  if (interp_ == TableInterpolation::Linear) {
    evalLinear(k, s_k, out, false);
    return;
  }
  const HermiteCell c = hermiteCell(grid_.min, grid_.step, n_, s_k);
  const double A0 = c.A0, A1 = c.A1, C0 = c.C0, C1 = c.C1;
  const double* p0 = &herm_[k][c.i * kKecQuantities * 2];
  const double* p1 = p0 + kKecQuantities * 2;
  constexpr auto kFirstPoint = static_cast<std::size_t>(KecQuantity::SwA);
  for (std::size_t q = 1; q < kFirstPoint; ++q)
    out.value[q] = A0 * p0[2 * q] + A1 * p1[2 * q] + C0 * p0[2 * q + 1] + C1 * p1[2 * q + 1];
  for (std::size_t q = kFirstPoint; q < kKecQuantities; ++q) {
    const bool constant = p0[2 * q] == p1[2 * q] && p0[2 * q + 1] == 0.0 && p1[2 * q + 1] == 0.0;
    out.value[q] = constant
                       ? p0[2 * q]
                       : A0 * p0[2 * q] + A1 * p1[2 * q] + C0 * p0[2 * q + 1] + C1 * p1[2 * q + 1];
  }
  out.inside = s_k >= valid_[k][0] && s_k <= valid_[k][1];
}

double KecTable::f(Side side, double s_k, double* df, double* d2f) const {
  if (interp_ == TableInterpolation::Linear) return fLinear(idx(side), s_k, df, d2f);
  return fCubic(side, s_k, df, d2f);
}

double KecTable::fCubic(Side side, double s_k, double* df, double* d2f) const {
  // One interval lookup for all orders (solveKec calls this twice per Newton iteration).
  double v = 0.0, d1 = 0.0, d2 = 0.0;
  fspl_[idx(side)].eval(s_k, {&v, 1}, {&d1, 1}, {&d2, 1});
  if (df) *df = d1;
  if (d2f) *d2f = d2;
  return v;
}

// ---- Linear tables (TableInterpolation::Linear) ------------------------------------------------
//
// The paper obtains "the required parameters or variables for the dynamic analysis ... by using
// linear interpolation between the stored data" (section 5.5); the KEC tables have one entry, the
// knife position s_k, so every channel (f_k and the contact-point maps) is the straight segment
// between its two stored nodes: v = (1 - t) v_i + t v_i+1, exactly v_i at t = 0 and v_i+1 at
// t = 1. Its derivative is the slope of the segment, (v_i+1 - v_i) / h, constant between nodes
// and jumping at them (the right-hand segment's at a node: the cell of s_k is floor((s_k - min) /
// h)), and f'' = 0. These are the derivatives of the interpolant actually used, so the Newton
// iteration of solveKec solves Eq. (22) for the piecewise-linear profile exactly: inside one
// segment the equations are linear in (z, s_lk, s_rk) and bilinear with phi, and Newton converges
// quadratically. A step that crosses a node continues with the next segment's slope. The knife
// positions are fixed almost entirely by the lateral rows, where f' enters only as phi f'
// (|phi| ~ 1e-3 rad), and z, phi then follow from the vertical rows, which are linear in them; so
// a kink changes the Jacobian little, the iteration keeps contracting across nodes and a crossing
// costs an extra iteration or two. At a root on a node both one-sided linearisations pass through
// the root, so the iteration ends there. The velocity relation dx_dp jumps where a
// knife crosses a node and the quadratic term (kecQuadraticTerm) has no f'' contribution: the
// dynamics of the paper's C0 equivalent profile.

void KecTable::evalLinear(std::size_t k, double s_k, KecPoint& out, bool derivatives) const {
  const LinearCell c = linearCell(grid_.min, grid_.step, n_, s_k);
  const double t = c.t, t0 = 1.0 - t, h = grid_.step;
  const double* p0 = &herm_[k][c.i * kKecQuantities * 2];
  const double* p1 = p0 + kKecQuantities * 2;
  // eval() sets every channel with its slope; evalValues() leaves F and the derivatives alone.
  // A channel with equal node values is returned as exactly that value (as evalValues' cubic).
  for (std::size_t q = derivatives ? 0 : 1; q < kKecQuantities; ++q) {
    const double v0 = p0[2 * q], v1 = p1[2 * q];
    out.value[q] = v0 == v1 ? v0 : t0 * v0 + t * v1;
    if (derivatives) out.d_ds[q] = (v1 - v0) / h;
  }
  if (derivatives) out.d2f = 0.0;
  out.inside = s_k >= valid_[k][0] && s_k <= valid_[k][1];
}

double KecTable::fLinear(std::size_t k, double s_k, double* df, double* d2f) const {
  const LinearCell c = linearCell(grid_.min, grid_.step, n_, s_k);
  const double f0 = herm_[k][c.i * kKecQuantities * 2];
  const double f1 = herm_[k][(c.i + 1) * kKecQuantities * 2];
  if (df) *df = (f1 - f0) / grid_.step;
  if (d2f) *d2f = 0.0;
  return f0 == f1 ? f0 : (1.0 - c.t) * f0 + c.t * f1;  // as evalLinear's F
}

// ---- Online solver ------------------------------------------------------------------------------

namespace {

// The Newton solve of Eq. (23) with the equivalent profile f(side, s_k, &f', &f'') given.
template <class Profile>
KecSolution solveKecWith(const KecTable& tab, const KecInput& in, const KecSolution* warm,
                         Profile profile) {
  KecSolution sol;
  const double r0 = tab.r0(), lr = tab.railLr();
  double z, phi, sl, sr;
  if (warm && warm->status != KecStatus::NotConverged) {
    z = warm->z;
    phi = warm->phi;
    sl = warm->s_lk;
    sr = warm->s_rk;
  } else {
    phi = 0.0;
    sl = in.y_lir - in.y;
    sr = in.y_rir - in.y;
    z = r0 + profile(Side::Left, sl, nullptr, nullptr) + in.z_lir;
  }
  constexpr int kMaxIter = 30;
  constexpr double kTol = 1e-13;
  constexpr double kMaxStep = 2e-3;
  Eigen::Matrix4d J;
  Eigen::Vector4d g;
  double fl = 0, dfl = 0, d2fl = 0, fr = 0, dfr = 0, d2fr = 0;
  bool ok = false;
  for (int it = 0; it <= kMaxIter; ++it) {
    fl = profile(Side::Left, sl, &dfl, &d2fl);
    fr = profile(Side::Right, sr, &dfr, &d2fr);
    g << in.y + sl + phi * (r0 + fl) - in.y_lir, in.y + sr + phi * (r0 + fr) - in.y_rir,
        z + phi * (lr + sl) - r0 - fl - in.z_lir, z + phi * (-lr + sr) - r0 - fr - in.z_rir;
    J << 0.0, r0 + fl, 1.0 + phi * dfl, 0.0,  //
        0.0, r0 + fr, 0.0, 1.0 + phi * dfr,   //
        1.0, lr + sl, phi - dfl, 0.0,         //
        1.0, -lr + sr, 0.0, phi - dfr;
    sol.residual = g.cwiseAbs().maxCoeff();
    sol.iterations = it;
    if (!std::isfinite(sol.residual)) break;
    if (sol.residual <= kTol) {
      ok = true;
      break;
    }
    if (it == kMaxIter) break;
    // 4x4: the closed-form (cofactor) inverse of Eigen is several times cheaper than a pivoted
    // LU here; a singular J gives non-finite steps, caught below.
    Eigen::Vector4d dx = -(J.inverse() * g);
    if (!dx.allFinite()) break;
    const double m = std::max(std::abs(dx(2)), std::abs(dx(3)));
    if (m > kMaxStep) dx *= kMaxStep / m;
    z += dx(0);
    phi += dx(1);
    sl += dx(2);
    sr += dx(3);
  }
  sol.z = z;
  sol.phi = phi;
  sol.s_lk = sl;
  sol.s_rk = sr;
  sol.f_lk = fl;
  sol.f_rk = fr;
  sol.df_lk = dfl;
  sol.df_rk = dfr;
  sol.d2f_lk = d2fl;
  sol.d2f_rk = d2fr;
  sol.g_x = J;
  if (!ok) {
    sol.status = KecStatus::NotConverged;
    return sol;
  }
  Eigen::Matrix<double, 4, 5> gp;
  gp << 1, -1, 0, 0, 0,  //
      1, 0, -1, 0, 0,    //
      0, 0, 0, -1, 0,    //
      0, 0, 0, 0, -1;
  sol.dx_dp = -(J.inverse() * gp);
  const bool inside = sl >= tab.validMin(Side::Left) && sl <= tab.validMax(Side::Left) &&
                      sr >= tab.validMin(Side::Right) && sr <= tab.validMax(Side::Right);
  sol.status = inside ? KecStatus::Ok : KecStatus::OutOfTable;
  return sol;
}

}  // namespace

KecSolution solveKec(const KecTable& tab, const KecInput& in, const KecSolution* warm) {
  if (tab.interpolation() == TableInterpolation::Linear)
    return solveKecWith(tab, in, warm, [&tab](Side side, double s_k, double* df, double* d2f) {
      return tab.fLinear(side, s_k, df, d2f);
    });
  return solveKecWith(tab, in, warm, [&tab](Side side, double s_k, double* df, double* d2f) {
    return tab.fCubic(side, s_k, df, d2f);
  });
}

Eigen::Vector4d kecQuadraticTerm(const KecSolution& sol, const Eigen::Vector4d& xd) {
  // Second time derivative of g at fixed xddot, pddot: the terms quadratic in velocities.
  const double phid = xd(1), sld = xd(2), srd = xd(3);
  Eigen::Vector4d c;
  c << 2.0 * phid * sol.df_lk * sld + sol.phi * sol.d2f_lk * sld * sld,
      2.0 * phid * sol.df_rk * srd + sol.phi * sol.d2f_rk * srd * srd,
      2.0 * phid * sld - sol.d2f_lk * sld * sld, 2.0 * phid * srd - sol.d2f_rk * srd * srd;
  // A solved system already holds g_x^-1: dx_dp = -g_x^-1 g_p and the last four columns of -g_p
  // are the unit vectors, so dx_dp's last four columns ARE g_x^-1 (exactly, the products with
  // 0 / -1 round nothing). That saves a pivoted 4x4 LU per wheelset and evaluation.
  if (sol.status != KecStatus::NotConverged) return -(sol.dx_dp.rightCols<4>() * c);
  return -sol.g_x.partialPivLu().solve(c);
}

}  // namespace rb::contact
