#include "workbench/contact/elastic_search.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "workbench/core/error.hpp"

namespace rb::contact {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxStep = 2e-3;         // [m] Newton step limit on s_w, s_r
constexpr double kDomainSlack = 1e-3;     // [m] how far a parameter may leave its profile in Newton
constexpr double kMaxSinTheta = 0.5;      // |sin(theta + eps)| bound of the locus equation
constexpr std::size_t kPruneStride = 16;  // coarse scan: every 16th sample (4 mm at 0.25 mm)
constexpr std::size_t kMinBlock = 8;      // shorter blocks are scanned without a bound
constexpr double kMaxPruneStep = 0.3e-3;  // [m] coarser scans are not pruned
constexpr double kRailBinPad = 10e-3;     // [m] rail bins beyond the rail ends (extrapolation)

// Bounds of a profile over [lo, hi]: upper bounds of |h'|, |h''|, |h'''| and of h'' and -h''
// (signed). h'' is continuous and piecewise linear between the knots, so its values at the knots
// inside and at 16 sub-points (all sorted) bound it and their difference quotients are the exact
// h''' of the knot intervals; h' is bounded by its values there plus max |h''| times half the
// largest spacing.
struct ProfileBound {
  double d1 = 0.0, d2 = 0.0, d3 = 0.0;
  double d2_hi = 0.0, d2_neg = 0.0;  // h'' <= d2_hi, -h'' <= d2_neg
};
ProfileBound profileBounds(const profiles::Profile& p, const std::vector<double>& knots, double lo,
                           double hi) {
  constexpr int kSub = 16;
  std::array<double, kSub + 1 + 64> pts{};
  std::size_t n = 0;
  auto k = std::upper_bound(knots.begin(), knots.end(), lo);
  for (int j = 0; j <= kSub; ++j) {
    const double x = lo + (hi - lo) * j / kSub;
    while (k != knots.end() && *k < x && n + 1 < pts.size()) pts[n++] = *k++;
    if (n < pts.size()) pts[n++] = x;
  }
  ProfileBound b;
  double gmax = 0.0, prev_x = 0.0, prev_d2 = 0.0;
  double d2_hi = -kInf, d2_lo = kInf;
  for (std::size_t j = 0; j < n; ++j) {
    const profiles::ProfilePoint q = p.at(pts[j]);
    b.d1 = std::max(b.d1, std::abs(q.dh));
    b.d2 = std::max(b.d2, std::abs(q.d2h));
    d2_hi = std::max(d2_hi, q.d2h);
    d2_lo = std::min(d2_lo, q.d2h);
    if (j > 0 && pts[j] > prev_x) {
      b.d3 = std::max(b.d3, std::abs(q.d2h - prev_d2) / (pts[j] - prev_x));
      gmax = std::max(gmax, pts[j] - prev_x);
    }
    prev_x = pts[j];
    prev_d2 = q.d2h;
  }
  b.d1 = 1.01 * (b.d1 + 0.5 * b.d2 * gmax) + 1e-9;
  // (The signed bounds get 1 % of max |h''| as margin, like the magnitude bound.)
  b.d2_hi = d2_hi + 0.01 * b.d2 + 1e-9;
  b.d2_neg = -d2_lo + 0.01 * b.d2 + 1e-9;
  b.d2 = 1.01 * b.d2 + 1e-9;
  b.d3 = 1.01 * b.d3 + 1e-9;
  return b;
}

}  // namespace

std::array<WheelRailPair, 2> wheelRailPairs(const ContactGeometryConfig& config) {
  checkConfig(config);
  std::array<WheelRailPair, 2> p;
  p[0].wheel = config.left_wheel;
  p[0].rail = config.left_rail;
  p[0].side = Side::Left;
  p[1].wheel = config.right_wheel;
  p[1].rail = config.right_rail;
  p[1].side = Side::Right;
  for (WheelRailPair& q : p) {
    q.wheel_lw = config.wheel_lw;
    q.rail_lr = config.rail_lr;
    q.beta = config.beta;
  }
  return p;
}

std::array<std::array<double, 3>, 3> wheelsetRotation(double phi, double psi, EulerOrder order) {
  const double cps = std::cos(psi), sps = std::sin(psi);
  const double cph = std::cos(phi), sph = std::sin(phi);
  if (order == EulerOrder::RollYaw)  // Rx(phi) Rz(psi)
    return {{{cps, -sps, 0.0}, {cph * sps, cph * cps, -sph}, {sph * sps, sph * cps, cph}}};
  // Rz(psi) Rx(phi)
  return {{{cps, -sps * cph, sps * sph}, {sps, cps * cph, -cps * sph}, {0.0, sph, cph}}};
}

// Pose-dependent constants of one search: the rotation R (wheelset -> track) and the locus
// equation R00 sin(theta) - R02 cos(theta) = R01 h' written as rho sin(theta + eps) = R01 h'.
struct ElasticContactSearch::PoseTrig {
  double y = 0.0, z = 0.0;
  std::array<std::array<double, 3>, 3> r{};
  double rho = 1.0, ceps = 1.0, seps = 0.0;
  double oy = 0.0, oz = 0.0;  // rail profile origin
  double blend = 0.0;         // rail_next's share (0 on a prismatic rail)
  PoseTrig(const ElasticPose& p, const WheelRailPair& pair, double sigma, EulerOrder order) {
    y = p.y;
    z = p.z;
    if (pair.rail_next) blend = p.blend;
    r = wheelsetRotation(p.phi, p.psi, order);
    const double a = r[0][0], b = -r[0][2];
    rho = std::hypot(a, b);
    ceps = a / rho;
    seps = b / rho;
    oy = sigma * pair.rail_lr + pair.rail_dy;
    oz = pair.rail_dz;
  }
  // sin(theta), cos(theta) and w = cos(theta + eps) on the wheel circle of slope dh.
  void theta(double dh, double& st, double& ct, double& w) const {
    const double q = std::clamp(r[0][1] * dh / rho, -kMaxSinTheta, kMaxSinTheta);
    w = std::sqrt(1.0 - q * q);
    st = q * ceps - w * seps;
    ct = w * ceps + q * seps;
  }
  // Track-frame Y, Z of the wheel point (h sin theta, L, -h cos theta) (rows 1, 2 of R X).
  double py(double h, double L, double st, double ct) const {
    return y + r[1][0] * h * st + r[1][1] * L - r[1][2] * h * ct;
  }
  double pz(double h, double L, double st, double ct) const {
    return z + r[2][0] * h * st + r[2][1] * L - r[2][2] * h * ct;
  }
};

