#include "workbench/track/geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "workbench/core/error.hpp"

namespace rb::track {
namespace {

constexpr double sideSign(Side side) {
  return side == Side::Left ? 1.0 : -1.0;
}

// 8-point Gauss-Legendre rule on [-1, 1].
constexpr std::array<double, 4> kGlX = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                        0.9602898564975363};
constexpr std::array<double, 4> kGlW = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                        0.1012285362903763};
constexpr double kMaxPanel = 2.0;  // [m] quadrature panel length (kappa h <= 0.2 for R >= 10 m)

// Exact laws on a segment at local coordinate t in [0, length].
double segKappa(const Segment& g, double t) {
  return g.kappa0 + (g.kappa1 - g.kappa0) * t / g.length;
}
double segPsi(const Segment& g, double t) {
  return g.psi0 + g.kappa0 * t + 0.5 * (g.kappa1 - g.kappa0) * t * t / g.length;
}
double segCant(const Segment& g, double t) {
  return g.u0 + (g.u1 - g.u0) * t / g.length;
}
double segGradient(const Segment& g, double t) {
  return g.g0 + (g.g1 - g.g0) * t / g.length;
}

// Integral of the unit tangent (cos(theta) cos(psi), cos(theta) sin(psi), -sin(theta)) over
// [ta, tb] of one segment (composite Gauss-Legendre).
Eigen::Vector3d integrateTangent(const Segment& g, double ta, double tb) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  if (!(tb > ta)) return sum;
  const int panels = std::max(1, static_cast<int>(std::ceil((tb - ta) / kMaxPanel)));
  const double h = (tb - ta) / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = ta + (p + 0.5) * h;
    for (std::size_t k = 0; k < kGlX.size(); ++k) {
      for (const double sgn : {-1.0, 1.0}) {
        const double t = mid + sgn * 0.5 * h * kGlX[k];
        const double grad = segGradient(g, t);
        const double inv = 1.0 / std::sqrt(1.0 + grad * grad);  // cos(theta)
        const double psi = segPsi(g, t);
        const double wgt = 0.5 * h * kGlW[k];
        sum.x() += wgt * inv * std::cos(psi);
        sum.y() += wgt * inv * std::sin(psi);
        sum.z() += wgt * grad * inv;  // -sin(theta)
      }
    }
  }
  return sum;
}

// Exact x, y, z, psi, theta, phi and their first and second s-derivatives at local t of segment g
// whose start position is given. Angle laws: theta = -atan(g), phi = -asin(u / b).
void exactChannels(const Segment& g, double t, const Eigen::Vector3d& pos, double cant_base,
                   double* v, double* d1, double* d2) {
  const double psi = segPsi(g, t);
  const double psi_s = segKappa(g, t);
  const double psi_ss = (g.kappa1 - g.kappa0) / g.length;
  const double grad = segGradient(g, t);
  const double grad_s = (g.g1 - g.g0) / g.length;
  const double theta = -std::atan(grad);
  const double theta_s = -grad_s / (1.0 + grad * grad);
  const double theta_ss =
      2.0 * grad * grad_s * grad_s / ((1.0 + grad * grad) * (1.0 + grad * grad));
  const double w = segCant(g, t) / cant_base;
  const double w_s = (g.u1 - g.u0) / g.length / cant_base;
  const double phi = -std::asin(w);
  const double root = std::sqrt(1.0 - w * w);
  const double phi_s = -w_s / root;
  const double phi_ss = -w_s * w_s * w / (root * root * root);
  const double ct = std::cos(theta), st = std::sin(theta);
  const double cp = std::cos(psi), sp = std::sin(psi);
  v[0] = pos.x();
  v[1] = pos.y();
  v[2] = pos.z();
  v[3] = psi;
  v[4] = theta;
  v[5] = phi;
  d1[0] = ct * cp;
  d1[1] = ct * sp;
  d1[2] = -st;
  d1[3] = psi_s;
  d1[4] = theta_s;
  d1[5] = phi_s;
  d2[0] = -st * theta_s * cp - ct * sp * psi_s;
  d2[1] = -st * theta_s * sp + ct * cp * psi_s;
  d2[2] = -ct * theta_s;
  d2[3] = psi_ss;
  d2[4] = theta_ss;
  d2[5] = phi_ss;
}

}  // namespace

