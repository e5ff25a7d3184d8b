#include "workbench/contact/derived.hpp"

#include <algorithm>
#include <cmath>

namespace rb::contact {

namespace {

// One branch of Eq. (12): state and contact modes.
struct Branch {
  ContactState x;
  std::array<ContactMode, 2> modes{ContactMode::Tangent, ContactMode::Tangent};
};

// The tread solution at node iy of the table line, warm-started from the table values.
bool nodeBranch(const ContactSolver& solver, const RollingRadiusTable& t,
                const std::vector<double>& s_lw, const std::vector<double>& s_rw,
                const std::vector<double>& s_lr, const std::vector<double>& s_rr, std::size_t iy,
                Branch& out) {
  TreadContact warm;
  warm.converged = true;
  warm.z = t.z[iy];
  warm.phi = t.phi[iy];
  warm.s = {s_lw[iy], s_lr[iy], s_rw[iy], s_rr[iy]};
  const TreadContact c = solver.solveTread(t.y[iy], t.xi_g, &warm);
  if (!c.converged) return false;
  out.x = ContactState{c.y, c.z, c.phi, c.s};
  out.modes = c.mode;
  return true;
}

// Follows a branch to y by Newton; false when it does not converge or lands on the other
// branch (wheel k's contact point nearer to `other`'s).
bool follow(const ContactSolver& solver, double xi_g, std::size_t k, const Branch& from,
            const Branch& other, double y, Branch& out) {
  out = from;
  if (solver.newton(out.x, Parameter::Y, y, xi_g, out.modes) < 0) return false;
  const double s = out.x.s[2 * k];
  return std::abs(s - from.x.s[2 * k]) < std::abs(s - other.x.s[2 * k]);
}

double deltaR(const ContactSolver& solver, double xi_g, const ContactState& x) {
  const WheelsetPose pose{x.y, x.z, x.phi};
  return solver.describe(Side::Left, pose, xi_g, x.s[0], x.s[1]).radius -
         solver.describe(Side::Right, pose, xi_g, x.s[2], x.s[3]).radius;
}

// Jump of wheel k's contact point between the branches a (left, y smaller) and b (right):
// bisection on which branch holds the wheelset higher.
bool locateJump(const ContactSolver& solver, double xi_g, std::size_t k, Branch a, Branch b,
                double tolerance, DeltaRJump& out) {
  for (int it = 0; it < 100 && b.x.y - a.x.y > tolerance; ++it) {
    const double ym = 0.5 * (a.x.y + b.x.y);
    Branch am, bm;
    const bool ok_a = follow(solver, xi_g, k, a, b, ym, am);
    const bool ok_b = follow(solver, xi_g, k, b, a, ym, bm);
    if (!ok_a && !ok_b) return false;
    if (ok_a && (!ok_b || am.x.z >= bm.x.z)) {
      a = am;
    } else {
      b = bm;
    }
  }
  const double yj = 0.5 * (a.x.y + b.x.y);
  Branch aj, bj;
  if (!follow(solver, xi_g, k, a, b, yj, aj) || !follow(solver, xi_g, k, b, a, yj, bj)) {
    return false;
  }
  out.side = k == 0 ? Side::Left : Side::Right;
  out.y = yj;
  out.delta_r_left = deltaR(solver, xi_g, aj.x);
  out.delta_r_right = deltaR(solver, xi_g, bj.x);
  out.s_w_left = aj.x.s[2 * k];
  out.s_w_right = bj.x.s[2 * k];
  out.z = 0.5 * (aj.x.z + bj.x.z);
  out.phi = 0.5 * (aj.x.phi + bj.x.phi);
  return true;
}

// delta_r on a branch between its node and the jump, clustered toward the jump (where a branch
// near its end bends most): y = y_node + (y_j - y_node) (1 - (1 - k/n)^2), k = 1..n-1, followed by
// Newton from the node. Samples where Newton fails are left out.
void branchSamples(const ContactSolver& solver, double xi_g, std::size_t k, const Branch& node,
                   const Branch& other, double yj, std::vector<double>& ys,
                   std::vector<double>& drs) {
  constexpr int kSamples = 24;
  Branch at = node;
  for (int i = 1; i < kSamples; ++i) {
    const double u = 1.0 - static_cast<double>(i) / kSamples;
    const double y = node.x.y + (yj - node.x.y) * (1.0 - u * u);
    Branch next;
    if (!follow(solver, xi_g, k, at, other, y, next)) continue;
    at = next;
    ys.push_back(y);
    drs.push_back(deltaR(solver, xi_g, at.x));
  }
  if (node.x.y > yj) {  // sampled downward: store increasing
    std::reverse(ys.begin(), ys.end());
    std::reverse(drs.begin(), drs.end());
  }
}

}  // namespace

RollingRadiusTable rollingRadiusDifference(const LutTable& lut, double xi_g) {
  RollingRadiusTable t;
  t.xi_g = xi_g;
  const std::size_t ny = lut.ny();
  // Gauge node index when xi_g is (to rounding) a node.
  const GridSpec& g = lut.gaugeGrid();
  long node = -1;
  if (lut.ng() == 1) {
    if (std::abs(xi_g - g.min) < 1e-12) node = 0;
  } else {
    const double k = (xi_g - g.min) / g.step;
    const double kr = std::round(k);
    if (std::abs(k - kr) < 1e-9 && kr >= 0 && kr < static_cast<double>(lut.ng())) {
      node = static_cast<long>(kr);
    }
  }
  auto value = [&](std::size_t c, std::size_t iy) {
    if (node >= 0) return lut.node(c, iy, static_cast<std::size_t>(node));
    return lut.evalChannel(c, lut.yGrid().at(iy), xi_g).v;
  };
  for (std::size_t iy = 0; iy < ny; ++iy) {
    t.y.push_back(lut.yGrid().at(iy));
    t.z.push_back(value(kLutZ, iy));
    t.phi.push_back(value(kLutPhi, iy));
    const double rl = value(lutChannel(Side::Left, TreadQuantity::Radius), iy);
    const double rr = value(lutChannel(Side::Right, TreadQuantity::Radius), iy);
    const double gl = value(lutChannel(Side::Left, TreadQuantity::Gamma), iy);
    const double gr = value(lutChannel(Side::Right, TreadQuantity::Gamma), iy);
    t.r_left.push_back(rl);
    t.r_right.push_back(rr);
    t.delta_r.push_back(rl - rr);
    t.gamma_left.push_back(gl);
    t.gamma_right.push_back(gr);
    t.delta_gamma.push_back(gl - gr);
  }
  return t;
}

RollingRadiusTable rollingRadiusDifference(const LutTable& lut, const ContactSolver& solver,
                                           double xi_g, double tolerance) {
  RollingRadiusTable t = rollingRadiusDifference(lut, xi_g);
  const std::size_t ny = t.y.size();
  std::vector<double> s_lw(ny), s_rw(ny), s_lr(ny), s_rr(ny);
  for (std::size_t iy = 0; iy < ny; ++iy) {
    auto at = [&](Side side, TreadQuantity q) {
      return lut.evalChannel(lutChannel(side, q), t.y[iy], xi_g).v;
    };
    s_lw[iy] = at(Side::Left, TreadQuantity::Sw);
    s_lr[iy] = at(Side::Left, TreadQuantity::Sr);
    s_rw[iy] = at(Side::Right, TreadQuantity::Sw);
    s_rr[iy] = at(Side::Right, TreadQuantity::Sr);
  }
  const double threshold = solver.config().jump_threshold;
  for (std::size_t iy = 0; iy + 1 < ny; ++iy) {
    const bool left = std::abs(s_lw[iy + 1] - s_lw[iy]) > threshold;
    const bool right = std::abs(s_rw[iy + 1] - s_rw[iy]) > threshold;
    if (!left && !right) continue;
    Branch a, b;
    DeltaRJump j;
    if (nodeBranch(solver, t, s_lw, s_rw, s_lr, s_rr, iy, a) &&
        nodeBranch(solver, t, s_lw, s_rw, s_lr, s_rr, iy + 1, b) &&
        locateJump(solver, xi_g, left ? 0 : 1, a, b, tolerance, j)) {
      const std::size_t k = left ? 0 : 1;
      branchSamples(solver, xi_g, k, a, b, j.y, j.y_left, j.delta_r_left_branch);
      branchSamples(solver, xi_g, k, b, a, j.y, j.y_right, j.delta_r_right_branch);
      t.jumps.push_back(j);
    }
  }
  return t;
}

profiles::RollingRadiusDifference conicityInput(const RollingRadiusTable& table) {
  std::vector<double> y, dr;
  std::vector<profiles::DrJump> jumps;
  std::size_t next = 0;
  for (std::size_t i = 0; i < table.y.size(); ++i) {
    y.push_back(table.y[i]);
    dr.push_back(table.delta_r[i]);
    for (; next < table.jumps.size() && i + 1 < table.y.size() &&
           table.jumps[next].y < table.y[i + 1];
         ++next) {
      const DeltaRJump& j = table.jumps[next];
      y.insert(y.end(), j.y_left.begin(), j.y_left.end());
      dr.insert(dr.end(), j.delta_r_left_branch.begin(), j.delta_r_left_branch.end());
      y.insert(y.end(), j.y_right.begin(), j.y_right.end());
      dr.insert(dr.end(), j.delta_r_right_branch.begin(), j.delta_r_right_branch.end());
      jumps.push_back({j.y, j.delta_r_left, j.delta_r_right});
    }
  }
  return {y, dr, jumps};
}

}  // namespace rb::contact