ElasticContactSearch::ElasticContactSearch(WheelRailPair pair, ElasticSearchSpec spec)
    : pair_(std::move(pair)), spec_(spec) {
  if (!pair_.wheel || !pair_.rail) {
    throw InputError(SourceLoc{}, "elastic contact search: a wheel and a rail profile are needed");
  }
  if (!(spec_.sample_step > 0.0) || !(spec_.newton_tol > 0.0) || spec_.newton_max_iter < 1) {
    throw InputError(SourceLoc{}, "elastic contact search: sample_step and newton_tol must be > 0");
  }
  static std::atomic<std::uint64_t> models{0};
  id_ = ++models;
  sigma_ = pair_.side == Side::Left ? 1.0 : -1.0;
  cb_ = std::cos(pair_.beta);
  sb_ = sigma_ * std::sin(pair_.beta);
  const profiles::Profile& w = *pair_.wheel;
  const auto n = static_cast<std::size_t>(std::floor((w.sMax() - w.sMin()) / spec_.sample_step));
  s_.reserve(n + 2);
  for (std::size_t i = 0; i <= n; ++i)
    s_.push_back(w.sMin() + static_cast<double>(i) * spec_.sample_step);
  if (w.sMax() - s_.back() > 1e-12) s_.push_back(w.sMax());
  for (double s : s_) {
    const profiles::ProfilePoint p = w.at(s);
    h_.push_back(p.h);
    dh_.push_back(p.dh);
  }
  // Scan pruning bounds (scanPruned()).
  const std::vector<double> wk = w.knots();
  std::vector<double> d1(s_.size(), 0.0), d2(s_.size(), 0.0), d3(s_.size(), 0.0);
  std::vector<double> d2_hi(s_.size(), 0.0), d2_neg(s_.size(), 0.0);
  for (std::size_t i = 0; i + 1 < s_.size(); ++i) {
    const ProfileBound b = profileBounds(w, wk, s_[i], s_[i + 1]);
    d1[i] = b.d1;
    d2[i] = b.d2;
    d3[i] = b.d3;
    d2_hi[i] = b.d2_hi;
    d2_neg[i] = b.d2_neg;
  }
  wheel_d1_.build(d1);
  wheel_d2_.build(d2);
  wheel_d3_.build(d3);
  wheel_d2_hi_.build(d2_hi);
  wheel_d2_neg_.build(d2_neg);
  for (std::size_t i = 0; i < s_.size(); ++i) {
    d2h_.push_back(w.at(s_[i]).d2h);
    wheel_hmax_ = std::max(wheel_hmax_, std::abs(h_[i]));
  }
  wheel_hmax_ = 1.01 * wheel_hmax_ + 1e-3;  // (h between samples: |h'| Delta s is far below 1 mm)
  double l_max = 0.0;
  for (double s : s_) l_max = std::max(l_max, std::abs(sigma_ * pair_.wheel_lw + s));
  wheel_xmax_ = std::hypot(wheel_hmax_, l_max) + 1e-3;  // |X| = sqrt(h^2 + L^2) at any sample
  // Rail bins over the rail and kRailBinPad beyond its ends (at() extrapolates the end cubics).
  // A blended rail (rail_next) is a convex combination of the two slices at every u: each bound
  // of its derivatives is the larger of the two slices' bounds.
  const profiles::Profile& r = *pair_.rail;
  rail_smin_ = r.sMin();
  rail_smax_ = r.sMax();
  if (pair_.rail_next) {
    rail_smin_ = std::max(rail_smin_, pair_.rail_next->sMin());
    rail_smax_ = std::min(rail_smax_, pair_.rail_next->sMax());
    if (!(rail_smax_ > rail_smin_)) {
      throw InputError(SourceLoc{}, "elastic contact search: the two rail slices '" + r.name() +
                                        "' and '" + pair_.rail_next->name() +
                                        "' have no profile parameter in common");
    }
  }
  rail_bin0_ = rail_smin_ - kRailBinPad;
  const auto nb = static_cast<std::size_t>(
      std::ceil((rail_smax_ - rail_smin_ + 2.0 * kRailBinPad) / rail_bin_));
  std::vector<double> r1(nb, 0.0), r2(nb, 0.0), r2_hi(nb, 0.0), r2_neg(nb, 0.0);
  for (const profiles::Profile* rp : {pair_.rail.get(), pair_.rail_next.get()}) {
    if (rp == nullptr) continue;
    const std::vector<double> rk = rp->knots();
    for (std::size_t b = 0; b < nb; ++b) {
      const double u0 = rail_bin0_ + static_cast<double>(b) * rail_bin_;
      const ProfileBound pb = profileBounds(*rp, rk, u0, u0 + rail_bin_);
      r1[b] = std::max(r1[b], pb.d1);
      r2[b] = std::max(r2[b], pb.d2);
      r2_hi[b] = rp == pair_.rail.get() ? pb.d2_hi : std::max(r2_hi[b], pb.d2_hi);
      r2_neg[b] = rp == pair_.rail.get() ? pb.d2_neg : std::max(r2_neg[b], pb.d2_neg);
    }
  }
  rail_d1_.build(r1);
  rail_d2_.build(r2);
  rail_d2_hi_.build(r2_hi);
  rail_d2_neg_.build(r2_neg);
  rail_bins_ = nb;
}

void ElasticContactSearch::RangeMax::build(const std::vector<double>& v) {
  level.assign(1, v);
  for (std::size_t w = 1; 2 * w <= v.size(); w *= 2) {
    const std::vector<double>& p = level.back();
    std::vector<double> q(v.size() - 2 * w + 1);
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = std::max(p[i], p[i + w]);
    level.push_back(std::move(q));
  }
}

double ElasticContactSearch::RangeMax::operator()(std::size_t a, std::size_t b) const {
  const auto l = static_cast<std::size_t>(std::bit_width(b - a) - 1);
  const std::vector<double>& q = level[l];
  return std::max(q[a], q[b - (std::size_t{1} << l)]);
}

profiles::ProfilePoint ElasticContactSearch::railAt(double u, double blend) const {
  profiles::ProfilePoint a = pair_.rail->at(u);
  if (!pair_.rail_next) return a;
  // a + b (next - a): exactly a where the two slices are the same profile.
  const profiles::ProfilePoint n = pair_.rail_next->at(u);
  a.h += blend * (n.h - a.h);
  a.dh += blend * (n.dh - a.dh);
  a.d2h += blend * (n.d2h - a.d2h);
  return a;
}

profiles::ProfilePoint ElasticContactSearch::railAt(const PoseTrig& t, double u) const {
  return railAt(u, t.blend);
}

ElasticContactSearch::LocusPoint ElasticContactSearch::locus(const ElasticPose& pose,
                                                             double s_w) const {
  return locus(PoseTrig(pose, pair_, sigma_, spec_.angles), s_w);
}