Eigen::Matrix3d trackRotation(double psi, double theta, double phi) {
  const double cps = std::cos(psi), sps = std::sin(psi);
  const double cth = std::cos(theta), sth = std::sin(theta);
  const double cph = std::cos(phi), sph = std::sin(phi);
  Eigen::Matrix3d A;
  // Eq. (1), row by row.
  A << cth * cps, sph * sth * cps - cph * sps, sph * sps + cph * sth * cps,  //
      cth * sps, cph * cps + sph * sth * sps, cph * sth * sps - sph * cps,   //
      -sth, sph * cth, cph * cth;
  return A;
}

Eigen::Vector3d trackAngularRate(double theta, double phi, double psi_s, double theta_s,
                                 double phi_s) {
  const double cth = std::cos(theta), sth = std::sin(theta);
  const double cph = std::cos(phi), sph = std::sin(phi);
  return {phi_s - psi_s * sth, theta_s * cph + psi_s * cth * sph,
          -theta_s * sph + psi_s * cth * cph};
}

Eigen::Vector3d trackAngularRateDerivative(double theta, double phi, double psi_s, double theta_s,
                                           double phi_s, double psi_ss, double theta_ss,
                                           double phi_ss) {
  const double cth = std::cos(theta), sth = std::sin(theta);
  const double cph = std::cos(phi), sph = std::sin(phi);
  return {phi_ss - psi_ss * sth - psi_s * cth * theta_s,
          theta_ss * cph - theta_s * sph * phi_s + psi_ss * cth * sph -
              psi_s * sth * theta_s * sph + psi_s * cth * cph * phi_s,
          -theta_ss * sph - theta_s * cph * phi_s + psi_ss * cth * cph -
              psi_s * sth * theta_s * cph - psi_s * cth * sph * phi_s};
}

Eigen::Vector3d leftRailFramePosition(double rail_lr) {
  return {0.0, rail_lr, 0.0};
}
Eigen::Vector3d rightRailFramePosition(double rail_lr) {
  return {0.0, -rail_lr, 0.0};
}

namespace {
Eigen::Matrix3d rotX(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  m << 1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c;
  return m;
}
}  // namespace

Eigen::Matrix3d leftRailFrameRotation(double beta, double delta) {
  return rotX(beta + delta);
}
Eigen::Matrix3d rightRailFrameRotation(double beta, double delta) {
  return rotX(-beta + delta);
}

TrackGeometry::TrackGeometry(const TrackSpec& spec)
    : cant_base_(spec.cant_base), rail_lr_(spec.rail_lr), beta_(spec.rail_inclination) {
  RB_CHECK(!spec.segments.empty(), "track without segments");
  RB_CHECK(spec.step > 0.0 && spec.cant_base > 0.0, "invalid track spec");
  // Segment laws (curvature, signed cant, gradient), starting straight, level and without cant.
  double kappa = 0.0, u = 0.0, grad = 0.0, s0 = 0.0;
  segments_.reserve(spec.segments.size());
  for (const SegmentSpec& ss : spec.segments) {
    RB_CHECK(ss.length > 0.0, "segment length must be > 0");
    Segment g;
    g.kind = ss.kind;
    g.s0 = s0;
    g.length = ss.length;
    g.radius = ss.radius;
    g.side = ss.side;
    g.cant = ss.cant;
    const double sgn = sideSign(ss.side);
    const double kEnd = ss.radius > 0.0 ? sgn / ss.radius : 0.0;
    switch (ss.kind) {
      case SegmentKind::Tangent:
        g.kappa0 = g.kappa1 = 0.0;
        g.u0 = g.u1 = 0.0;
        g.g0 = g.g1 = ss.gradient;
        break;
      case SegmentKind::Curve:
        g.kappa0 = g.kappa1 = kEnd;
        g.u0 = g.u1 = sgn * ss.cant;
        g.g0 = g.g1 = ss.gradient;
        break;
      case SegmentKind::Transition:
        g.kappa0 = kappa;
        g.kappa1 = kEnd;
        g.u0 = u;
        g.u1 = sgn * ss.cant;
        g.g0 = grad;
        g.g1 = ss.gradient;
        break;
    }
    kappa = g.kappa1;
    u = g.u1;
    grad = g.g1;
    s0 += ss.length;
    segments_.push_back(g);
  }
  length_ = s0;
  // Exact start states.
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();
  double psi = 0.0;
  for (Segment& g : segments_) {
    g.x0 = pos.x();
    g.y0 = pos.y();
    g.z0 = pos.z();
    g.psi0 = psi;
    pos += integrateTangent(g, 0.0, g.length);
    psi = segPsi(g, g.length);
  }

  // Preprocessor (paper Fig. 4): uniform knots with spacing <= step covering [0, length].
  const auto intervals =
      static_cast<std::size_t>(std::max(1.0, std::ceil(length_ / spec.step - 1e-9)));
  grid_step_ = length_ / static_cast<double>(intervals);
  std::vector<double> knots(intervals + 1);
  for (std::size_t j = 0; j <= intervals; ++j) knots[j] = static_cast<double>(j) * grid_step_;
  knots.back() = length_;
  std::vector<std::vector<double>> ch(6, std::vector<double>(knots.size()));
  std::size_t prevSeg = segments_.size();
  double prevT = 0.0;
  for (std::size_t j = 0; j < knots.size(); ++j) {
    const std::size_t k = segmentIndex(knots[j]);
    const Segment& g = segments_[k];
    const double t = std::clamp(knots[j] - g.s0, 0.0, g.length);
    // March from the previous knot inside a segment, else from the segment start.
    if (k != prevSeg) pos = Eigen::Vector3d(g.x0, g.y0, g.z0), prevT = 0.0;
    pos += integrateTangent(g, prevT, t);
    prevSeg = k;
    prevT = t;
    double v[6], d1[6], d2[6];
    exactChannels(g, t, pos, cant_base_, v, d1, d2);
    for (std::size_t c = 0; c < 6; ++c) ch[c][j] = v[c];
  }
  spline_ = CubicSplineSet(SplineGrid(std::move(knots)), ch, SplineEnd::NotAKnot);
}

