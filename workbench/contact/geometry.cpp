#include "workbench/contact/geometry.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "workbench/core/error.hpp"

namespace rb::contact {
namespace {

// A warm solution is rejected when the sampled gap elsewhere in the tread window is below -kPenTol.
constexpr double kPenTol = 1e-9;  // [m]
// Newton step limits (whole step scaled down to respect them).
constexpr double kMaxStepS = 2e-3;     // [m] surface parameters, y, z
constexpr double kMaxStepPhi = 5e-3;   // [rad]
constexpr double kDomainSlack = 1e-3;  // [m] how far a surface parameter may leave its profile

std::vector<double> sampleRange(double lo, double hi, double step) {
  std::vector<double> s;
  if (!(hi >= lo)) return s;
  const auto n = static_cast<std::size_t>(std::floor((hi - lo) / step + 1e-9));
  s.reserve(n + 2);
  for (std::size_t i = 0; i <= n; ++i) s.push_back(lo + static_cast<double>(i) * step);
  if (hi - s.back() > 1e-12) s.push_back(hi);
  return s;
}

bool inDomain(const profiles::Profile& p, double s) {
  return s >= p.sMin() - kDomainSlack && s <= p.sMax() + kDomainSlack;
}

// Inserts g into the ascending list starts[0..n) of the deepest distinct sampled gaps, which holds
// at most starts.size() entries (the deepest are kept).
void keepDeepest(std::array<ContactSolver::Gap, 4>& starts, int& n, const ContactSolver::Gap& g) {
  constexpr int kMax = 4;
  for (int k = 0; k < n; ++k) {
    if (starts[static_cast<std::size_t>(k)].s_w == g.s_w) return;
  }
  int pos = n < kMax ? n++ : kMax;
  if (pos == kMax) {
    if (g.gap >= starts[kMax - 1].gap) return;
    pos = kMax - 1;
  }
  starts[static_cast<std::size_t>(pos)] = g;
  for (int k = pos; k > 0 && starts[static_cast<std::size_t>(k)].gap <
                                 starts[static_cast<std::size_t>(k - 1)].gap;
       --k) {
    std::swap(starts[static_cast<std::size_t>(k)], starts[static_cast<std::size_t>(k - 1)]);
  }
}

// Tread/flange boundary of a wheel profile: the first sample from s_w = 0 toward the flange
// (-sigma s_w) whose slope reaches tan(flange_angle); NaN when there is none (no flange).
double flangeStart(const profiles::Profile& w, double sigma, double flange_angle, double step) {
  const double lo = w.sMin(), hi = w.sMax();
  const double tan_min = std::tan(flange_angle);
  const double start = std::clamp(0.0, lo, hi);
  for (double s = start; s >= lo - 1e-15 && s <= hi + 1e-15; s -= sigma * step) {
    if (std::abs(w.at(s).dh) >= tan_min) return s;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// The sample of [lo, hi] with the largest radius h (the first of equal ones); `fallback` when the
// range has no samples. On the flange side of the boundary this is the flange tip.
double highestSample(const profiles::Profile& w, double lo, double hi, double step,
                     double fallback) {
  double tip = fallback, hmax = -std::numeric_limits<double>::infinity();
  for (double s : sampleRange(lo, hi, step)) {
    const double h = w.at(s).h;
    if (h > hmax) {
      hmax = h;
      tip = s;
    }
  }
  return tip;
}

// Appends the samples of [lo, hi] (sampleRange) and the wheel radius h there to s and h.
void sampleWheel(const profiles::Profile& w, double lo, double hi, double step,
                 std::vector<double>& s, std::vector<double>& h) {
  for (double v : sampleRange(lo, hi, step)) {
    s.push_back(v);
    h.push_back(w.at(v).h);
  }
}

// Row of the continuation parameter in the Newton system of Eq. (12): its residual p(x) - value
// and gradient with respect to (y, z, phi). sig_p: side sign of a knife parameter.
struct ParameterRow {
  double f = 0.0, gy = 0.0, gz = 0.0, gphi = 0.0;
};
ParameterRow parameterRow(const ContactState& x, Parameter param, double value, double sig_p,
                          double rail_lr) {
  ParameterRow r;
  switch (param) {
    case Parameter::Y:
      r.f = x.y - value;
      r.gy = 1.0;
      break;
    case Parameter::Z:
      r.f = x.z - value;
      r.gz = 1.0;
      break;
    case Parameter::LeftKnife:
    case Parameter::RightKnife: {
      // s_k = (py + phi pz) / (1 + phi^2) - sigma Lr, py = sigma Lr - y, pz = -z.
      const double py = sig_p * rail_lr - x.y, pz = -x.z;
      const double q = 1.0 / (1.0 + x.phi * x.phi);
      r.f = q * (py + x.phi * pz) - sig_p * rail_lr - value;
      r.gy = -q;
      r.gz = -q * x.phi;
      r.gphi = q * pz - 2.0 * x.phi * q * q * (py + x.phi * pz);
      break;
    }
  }
  return r;
}

// Scales the whole Newton step dx = (y, z, phi, s_lw, s_lr, s_rw, s_rr) so that no unknown moves
// more than its limit (the direction is kept).
void limitStep(Eigen::Matrix<double, 7, 1>& dx) {
  double scale = 1.0;
  for (int k = 0; k < 7; ++k) {
    const double lim = k == 2 ? kMaxStepPhi : kMaxStepS;
    if (std::abs(dx(k)) * scale > lim) scale = lim / std::abs(dx(k));
  }
  dx *= scale;
}

}  // namespace

KnifePoint knifePoint(double sigma, double lr, double r0, double y, double z, double phi,
                      double y_ir, double z_ir) {
  // u = A^-1 (p - r) with A = [[1, -phi], [phi, 1]], p the knife point, r = (y, z).
  const double py = sigma * lr + y_ir - y, pz = z_ir - z;
  const double q = 1.0 / (1.0 + phi * phi);
  const double uy = q * (py + phi * pz), uz = q * (-phi * py + pz);
  return {uy - sigma * lr, -uz - r0};
}

ContactSolver::ContactSolver(ContactGeometryConfig config) : cfg_(std::move(config)) {
  checkConfig(cfg_);
  cb_ = std::cos(cfg_.beta);
  sb_ = std::sin(cfg_.beta);
  for (Side side : {Side::Left, Side::Right}) {
    SideData& sd = side_[idx(side)];
    sd.sigma = kSideSign[idx(side)];
    sd.wheel = side == Side::Left ? cfg_.left_wheel.get() : cfg_.right_wheel.get();
    sd.rail = side == Side::Left ? cfg_.left_rail.get() : cfg_.right_rail.get();
    const profiles::Profile& w = *sd.wheel;
    // The flange lies toward -sigma s_w. Work in "flange-ward" coordinate t = -sigma s_w.
    const double lo = w.sMin(), hi = w.sMax();
    double boundary = std::numeric_limits<double>::quiet_NaN();
    if (std::isfinite(cfg_.flange_boundary)) {
      boundary = sd.sigma * cfg_.flange_boundary;
      sd.has_flange = boundary > lo && boundary < hi;
    } else {
      boundary = flangeStart(w, sd.sigma, cfg_.flange_angle, cfg_.search_step);
      sd.has_flange = std::isfinite(boundary);
    }
    if (!sd.has_flange) boundary = sd.sigma > 0 ? lo : hi;
    sd.boundary = boundary;
    sd.tip = sd.sigma > 0 ? highestSample(w, lo, boundary, cfg_.search_step, boundary)
                          : highestSample(w, boundary, hi, cfg_.search_step, boundary);
    if (sd.sigma > 0) {
      sampleWheel(w, boundary, hi, cfg_.search_step, sd.tread_s, sd.tread_h);
      sampleWheel(w, sd.tip, hi, cfg_.search_step, sd.all_s, sd.all_h);
    } else {
      sampleWheel(w, lo, boundary, cfg_.search_step, sd.tread_s, sd.tread_h);
      sampleWheel(w, lo, sd.tip, cfg_.search_step, sd.all_s, sd.all_h);
    }
    if (sd.has_flange) {
      if (sd.sigma > 0) {
        sampleWheel(w, sd.tip, boundary, cfg_.search_step, sd.flange_s, sd.flange_h);
      } else {
        sampleWheel(w, boundary, sd.tip, cfg_.search_step, sd.flange_s, sd.flange_h);
      }
    }
  }
}

// f[0..2] = (W_Y - R_Y, W_Z - R_Z, t_w . n_r); jac[k][0..4] = d f_k / d(y, z, phi, s_w, s_r).
void ContactSolver::sideResidual(const SideData& sd, double y, double z, double phi, double s_w,
                                 double s_r, double xi_g, double* f, double (*jac)[5]) const {
  const profiles::ProfilePoint w = sd.wheel->at(s_w);
  const profiles::ProfilePoint r = sd.rail->at(s_r);
  const double sig = sd.sigma;
  const double sb = sig * sb_, cb = cb_;
  const double a = sig * cfg_.wheel_lw + s_w;
  const double wy = y + a + phi * w.h;
  const double wz = z + phi * a - w.h;
  const double ry = sig * (cfg_.rail_lr + 0.5 * xi_g) + cb * s_r - sb * r.h;
  const double rz = sb * s_r + cb * r.h;
  const double ty = 1.0 + phi * w.dh, tz = phi - w.dh;      // wheel tangent A (1, -h')
  const double ny = -cb * r.dh - sb, nz = -sb * r.dh + cb;  // rail normal Rx (-h', 1)
  f[0] = wy - ry;
  f[1] = wz - rz;
  f[2] = ty * ny + tz * nz;
  if (jac) {
    // y
    jac[0][0] = 1.0;
    jac[1][0] = 0.0;
    jac[2][0] = 0.0;
    // z
    jac[0][1] = 0.0;
    jac[1][1] = 1.0;
    jac[2][1] = 0.0;
    // phi
    jac[0][2] = w.h;
    jac[1][2] = a;
    jac[2][2] = w.dh * ny + nz;
    // s_w
    jac[0][3] = 1.0 + phi * w.dh;
    jac[1][3] = phi - w.dh;
    jac[2][3] = phi * w.d2h * ny - w.d2h * nz;
    // s_r
    jac[0][4] = -(cb - sb * r.dh);
    jac[1][4] = -(sb + cb * r.dh);
    jac[2][4] = ty * (-cb * r.d2h) + tz * (-sb * r.d2h);
  }
}

std::array<double, 6> ContactSolver::residual(const ContactState& x, double xi_g) const {
  std::array<double, 6> f{};
  sideResidual(side_[0], x.y, x.z, x.phi, x.s[0], x.s[1], xi_g, f.data(), nullptr);
  sideResidual(side_[1], x.y, x.z, x.phi, x.s[2], x.s[3], xi_g, f.data() + 3, nullptr);
  return f;
}

double ContactSolver::parameterValue(const ContactState& x, Parameter param) const {
  switch (param) {
    case Parameter::Y:
      return x.y;
    case Parameter::Z:
      return x.z;
    case Parameter::LeftKnife:
      return knifePoint(1.0, cfg_.rail_lr, cfg_.r0, x.y, x.z, x.phi).s_k;
    case Parameter::RightKnife:
      return knifePoint(-1.0, cfg_.rail_lr, cfg_.r0, x.y, x.z, x.phi).s_k;
  }
  return 0.0;
}

int ContactSolver::newton(ContactState& x, Parameter param, double value, double xi_g,
                          std::array<ContactMode, 2> modes) const {
  // Edge sides: s_w pinned at the boundary (the tangency row becomes s_w - boundary = 0).
  for (std::size_t k = 0; k < 2; ++k) {
    if (modes[k] == ContactMode::Edge) x.s[2 * k] = side_[k].boundary;
  }
  const double sig_p = param == Parameter::RightKnife ? -1.0 : 1.0;
  for (int it = 0; it <= cfg_.newton_max_iter; ++it) {
    double f[6];
    double jl[3][5], jr[3][5];
    sideResidual(side_[0], x.y, x.z, x.phi, x.s[0], x.s[1], xi_g, f, jl);
    sideResidual(side_[1], x.y, x.z, x.phi, x.s[2], x.s[3], xi_g, f + 3, jr);
    for (std::size_t k = 0; k < 2; ++k) {
      if (modes[k] == ContactMode::Edge) f[3 * k + 2] = 0.0;
    }
    const ParameterRow pr = parameterRow(x, param, value, sig_p, cfg_.rail_lr);
    const double fp = pr.f;
    double fmax = std::abs(fp);
    for (double v : f) fmax = std::max(fmax, std::abs(v));
    if (!std::isfinite(fmax)) return -1;
    if (fmax <= cfg_.newton_tol) return it;
    if (it == cfg_.newton_max_iter) break;
    // Unknowns: [y, z, phi, s_lw, s_lr, s_rw, s_rr]; rows: left 3, right 3, parameter.
    Eigen::Matrix<double, 7, 7> J = Eigen::Matrix<double, 7, 7>::Zero();
    Eigen::Matrix<double, 7, 1> F;
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 3; ++c) {
        J(k, c) = jl[k][c];
        J(k + 3, c) = jr[k][c];
      }
      J(k, 3) = jl[k][3];
      J(k, 4) = jl[k][4];
      J(k + 3, 5) = jr[k][3];
      J(k + 3, 6) = jr[k][4];
      F(k) = f[k];
      F(k + 3) = f[k + 3];
    }
    for (int k = 0; k < 2; ++k) {
      if (modes[static_cast<std::size_t>(k)] != ContactMode::Edge) continue;
      const int row = 3 * k + 2;
      J.row(row).setZero();
      J(row, 3 + 2 * k) = 1.0;
      F(row) = 0.0;  // s_w stays at the boundary
    }
    J(6, 0) = pr.gy;
    J(6, 1) = pr.gz;
    J(6, 2) = pr.gphi;
    F(6) = fp;
    const Eigen::PartialPivLU<Eigen::Matrix<double, 7, 7>> lu(J);
    Eigen::Matrix<double, 7, 1> dx = lu.solve(-F);
    if (!dx.allFinite()) return -1;
    limitStep(dx);
    x.y += dx(0);
    x.z += dx(1);
    x.phi += dx(2);
    for (int k = 0; k < 4; ++k) x.s[static_cast<std::size_t>(k)] += dx(3 + k);
    const SideData& l = side_[0];
    const SideData& r = side_[1];
    if (!inDomain(*l.wheel, x.s[0]) || !inDomain(*l.rail, x.s[1]) || !inDomain(*r.wheel, x.s[2]) ||
        !inDomain(*r.rail, x.s[3])) {
      return -1;
    }
  }
  return -1;
}

bool ContactSolver::minimumGap(Side side, const WheelsetPose& pose, double xi_g, Window window,
                               Gap& out) const {
  const SideData& sd = side_[idx(side)];
  const std::vector<double>& ss = window == Window::Tread    ? sd.tread_s
                                  : window == Window::Flange ? sd.flange_s
                                                             : sd.all_s;
  const std::vector<double>& hh = window == Window::Tread    ? sd.tread_h
                                  : window == Window::Flange ? sd.flange_h
                                                             : sd.all_h;
  const double sig = sd.sigma;
  const double sb = sig * sb_, cb = cb_;
  const double oy = sig * (cfg_.rail_lr + 0.5 * xi_g);
  const double rlo = sd.rail->sMin(), rhi = sd.rail->sMax();
  bool found = false;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < ss.size(); ++i) {
    const double a = sig * cfg_.wheel_lw + ss[i];
    const double py = pose.y + a + pose.phi * hh[i] - oy;
    const double pz = pose.z + pose.phi * a - hh[i];
    const double u = cb * py + sb * pz;
    if (u < rlo || u > rhi) continue;
    const double v = -sb * py + cb * pz;
    // Tread: vertical gap in the rail frame (what a z shift closes). Flange and All: distance to
    // the rail tangent line, which ranks steep flank points correctly.
    const profiles::ProfilePoint r = sd.rail->at(u);
    const double gap = window == Window::Tread ? v - r.h : (v - r.h) / std::sqrt(1.0 + r.dh * r.dh);
    if (gap < best) {
      best = gap;
      out.gap = gap;
      out.s_w = ss[i];
      out.s_r = u;
      found = true;
    }
  }
  return found;
}

