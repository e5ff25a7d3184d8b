#include "workbench/contact/lut.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "workbench/core/error.hpp"
#include "workbench/core/spline.hpp"

namespace rb::contact {
namespace {

constexpr const char* kTreadNames[kTreadQuantities] = {
    "s_w", "s_r", "gamma", "radius", "k_w_trans", "k_w_long", "k_r_trans"};
constexpr const char* kFlangeNames[kFlangeQuantities] = {
    "delta",    "s_w",       "s_r", "gamma", "radius",     "k_w_trans",
    "k_w_long", "k_r_trans", "n_y", "n_z",   "ddelta_dphi"};

std::string fmtMm(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f mm", v * 1e3);
  return b;
}

// Node derivatives of one line of values with breaks: not-a-knot spline per run of nodes.
void splineSlopesWithBreaks(const std::vector<double>& x, const std::vector<double>& f,
                            const std::vector<bool>& break_after, std::vector<double>& d) {
  const std::size_t n = x.size();
  d.assign(n, 0.0);
  std::size_t a = 0;
  while (a < n) {
    std::size_t b = a;
    while (b + 1 < n && !break_after[b]) ++b;
    const std::size_t m = b - a + 1;
    if (m >= 3) {
      std::vector<double> xs(x.begin() + static_cast<std::ptrdiff_t>(a),
                             x.begin() + static_cast<std::ptrdiff_t>(b + 1));
      std::vector<double> fs(f.begin() + static_cast<std::ptrdiff_t>(a),
                             f.begin() + static_cast<std::ptrdiff_t>(b + 1));
      const CubicSpline sp(std::move(xs), fs);
      for (std::size_t i = a; i <= b; ++i) d[i] = sp.deriv1(x[i]);
    } else if (m == 2) {
      d[a] = d[b] = (f[b] - f[a]) / (x[b] - x[a]);
    }
    a = b + 1;
  }
}

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

void makimaSlopes(const double* x, const double* f, std::size_t n, double* d) {
  if (n < 2) {
    if (n == 1) d[0] = 0.0;
    return;
  }
  if (n == 2) {
    d[0] = d[1] = (f[1] - f[0]) / (x[1] - x[0]);
    return;
  }
  // Secants with two extrapolated ones at each end: m[k + 2] is the secant of [x_k, x_k+1].
  std::vector<double> m(n + 3);
  for (std::size_t k = 0; k + 1 < n; ++k) m[k + 2] = (f[k + 1] - f[k]) / (x[k + 1] - x[k]);
  m[1] = 2.0 * m[2] - m[3];
  m[0] = 2.0 * m[1] - m[2];
  m[n + 1] = 2.0 * m[n] - m[n - 1];
  m[n + 2] = 2.0 * m[n + 1] - m[n];
  for (std::size_t i = 0; i < n; ++i) {
    // Node i: left secants m[i], m[i+1]; right secants m[i+2], m[i+3].
    const double w1 = std::abs(m[i + 3] - m[i + 2]) + 0.5 * std::abs(m[i + 3] + m[i + 2]);
    const double w2 = std::abs(m[i + 1] - m[i]) + 0.5 * std::abs(m[i + 1] + m[i]);
    d[i] =
        w1 + w2 > 0.0 ? (w1 * m[i + 1] + w2 * m[i + 2]) / (w1 + w2) : 0.5 * (m[i + 1] + m[i + 2]);
  }
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
  LutValue r;
  const Cell c = locate(y, xi_g);
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

void LutTable::evalZPhi(double y, double xi_g, LutValue& z, LutValue& phi) const {
  z = evalChannel(kLutZ, y, xi_g);
  phi = evalChannel(kLutPhi, y, xi_g);
}

// ---- Build --------------------------------------------------------------------------------------

namespace {

void fillNode(double* v, const TreadContact& t, const FlangeContact& fl, const FlangeContact& fr) {
  v[kLutZ] = t.z;
  v[kLutPhi] = t.phi;
  for (Side side : {Side::Left, Side::Right}) {
    const ContactPoint& p = side == Side::Left ? t.left : t.right;
    v[lutChannel(side, TreadQuantity::Sw)] = p.s_w;
    v[lutChannel(side, TreadQuantity::Sr)] = p.s_r;
    v[lutChannel(side, TreadQuantity::Gamma)] = p.gamma;
    v[lutChannel(side, TreadQuantity::Radius)] = p.radius;
    v[lutChannel(side, TreadQuantity::KwTrans)] = p.k_wheel_trans;
    v[lutChannel(side, TreadQuantity::KwLong)] = p.k_wheel_long;
    v[lutChannel(side, TreadQuantity::KrTrans)] = p.k_rail_trans;
    const FlangeContact& f = side == Side::Left ? fl : fr;
    if (!f.exists) {
      for (std::size_t q = 0; q < kFlangeQuantities; ++q) {
        v[lutChannel(side, static_cast<FlangeQuantity>(q))] = 0.0;
      }
      continue;
    }
    v[lutChannel(side, FlangeQuantity::Delta)] = f.delta;
    v[lutChannel(side, FlangeQuantity::Sw)] = f.point.s_w;
    v[lutChannel(side, FlangeQuantity::Sr)] = f.point.s_r;
    v[lutChannel(side, FlangeQuantity::Gamma)] = f.point.gamma;
    v[lutChannel(side, FlangeQuantity::Radius)] = f.point.radius;
    v[lutChannel(side, FlangeQuantity::KwTrans)] = f.point.k_wheel_trans;
    v[lutChannel(side, FlangeQuantity::KwLong)] = f.point.k_wheel_long;
    v[lutChannel(side, FlangeQuantity::KrTrans)] = f.point.k_rail_trans;
    v[lutChannel(side, FlangeQuantity::Ny)] = f.nw_y;
    v[lutChannel(side, FlangeQuantity::Nz)] = f.nw_z;
    v[lutChannel(side, FlangeQuantity::DdeltaDphi)] = f.ddelta_dphi;
  }
}

struct NodeSolution {
  TreadContact tread;
  FlangeContact left, right;
};

}  // namespace

LutTable buildLut(const ContactGeometryConfig& config) {
  const auto t0 = std::chrono::steady_clock::now();
  const ContactSolver solver(config);
  LutTable tab;
  tab.y_ = config.lut_y;
  tab.g_ = config.lut_gauge;
  tab.ny_ = config.lut_y.count();
  tab.ng_ = config.lut_gauge.count();
  tab.hy_ = config.lut_y.step;
  tab.hg_ = tab.ng_ >= 2 ? config.lut_gauge.step : 1.0;
  tab.hash_ = configHash(config);
  tab.has_flange_ = {solver.hasFlange(Side::Left), solver.hasFlange(Side::Right)};
  const std::size_t ny = tab.ny_, ng = tab.ng_;
  TableBuildStats& st = tab.stats_;
  st.nodes = ny * ng;
  // Raw node values vals[(ig * ny + iy) * C + c].
  std::vector<double> vals(ny * ng * kLutChannels, 0.0);
  tab.flags_.assign(ny * ng, 0);
  std::vector<std::vector<bool>> breaks(ng, std::vector<bool>(ny, false));
  std::vector<NodeSolution> line(ny);

  // Index of the node nearest y = 0.
  const auto i0 = static_cast<std::size_t>(std::clamp(
      std::llround(-config.lut_y.min / config.lut_y.step), 0LL, static_cast<long long>(ny - 1)));

  for (std::size_t ig = 0; ig < ng; ++ig) {
    const double xi = config.lut_gauge.at(ig);
    std::vector<bool> solved(ny, false);
    auto solveNode = [&](std::size_t iy, const NodeSolution* prev) {
      const double y = config.lut_y.at(iy);
      NodeSolution ns;
      ns.tread = solver.solveTread(y, xi, prev ? &prev->tread : nullptr);
      st.newton_iterations += ns.tread.iterations;
      if (ns.tread.restarted) ++st.restarts;
      if (!ns.tread.converged) {
        ++st.failures;
        return ns;
      }
      const WheelsetPose pose{y, ns.tread.z, ns.tread.phi};
      ns.left = solver.flange(Side::Left, pose, xi);
      ns.right = solver.flange(Side::Right, pose, xi);
      st.newton_iterations += ns.left.iterations + ns.right.iterations;
      return ns;
    };
    // Continuation from the centre outward in both directions.
    line[i0] = solveNode(i0, nullptr);
    solved[i0] = line[i0].tread.converged;
    for (int dir : {+1, -1}) {
      std::size_t last_ok = i0;
      for (std::size_t iy = dir > 0 ? i0 + 1 : i0 - 1; iy<ny; iy = dir> 0 ? iy + 1 : iy - 1) {
        const NodeSolution* prev = solved[last_ok] ? &line[last_ok] : nullptr;
        line[iy] = solveNode(iy, prev);
        solved[iy] = line[iy].tread.converged;
        if (solved[iy]) last_ok = iy;
        if (iy == 0) break;
      }
    }
    // Node values, flags, jumps.
    for (std::size_t iy = 0; iy < ny; ++iy) {
      std::uint8_t fl = 0;
      const NodeSolution& ns = line[iy];
      if (!solved[iy]) {
        fl |= kLutFailed;
      } else {
        if (ns.tread.mode[0] == ContactMode::Edge) fl |= kLutLeftEdge;
        if (ns.tread.mode[1] == ContactMode::Edge) fl |= kLutRightEdge;
        if (ns.tread.restarted) fl |= kLutRestarted;
        if (ns.left.exists && ns.left.mode == ContactMode::Edge) fl |= kLutLeftFlangeEdge;
        if (ns.right.exists && ns.right.mode == ContactMode::Edge) fl |= kLutRightFlangeEdge;
        fillNode(&vals[(ig * ny + iy) * kLutChannels], ns.tread, ns.left, ns.right);
      }
      tab.flags_[ig * ny + iy] = fl;
    }
    // Unsolved nodes: copy the neighbour toward the centre (warned).
    if (!solved[i0]) {
      throw InputError(SourceLoc{"contact geometry", 0},
                       "no contact solution for the centred wheelset at xi_g = " + fmtMm(xi) +
                           ": check the profiles and their positioning (Lw, Lr)");
    }
    auto copyNode = [&](std::size_t iy, std::size_t from) {
      std::copy_n(&vals[(ig * ny + from) * kLutChannels], kLutChannels,
                  &vals[(ig * ny + iy) * kLutChannels]);
      st.warnings.push_back("LUT: Eq. (12) not solved at y = " + fmtMm(config.lut_y.at(iy)) +
                            ", xi_g = " + fmtMm(xi) + " (node copied from its neighbour)");
    };
    for (std::size_t iy = i0 + 1; iy < ny; ++iy) {
      if (!solved[iy]) copyNode(iy, iy - 1);
    }
    for (std::size_t iy = i0; iy-- > 0;) {
      if (!solved[iy]) copyNode(iy, iy + 1);
    }
    // Jumps between neighbouring nodes (ordered away from the centre).
    for (std::size_t iy = 0; iy + 1 < ny; ++iy) {
      if (!solved[iy] || !solved[iy + 1]) {
        breaks[ig][iy] = true;
        continue;
      }
      const bool outward_up = iy >= i0;  // the pair (iy, iy+1) was solved in direction +1
      const NodeSolution& a = outward_up ? line[iy] : line[iy + 1];
      const NodeSolution& b = outward_up ? line[iy + 1] : line[iy];
      for (Side side : {Side::Left, Side::Right}) {
        const std::size_t k = side == Side::Left ? 0 : 1;
        const double sa = a.tread.s[2 * k], sb = b.tread.s[2 * k];
        // A restart (global search) breaks the spline runs of every channel; a jump is reported
        // per side when s_w moves more than the threshold or the contact mode changes.
        if (b.tread.restarted) breaks[ig][iy] = true;
        const bool jump =
            std::abs(sb - sa) > config.jump_threshold || a.tread.mode[k] != b.tread.mode[k];
        if (jump) {
          breaks[ig][iy] = true;
          tab.jumps_.push_back({xi, side, a.tread.y, b.tread.y, sa, sb});
        }
      }
    }
    // Two-point contact: first zero crossing of the interior flange indentation away from the
    // centre (the window-end indentation is 0 by construction once the tread contact is pinned
    // at the boundary, so it does not count as a touch).
    for (Side side : {Side::Left, Side::Right}) {
      if (!solver.hasFlange(side)) continue;
      const int dir = side == Side::Left ? +1 : -1;
      // A flange touch must be a separate point: more than jump_threshold from the tread contact.
      const std::size_t k = side == Side::Left ? 0 : 1;
      auto interior = [&](const NodeSolution& ns) {
        const FlangeContact& f = side == Side::Left ? ns.left : ns.right;
        const bool separate = std::abs(f.interior_s_w - ns.tread.s[2 * k]) > config.jump_threshold;
        return std::isfinite(f.interior_delta) && separate ? f.interior_delta : -1.0;
      };
      for (std::size_t iy = i0; dir > 0 ? iy + 1 < ny : iy > 0; iy = dir > 0 ? iy + 1 : iy - 1) {
        const std::size_t jn = dir > 0 ? iy + 1 : iy - 1;
        if (!solved[iy] || !solved[jn]) break;
        if (!(interior(line[iy]) < 0.0 && interior(line[jn]) >= 0.0)) continue;
        // Bisection on y between the nodes; the interior point is followed by Newton (Eq. 15)
        // from the outer node, the tread warm-started from the inner node.
        const FlangeContact& outer = side == Side::Left ? line[jn].left : line[jn].right;
        double sw = outer.interior_s_w, sr = outer.interior_s_r;
        double ya = config.lut_y.at(iy), yb = config.lut_y.at(jn);
        NodeSolution inner = line[iy];
        NodeSolution at = line[jn];
        FlangeContact at_f = outer;
        for (int it = 0; it < 60 && std::abs(yb - ya) > 1e-12; ++it) {
          const double ym = 0.5 * (ya + yb);
          const TreadContact t = solver.solveTread(ym, xi, &inner.tread);
          if (!t.converged) break;
          const FlangeContact f =
              solver.indentation(side, WheelsetPose{ym, t.z, t.phi}, xi, sw, sr);
          const double b = solver.flangeBoundary(side), tip = solver.flangeTip(side);
          const bool in_window = f.converged && std::min(b, tip) <= f.point.s_w &&
                                 f.point.s_w <= std::max(b, tip) &&
                                 std::abs(f.point.s_w - t.s[2 * k]) > config.jump_threshold;
          if (!in_window || f.delta < 0.0) {
            ya = ym;
            inner.tread = t;
          } else {
            yb = ym;
            at.tread = t;
            at_f = f;
            sw = f.point.s_w;
            sr = f.point.s_r;
          }
        }
        const ContactPoint& tp = side == Side::Left ? at.tread.left : at.tread.right;
        tab.two_point_.push_back({xi, side, at.tread.mode[k] == ContactMode::Edge, at.tread.y,
                                  at.tread.z, at.tread.phi, tp.s_w, tp.s_r, tp.gamma,
                                  at_f.point.s_w, at_f.point.s_r, at_f.point.gamma});
        break;
      }
    }
  }

  // ---- Interpolant: node derivatives -----------------------------------------------------------
  tab.data_.assign(ny * ng * kLutChannels * 4, 0.0);
  std::vector<double> ys(ny), line_f(ny), line_d;
  for (std::size_t iy = 0; iy < ny; ++iy) ys[iy] = config.lut_y.at(iy);
  std::vector<double> fy(ny * ng * kLutChannels, 0.0);
  for (std::size_t ig = 0; ig < ng; ++ig) {
    for (std::size_t c = 0; c < kLutChannels; ++c) {
      for (std::size_t iy = 0; iy < ny; ++iy) line_f[iy] = vals[(ig * ny + iy) * kLutChannels + c];
      splineSlopesWithBreaks(ys, line_f, breaks[ig], line_d);
      for (std::size_t iy = 0; iy < ny; ++iy) fy[(ig * ny + iy) * kLutChannels + c] = line_d[iy];
    }
  }
  std::vector<double> gs(ng), col_f(ng), col_fy(ng), col_d(ng), col_dy(ng);
  for (std::size_t ig = 0; ig < ng; ++ig) gs[ig] = config.lut_gauge.at(ig);
  for (std::size_t iy = 0; iy < ny; ++iy) {
    for (std::size_t c = 0; c < kLutChannels; ++c) {
      for (std::size_t ig = 0; ig < ng; ++ig) {
        col_f[ig] = vals[(ig * ny + iy) * kLutChannels + c];
        col_fy[ig] = fy[(ig * ny + iy) * kLutChannels + c];
      }
      if (ng >= 2) {
        makimaSlopes(gs.data(), col_f.data(), ng, col_d.data());
        makimaSlopes(gs.data(), col_fy.data(), ng, col_dy.data());
      } else {
        col_d[0] = col_dy[0] = 0.0;
      }
      for (std::size_t ig = 0; ig < ng; ++ig) {
        double* p = &tab.data_[((ig * ny + iy) * kLutChannels + c) * 4];
        p[0] = col_f[ig];
        p[1] = col_fy[ig];
        p[2] = col_d[ig];
        p[3] = col_dy[ig];
      }
    }
  }
  st.bytes = tab.data_.size() * sizeof(double) + tab.flags_.size() +
             tab.jumps_.size() * sizeof(LutJump) + tab.two_point_.size() * sizeof(TwoPointContact);
  st.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return tab;
}

}  // namespace rb::contact