ElasticContactSearch::LocusPoint ElasticContactSearch::locus(const PoseTrig& t, double s_w,
                                                             bool full) const {
  const profiles::ProfilePoint w = pair_.wheel->at(s_w);
  double st = 0.0, ct = 1.0, wq = 1.0;
  t.theta(w.dh, st, ct, wq);
  const double L = sigma_ * pair_.wheel_lw + s_w;
  const auto& r = t.r;
  LocusPoint p;
  if (full) {
    p.theta = std::atan2(st, ct);
    p.x_w = w.h * st;
    p.x = r[0][0] * w.h * st + r[0][1] * L - r[0][2] * w.h * ct;
  }
  p.y = t.py(w.h, L, st, ct);
  p.z = t.pz(w.h, L, st, ct);
  // d theta / ds from the locus equation; D = dX/ds + theta' dX/dtheta (wheelset coordinates).
  const double dth = r[0][1] * w.d2h / (t.rho * wq);
  const double d0 = w.dh * st + dth * w.h * ct, d2 = -w.dh * ct + dth * w.h * st;
  p.t_y = r[1][0] * d0 + r[1][1] + r[1][2] * d2;
  p.t_z = r[2][0] * d0 + r[2][1] + r[2][2] * d2;
  // Outward normal m = (sin theta, -h', -cos theta) and dm/ds = (cos theta theta', -h'',
  // sin theta theta'), rotated to the track frame (rows Y and Z of R).
  p.ny_raw = r[1][0] * st - r[1][1] * w.dh - r[1][2] * ct;
  p.nz_raw = r[2][0] * st - r[2][1] * w.dh - r[2][2] * ct;
  p.dn_y = r[1][0] * ct * dth - r[1][1] * w.d2h + r[1][2] * st * dth;
  p.dn_z = r[2][0] * ct * dth - r[2][1] * w.d2h + r[2][2] * st * dth;
  if (full) {
    const double nn = std::hypot(p.ny_raw, p.nz_raw);
    p.n_y = p.ny_raw / nn;
    p.n_z = p.nz_raw / nn;
  }
  return p;
}

// Gap of wheel sample i: distance of its locus point to the rail tangent line at the rail point
// below it (rail frame vertical); +inf when the sample is not over the rail.
ElasticContactSearch::SampleOnRail ElasticContactSearch::sampleOnRail(const PoseTrig& t,
                                                                      std::size_t i) const {
  SampleOnRail p;
  t.theta(dh_[i], p.st, p.ct, p.wq);
  p.h = h_[i];
  const double L = sigma_ * pair_.wheel_lw + s_[i];
  const double py = t.py(p.h, L, p.st, p.ct) - t.oy;
  const double pz = t.pz(p.h, L, p.st, p.ct) - t.oz;
  p.u = cb_ * py + sb_ * pz;
  if (p.u < rail_smin_ || p.u > rail_smax_) return p;
  p.v = -sb_ * py + cb_ * pz;
  p.rp = railAt(t, p.u);
  p.over = true;
  return p;
}

double ElasticContactSearch::sampledGap(const PoseTrig& t, std::size_t i, double& s_r) const {
  const SampleOnRail p = sampleOnRail(t, i);
  if (!p.over) return kInf;
  s_r = p.u;
  return (p.v - p.rp.h) / std::sqrt(1.0 + p.rp.dh * p.rp.dh);
}

double ElasticContactSearch::sampledGap(const PoseTrig& t, std::size_t i, double& s_r, double& e,
                                        double& de) const {
  const SampleOnRail p = sampleOnRail(t, i);
  if (!p.over) return kInf;
  s_r = p.u;
  const double st = p.st, ct = p.ct, wq = p.wq, h = p.h, v = p.v;
  const profiles::ProfilePoint& rp = p.rp;
  // Locus tangent (as locus()), in the rail frame.
  const auto& m = t.r;
  const double q = m[0][1] * dh_[i] / t.rho;
  const double dth = std::abs(q) < kMaxSinTheta ? m[0][1] * d2h_[i] / (t.rho * wq) : 0.0;
  const double d0 = dh_[i] * st + dth * h * ct, d2 = -dh_[i] * ct + dth * h * st;
  const double ty = m[1][0] * d0 + m[1][1] + m[1][2] * d2;
  const double tz = m[2][0] * d0 + m[2][1] + m[2][2] * d2;
  const double du = cb_ * ty + sb_ * tz, dv = -sb_ * ty + cb_ * tz;
  e = v - rp.h;
  de = dv - rp.dh * du;
  return (v - rp.h) / std::sqrt(1.0 + rp.dh * rp.dh);
}

int ElasticContactSearch::refine(const PoseTrig& t, double& s_w, double& s_r) const {
  const profiles::Profile& wp = *pair_.wheel;
  const double oy = sigma_ * pair_.rail_lr + pair_.rail_dy, oz = pair_.rail_dz;
  for (int it = 0; it < spec_.newton_max_iter; ++it) {
    const LocusPoint w = locus(t, s_w, false);
    const profiles::ProfilePoint r = railAt(t, s_r);
    const double ry = oy + cb_ * s_r - sb_ * r.h, rz = oz + sb_ * s_r + cb_ * r.h;
    const double ty = cb_ - sb_ * r.dh, tz = sb_ + cb_ * r.dh;      // rail tangent
    const double dty = -sb_ * r.d2h, dtz = cb_ * r.d2h;             // its derivative
    const double nry = -cb_ * r.dh - sb_, nrz = -sb_ * r.dh + cb_;  // rail normal
    const double dnry = -cb_ * r.d2h, dnrz = -sb_ * r.d2h;          // its derivative
    const double dy = w.y - ry, dz = w.z - rz;
    const double f1 = dy * ty + dz * tz;
    const double f2 = w.ny_raw * nrz - w.nz_raw * nry;
    const double j11 = w.t_y * ty + w.t_z * tz;
    const double j12 = -(ty * ty + tz * tz) + dy * dty + dz * dtz;
    const double j21 = w.dn_y * nrz - w.dn_z * nry;
    const double j22 = w.ny_raw * dnrz - w.nz_raw * dnry;
    const double det = j11 * j22 - j12 * j21;
    if (!std::isfinite(det) || det == 0.0) return -1;
    double dsw = -(j22 * f1 - j12 * f2) / det;
    double dsr = -(-j21 * f1 + j11 * f2) / det;
    const double big = std::max(std::abs(dsw), std::abs(dsr));
    if (big > kMaxStep) {
      dsw *= kMaxStep / big;
      dsr *= kMaxStep / big;
    }
    s_w += dsw;
    s_r += dsr;
    if (s_w < wp.sMin() - kDomainSlack || s_w > wp.sMax() + kDomainSlack ||
        s_r < rail_smin_ - kDomainSlack || s_r > rail_smax_ + kDomainSlack) {
      return -1;
    }
    if (std::max(std::abs(dsw), std::abs(dsr)) <= spec_.newton_tol) return it + 1;
  }
  return -1;
}

double ElasticContactSearch::gapAt(const PoseTrig& t, double s_w, double& s_r, double* dgap) const {
  const LocusPoint w = locus(t, s_w, false);
  const double oy = sigma_ * pair_.rail_lr + pair_.rail_dy, oz = pair_.rail_dz;
  // Foot point on the rail: (W - R(s_r)) . t_r(s_r) = 0 (Newton, well conditioned while the
  // distance is far below the rail's radius of curvature).
  profiles::ProfilePoint r = railAt(t, s_r);
  for (int it = 0; it < spec_.newton_max_iter; ++it) {
    const double ry = oy + cb_ * s_r - sb_ * r.h, rz = oz + sb_ * s_r + cb_ * r.h;
    const double ty = cb_ - sb_ * r.dh, tz = sb_ + cb_ * r.dh;
    const double dty = -sb_ * r.d2h, dtz = cb_ * r.d2h;
    const double dy = w.y - ry, dz = w.z - rz;
    const double f = dy * ty + dz * tz;
    const double df = -(ty * ty + tz * tz) + dy * dty + dz * dtz;
    double step = df != 0.0 ? -f / df : 0.0;
    step = std::clamp(step, -kMaxStep, kMaxStep);
    s_r = std::clamp(s_r + step, rail_smin_, rail_smax_);
    r = railAt(t, s_r);
    if (std::abs(step) <= spec_.newton_tol) break;
  }
  const double ry = oy + cb_ * s_r - sb_ * r.h, rz = oz + sb_ * s_r + cb_ * r.h;
  const double ny = -cb_ * r.dh - sb_, nz = -sb_ * r.dh + cb_;
  const double nn = std::hypot(ny, nz);
  if (dgap) *dgap = (w.t_y * ny + w.t_z * nz) / nn;
  return ((w.y - ry) * ny + (w.z - rz) * nz) / nn;
}

