#include "workbench/contact/check_rail.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rb::contact {

using profiles::ProfilePoint;

FlangeBack::FlangeBack(const profiles::Profile& wheel, double s_face) {
  // The branch from the profile's first point (the back) to the flange tip, its largest radius on
  // the flange side of the tape circle, radius increasing: a measured profile's wiggles (a sample
  // no higher than the one before) are passed over, not taken for the tip.
  constexpr double kStep = 0.05e-3;
  const double end = std::min(0.0, wheel.sMax());
  double s_tip = wheel.sMin(), h_tip = -1.0;
  for (double s = wheel.sMin(); s <= end; s += kStep)
    if (const double h = wheel.at(s).h; h > h_tip) {
      h_tip = h;
      s_tip = s;
    }
  for (double s = wheel.sMin(); s <= s_tip; s += kStep) {
    const double h = wheel.at(s).h;
    if (!rho_.empty() && h <= rho_.back()) continue;
    rho_.push_back(h);
    s_.push_back(s);
  }
  rho_face_ = rho_.empty() ? 0.0 : rho_.front();
  rho_tip_ = rho_.empty() ? 0.0 : rho_.back();
  // The flat face at the flange-back distance, or where the profile itself begins if it reaches
  // farther back: s_back(rho) >= s_face everywhere (the search's bound relies on it).
  s_face_ = s_.empty() ? s_face : std::min(s_face, s_.front());
}

double FlangeBack::sBack(double rho, double* slope) const {
  if (rho <= rho_face_ || rho_.size() < 2) {
    if (slope) *slope = 0.0;
    return s_face_;
  }
  const auto it = std::upper_bound(rho_.begin(), rho_.end(), rho);
  const std::size_t k =
      std::clamp<std::size_t>(static_cast<std::size_t>(it - rho_.begin()), 1, rho_.size() - 1);
  const double t = (rho - rho_[k - 1]) / (rho_[k] - rho_[k - 1]);
  if (slope) *slope = (s_[k] - s_[k - 1]) / (rho_[k] - rho_[k - 1]);
  return s_[k - 1] + t * (s_[k] - s_[k - 1]);
}