double ContactSolver::railBelow(Side side, const WheelsetPose& pose, double xi_g,
                                double s_w) const {
  const SideData& sd = side_[idx(side)];
  const double sig = sd.sigma;
  const double h = sd.wheel->at(s_w).h;
  const double a = sig * cfg_.wheel_lw + s_w;
  const double py = pose.y + a + pose.phi * h - sig * (cfg_.rail_lr + 0.5 * xi_g);
  const double pz = pose.z + pose.phi * a - h;
  return cb_ * py + sig * sb_ * pz;
}

bool ContactSolver::globalGuess(double y, double xi_g, ContactState& x) const {
  x.y = y;
  x.z = cfg_.r0;
  x.phi = 0.0;
  Gap gl, gr;
  for (int it = 0; it < 60; ++it) {
    const WheelsetPose pose{x.y, x.z, x.phi};
    if (!minimumGap(Side::Left, pose, xi_g, Window::Tread, gl)) return false;
    if (!minimumGap(Side::Right, pose, xi_g, Window::Tread, gr)) return false;
    x.s = {gl.s_w, gl.s_r, gr.s_w, gr.s_r};
    if (it > 0 && std::max(std::abs(gl.gap), std::abs(gr.gap)) < 1e-10) return true;
    const double al = cfg_.wheel_lw + gl.s_w, ar = -cfg_.wheel_lw + gr.s_w;
    const double dphi = (gr.gap - gl.gap) / (al - ar);
    const double dz = -gl.gap - dphi * al;
    x.z += dz;
    x.phi += dphi;
  }
  return true;  // not settled to 1e-10 (oscillating between samples): still a usable guess
}