int ElasticContactSearch::refineBracketed(const PoseTrig& t, double lo, double hi, double& s_w,
                                          double& s_r) const {
  double sr_lo = s_r, sr_hi = s_r, d_lo = 0.0, d_hi = 0.0;
  (void)gapAt(t, lo, sr_lo, &d_lo);
  (void)gapAt(t, hi, sr_hi, &d_hi);
  if (!(d_lo < 0.0 && d_hi > 0.0)) return -1;
  // Illinois regula falsi on d gap / d s_w.
  int side = 0;
  for (int it = 1; it <= 4 * spec_.newton_max_iter; ++it) {
    double s = lo - d_lo * (hi - lo) / (d_hi - d_lo);
    if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
    double sr = d_lo < -d_hi ? sr_hi : sr_lo, d = 0.0;
    (void)gapAt(t, s, sr, &d);
    if (hi - lo <= spec_.newton_tol || d == 0.0) {
      s_w = s;
      s_r = sr;
      return it;
    }
    if (d < 0.0) {
      lo = s;
      d_lo = d;
      sr_lo = sr;
      if (side == -1) d_hi *= 0.5;
      side = -1;
    } else {
      hi = s;
      d_hi = d;
      sr_hi = sr;
      if (side == 1) d_lo *= 0.5;
      side = 1;
    }
  }
  s_w = 0.5 * (lo + hi);
  (void)gapAt(t, s_w, s_r);
  return 4 * spec_.newton_max_iter;
}

bool ElasticContactSearch::separation(const PoseTrig& t, double y0, double z0, double ny, double nz,
                                      double off, double s_w, double s_r, double& sep) const {
  const double ty = nz, tz = -ny;  // a unit tangent (either direction: sep(+-off) is symmetric)
  const profiles::Profile& wpf = *pair_.wheel;
  const double oy = sigma_ * pair_.rail_lr + pair_.rail_dy, oz = pair_.rail_dz;
  // Rail point with (R(s) - R0) . tau = off.
  double lam_r = 0.0, lam_w = 0.0;
  bool ok = false;
  for (int it = 0; it < spec_.newton_max_iter; ++it) {
    const profiles::ProfilePoint r = railAt(t, s_r);
    const double ry = oy + cb_ * s_r - sb_ * r.h - y0, rz = oz + sb_ * s_r + cb_ * r.h - z0;
    const double f = ry * ty + rz * tz - off;
    const double df = (cb_ - sb_ * r.dh) * ty + (sb_ + cb_ * r.dh) * tz;
    lam_r = ry * ny + rz * nz;
    if (std::abs(f) <= spec_.newton_tol) {
      ok = true;
      break;
    }
    if (df == 0.0) return false;
    s_r -= std::clamp(f / df, -kMaxStep, kMaxStep);
    if (!railInside(s_r)) return false;
  }
  if (!ok) return false;
  ok = false;
  for (int it = 0; it < spec_.newton_max_iter; ++it) {
    const LocusPoint w = locus(t, s_w, false);
    const double wy = w.y - y0, wz = w.z - z0;
    const double f = wy * ty + wz * tz - off;
    const double df = w.t_y * ty + w.t_z * tz;
    lam_w = wy * ny + wz * nz;
    if (std::abs(f) <= spec_.newton_tol) {
      ok = true;
      break;
    }
    if (df == 0.0) return false;
    s_w -= std::clamp(f / df, -kMaxStep, kMaxStep);
    if (!wpf.inside(s_w)) return false;
  }
  sep = lam_w - lam_r;
  return ok;
}

ElasticPatchGeometry ElasticContactSearch::describe(const PoseTrig& t, double s_w,
                                                    double s_r) const {
  const LocusPoint w = locus(t, s_w);
  const profiles::ProfilePoint wp = pair_.wheel->at(s_w);
  const profiles::ProfilePoint r = railAt(t, s_r);
  const double oy = sigma_ * pair_.rail_lr + pair_.rail_dy, oz = pair_.rail_dz;
  ElasticPatchGeometry g;
  g.s_w = s_w;
  g.s_r = s_r;
  g.y = oy + cb_ * s_r - sb_ * r.h;
  g.z = oz + sb_ * s_r + cb_ * r.h;
  g.x = w.x;
  g.x_w = w.x_w;
  g.theta = w.theta;
  const double ny = -cb_ * r.dh - sb_, nz = -sb_ * r.dh + cb_;
  const double nn = std::hypot(ny, nz);
  g.n_y = ny / nn;
  g.n_z = nz / nn;
  g.gamma = std::atan2(-sigma_ * g.n_y, g.n_z);
  g.radius = wp.h;
  g.gap_depth = -((w.y - g.y) * g.n_y + (w.z - g.z) * g.n_z);
  g.approach = g.gap_depth;
  const double qw = 1.0 + wp.dh * wp.dh, qr = 1.0 + r.dh * r.dh;
  if (pair_.rail_next)
    g.rail_rise = (pair_.rail_next->at(s_r).h - pair_.rail->at(s_r).h) / std::sqrt(qr);
  g.k_wheel_trans = -wp.d2h / (qw * std::sqrt(qw));
  g.k_wheel_rolling = 1.0 / (wp.h * std::sqrt(qw));
  g.k_rail_trans = -r.d2h / (qr * std::sqrt(qr));
  // hertz.hpp: A = (k_wheel,x + k_rail,x) / 2 with a straight rail, B = (k_wheel,y + k_rail,y) / 2.
  g.A = 0.5 * g.k_wheel_rolling;
  g.B = 0.5 * (g.k_wheel_trans + g.k_rail_trans);
  g.B_span = g.B;
  const double w2 = spec_.curvature_span;
  double sp = 0.0, sm = 0.0;
  if (w2 > 0.0 && separation(t, g.y, g.z, g.n_y, g.n_z, w2, s_w, s_r, sp) &&
      separation(t, g.y, g.z, g.n_y, g.n_z, -w2, s_w, s_r, sm)) {
    g.B_span = (sp + sm + 2.0 * g.gap_depth) / (2.0 * w2 * w2);
  }
  return g;
}