namespace {

// x of the line X(x) = x a + b (wheelset frame) where its distance from the axle is rho, on the
// side `dir` (+1 the larger root); NaN when the line stays farther away.
double lineAtRadius(double A, double B, double C, double rho, double dir) {
  const double disc = B * B - A * (C - rho * rho);
  if (!(disc >= 0.0) || !(A > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return (-B + dir * std::sqrt(disc)) / A;
}

// The deepest point of one check-rail line along the track: its lateral penetration d into
// the wheel's back, its x and its wheelset-frame point X.
struct OnLine {
  double d = -std::numeric_limits<double>::infinity(), x = 0.0;
  std::array<double, 3> X{};
  // On the flat face: the chord of the line over it [x_lo, x_hi] and the line's b (X = x a + b).
  bool flat = false;
  double x_lo = 0.0, x_hi = 0.0;
  std::array<double, 3> b{};
};

// The lines of one check rail at one pose (the rail's profile, blended, placed by its pair).
class CheckRailLines {
 public:
  CheckRailLines(const ElasticContactSearch& rail, const FlangeBack& back, const ElasticPose& pose)
      : rail_(rail), pair_(rail.pair()), back_(back), pose_(pose) {
    sigma_ = pair_.side == Side::Left ? 1.0 : -1.0;
    cb_ = std::cos(pair_.beta);
    sb_ = sigma_ * std::sin(pair_.beta);
    oy_ = sigma_ * pair_.rail_lr + pair_.rail_dy;
    oz_ = pair_.rail_dz;
    r_ = wheelsetRotation(pose.phi, pose.psi, rail.spec().angles);
    a_ = {r_[0][0], r_[0][1], r_[0][2]};  // the rail's direction in the wheelset frame
    A_ = a_[0] * a_[0] + a_[2] * a_[2];
    g_ = sigma_ * a_[1];  // d(sigma L)/dx
  }
  double sigma() const { return sigma_; }
  double slope() const { return g_; }
  const std::array<double, 3>& direction() const { return a_; }
  const std::array<std::array<double, 3>, 3>& rotation() const { return r_; }
  ProfilePoint railAt(double s) const { return rail_.railAt(s, pose_.blend); }

  // The deepest point of the line of rail point s: X(x) = x a + b in the wheelset frame. Over
  // the flat face d is linear in x (slope g): its edge on the side g points to, or the line's
  // nearest point to the axle; beyond, samples of the rounded edge out to the tip. A line that
  // cannot beat `bound` (|x| <= rho_tip / sqrt(A) within the tip's radius) is not searched.
  OnLine at(double s, double bound) const {
    OnLine o;
    const double h = railAt(s).h;
    const double dy = oy_ + cb_ * s - sb_ * h - pose_.y, dz = oz_ + sb_ * s + cb_ * h - pose_.z;
    const std::array<double, 3> b = {r_[1][0] * dy + r_[2][0] * dz, r_[1][1] * dy + r_[2][1] * dz,
                                     r_[1][2] * dy + r_[2][2] * dz};
    const double B = a_[0] * b[0] + a_[2] * b[2], C = b[0] * b[0] + b[2] * b[2];
    const double base = sigma_ * b[1] - pair_.wheel_lw;  // sigma L(0) - Lw
    // The line's points within the tip's radius lie at |x| <= x_max; none: no contact.
    const double disc = B * B - A_ * (C - back_.rhoTip() * back_.rhoTip());
    if (!(disc >= 0.0) || !(A_ > 0.0)) return o;
    const double x_max = (std::abs(B) + std::sqrt(disc)) / A_;
    if (base + std::abs(g_) * x_max - back_.sFace() <= bound) return o;
    const auto consider = [&](double x, double d) {
      if (!(d > o.d)) return;
      o.flat = false;
      o.d = d;
      o.x = x;
      for (std::size_t i = 0; i < 3; ++i) o.X[i] = x * a_[i] + b[i];
    };
    const double x0 = -B / A_;
    const double rho0 = std::sqrt(std::max(0.0, C - B * B / A_));
    if (rho0 <= back_.rhoTip()) consider(x0, base + g_ * x0 - back_.sBack(rho0));
    const double x_lo = lineAtRadius(A_, B, C, back_.rhoFace(), -1.0);
    const double x_hi = lineAtRadius(A_, B, C, back_.rhoFace(), 1.0);
    if (std::isfinite(x_lo)) {
      const double edge = g_ > 0.0 ? x_hi : x_lo;
      const double d_edge = base + g_ * edge - back_.sFace();
      consider(edge, d_edge);
      if (o.d == d_edge) {
        o.flat = true;
        o.x_lo = x_lo;
        o.x_hi = x_hi;
        o.b = b;
      }
    }
    if (g_ == 0.0) return o;
    const double dir = g_ > 0.0 ? 1.0 : -1.0;
    for (int k = 1; k <= kBackSamples; ++k) {
      const double rho = back_.rhoFace() + (back_.rhoTip() - back_.rhoFace()) * k / kBackSamples;
      const double x = lineAtRadius(A_, B, C, rho, dir);
      if (std::isfinite(x)) consider(x, base + g_ * x - back_.sBack(rho));
    }
    return o;
  }

 private:
  const ElasticContactSearch& rail_;
  const WheelRailPair& pair_;
  const FlangeBack& back_;
  const ElasticPose& pose_;
  double sigma_ = 1.0, cb_ = 1.0, sb_ = 0.0, oy_ = 0.0, oz_ = 0.0;
  std::array<std::array<double, 3>, 3> r_{};
  std::array<double, 3> a_{};
  double A_ = 1.0, g_ = 0.0;
};

// Golden-section search for the deepest line between u0 and u1 (d is unimodal there: one sample
// step either side of the deepest sample); `top` and `s_top` keep the deepest seen.
void refineDeepest(const CheckRailLines& lines, double u0, double u1, OnLine& top, double& s_top,
                   int& evaluations) {
  constexpr double kGolden = 0.6180339887498949;
  constexpr double kNoBound = -std::numeric_limits<double>::infinity();
  double m0 = u1 - kGolden * (u1 - u0), m1 = u0 + kGolden * (u1 - u0);
  OnLine f0 = lines.at(m0, kNoBound), f1 = lines.at(m1, kNoBound);
  for (int it = 0; it < 40 && u1 - u0 > 1e-8; ++it) {
    ++evaluations;
    if (f0.d >= f1.d) {
      u1 = m1;
      m1 = m0;
      f1 = f0;
      m0 = u1 - kGolden * (u1 - u0);
      f0 = lines.at(m0, kNoBound);
    } else {
      u0 = m0;
      m0 = m1;
      f0 = f1;
      m1 = u0 + kGolden * (u1 - u0);
      f1 = lines.at(m1, kNoBound);
    }
  }
  for (const auto& [f, m] : {std::pair{f0, m0}, std::pair{f1, m1}})
    if (f.d > top.d) {
      top = f;
      s_top = m;
    }
}

}  // namespace

void searchCheckRail(const ElasticContactSearch& rail, const FlangeBack& back,
                     const ElasticPose& pose, ElasticWheelGeometry& out) {
  out.count = 0;
  out.truncated = false;
  out.newton_iterations = 0;
  const CheckRailLines lines(rail, back, pose);
  const double sigma = lines.sigma();
  const double lo = rail.railMin(), hi = rail.railMax();
  // The rail's samples from its end nearest the wheel's back (its field side on the left, its
  // mirror on the right), so that the bound prunes the rest early; then a golden-section search
  // between the deepest one's neighbours: where the head's side falls steeply, one sample step is
  // millimetres of height.
  const double step = rail.spec().sample_step;
  double s_top = lo;
  OnLine top;
  const auto n = static_cast<int>(std::floor((hi - lo) / step));
  for (int k = 0; k <= n + 1; ++k) {
    const double sc = sigma > 0.0 ? std::max(lo, hi - k * step) : std::min(hi, lo + k * step);
    const OnLine o = lines.at(sc, top.d);
    if (o.d > top.d) {
      top = o;
      s_top = sc;
    }
  }
  if (std::isfinite(top.d))
    refineDeepest(lines, std::max(lo, s_top - step), std::min(hi, s_top + step), top, s_top,
                  out.newton_iterations);
  out.min_gap = -top.d;
  if (!(top.d > 0.0)) return;
  // On the flat face the penetration falls linearly from the deepest edge along the chord, by
  // |g| per metre (the yaw relative to the rail): the patch is placed at the centroid of the
  // penetrated part, which moves continuously from the chord's middle (no yaw: the face lies
  // along the rail over the whole chord) toward its edge as the yaw grows. Its depth stays the
  // deepest.
  if (top.flat) {
    const double g = lines.slope();
    const double len = top.x_hi - top.x_lo;
    const double wet = g == 0.0 ? len : std::min(len, top.d / std::abs(g));
    const double ag = std::abs(g);
    const double u = wet > 0.0 ? (0.5 * top.d * wet * wet - ag * wet * wet * wet / 3.0) /
                                     (top.d * wet - 0.5 * ag * wet * wet)
                               : 0.0;
    top.x = g > 0.0 ? top.x_hi - u : top.x_lo + u;
    const std::array<double, 3> a = lines.direction();
    for (std::size_t i = 0; i < 3; ++i) top.X[i] = top.x * a[i] + top.b[i];
  }
  // The contact: the wheel-back point X, its radius and angle, the back's normal there.
  const auto& r = lines.rotation();
  const std::array<double, 3>& bx = top.X;
  ElasticPatchGeometry& p = out.patch[0];
  const double rho = std::hypot(bx[0], bx[2]);
  double slope = 0.0;
  const double sb_w = back.sBack(rho, &slope);
  const double root = std::sqrt(1.0 + slope * slope);
  // Inward normal of the wheel's back (the force on the wheel): sigma e_y - slope e_rho.
  const double er = rho > 0.0 ? slope / (rho * root) : 0.0;  // slope e_rho / root, per X
  const std::array<double, 3> nw = {-er * bx[0], sigma / root, -er * bx[2]};
  const auto turn = [&](std::size_t i, const std::array<double, 3>& v) {
    return r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2];
  };
  p.n_x = turn(0, nw);
  p.n_y = turn(1, nw);
  p.n_z = turn(2, nw);
  p.s_w = sigma * sb_w;
  p.s_r = s_top;
  p.theta = std::atan2(bx[0], -bx[2]);
  p.radius = rho;
  p.x_w = rho * std::sin(p.theta);
  p.x = top.x;
  p.y = pose.y + turn(1, bx);
  p.z = pose.z + turn(2, bx);
  // Contact angle: positive toward the track centre (geometry.hpp); the check rail pushes the
  // wheel toward its field side.
  p.gamma = std::atan2(-sigma * p.n_y, p.n_z);
  p.gap_depth = top.d / root;
  p.approach = p.gap_depth;
  // Curvatures: the flat back (the rounded edge's transverse curvature is left out: it is where
  // the back face ends), the check rail head's transverse curvature, nothing along the track.
  const ProfilePoint hp = lines.railAt(s_top);
  p.k_wheel_trans = 0.0;
  p.k_wheel_rolling = 0.0;
  p.k_rail_trans = std::max(0.0, -hp.d2h / std::pow(1.0 + hp.dh * hp.dh, 1.5));
  p.A = 0.0;
  p.B = 0.5 * p.k_rail_trans;
  p.B_span = p.B;
  p.refined = false;
  p.rail_rise = 0.0;
  out.count = 1;
}

}  // namespace rb::contact