ContactPoint ContactSolver::describe(Side side, const WheelsetPose& pose, double xi_g, double s_w,
                                     double s_r) const {
  (void)pose;
  const SideData& sd = side_[idx(side)];
  const profiles::ProfilePoint w = sd.wheel->at(s_w);
  const profiles::ProfilePoint r = sd.rail->at(s_r);
  const double sig = sd.sigma;
  const double sb = sig * sb_, cb = cb_;
  ContactPoint p;
  p.s_w = s_w;
  p.s_r = s_r;
  p.y = sig * (cfg_.rail_lr + 0.5 * xi_g) + cb * s_r - sb * r.h;
  p.z = sb * s_r + cb * r.h;
  const double ny = -cb * r.dh - sb, nz = -sb * r.dh + cb;
  const double nn = std::hypot(ny, nz);
  p.n_y = ny / nn;
  p.n_z = nz / nn;
  p.gamma = std::atan2(-sig * p.n_y, p.n_z);
  p.radius = w.h;
  const double qw = 1.0 + w.dh * w.dh, qr = 1.0 + r.dh * r.dh;
  p.k_wheel_trans = -w.d2h / (qw * std::sqrt(qw));
  p.k_wheel_long = 1.0 / (w.h * std::sqrt(qw));
  p.k_rail_trans = -r.d2h / (qr * std::sqrt(qr));
  p.k_rail_long = 0.0;
  return p;
}