void ElasticContactSearch::refineCandidates(const PoseTrig& t, ElasticWheelGeometry& out,
                                            ElasticSearchWorkspace& ws,
                                            const ElasticWheelGeometry* seed) const {
  const std::size_t nc = ws.minima.size();
  ws.depth.assign(nc, kInf);
  ws.sw.assign(nc, 0.0);
  ws.sr.assign(nc, 0.0);
  ws.ok.assign(nc, 0);
  for (std::size_t k = 0; k < nc; ++k) {
    const auto i = static_cast<std::size_t>(ws.minima[k]);
    double s_w = s_[i], s_r = 0.0;
    (void)sampledGap(t, i, s_r);
    const double s_r0 = s_r;
    // The minimum lies between the neighbouring samples (the gap proxy and the exact gap differ
    // little); a refinement that leaves that interval went to another minimum.
    const double lo = s_[i > 0 ? i - 1 : i], hi = s_[i + 1 < s_.size() ? i + 1 : i];
    auto inside = [&](double v) { return v >= lo - 1e-12 && v <= hi + 1e-12; };
    int it = refine(t, s_w, s_r);
    if (it < 0 || !inside(s_w)) {
      s_w = s_[i];
      s_r = s_r0;
      it = refineBracketed(t, lo, hi, s_w, s_r);
    }
    // A failed refinement may restart from the nearest seed patch (seeds never add patches).
    if (it < 0 && seed) {
      for (int p = 0; p < seed->count; ++p) {
        const ElasticPatchGeometry& sp = seed->patch[static_cast<std::size_t>(p)];
        if (!inside(sp.s_w)) continue;
        double sw = sp.s_w, sr = sp.s_r;
        const int n = refine(t, sw, sr);
        if (n >= 0 && inside(sw)) {
          it = n;
          s_w = sw;
          s_r = sr;
          break;
        }
      }
    }
    out.newton_iterations += std::max(it, 0);
    // A refined point must stay near its sampled minimum (else it belongs to another minimum).
    if (it >= 0 && inside(s_w)) {
      double sr = s_r;
      ws.depth[k] = gapAt(t, s_w, sr);
      ws.sw[k] = s_w;
      ws.sr[k] = s_r;
      ws.ok[k] = 1;
    } else {
      ws.depth[k] = ws.gap[i];
      ws.sw[k] = s_[i];
      ws.sr[k] = s_r0;
      ws.ok[k] = 2;  // sampled point only
    }
  }
  // Minima refined onto the same wheel point are one: keep the first (deeper sample wins ties).
  for (std::size_t k = 0; k < nc; ++k) {
    for (std::size_t j = k + 1; j < nc; ++j) {
      if (ws.ok[k] && ws.ok[j] && std::abs(ws.sw[k] - ws.sw[j]) < spec_.same_point) {
        const auto ik = static_cast<std::size_t>(ws.minima[k]);
        const auto ij = static_cast<std::size_t>(ws.minima[j]);
        ws.ok[ws.gap[ik] <= ws.gap[ij] ? j : k] = 0;
      }
    }
  }
}

void ElasticContactSearch::collectPatches(const PoseTrig& t, ElasticWheelGeometry& out,
                                          ElasticSearchWorkspace& ws) const {
  const std::size_t nc = ws.minima.size();
  // Shared overlap (header comment): the lowest ridge r to a neighbouring minimum j; the depths
  // below it, e_k and e_j, are each minimum's own; the common part max(0, -r) is split between
  // the two in proportion to e_k and e_j, so that nothing jumps when two minima swap depth, merge
  // at a fold (e_k -> 0) or separate (r -> 0).
  for (std::size_t k = 0; k < nc; ++k) {
    if (!ws.ok[k] || !(ws.depth[k] < 0.0)) continue;
    double ridge = kInf;
    std::size_t partner = k;
    for (int dir : {-1, 1}) {
      auto j = static_cast<std::ptrdiff_t>(k) + dir;
      while (j >= 0 && j < static_cast<std::ptrdiff_t>(nc) && !ws.ok[static_cast<std::size_t>(j)]) {
        j += dir;
      }
      if (j < 0 || j >= static_cast<std::ptrdiff_t>(nc)) continue;
      const auto ju = static_cast<std::size_t>(j);
      const int a = std::min(ws.minima[k], ws.minima[ju]);
      const int b = std::max(ws.minima[k], ws.minima[ju]);
      double run = -kInf;
      for (int i = a; i <= b; ++i) run = std::max(run, ws.gap[static_cast<std::size_t>(i)]);
      if (run < ridge) {
        ridge = run;
        partner = ju;
      }
    }
    const double delta_g = -ws.depth[k];
    double delta = delta_g;
    if (partner != k && ridge < 0.0) {
      const double e_k = ridge - ws.depth[k], e_j = std::max(ridge - ws.depth[partner], 0.0);
      const double w = e_k + e_j > 0.0 ? e_k / (e_k + e_j) : 0.5;
      delta = std::min(delta_g, e_k - w * ridge);
    }
    if (!(delta > spec_.min_approach)) continue;
    ElasticPatchGeometry g = describe(t, ws.sw[k], ws.sr[k]);
    if (ws.ok[k] == 2) {
      g.refined = false;
      g.gap_depth = delta_g;
    }
    g.approach = delta;
    if (out.count < kMaxElasticPatches) {
      out.patch[static_cast<std::size_t>(out.count++)] = g;
    } else {
      out.truncated = true;
      // Replace the shallowest kept patch when this one is deeper.
      auto* lo =
          std::min_element(out.patch.begin(), out.patch.end(),
                           [](const auto& p, const auto& q) { return p.approach < q.approach; });
      if (lo->approach < g.approach) *lo = g;
    }
  }
  std::sort(out.patch.begin(), out.patch.begin() + out.count,
            [](const auto& p, const auto& q) { return p.approach > q.approach; });
}

