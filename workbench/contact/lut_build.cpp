// Build of the contact lookup table (paper section 2.3, Eq. 11-15, 21): Eq. (12) and the flange
// search on every node, contact-point jumps, two-point contacts and the node derivatives of the
// interpolant. The evaluation is in lut_eval.cpp.
#include "workbench/contact/lut.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "workbench/core/error.hpp"
#include "workbench/core/spline.hpp"

namespace rb::contact {
namespace {

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

// Eq. (12) and the flange search of both sides at one node.
struct NodeSolution {
  TreadContact tread;
  FlangeContact left, right;
};

// The node values of one gauge value xi_g along the y grid, and which nodes were solved.
struct GaugeLine {
  std::vector<NodeSolution> line;
  std::vector<bool> solved;
};

// Index of the y node nearest the centred wheelset (y = 0).
std::size_t centreNode(const GridSpec& y_grid) {
  const std::size_t ny = y_grid.count();
  return static_cast<std::size_t>(
      std::clamp(std::llround(-y_grid.min / y_grid.step), 0LL, static_cast<long long>(ny - 1)));
}

// Eq. (12) at (y, xi_g), warm-started from `prev` (global search without one or when the warm
// start is rejected), then the flange indentation of Eq. (15)/(21) on both sides.
NodeSolution solveNode(const ContactSolver& solver, double y, double xi, const NodeSolution* prev,
                       TableBuildStats& st) {
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
}

// Contact points of every y node at gauge value xi: continuation in y from the centre node i0
// outward in both directions, each node warm-started from the last solved one toward the centre.
GaugeLine solveGaugeLine(const ContactSolver& solver, const GridSpec& y_grid, double xi,
                         std::size_t i0, TableBuildStats& st) {
  const std::size_t ny = y_grid.count();
  GaugeLine gl;
  gl.line.resize(ny);
  gl.solved.assign(ny, false);
  gl.line[i0] = solveNode(solver, y_grid.at(i0), xi, nullptr, st);
  gl.solved[i0] = gl.line[i0].tread.converged;
  for (int dir : {+1, -1}) {
    std::size_t last_ok = i0;
    for (std::size_t iy = dir > 0 ? i0 + 1 : i0 - 1; iy<ny; iy = dir> 0 ? iy + 1 : iy - 1) {
      const NodeSolution* prev = gl.solved[last_ok] ? &gl.line[last_ok] : nullptr;
      gl.line[iy] = solveNode(solver, y_grid.at(iy), xi, prev, st);
      gl.solved[iy] = gl.line[iy].tread.converged;
      if (gl.solved[iy]) last_ok = iy;
      if (iy == 0) break;
    }
  }
  return gl;
}

// Flags of a node (LutNodeFlag).
std::uint8_t nodeFlags(const NodeSolution& ns, bool solved) {
  if (!solved) return kLutFailed;
  std::uint8_t fl = 0;
  if (ns.tread.mode[0] == ContactMode::Edge) fl |= kLutLeftEdge;
  if (ns.tread.mode[1] == ContactMode::Edge) fl |= kLutRightEdge;
  if (ns.tread.restarted) fl |= kLutRestarted;
  if (ns.left.exists && ns.left.mode == ContactMode::Edge) fl |= kLutLeftFlangeEdge;
  if (ns.right.exists && ns.right.mode == ContactMode::Edge) fl |= kLutRightFlangeEdge;
  return fl;
}

// Unsolved nodes of the line (values at vals[iy * kLutChannels]) take the values of their
// neighbour toward the centre node i0 (warned).
void copyUnsolvedNodes(const std::vector<bool>& solved, std::size_t i0, const GridSpec& y_grid,
                       double xi, double* vals, TableBuildStats& st) {
  const std::size_t ny = solved.size();
  auto copyNode = [&](std::size_t iy, std::size_t from) {
    std::copy_n(&vals[from * kLutChannels], kLutChannels, &vals[iy * kLutChannels]);
    st.warnings.push_back("LUT: Eq. (12) not solved at y = " + fmtMm(y_grid.at(iy)) +
                          ", xi_g = " + fmtMm(xi) + " (node copied from its neighbour)");
  };
  for (std::size_t iy = i0 + 1; iy < ny; ++iy) {
    if (!solved[iy]) copyNode(iy, iy - 1);
  }
  for (std::size_t iy = i0; iy-- > 0;) {
    if (!solved[iy]) copyNode(iy, iy + 1);
  }
}

// Contact-point jumps between neighbouring y nodes (ordered away from the centre node i0), and
// the breaks of the spline runs along y: after an unsolved node, a restart (global search breaks
// the runs of every channel), or a jump of either side's contact point (s_w moves more than
// jump_threshold, or the contact mode changes; reported per side).
void detectJumps(const GaugeLine& gl, std::size_t i0, double xi, double jump_threshold,
                 std::vector<bool>& breaks, std::vector<LutJump>& jumps) {
  const std::size_t ny = gl.line.size();
  for (std::size_t iy = 0; iy + 1 < ny; ++iy) {
    if (!gl.solved[iy] || !gl.solved[iy + 1]) {
      breaks[iy] = true;
      continue;
    }
    const bool outward_up = iy >= i0;  // the pair (iy, iy+1) was solved in direction +1
    const NodeSolution& a = outward_up ? gl.line[iy] : gl.line[iy + 1];
    const NodeSolution& b = outward_up ? gl.line[iy + 1] : gl.line[iy];
    for (Side side : {Side::Left, Side::Right}) {
      const std::size_t k = side == Side::Left ? 0 : 1;
      const double sa = a.tread.s[2 * k], sb = b.tread.s[2 * k];
      if (b.tread.restarted) breaks[iy] = true;
      const bool jump = std::abs(sb - sa) > jump_threshold || a.tread.mode[k] != b.tread.mode[k];
      if (jump) {
        breaks[iy] = true;
        jumps.push_back({xi, side, a.tread.y, b.tread.y, sa, sb});
      }
    }
  }
}

// Branch labels of the line (LutTable::branch): per side, 0 at the centre node i0, and one more
// (+y) or less (-y) past every jump of that side's contact point, |delta s_w| > jump_threshold,
// between two solved neighbours. A change of contact mode alone (interior/edge, s_w continuous)
// and a global-search restart do not change the branch; an unsolved node carries the neighbour's
// values it was copied from, and its label.
void assignBranches(const GaugeLine& gl, std::size_t i0, double jump_threshold,
                    std::int8_t* labels) {
  const std::size_t ny = gl.line.size();
  const auto jumped = [&](std::size_t a, std::size_t b, std::size_t k) {
    return gl.solved[a] && gl.solved[b] &&
           std::abs(gl.line[b].tread.s[2 * k] - gl.line[a].tread.s[2 * k]) > jump_threshold;
  };
  for (std::size_t k = 0; k < 2; ++k) {
    labels[i0 * 2 + k] = 0;
    for (std::size_t iy = i0 + 1; iy < ny; ++iy) {
      const int l = labels[(iy - 1) * 2 + k] + (jumped(iy - 1, iy, k) ? 1 : 0);
      labels[iy * 2 + k] = static_cast<std::int8_t>(std::min(l, 127));
    }
    for (std::size_t iy = i0; iy-- > 0;) {
      const int l = labels[(iy + 1) * 2 + k] - (jumped(iy + 1, iy, k) ? 1 : 0);
      labels[iy * 2 + k] = static_cast<std::int8_t>(std::max(l, -127));
    }
  }
}

// Interior flange indentation of a node on `side` (Eq. 15), or -1 when there is none or it is not
// a separate point (within jump_threshold of the tread contact).
double interiorIndentation(const NodeSolution& ns, Side side, double jump_threshold) {
  const std::size_t k = side == Side::Left ? 0 : 1;
  const FlangeContact& f = side == Side::Left ? ns.left : ns.right;
  const bool separate = std::abs(f.interior_s_w - ns.tread.s[2 * k]) > jump_threshold;
  return std::isfinite(f.interior_delta) && separate ? f.interior_delta : -1.0;
}

// The two-point contact between the y nodes `inner_node` (interior indentation < 0) and
// `outer_node` (>= 0): bisection on y; the interior point is followed by Newton (Eq. 15) from the
// outer node, the tread (Eq. 12) warm-started from the inner side.
TwoPointContact locateTwoPointContact(const ContactSolver& solver, Side side, double xi,
                                      double jump_threshold, double y_inner, double y_outer,
                                      const NodeSolution& inner_node,
                                      const NodeSolution& outer_node) {
  const std::size_t k = side == Side::Left ? 0 : 1;
  const FlangeContact& outer = side == Side::Left ? outer_node.left : outer_node.right;
  double sw = outer.interior_s_w, sr = outer.interior_s_r;
  double ya = y_inner, yb = y_outer;
  NodeSolution inner = inner_node;
  NodeSolution at = outer_node;
  FlangeContact at_f = outer;
  const double b = solver.flangeBoundary(side), tip = solver.flangeTip(side);
  for (int it = 0; it < 60 && std::abs(yb - ya) > 1e-12; ++it) {
    const double ym = 0.5 * (ya + yb);
    const TreadContact t = solver.solveTread(ym, xi, &inner.tread);
    if (!t.converged) break;
    const FlangeContact f = solver.indentation(side, WheelsetPose{ym, t.z, t.phi}, xi, sw, sr);
    const bool in_window = f.converged && std::min(b, tip) <= f.point.s_w &&
                           f.point.s_w <= std::max(b, tip) &&
                           std::abs(f.point.s_w - t.s[2 * k]) > jump_threshold;
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
  return {xi,
          side,
          at.tread.mode[k] == ContactMode::Edge,
          at.tread.y,
          at.tread.z,
          at.tread.phi,
          tp.s_w,
          tp.s_r,
          tp.gamma,
          at_f.point.s_w,
          at_f.point.s_r,
          at_f.point.gamma};
}

// Two-point contacts of the line: per side with a flange, the first zero crossing of the interior
// flange indentation away from the centre node i0 (the window-end indentation is 0 by construction
// once the tread contact is pinned at the boundary, so it does not count as a touch).
void findTwoPointContacts(const ContactSolver& solver, const GaugeLine& gl, std::size_t i0,
                          const GridSpec& y_grid, double xi, double jump_threshold,
                          std::vector<TwoPointContact>& two_point) {
  const std::size_t ny = gl.line.size();
  for (Side side : {Side::Left, Side::Right}) {
    if (!solver.hasFlange(side)) continue;
    const int dir = side == Side::Left ? +1 : -1;
    for (std::size_t iy = i0; dir > 0 ? iy + 1 < ny : iy > 0; iy = dir > 0 ? iy + 1 : iy - 1) {
      const std::size_t jn = dir > 0 ? iy + 1 : iy - 1;
      if (!gl.solved[iy] || !gl.solved[jn]) break;
      if (!(interiorIndentation(gl.line[iy], side, jump_threshold) < 0.0 &&
            interiorIndentation(gl.line[jn], side, jump_threshold) >= 0.0)) {
        continue;
      }
      two_point.push_back(locateTwoPointContact(solver, side, xi, jump_threshold, y_grid.at(iy),
                                                y_grid.at(jn), gl.line[iy], gl.line[jn]));
      break;
    }
  }
}

// Node derivatives along y, fy[(ig * ny + iy) * kLutChannels + c]: a not-a-knot spline per run of
// nodes between breaks (O(h^4) where the geometry is smooth, no ringing carried across a jump).
std::vector<double> slopesAlongY(const std::vector<double>& vals,
                                 const std::vector<std::vector<bool>>& breaks,
                                 const GridSpec& y_grid, std::size_t ng) {
  const std::size_t ny = y_grid.count();
  std::vector<double> ys(ny), line_f(ny), line_d;
  for (std::size_t iy = 0; iy < ny; ++iy) ys[iy] = y_grid.at(iy);
  std::vector<double> fy(ny * ng * kLutChannels, 0.0);
  for (std::size_t ig = 0; ig < ng; ++ig) {
    for (std::size_t c = 0; c < kLutChannels; ++c) {
      for (std::size_t iy = 0; iy < ny; ++iy) line_f[iy] = vals[(ig * ny + iy) * kLutChannels + c];
      splineSlopesWithBreaks(ys, line_f, breaks[ig], line_d);
      for (std::size_t iy = 0; iy < ny; ++iy) fy[(ig * ny + iy) * kLutChannels + c] = line_d[iy];
    }
  }
  return fy;
}

// The interpolant's node data ((ig * ny + iy) * kLutChannels + c) * 4 + {f, f_y, f_xi, f_yxi}:
// values, y slopes, and the modified Akima slopes of both along xi_g (local, no overshoot where a
// jump position moves with the gauge).
std::vector<double> hermiteNodeData(const std::vector<double>& vals, const std::vector<double>& fy,
                                    std::size_t ny, const GridSpec& gauge_grid, std::size_t ng) {
  std::vector<double> data(ny * ng * kLutChannels * 4, 0.0);
  std::vector<double> gs(ng), col_f(ng), col_fy(ng), col_d(ng), col_dy(ng);
  for (std::size_t ig = 0; ig < ng; ++ig) gs[ig] = gauge_grid.at(ig);
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
        double* p = &data[((ig * ny + iy) * kLutChannels + c) * 4];
        p[0] = col_f[ig];
        p[1] = col_fy[ig];
        p[2] = col_d[ig];
        p[3] = col_dy[ig];
      }
    }
  }
  return data;
}

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
  tab.interp_ = config.interpolation;
  tab.has_flange_ = {solver.hasFlange(Side::Left), solver.hasFlange(Side::Right)};
  const std::size_t ny = tab.ny_, ng = tab.ng_;
  TableBuildStats& st = tab.stats_;
  st.nodes = ny * ng;
  // Raw node values vals[(ig * ny + iy) * C + c].
  std::vector<double> vals(ny * ng * kLutChannels, 0.0);
  tab.flags_.assign(ny * ng, 0);
  tab.branch_.assign(ny * ng * 2, 0);
  tab.jump_threshold_ = config.jump_threshold;
  std::vector<std::vector<bool>> breaks(ng, std::vector<bool>(ny, false));
  const std::size_t i0 = centreNode(config.lut_y);

  for (std::size_t ig = 0; ig < ng; ++ig) {
    const double xi = config.lut_gauge.at(ig);
    const GaugeLine gl = solveGaugeLine(solver, config.lut_y, xi, i0, st);
    double* line_vals = &vals[ig * ny * kLutChannels];
    for (std::size_t iy = 0; iy < ny; ++iy) {
      const NodeSolution& ns = gl.line[iy];
      if (gl.solved[iy]) fillNode(&line_vals[iy * kLutChannels], ns.tread, ns.left, ns.right);
      tab.flags_[ig * ny + iy] = nodeFlags(ns, gl.solved[iy]);
    }
    if (!gl.solved[i0]) {
      throw InputError(SourceLoc{"contact geometry", 0},
                       "no contact solution for the centred wheelset at xi_g = " + fmtMm(xi) +
                           ": check the profiles and their positioning (Lw, Lr)");
    }
    copyUnsolvedNodes(gl.solved, i0, config.lut_y, xi, line_vals, st);
    detectJumps(gl, i0, xi, config.jump_threshold, breaks[ig], tab.jumps_);
    assignBranches(gl, i0, config.jump_threshold, &tab.branch_[ig * ny * 2]);
    findTwoPointContacts(solver, gl, i0, config.lut_y, xi, config.jump_threshold, tab.two_point_);
  }

  const std::vector<double> fy = slopesAlongY(vals, breaks, config.lut_y, ng);
  tab.data_ = hermiteNodeData(vals, fy, ny, config.lut_gauge, ng);
  st.bytes = tab.data_.size() * sizeof(double) + tab.flags_.size() + tab.branch_.size() +
             tab.jumps_.size() * sizeof(LutJump) + tab.two_point_.size() * sizeof(TwoPointContact);
  st.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return tab;
}

}  // namespace rb::contact