bool ContactSolver::acceptTread(const ContactState& x, std::array<ContactMode, 2> modes,
                                double xi_g, double& penetration) const {
  // Tangent contacts must lie in the tread window (the flange side belongs to the flange search).
  const double tol = 1e-9;
  if (modes[0] == ContactMode::Tangent && x.s[0] < side_[0].boundary - tol) return false;
  if (modes[1] == ContactMode::Tangent && x.s[2] > side_[1].boundary + tol) return false;
  const WheelsetPose pose{x.y, x.z, x.phi};
  Gap gl, gr;
  penetration = 0.0;
  if (minimumGap(Side::Left, pose, xi_g, Window::Tread, gl))
    penetration = std::max(penetration, -gl.gap);
  if (minimumGap(Side::Right, pose, xi_g, Window::Tread, gr))
    penetration = std::max(penetration, -gr.gap);
  return penetration <= kPenTol;
}

TreadContact ContactSolver::solveTread(double y, double xi_g, const TreadContact* warm) const {
  using M = ContactMode;
  TreadContact res;
  res.y = y;
  res.xi_g = xi_g;
  ContactState x;
  std::array<M, 2> modes{M::Tangent, M::Tangent};
  bool ok = false;
  // One attempt: Newton from `start` with `m`; on success the solution is kept in x / modes.
  auto attempt = [&](const ContactState& start, std::array<M, 2> m) {
    ContactState t = start;
    const int n = newton(t, Parameter::Y, y, xi_g, m);
    res.iterations += n >= 0 ? n : cfg_.newton_max_iter;
    if (n < 0) return false;
    double pen = 0.0;
    const bool good = acceptTread(t, m, xi_g, pen);
    if (good) {
      x = t;
      modes = m;
      res.penetration = pen;
    }
    return good;
  };
  // A tangent contact that left the tread window continues as an edge contact (and back).
  auto attemptWithModes = [&](const ContactState& start, std::array<M, 2> m) {
    if (attempt(start, m)) return true;
    auto flip = [&](std::array<M, 2> a, std::size_t k) {
      if (side_[k].has_flange) a[k] = a[k] == M::Tangent ? M::Edge : M::Tangent;
      return a;
    };
    const std::array<M, 2> m0 = flip(m, 0), m1 = flip(m, 1), m01 = flip(m0, 1);
    if (m0 != m && attempt(start, m0)) return true;
    if (m1 != m && attempt(start, m1)) return true;
    return m01 != m && m01 != m0 && m01 != m1 && attempt(start, m01);
  };
  if (warm && warm->converged) {
    ContactState start;
    start.y = y;
    start.z = warm->z;
    start.phi = warm->phi;
    start.s = warm->s;
    ok = attemptWithModes(start, warm->mode);
    if (!ok) res.restarted = true;
  }
  if (!ok) {
    ContactState g;
    if (globalGuess(y, xi_g, g)) {
      // A side whose sampled minimum sits on the window end starts in edge mode.
      const double tol = 0.5 * cfg_.search_step;
      std::array<M, 2> m{M::Tangent, M::Tangent};
      if (side_[0].has_flange && std::abs(g.s[0] - side_[0].boundary) < tol) m[0] = M::Edge;
      if (side_[1].has_flange && std::abs(g.s[2] - side_[1].boundary) < tol) m[1] = M::Edge;
      ok = attemptWithModes(g, m);
    }
  }
  res.converged = ok;
  if (!ok) return res;
  res.z = x.z;
  res.phi = x.phi;
  res.s = x.s;
  res.mode = modes;
  const WheelsetPose pose{y, x.z, x.phi};
  res.left = describe(Side::Left, pose, xi_g, x.s[0], x.s[1]);
  res.right = describe(Side::Right, pose, xi_g, x.s[2], x.s[3]);
  return res;
}