// What the ends of the block (a, b) prove about the samples inside it:
//   skip (lb > threshold): every sampled gap inside is above candidate_gap, lb a lower bound;
//   increasing / decreasing: the gap is strictly monotonic over the block.
// e = v - h_r(u) (rail frame), g = e / q_r, so g' = (e' - e h_r' h_r'' u' / q_r^2) / q_r and
// e'' = (v'' - h_r' u'') - h_r'' u'^2 with |v'' - h_r' u''| <= q_r |P''|; |P'| <= |X'| and
// |P''| <= |X''| (the rotations to the track and rail frames keep lengths), where
//   |X'|^2 = 1 + h'^2 + (h theta')^2,
//   |X''| <= |h''| + 2 |h'| |theta'| + h theta'^2 + h |theta''|.
// From an end at distance d <= D/2 (D the block length), e >= e_end +- e'_end d - M d^2 / 2
// (concave in d: its minimum is at d = 0 or D/2) and |e' - e'_end| <= M d.
ElasticContactSearch::ScanBlock ElasticContactSearch::classifyBlock(const PoseTrig& t,
                                                                    const ScanNode& a,
                                                                    const ScanNode& b,
                                                                    BlockInfo& info) const {
  // |kappa| / w with kappa = R01 / rho, w = cos(theta + eps) >= sqrt(1 - kMaxSinTheta^2) where
  // the locus equation is not clamped: theta' = kappa h'' / w, theta'' = kappa h''' / w +
  // kappa^2 q h''^2 / w^3.
  const double kap = std::abs(t.r[0][1]) / t.rho;
  const double k = kap / std::sqrt(1.0 - kMaxSinTheta * kMaxSinTheta);
  const auto nbins = static_cast<double>(rail_bins_);
  const double threshold = spec_.candidate_gap * (1.0 + 1e-9) + 1e-12;
  // (A block with an end off the rail is scanned in full: only the few at the rail ends.)
  if (a.g == kInf || b.g == kInf) return ScanBlock::Scan;
  const double d1 = wheel_d1_(a.i, b.i), d2 = wheel_d2_(a.i, b.i), d3 = wheel_d3_(a.i, b.i);
  if (!(kap * d1 < kMaxSinTheta)) return ScanBlock::Scan;  // the locus equation may be clamped
  const double th1 = k * d2, th2 = k * d3 + k * k * d2 * d2;
  const double speed = std::sqrt(1.0 + d1 * d1 + wheel_hmax_ * wheel_hmax_ * th1 * th1);
  const double acc = d2 + 2.0 * d1 * th1 + wheel_hmax_ * (th1 * th1 + th2);
  const double half = 0.5 * (s_[b.i] - s_[a.i]);
  // Rail bins the paths from either end to the block middle can reach.
  const double lo = (std::min(a.u, b.u) - speed * half - rail_bin0_) / rail_bin_;
  const double hi = (std::max(a.u, b.u) + speed * half - rail_bin0_) / rail_bin_;
  if (!(lo >= 0.0 && hi < nbins)) return ScanBlock::Scan;
  const auto b_lo = static_cast<std::size_t>(lo), b_hi = static_cast<std::size_t>(hi) + 1;
  info.u_lo = std::min(a.u, b.u) - speed * half;
  info.u_hi = std::max(a.u, b.u) + speed * half;
  const double r1 = rail_d1_(b_lo, b_hi), r2 = rail_d2_(b_lo, b_hi);
  const double qmax = std::sqrt(1.0 + r1 * r1);
  const double M = qmax * acc + r2 * speed * speed;
  // The signed bound e_min <= e'' <= e_max (no wider than +-M). With U, V the rows of the
  // rotation to the rail frame (u = U . X, v = V . X + const) and X = (h st, L, -h ct):
  //   e'' = -(V2 - h_r' U2) ct h'' - h_r'' u'^2 + (V2 - h_r' U2) z_r + (V0 - h_r' U0) x''
  // where z'' = -h'' ct + z_r; the first two terms are the two profiles' curvatures with their
  // signs (they cancel on a conformal tread), bounded from the signed ranges of h'' and h_r''
  // and of (V2 - h_r' U2) ct > 0 and u'^2, the rest in magnitude (|st| <= |q| + |sin eps|).
  double e_min = -M, e_max = M;
  {
    const auto& r = t.r;
    const double u0 = cb_ * r[1][0] + sb_ * r[2][0], u1 = cb_ * r[1][1] + sb_ * r[2][1];
    const double u2 = cb_ * r[1][2] + sb_ * r[2][2];
    const double v0 = -sb_ * r[1][0] + cb_ * r[2][0], v2 = -sb_ * r[1][2] + cb_ * r[2][2];
    const double hm = wheel_hmax_;
    const double sm = std::min(1.0, kap * d1 + std::abs(t.seps));
    const double g_hi = v2 + r1 * std::abs(u2);
    const double g_lo = (v2 - r1 * std::abs(u2)) * std::sqrt(1.0 - sm * sm);
    if (g_lo > 0.0) {
      const double w_hi = wheel_d2_hi_(a.i, b.i), w_lo = -wheel_d2_neg_(a.i, b.i);
      const double rr_hi = rail_d2_hi_(b_lo, b_hi), rr_lo = -rail_d2_neg_(b_lo, b_hi);
      const double t1_lo = -std::max(g_lo * w_hi, g_hi * w_hi);
      const double t1_hi = -std::min(g_lo * w_lo, g_hi * w_lo);
      const double du = std::abs(u0) * (d1 * sm + hm * th1) + std::abs(u2) * (d1 + hm * th1 * sm);
      const double u_min = std::max(0.0, std::abs(u1) - du), u_max = std::abs(u1) + du;
      const double p_lo = u_min * u_min, p_hi = u_max * u_max;
      const double t3_lo = -std::max(rr_hi * p_lo, rr_hi * p_hi);
      const double t3_hi = -std::min(rr_lo * p_lo, rr_lo * p_hi);
      const double z_r = 2.0 * d1 * th1 * sm + hm * th2 * sm + hm * th1 * th1;
      const double x2 = d2 * sm + 2.0 * d1 * th1 + hm * th2 + hm * th1 * th1 * sm;
      // (With 0.1 % of the main terms and 1e-9 / m for the rounding of this bound.)
      const double rest =
          g_hi * z_r + (std::abs(v0) + r1 * std::abs(u0)) * x2 +
          1e-3 * (std::abs(t1_lo) + std::abs(t1_hi) + std::abs(t3_lo) + std::abs(t3_hi)) + 1e-9;
      e_min = std::max(e_min, t1_lo + t3_lo - rest);
      e_max = std::min(e_max, t1_hi + t3_hi + rest);
    }
  }
  // From an end, e >= e_end +- e'_end d + min(e_min, 0) d^2 / 2: concave in d, its minimum at
  // d = 0 or D/2.
  const double c_lo = 0.5 * std::min(e_min, 0.0) * half * half;
  const double e_lo =
      std::min(std::min(a.e, a.e + a.de * half + c_lo), std::min(b.e, b.e - b.de * half + c_lo));
  const double c_abs = 0.5 * std::max(-e_min, e_max) * half * half;
  const double e_abs = std::max(std::abs(a.e) + std::abs(a.de) * half + c_abs,
                                std::abs(b.e) + std::abs(b.de) * half + c_abs);
  info.g_abs = e_abs;  // |g| <= |e|
  if (e_lo > 0.0) {
    info.lb = e_lo / qmax;
    if (info.lb > threshold) return ScanBlock::Skip;
  }
  // Monotonic: e' keeps its sign and dominates the term e h_r' h_r'' u' / q_r^2 (|h_r'| /
  // q_r^2 <= min(|h_r'|, 1/2)); the samples then differ by far more than rounding (1e-15 m per
  // sample).
  const double other = std::min(0.5, r1) * e_abs * r2 * speed;
  const double min_slope = 1e-15 / (2.0 * half / static_cast<double>(b.i - a.i)) + other;
  // e' over the block from either end: e'_a + [e_min, e_max] d, e'_b - [e_min, e_max] d.
  const double de_lo =
      std::min(a.de + std::min(e_min, 0.0) * half, b.de - std::max(e_max, 0.0) * half);
  const double de_hi =
      std::max(a.de + std::max(e_max, 0.0) * half, b.de - std::min(e_min, 0.0) * half);
  if (de_lo > min_slope) return ScanBlock::Increasing;
  if (de_hi < -min_slope) return ScanBlock::Decreasing;
  return ScanBlock::Scan;
}