std::size_t TrackGeometry::segmentIndex(double s) const {
  const auto it = std::upper_bound(segments_.begin() + 1, segments_.end(), s,
                                   [](double x, const Segment& g) { return x < g.s0; });
  return static_cast<std::size_t>(it - segments_.begin()) - 1;
}

TrackFrame TrackGeometry::fromAngles(double s, const double* v, const double* d1,
                                     const double* d2) const {
  TrackFrame f;
  f.s = s;
  f.R = {v[0], v[1], v[2]};
  f.R_s = {d1[0], d1[1], d1[2]};
  f.R_ss = {d2[0], d2[1], d2[2]};
  f.psi = v[3];
  f.theta = v[4];
  f.phi = v[5];
  f.psi_s = d1[3];
  f.theta_s = d1[4];
  f.phi_s = d1[5];
  f.psi_ss = d2[3];
  f.theta_ss = d2[4];
  f.phi_ss = d2[5];
  f.A = trackRotation(f.psi, f.theta, f.phi);
  f.w = trackAngularRate(f.theta, f.phi, f.psi_s, f.theta_s, f.phi_s);
  f.w_s = trackAngularRateDerivative(f.theta, f.phi, f.psi_s, f.theta_s, f.phi_s, f.psi_ss,
                                     f.theta_ss, f.phi_ss);
  f.curvature = f.psi_s;
  f.cant = -cant_base_ * std::sin(f.phi);
  f.gradient = -std::tan(f.theta);
  return f;
}

namespace {
// Straight extension beyond the track ends: move along the end tangent, freeze the angles.
void extendStraight(TrackFrame& f, double s) {
  f.R += f.R_s * (s - f.s);
  f.s = s;
  f.R_ss.setZero();
  f.psi_s = f.theta_s = f.phi_s = 0.0;
  f.psi_ss = f.theta_ss = f.phi_ss = 0.0;
  f.w.setZero();
  f.w_s.setZero();
  f.curvature = 0.0;
}
}  // namespace

TrackFrame TrackGeometry::at(double s) const {
  const double sc = std::clamp(s, 0.0, length_);
  std::array<double, 6> v{}, d1{}, d2{};
  spline_.eval(sc, v, d1, d2);
  TrackFrame f = fromAngles(sc, v.data(), d1.data(), d2.data());
  if (s != sc) extendStraight(f, s);
  return f;
}

TrackFrame TrackGeometry::exactAt(double s) const {
  const double sc = std::clamp(s, 0.0, length_);
  const Segment& g = segments_[segmentIndex(sc)];
  const double t = std::clamp(sc - g.s0, 0.0, g.length);
  const Eigen::Vector3d pos = Eigen::Vector3d(g.x0, g.y0, g.z0) + integrateTangent(g, 0.0, t);
  double v[6], d1[6], d2[6];
  exactChannels(g, t, pos, cant_base_, v, d1, d2);
  TrackFrame f = fromAngles(sc, v, d1, d2);
  if (s != sc) extendStraight(f, s);
  return f;
}

}  // namespace rb::track