void ContactSolver::edgeFlange(const SideData& sd, Side side, const WheelsetPose& pose, double xi_g,
                               FlangeContact& fc) const {
  // Largest indentation of the flange window at its end s_w = boundary: the signed distance from
  // the wheel point to the rail curve (closest rail point: (W - R) . T_r = 0).
  const double sig = sd.sigma;
  const double sb = sig * sb_, cb = cb_;
  const double oy = sig * (cfg_.rail_lr + 0.5 * xi_g);
  const double s_w = sd.boundary;
  const profiles::ProfilePoint w = sd.wheel->at(s_w);
  const double a = sig * cfg_.wheel_lw + s_w;
  const double wy = pose.y + a + pose.phi * w.h, wz = pose.z + pose.phi * a - w.h;
  const double lo = sd.rail->sMin(), hi = sd.rail->sMax();
  // Start: vertical projection in the rail frame, clamped to the rail.
  double s_r = std::clamp(cb * (wy - oy) + sb * wz, lo, hi);
  bool interior = false;
  int it = 0;
  for (; it <= cfg_.newton_max_iter; ++it) {
    const profiles::ProfilePoint r = sd.rail->at(s_r);
    const double dy = wy - (oy + cb * s_r - sb * r.h), dz = wz - (sb * s_r + cb * r.h);
    const double ty = cb - sb * r.dh, tz = sb + cb * r.dh;
    const double g = dy * ty + dz * tz;
    if (std::abs(g) <= cfg_.newton_tol) {
      interior = true;
      break;
    }
    const double dg = -(ty * ty + tz * tz) + dy * (-sb * r.d2h) + dz * (cb * r.d2h);
    if (!(std::abs(dg) > 0.0)) break;
    double step = -g / dg;
    step = std::clamp(step, -kMaxStepS, kMaxStepS);
    const double next = std::clamp(s_r + step, lo, hi);
    if (next == s_r) break;  // pinned at a rail end
    s_r = next;
  }
  fc.iterations += it;
  fc.mode = ContactMode::Edge;
  fc.point = describe(side, pose, xi_g, s_w, s_r);
  const double dy = wy - fc.point.y, dz = wz - fc.point.z;
  double ny = -fc.point.n_y, nz = -fc.point.n_z;
  if (!interior) {
    // Closest point is a rail end: the direction from the wheel point to it.
    const double d = std::hypot(dy, dz);
    if (d > 0.0) {
      ny = -dy / d;
      nz = -dz / d;
    }
  }
  fc.nw_y = ny;
  fc.nw_z = nz;
  fc.delta = dy * ny + dz * nz;
  fc.ddelta_dy = ny;
  fc.ddelta_dz = nz;
  fc.ddelta_dphi = ny * w.h + nz * a;
  fc.ddelta_dxi = -0.5 * sig * ny;
  fc.converged = true;
}