// The scan of samples i_lo..i_hi, skipping those that cannot be below candidate_gap (header
// comment "Cost"): exact gaps every kPruneStride samples, then each block between two exact
// samples is either skipped (the bound below says no sample in it is below candidate_gap) or
// halved at an exactly evaluated middle sample, down to single intervals. Exact samples get their
// sampled gap, skipped ones a lower bound of it that is above candidate_gap; out.min_gap is the
// smallest exact gap.
// Bound of the movement of any wheel sample's locus point (track Y-Z) from the pose of a
// certificate to the pose t, fixed + per_slope |h'|: the translation, the change of the
// rotation rows Y and Z times |X| <= x_max, and h times the change of the locus angle theta =
// asin(clamp(kappa h')) - eps (asin is 1/sqrt(1 - 0.5^2)-Lipschitz where |q| <= 0.5; an arc is
// at most pi/2 times its chord for eps).
void ElasticContactSearch::poseShift(const PoseTrig& t, const ElasticScanCert& c, double& fixed,
                                     double& per_slope) const {
  double dr2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double d_y = t.r[1][i] - c.ref[2 + i], d_z = t.r[2][i] - c.ref[5 + i];
    dr2 += d_y * d_y + d_z * d_z;
  }
  const double dkap = std::abs(t.r[0][1] / t.rho - c.ref[8]);
  const double deps = 0.5 * std::numbers::pi * std::hypot(t.ceps - c.ref[9], t.seps - c.ref[10]);
  fixed = std::hypot(t.y - c.ref[0], t.z - c.ref[1]) + std::sqrt(dr2) * wheel_xmax_ +
          wheel_hmax_ * deps;
  per_slope = wheel_hmax_ * dkap / std::sqrt(1.0 - kMaxSinTheta * kMaxSinTheta);
}

// The scan of samples i_lo..i_hi, skipping those that cannot be below candidate_gap (header
// comment "Cost"): exact gaps every kPruneStride samples, then each block between two exact
// samples is either skipped (the bound below says no sample in it is below candidate_gap) or
// halved at an exactly evaluated middle sample, down to single intervals. Exact samples get their
// sampled gap, skipped ones a lower bound of it that is above candidate_gap; out.min_gap is the
// smallest exact gap.
// Blocks of kPruneStride samples (aligned on multiples of it) found above candidate_gap keep a
// certificate in the workspace (lower bound, |gap| and rail parameter range, pose): at a later
// pose the gap of each sample has moved by at most (1 + max |h_r'|) dP + |g| max |h_r''| dP
// (e = v - h_r(u) moves by at most dP + |h_r'| dP, g = e / q_r with |q_r' / q_r| <= |h_r''| per
// unit of u, and (u, v) by at most dP, poseShift()), so while the bound stays above
// candidate_gap the block is skipped without evaluating any sample.
void ElasticContactSearch::scanPruned(const PoseTrig& t, std::size_t i_lo, std::size_t i_hi,
                                      ElasticWheelGeometry& out, ElasticSearchWorkspace& ws) const {
  const double threshold = spec_.candidate_gap * (1.0 + 1e-9) + 1e-12;
  ScanTrack track;
  auto exact = [&](std::size_t i) {
    ScanNode n{i, 0.0, 0.0, 0.0, 0.0};
    n.g = sampledGap(t, i, n.u, n.e, n.de);
    ws.gap[i] = n.g;
    ws.bound[i] = 0;
    out.min_gap = std::min(out.min_gap, n.g);
    track.sample(n.g, n.u);
    return n;
  };
  // A certificate still valid at this pose: lb the bound of the block's samples.
  // (Certificates made by one search share its pose: the pose part once per reference.)
  std::uint64_t shift_ref = 0;
  double shift_fixed = 0.0, shift_slope = 0.0;
  auto certified = [&](const ElasticScanCert& c, std::size_t a, std::size_t b, double& lb) {
    if (std::bit_cast<std::uint64_t>(c.blend) != std::bit_cast<std::uint64_t>(t.blend))
      return false;
    if (c.ref_id != shift_ref) {
      poseShift(t, c, shift_fixed, shift_slope);
      shift_ref = c.ref_id;
    }
    const double dp = shift_fixed + shift_slope * wheel_d1_(a, b);
    const double u_lo = c.u_lo - dp - 1e-12, u_hi = c.u_hi + dp + 1e-12;
    if (!(u_lo > rail_smin_ && u_hi < rail_smax_)) return false;  // may leave the rail
    const double lo = (u_lo - rail_bin0_) / rail_bin_, hi = (u_hi - rail_bin0_) / rail_bin_;
    if (!(lo >= 0.0 && hi < static_cast<double>(rail_bins_))) return false;
    const auto b_lo = static_cast<std::size_t>(lo), b_hi = static_cast<std::size_t>(hi) + 1;
    const double r1 = rail_d1_(b_lo, b_hi), r2 = rail_d2_(b_lo, b_hi);
    lb = c.lb - (1.01 * ((1.0 + r1) * dp + c.g_abs * r2 * dp) + 1e-12);
    return lb > threshold;
  };
  ScanNode na{};
  bool have_a = false;
  for (std::size_t a = i_lo; a < i_hi;) {
    const std::size_t b = std::min((a / kPruneStride + 1) * kPruneStride, i_hi);
    ElasticScanCert* cert =
        a % kPruneStride == 0 && b == a + kPruneStride ? &ws.cert[a / kPruneStride] : nullptr;
    double lb = 0.0;
    if (cert && cert->model == id_ && certified(*cert, a, b, lb)) {
      for (std::size_t i = have_a ? a + 1 : a; i <= b; ++i) {
        ws.gap[i] = lb;
        ws.bound[i] = 1;
      }
      have_a = false;
      a = b;
      continue;
    }
    track = ScanTrack{};
    if (have_a) {
      track.sample(na.g, na.u);
    } else {
      na = exact(a);
    }
    const ScanNode nb = exact(b);
    scanBlock(t, na, nb, exact, track, out, ws);
    if (cert) {
      cert->model = 0;
      if (track.ok && track.lb > threshold) {
        cert->model = id_;
        cert->ref_id = ws.searches;
        cert->lb = track.lb;
        cert->g_abs = track.g_abs;
        cert->u_lo = track.u_lo;
        cert->u_hi = track.u_hi;
        cert->blend = t.blend;
        cert->ref = {t.y,       t.z,       t.r[1][0],         t.r[1][1], t.r[1][2], t.r[2][0],
                     t.r[2][1], t.r[2][2], t.r[0][1] / t.rho, t.ceps,    t.seps};
      }
    }
    a = b;
    na = nb;
    have_a = true;
  }
}

void ElasticContactSearch::search(const ElasticPose& pose, ElasticWheelGeometry& out,
                                  ElasticSearchWorkspace& ws,
                                  const ElasticWheelGeometry* seed) const {
  auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  const ElasticPose& q = ws.last_pose;
  if (!seed && ws.last_model == id_ && bits(pose.y) == bits(q.y) && bits(pose.z) == bits(q.z) &&
      bits(pose.phi) == bits(q.phi) && bits(pose.psi) == bits(q.psi) &&
      (!pair_.rail_next || bits(pose.blend) == bits(q.blend))) {
    out = ws.last_out;
    return;
  }
  ws.last_model = 0;
  searchFull(pose, out, ws, seed);
  if (!seed) {
    ws.last_model = id_;
    ws.last_pose = pose;
    ws.last_out = out;
  }
}

