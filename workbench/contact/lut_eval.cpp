// Hot path of the LUT method: evaluation of the contact lookup table (bicubic Hermite, Eq. 14, or
// bilinear, section 5.5).
// The table build is in lut_build.cpp.
#include "workbench/contact/lut.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

namespace rb::contact {
namespace {

constexpr const char* kTreadNames[kTreadQuantities] = {
    "s_w", "s_r", "gamma", "radius", "k_w_trans", "k_w_long", "k_r_trans"};
constexpr const char* kFlangeNames[kFlangeQuantities] = {
    "delta",    "s_w",       "s_r", "gamma", "radius",     "k_w_trans",
    "k_w_long", "k_r_trans", "n_y", "n_z",   "ddelta_dphi"};

}  // namespace

std::string lutChannelName(std::size_t c) {
  if (c == kLutZ) return "z";
  if (c == kLutPhi) return "phi";
  if (c < 2 + 2 * kTreadQuantities) {
    const std::size_t k = c - 2;
    return std::string(k < kTreadQuantities ? "left." : "right.") +
           kTreadNames[k % kTreadQuantities];
  }
  if (c < kLutChannels) {
    const std::size_t k = c - 2 - 2 * kTreadQuantities;
    return std::string(k < kFlangeQuantities ? "left.flange." : "right.flange.") +
           kFlangeNames[k % kFlangeQuantities];
  }
  return "?";
}

// ---- Evaluation ---------------------------------------------------------------------------------

LutTable::Cell LutTable::locate(double y, double xi_g) const {
  Cell c;
  const double ty = (y - y_.min) / hy_;
  const double ly = static_cast<double>(ny_ - 2);
  double fy = std::floor(ty);
  if (!(fy >= 0.0)) fy = 0.0;  // also NaN
  if (fy > ly) fy = ly;
  c.i = static_cast<std::size_t>(fy);
  c.t = ty - fy;
  c.inside = ty >= -1e-9 && ty <= ly + 1.0 + 1e-9;
  if (ng_ >= 2) {
    const double tg = (xi_g - g_.min) / hg_;
    const double lg = static_cast<double>(ng_ - 2);
    double fg = std::floor(tg);
    if (!(fg >= 0.0)) fg = 0.0;
    if (fg > lg) fg = lg;
    c.j = static_cast<std::size_t>(fg);
    c.u = tg - fg;
    c.inside = c.inside && tg >= -1e-9 && tg <= lg + 1.0 + 1e-9;
  } else {
    c.inside = c.inside && std::abs(xi_g - g_.min) <= 1e-12;
  }
  return c;
}

namespace {
struct Basis {
  // Hermite basis: A = (h00, h01) value weights, C = (h10, h11) slope weights; first and second
  // derivatives with respect to the unit coordinate.
  double A[2], C[2], dA[2], dC[2], ddA[2], ddC[2];
  explicit Basis(double t) {
    const double t2 = t * t, t3 = t2 * t;
    A[0] = 2 * t3 - 3 * t2 + 1;
    A[1] = -2 * t3 + 3 * t2;
    C[0] = t3 - 2 * t2 + t;
    C[1] = t3 - t2;
    dA[0] = 6 * t2 - 6 * t;
    dA[1] = -6 * t2 + 6 * t;
    dC[0] = 3 * t2 - 4 * t + 1;
    dC[1] = 3 * t2 - 2 * t;
    ddA[0] = 12 * t - 6;
    ddA[1] = -12 * t + 6;
    ddC[0] = 6 * t - 4;
    ddC[1] = 6 * t - 2;
  }
};
}  // namespace

void LutTable::eval(double y, double xi_g, LutSample& out) const {
  evalRange<true>(y, xi_g, out, 0, kLutChannels);
}

void LutTable::evalValues(double y, double xi_g, LutSample& out) const {
  evalValues(y, xi_g, out, 0, kLutChannels);
}

void LutTable::evalValues(double y, double xi_g, LutSample& out, std::size_t first,
                          std::size_t last) const {
  evalRange<false>(y, xi_g, out, first, std::min(last, kLutChannels));
}

// Channels [first, last): values, and with kDerivatives their first derivatives in y and xi_g
// (the same expressions for the values either way, so eval and evalValues agree to the bit).
template <bool kDerivatives>
void LutTable::evalRange(double y, double xi_g, LutSample& out, std::size_t first,
                         std::size_t last) const {
  const Cell c = locate(y, xi_g);
  out.inside = c.inside;
  if (interp_ == TableInterpolation::Linear) {
    evalRangeLinear<kDerivatives>(c, out, first, last);
    return;
  }
  const Basis by(c.t);
  const std::size_t stride_y = kLutChannels * 4, stride_g = ny_ * kLutChannels * 4;
  const double* base = &data_[(c.j * ny_ + c.i) * kLutChannels * 4];
  if (ng_ < 2) {
    for (std::size_t ch = first; ch < last; ++ch) {
      double v = 0.0, dv = 0.0;
      for (std::size_t a = 0; a < 2; ++a) {
        const double* p = base + a * stride_y + ch * 4;
        v += by.A[a] * p[0] + hy_ * by.C[a] * p[1];
        if constexpr (kDerivatives) dv += by.dA[a] * p[0] + hy_ * by.dC[a] * p[1];
      }
      out.value[ch] = v;
      if constexpr (kDerivatives) {
        out.d_dy[ch] = dv / hy_;
        out.d_dxi[ch] = 0.0;
      }
    }
    return;
  }
  const Basis bg(c.u);
  for (std::size_t ch = first; ch < last; ++ch) {
    double v = 0.0, vt = 0.0, vu = 0.0;
    for (std::size_t b = 0; b < 2; ++b) {
      for (std::size_t a = 0; a < 2; ++a) {
        const double* p = base + b * stride_g + a * stride_y + ch * 4;
        const double f = p[0], fy = hy_ * p[1], fg = hg_ * p[2], fyg = hy_ * hg_ * p[3];
        v += by.A[a] * bg.A[b] * f + by.C[a] * bg.A[b] * fy + by.A[a] * bg.C[b] * fg +
             by.C[a] * bg.C[b] * fyg;
        if constexpr (kDerivatives) {
          vt += by.dA[a] * bg.A[b] * f + by.dC[a] * bg.A[b] * fy + by.dA[a] * bg.C[b] * fg +
                by.dC[a] * bg.C[b] * fyg;
          vu += by.A[a] * bg.dA[b] * f + by.C[a] * bg.dA[b] * fy + by.A[a] * bg.dC[b] * fg +
                by.C[a] * bg.dC[b] * fyg;
        }
      }
    }
    out.value[ch] = v;
    if constexpr (kDerivatives) {
      out.d_dy[ch] = vt / hy_;
      out.d_dxi[ch] = vu / hg_;
    }
  }
}

LutValue LutTable::evalChannel(std::size_t ch, double y, double xi_g) const {
  return channelAt(ch, locate(y, xi_g));
}

LutValue LutTable::channelAt(std::size_t ch, const Cell& c) const {
  if (interp_ == TableInterpolation::Linear) return channelAtLinear(ch, c);
  LutValue r;
  r.inside = c.inside;
  const Basis by(c.t);
  const std::size_t stride_y = kLutChannels * 4, stride_g = ny_ * kLutChannels * 4;
  const double* base = &data_[(c.j * ny_ + c.i) * kLutChannels * 4 + ch * 4];
  if (ng_ < 2) {
    for (std::size_t a = 0; a < 2; ++a) {
      const double* p = base + a * stride_y;
      r.v += by.A[a] * p[0] + hy_ * by.C[a] * p[1];
      r.dy += by.dA[a] * p[0] + hy_ * by.dC[a] * p[1];
      r.dyy += by.ddA[a] * p[0] + hy_ * by.ddC[a] * p[1];
    }
    r.dy /= hy_;
    r.dyy /= hy_ * hy_;
    return r;
  }
  const Basis bg(c.u);
  for (std::size_t b = 0; b < 2; ++b) {
    for (std::size_t a = 0; a < 2; ++a) {
      const double* p = base + b * stride_g + a * stride_y;
      const double f = p[0], fy = hy_ * p[1], fg = hg_ * p[2], fyg = hy_ * hg_ * p[3];
      auto term = [&](double ta, double tc, double ua, double uc) {
        return ta * ua * f + tc * ua * fy + ta * uc * fg + tc * uc * fyg;
      };
      r.v += term(by.A[a], by.C[a], bg.A[b], bg.C[b]);
      r.dy += term(by.dA[a], by.dC[a], bg.A[b], bg.C[b]);
      r.dxi += term(by.A[a], by.C[a], bg.dA[b], bg.dC[b]);
      r.dyy += term(by.ddA[a], by.ddC[a], bg.A[b], bg.C[b]);
      r.dyxi += term(by.dA[a], by.dC[a], bg.dA[b], bg.dC[b]);
      r.dxixi += term(by.A[a], by.C[a], bg.ddA[b], bg.ddC[b]);
    }
  }
  r.dy /= hy_;
  r.dxi /= hg_;
  r.dyy /= hy_ * hy_;
  r.dyxi /= hy_ * hg_;
  r.dxixi /= hg_ * hg_;
  return r;
}

// ---- Bilinear evaluation (TableInterpolation::Linear) ------------------------------------------
//
// The paper obtains "the required parameters or variables for the dynamic analysis ... by using
// linear interpolation between the stored data" (section 5.5); with the LUT's two entries (y and
// xi_g) that is the bilinear interpolant of the four nodes of the cell:
//   v = (1 - u) [(1 - t) f00 + t f10] + u [(1 - t) f01 + t f11],  t = (y - y_i) / h_y,
//   u = (xi_g - xi_j) / h_g,
// which returns the stored node values exactly where t, u are 0 or 1 (the weights are then exactly
// 1 and 0). Its derivatives are those of this polynomial on the cell: d/dy and d/dxi_g the slopes
// of the cell's edges (constant along y in a cell, and jumping at every node line), d2/dy2 =
// d2/dxi_g2 = 0 and the cross derivative the constant (f11 - f10 - f01 + f00) / (h_y h_g). The
// Jacobian of the LUT constraints (Eq. 17) and their acceleration terms use these slopes, so the
// dynamics is the exact dynamics of the piecewise-bilinear surfaces z(y, xi_g), phi(y, xi_g): the
// constraint velocities jump where a wheelset crosses a node line, the price of the paper's C0
// tables. The node slopes of the stored data are not read.

namespace {

// The bilinear interpolant of one channel on its cell (p: the channel's node at (y_i, xi_j); the
// other three nodes stride_y and stride_g further on), with its slopes and cross derivative.
struct Bilinear {
  double v, dy, dxi, dyxi;
};
Bilinear bilinear(const double* p, std::size_t stride_y, std::size_t stride_g, double t, double u,
                  double hy, double hg) {
  const double t0 = 1.0 - t, u0 = 1.0 - u;
  const double f00 = p[0], f10 = p[stride_y], f01 = p[stride_g], f11 = p[stride_g + stride_y];
  return {u0 * (t0 * f00 + t * f10) + u * (t0 * f01 + t * f11),
          (u0 * (f10 - f00) + u * (f11 - f01)) / hy, (t0 * (f01 - f00) + t * (f11 - f10)) / hg,
          (f11 - f10 - f01 + f00) / (hy * hg)};
}

}  // namespace

template <bool kDerivatives>
void LutTable::evalRangeLinear(const Cell& c, LutSample& out, std::size_t first,
                               std::size_t last) const {
  const std::size_t stride_y = kLutChannels * 4, stride_g = ny_ * kLutChannels * 4;
  const double* base = &data_[(c.j * ny_ + c.i) * kLutChannels * 4];
  const double t = c.t, t0 = 1.0 - t;
  if (ng_ < 2) {
    for (std::size_t ch = first; ch < last; ++ch) {
      const double f0 = base[ch * 4], f1 = base[stride_y + ch * 4];
      out.value[ch] = t0 * f0 + t * f1;
      if constexpr (kDerivatives) {
        out.d_dy[ch] = (f1 - f0) / hy_;
        out.d_dxi[ch] = 0.0;
      }
    }
    return;
  }
  for (std::size_t ch = first; ch < last; ++ch) {
    const Bilinear b = bilinear(base + ch * 4, stride_y, stride_g, t, c.u, hy_, hg_);
    out.value[ch] = b.v;
    if constexpr (kDerivatives) {
      out.d_dy[ch] = b.dy;
      out.d_dxi[ch] = b.dxi;
    }
  }
}

LutValue LutTable::channelAtLinear(std::size_t ch, const Cell& c) const {
  LutValue r;
  r.inside = c.inside;
  const std::size_t stride_y = kLutChannels * 4, stride_g = ny_ * kLutChannels * 4;
  const double* p = &data_[(c.j * ny_ + c.i) * kLutChannels * 4 + ch * 4];
  const double t = c.t, t0 = 1.0 - t;
  if (ng_ < 2) {
    r.v = t0 * p[0] + t * p[stride_y];
    r.dy = (p[stride_y] - p[0]) / hy_;
    return r;
  }
  const Bilinear b = bilinear(p, stride_y, stride_g, t, c.u, hy_, hg_);
  r.v = b.v;
  r.dy = b.dy;
  r.dxi = b.dxi;
  r.dyxi = b.dyxi;
  return r;
}

void LutTable::evalZPhi(double y, double xi_g, LutValue& z, LutValue& phi) const {
  const Cell c = locate(y, xi_g);  // one cell lookup for both channels
  z = channelAt(kLutZ, c);
  phi = channelAt(kLutPhi, c);
}

// ---- Contact-point branches (treadBranches) ----------------------------------------------------
//
// Where a wheel's contact point jumps between two y nodes (Eq. 12 changes branch: the S1002 tread
// to its flange root at |y| = 4.99 mm, tread to tread at 0.23 mm, docs/contact_geometry.md), the
// real contact point is on one branch on each side of the jump and on both at the jump (two-point
// contact). The interpolant of the cell blends the two nodes' points into one on neither branch
// (s_w, contact angle, radius halfway between tread and root): a contact patch there is not a
// contact of the profiles. Here each branch is interpolated from its own nodes alone: within the
// line where both nodes of the cell are on it, otherwise by extending the neighbouring cell of
// that branch into this one (the Hermite cubic, or the linear segment, of that cell at t - 1 or
// t + 1; the node's value when the branch has a single node there). Along xi_g the branch's values
// on the two gauge lines are blended linearly (the modified Akima slopes of the stored data mix the
// branches where the jump moves with the gauge).

bool LutTable::branchLineValue(std::size_t ch, std::size_t k, const Cell& c, std::size_t jj, int b,
                               double& v) const {
  const auto on = [&](std::size_t iy) { return branch_[(jj * ny_ + iy) * 2 + k] == b; };
  const auto node = [&](std::size_t iy) {
    return &data_[((jj * ny_ + iy) * kLutChannels + ch) * 4];
  };
  // The interpolant of line jj on the y interval [i0, i0 + 1] at unit coordinate t.
  const auto interval = [&](std::size_t i0, double t) {
    const double *p0 = node(i0), *p1 = node(i0 + 1);
    if (interp_ == TableInterpolation::Linear) return (1.0 - t) * p0[0] + t * p1[0];
    const Basis by(t);
    return by.A[0] * p0[0] + by.A[1] * p1[0] + hy_ * (by.C[0] * p0[1] + by.C[1] * p1[1]);
  };
  const std::size_t i = c.i;
  const bool lo = on(i), hi = on(i + 1);
  if (lo && hi) {
    v = interval(i, c.t);
  } else if (hi) {
    v = i + 2 < ny_ && on(i + 2) ? interval(i + 1, c.t - 1.0) : node(i + 1)[0];
  } else if (lo) {
    v = i >= 1 && on(i - 1) ? interval(i - 1, c.t + 1.0) : node(i)[0];
  }
  return lo || hi;
}

void LutTable::treadBranches(double y, double xi_g, Side side, LutTreadBranches& out) const {
  out.split = false;
  if (branch_.empty()) return;
  const Cell c = locate(y, xi_g);
  const std::size_t k = side == Side::Left ? 0 : 1;
  const bool two_lines = ng_ >= 2 && c.u > 0.0;  // the second gauge line carries weight
  // The branches of the corners that carry weight: the first one and the first other one.
  std::array<int, 2> b{branch(c.i, c.j, side), 0};
  bool mixed = false;
  for (std::size_t n = 1; n < (two_lines ? 4U : 2U) && !mixed; ++n) {
    const int l = branch(c.i + n % 2, c.j + n / 2, side);
    mixed = l != b[0];
    b[1] = l;
  }
  if (!mixed) return;
  if (std::abs(b[1]) < std::abs(b[0])) std::swap(b[0], b[1]);  // nearer the centre first
  for (std::size_t r = 0; r < 2; ++r) {
    for (std::size_t q = 0; q < kTreadQuantities; ++q) {
      const std::size_t ch = lutChannel(side, static_cast<TreadQuantity>(q));
      double v0 = 0.0, v1 = 0.0;
      const bool a0 = branchLineValue(ch, k, c, c.j, b[r], v0);
      const bool a1 = two_lines && branchLineValue(ch, k, c, c.j + 1, b[r], v1);
      out.value[r][q] = a0 && a1 ? (1.0 - c.u) * v0 + c.u * v1 : (a0 ? v0 : v1);
    }
  }
  // Labels that differ by a jump elsewhere on the other gauge line can name one point: no split.
  constexpr auto kSw = static_cast<std::size_t>(TreadQuantity::Sw);
  out.split = std::abs(out.value[0][kSw] - out.value[1][kSw]) > jump_threshold_;
}

}  // namespace rb::contact