bool ContactSolver::interiorIndentation(const SideData& sd, Side side, const WheelsetPose& pose,
                                        double xi_g, double s_w, double s_r,
                                        FlangeContact& fc) const {
  const double sig = sd.sigma;
  const double sb = sig * sb_, cb = cb_;
  const double oy = sig * (cfg_.rail_lr + 0.5 * xi_g);
  bool ok = false;
  int it = 0, clamped = 0;
  for (; it <= cfg_.newton_max_iter; ++it) {
    const profiles::ProfilePoint w = sd.wheel->at(s_w);
    const profiles::ProfilePoint r = sd.rail->at(s_r);
    const double a = sig * cfg_.wheel_lw + s_w;
    const double dy = pose.y + a + pose.phi * w.h - (oy + cb * s_r - sb * r.h);
    const double dz = pose.z + pose.phi * a - w.h - (sb * s_r + cb * r.h);
    const double ty = 1.0 + pose.phi * w.dh, tz = pose.phi - w.dh;
    const double tpy = pose.phi * w.d2h, tpz = -w.d2h;
    const double try_ = cb - sb * r.dh, trz = sb + cb * r.dh;
    const double ny = -cb * r.dh - sb, nz = -sb * r.dh + cb;
    const double npy = -cb * r.d2h, npz = -sb * r.d2h;
    const double f1 = ty * dy + tz * dz;  // distance vector along the wheel normal
    const double f2 = ty * ny + tz * nz;  // wheel tangent orthogonal to the rail normal
    if (std::abs(f1) <= cfg_.newton_tol && std::abs(f2) <= cfg_.newton_tol) {
      ok = true;
      break;
    }
    if (it == cfg_.newton_max_iter) break;
    const double j11 = tpy * dy + tpz * dz + ty * ty + tz * tz;
    const double j12 = -(ty * try_ + tz * trz);
    const double j21 = tpy * ny + tpz * nz;
    const double j22 = ty * npy + tz * npz;
    const double det = j11 * j22 - j12 * j21;
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) break;
    double dsw = (-f1 * j22 + f2 * j12) / det;
    double dsr = (-f2 * j11 + f1 * j21) / det;
    const double m = std::max(std::abs(dsw), std::abs(dsr));
    if (m > kMaxStepS) {
      dsw *= kMaxStepS / m;
      dsr *= kMaxStepS / m;
    }
    s_w += dsw;
    s_r += dsr;
    // A step leaving the rail is cut back to the rail end (a few times, then give up).
    if (!sd.rail->inside(s_r)) {
      s_r = std::clamp(s_r, sd.rail->sMin(), sd.rail->sMax());
      if (++clamped > 5) break;
    }
    if (!inDomain(*sd.wheel, s_w)) break;
  }
  fc.iterations += it;
  if (!ok) return false;
  const profiles::ProfilePoint w = sd.wheel->at(s_w);
  const double a = sig * cfg_.wheel_lw + s_w;
  const double wy = pose.y + a + pose.phi * w.h, wz = pose.z + pose.phi * a - w.h;
  fc.point = describe(side, pose, xi_g, s_w, s_r);
  double ny = -w.dh + pose.phi, nz = -pose.phi * w.dh - 1.0;  // A (-h', -1)
  const double nn = std::hypot(ny, nz);
  ny /= nn;
  nz /= nn;
  fc.mode = ContactMode::Tangent;
  fc.converged = true;
  fc.nw_y = ny;
  fc.nw_z = nz;
  fc.delta = (wy - fc.point.y) * ny + (wz - fc.point.z) * nz;
  fc.ddelta_dy = ny;
  fc.ddelta_dz = nz;
  fc.ddelta_dphi = ny * w.h + nz * a;
  fc.ddelta_dxi = -0.5 * sig * ny;
  return true;
}