void ElasticContactSearch::searchFull(const ElasticPose& pose, ElasticWheelGeometry& out,
                                      ElasticSearchWorkspace& ws,
                                      const ElasticWheelGeometry* seed) const {
  out = ElasticWheelGeometry{};
  const PoseTrig t(pose, pair_, sigma_, spec_.angles);
  const std::size_t n = s_.size();
  ws.gap.assign(n, kInf);
  ws.bound.assign(n, 0);
  ++ws.searches;
  // (Certificates are kept from one search to the next; each names its search model.)
  if (ws.cert.size() < n / kPruneStride + 1) ws.cert.resize(n / kPruneStride + 1);
  out.min_gap = kInf;
  // Only the wheel samples above the rail matter: to first order the rail parameter below wheel
  // sample s is s + offset (offset from y, Lw, Lr and the roll times the radius); the margin
  // covers the neglected terms (flange height x roll, the yaw's cosine, the rail inclination x
  // height: together below 2 mm for |phi|, |psi| < 0.05 and beta < 0.05), and every sample in the
  // range is still checked exactly (sampledGap returns +inf off the rail).
  constexpr double kMargin = 5e-3;  // [m]
  const double offset = t.y + sigma_ * pair_.wheel_lw - t.oy - t.r[1][2] * h_.front();
  const double s_lo = rail_smin_ - offset - kMargin;
  const double s_hi = rail_smax_ - offset + kMargin;
  const double step = spec_.sample_step, s0 = s_.front();
  const auto i_lo = static_cast<std::size_t>(
      std::clamp(std::floor((s_lo - s0) / step), 0.0, static_cast<double>(n - 1)));
  const auto i_hi = static_cast<std::size_t>(
      std::clamp(std::ceil((s_hi - s0) / step), 0.0, static_cast<double>(n - 1)));
  // (Coarser scans than kMaxPruneStep are faster in full: measured, docs "Cost".)
  if (spec_.prune_scan && spec_.sample_step <= kMaxPruneStep) {
    scanPruned(t, i_lo, i_hi, out, ws);
    if (!(out.min_gap < spec_.candidate_gap)) {
      // Nothing below candidate_gap: min_gap must still be the smallest sampled gap, so the
      // skipped samples whose bound is below the smallest exact gap are evaluated.
      for (std::size_t i = i_lo; i <= i_hi; ++i) {
        if (ws.bound[i] && ws.gap[i] < out.min_gap) {
          double s_r = 0.0;
          ws.gap[i] = sampledGap(t, i, s_r);
          ws.bound[i] = 0;
          out.min_gap = std::min(out.min_gap, ws.gap[i]);
        }
      }
    }
  } else {
    for (std::size_t i = i_lo; i <= i_hi; ++i) {
      double s_r = 0.0;
      ws.gap[i] = sampledGap(t, i, s_r);
      out.min_gap = std::min(out.min_gap, ws.gap[i]);
    }
  }
  // (Samples outside i_lo..i_hi are +inf: never minima.)
  ws.minima.clear();
  const double candidate = spec_.candidate_gap;
  const double* gap = ws.gap.data();
  for (std::size_t i = i_lo; i <= i_hi; ++i) {
    const double g = gap[i];
    if (!(g < candidate)) continue;
    const double gl = i > 0 ? gap[i - 1] : kInf;
    const double gr = i + 1 < n ? gap[i + 1] : kInf;
    if (g <= gl && g < gr) ws.minima.push_back(static_cast<int>(i));
  }
  if (ws.minima.empty()) return;
  refineCandidates(t, out, ws, seed);
  collectPatches(t, out, ws);
}

ElasticWheelGeometry ElasticContactSearch::search(const ElasticPose& pose,
                                                  const ElasticWheelGeometry* seed) const {
  ElasticWheelGeometry out;
  ElasticSearchWorkspace ws;
  search(pose, out, ws, seed);
  return out;
}

int ElasticContactSearch::refine(const ElasticPose& pose, double& s_w, double& s_r) const {
  return refine(PoseTrig(pose, pair_, sigma_, spec_.angles), s_w, s_r);
}

double ElasticContactSearch::gapAt(const ElasticPose& pose, double s_w, double& s_r,
                                   double* dgap) const {
  return gapAt(PoseTrig(pose, pair_, sigma_, spec_.angles), s_w, s_r, dgap);
}

int ElasticContactSearch::refineBracketed(const ElasticPose& pose, double lo, double hi,
                                          double& s_w, double& s_r) const {
  return refineBracketed(PoseTrig(pose, pair_, sigma_, spec_.angles), lo, hi, s_w, s_r);
}

ElasticPatchGeometry ElasticContactSearch::describe(const ElasticPose& pose, double s_w,
                                                    double s_r) const {
  return describe(PoseTrig(pose, pair_, sigma_, spec_.angles), s_w, s_r);
}

// One block of the pruned scan between the exact samples na and nb (scanPruned): halved at
// exact middle samples until every part is skipped, filled as monotonic, or short enough to scan.
template <class Exact>
void ElasticContactSearch::scanBlock(const PoseTrig& t, const ScanNode& na, const ScanNode& nb,
                                     Exact& exact, ScanTrack& track, ElasticWheelGeometry& out,
                                     ElasticSearchWorkspace& ws) const {
  std::array<std::pair<ScanNode, ScanNode>, 16> stack{};
  std::size_t top = 0;
  stack[top++] = {na, nb};
  while (top > 0) {
    const auto [p, q] = stack[--top];
    if (q.i <= p.i + 1) continue;
    if (q.i < p.i + kMinBlock) {  // a bound costs about as much as a sample: scan short blocks
      for (std::size_t i = p.i + 1; i < q.i; ++i) {
        double s_r = 0.0;
        ws.gap[i] = sampledGap(t, i, s_r);
        out.min_gap = std::min(out.min_gap, ws.gap[i]);
        track.sample(ws.gap[i], s_r);
      }
      continue;
    }
    BlockInfo info;
    const ScanBlock kind = classifyBlock(t, p, q, info);
    if (kind == ScanBlock::Skip) {
      for (std::size_t i = p.i + 1; i < q.i; ++i) {
        ws.gap[i] = info.lb;
        ws.bound[i] = 1;
      }
      track.sample(info.lb, info.u_lo);
      track.sample(info.lb, info.u_hi);
      track.g_abs = std::max(track.g_abs, info.g_abs);
      continue;
    }
    if ((kind == ScanBlock::Increasing && q.g > p.g) ||
        (kind == ScanBlock::Decreasing && q.g < p.g)) {
      // Strictly between the ends like the true samples: not minima, below the larger end
      // (ridges), above the smaller one (min_gap): the scan's result is unchanged.
      const double slope = (q.g - p.g) / static_cast<double>(q.i - p.i);
      for (std::size_t i = p.i + 1; i < q.i; ++i) {
        ws.gap[i] = p.g + slope * static_cast<double>(i - p.i);
      }
      track.u_lo = std::min(track.u_lo, info.u_lo);
      track.u_hi = std::max(track.u_hi, info.u_hi);
      continue;
    }
    const ScanNode m = exact((p.i + q.i) / 2);
    stack[top++] = {m, q};
    stack[top++] = {p, m};
  }
}

}  // namespace rb::contact