FlangeContact ContactSolver::indentation(Side side, const WheelsetPose& pose, double xi_g,
                                         double s_w, double s_r) const {
  FlangeContact fc;
  fc.exists = true;
  interiorIndentation(side_[idx(side)], side, pose, xi_g, s_w, s_r, fc);
  return fc;
}

int ContactSolver::localMinima(Side side, const WheelsetPose& pose, double xi_g, Window window,
                               double exclude_s, double exclude_radius,
                               std::array<Gap, 4>& starts) const {
  const SideData& sd = side_[idx(side)];
  const std::vector<double>& ss = window == Window::Tread    ? sd.tread_s
                                  : window == Window::Flange ? sd.flange_s
                                                             : sd.all_s;
  const std::vector<double>& hh = window == Window::Tread    ? sd.tread_h
                                  : window == Window::Flange ? sd.flange_h
                                                             : sd.all_h;
  const double sig = sd.sigma;
  const double sb = sig * sb_, cb = cb_;
  const double oy = sig * (cfg_.rail_lr + 0.5 * xi_g);
  const double rlo = sd.rail->sMin(), rhi = sd.rail->sMax();
  int n = 0;
  double g_prev2 = std::numeric_limits<double>::infinity();
  double g_prev = std::numeric_limits<double>::infinity();
  Gap prev;
  Gap best_below{std::numeric_limits<double>::infinity(), 0.0, 0.0};
  Gap best_above{std::numeric_limits<double>::infinity(), 0.0, 0.0};
  auto offer = [&](const Gap& g) {
    if (exclude_radius > 0.0 && std::abs(g.s_w - exclude_s) <= exclude_radius) return;
    keepDeepest(starts, n, g);
  };
  for (std::size_t i = 0; i <= ss.size(); ++i) {
    double g = std::numeric_limits<double>::infinity();
    Gap cur;
    if (i < ss.size()) {
      const double a = sig * cfg_.wheel_lw + ss[i];
      const double py = pose.y + a + pose.phi * hh[i] - oy;
      const double pz = pose.z + pose.phi * a - hh[i];
      const double u = cb * py + sb * pz;
      if (u >= rlo && u <= rhi) {
        const double v = -sb * py + cb * pz;
        const profiles::ProfilePoint r = sd.rail->at(u);
        g = (v - r.h) / std::sqrt(1.0 + r.dh * r.dh);
        cur = {g, ss[i], u};
      }
    }
    // prev is a local minimum when below both neighbours (window ends count as +inf).
    if (std::isfinite(g_prev) && g_prev <= g_prev2 && g_prev < g) offer(prev);
    if (exclude_radius > 0.0 && std::isfinite(g)) {
      Gap& side_best = cur.s_w < exclude_s ? best_below : best_above;
      if (std::abs(cur.s_w - exclude_s) > exclude_radius && g < side_best.gap) side_best = cur;
    }
    g_prev2 = g_prev;
    g_prev = g;
    prev = cur;
  }
  if (std::isfinite(best_below.gap)) offer(best_below);
  if (std::isfinite(best_above.gap)) offer(best_above);
  return n;
}

FlangeContact ContactSolver::flange(Side side, const WheelsetPose& pose, double xi_g,
                                    const FlangeContact* warm) const {
  FlangeContact fc;
  const SideData& sd = side_[idx(side)];
  if (!sd.has_flange) return fc;
  fc.exists = true;
  // Edge candidate (always defined), then the deepest interior stationary point of Eq. (15) in
  // the window, from the warm start and from the deepest sampled local minima.
  edgeFlange(sd, side, pose, xi_g, fc);
  std::array<Gap, 5> starts;
  int n = 0;
  if (warm && warm->converged && std::isfinite(warm->interior_delta)) {
    starts[0] = {0.0, warm->interior_s_w, warm->interior_s_r};
    n = 1;
  }
  std::array<Gap, 4> sampled;
  const int ns = localMinima(side, pose, xi_g, Window::Flange, 0.0, 0.0, sampled);
  for (int k = 0; k < ns; ++k)
    starts[static_cast<std::size_t>(n++)] = sampled[static_cast<std::size_t>(k)];
  const double tol = 1e-12;
  FlangeContact best;
  bool have = false;
  for (int k = 0; k < n; ++k) {
    FlangeContact in;
    in.exists = true;
    const Gap& st = starts[static_cast<std::size_t>(k)];
    const bool ok = interiorIndentation(sd, side, pose, xi_g, st.s_w, st.s_r, in);
    fc.iterations += in.iterations;
    if (!ok) continue;
    const double sw = in.point.s_w;
    const bool in_window = sd.sigma > 0 ? (sw >= sd.tip - tol && sw <= sd.boundary + tol)
                                        : (sw <= sd.tip + tol && sw >= sd.boundary - tol);
    if (!in_window) continue;
    if (!have || in.delta > best.delta) {
      best = in;
      have = true;
    }
  }
  if (!have) return fc;
  fc.interior_delta = best.delta;
  fc.interior_s_w = best.point.s_w;
  fc.interior_s_r = best.point.s_r;
  if (best.delta <= fc.delta) return fc;  // the window end is deeper
  best.iterations = fc.iterations;
  best.interior_delta = best.delta;
  best.interior_s_w = best.point.s_w;
  best.interior_s_r = best.point.s_r;
  return best;
}

}  // namespace rb::contact
