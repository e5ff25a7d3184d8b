#include "workbench/train/connection.hpp"

#include <algorithm>
#include <cmath>

#include "workbench/core/strings.hpp"

namespace rb::train {

namespace {

bool finiteNonNegative(double v) {
  return std::isfinite(v) && v >= 0.0;
}

void validateCurve(const std::vector<double>& x, const std::vector<double>& f,
                   const std::string& what, const SourceLoc& loc, Diagnostics& d) {
  if (x.size() < 2 || x.size() != f.size()) {
    d.add(loc, what + " needs at least 2 {stroke, force} points, got " + std::to_string(x.size()));
    return;
  }
  if (!(x[0] == 0.0 && f[0] == 0.0))
    d.add(loc, what + " must begin at {0, 0} (no force before the buffer is pressed)");
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !(x[i] > x[i - 1]) || x[i] > 1.0)
      d.add(loc, what + ": strokes must be finite, strictly ascending and at most 1 m (point " +
                     std::to_string(i + 1) + ")");
    if (!finiteNonNegative(f[i]) || f[i] < f[i - 1] || f[i] > 1e8)
      d.add(loc, what + ": forces must be finite, non-decreasing and at most 1e8 N (point " +
                     std::to_string(i + 1) + ")");
  }
}

void validateBuffers(const BufferSpec& b, const std::string& what, Diagnostics& d) {
  Diagnostics curves;
  validateCurve(b.load_stroke, b.load_force, what + ".buffers.loading", b.loc, curves);
  validateCurve(b.unload_stroke, b.unload_force, what + ".buffers.unloading", b.loc, curves);
  if (curves.empty()) {
    // Both curves are piecewise linear (extrapolated linearly, and no stroke exceeds 1 m): the
    // unloading curve stays below the loading one everywhere when it does at every point of
    // either curve and at 1 m. The unloading points alone miss a loading curve's knee.
    std::vector<double> at = b.unload_stroke;
    at.insert(at.end(), b.load_stroke.begin(), b.load_stroke.end());
    at.push_back(1.0);
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    for (const double x : at) {
      const double load = curveForce(b.load_stroke, b.load_force, x);
      const double unload = curveForce(b.unload_stroke, b.unload_force, x);
      if (unload > load * (1.0 + 1e-12) + 1e-9) {
        d.add(b.loc, what + ".buffers: the unloading force " + formatNumber(unload) +
                         " N at stroke " + formatNumber(x) + " m exceeds the loading force " +
                         formatNumber(load) + " N there (a buffer gives back less than it takes)");
        break;  // one place is enough to name the curve
      }
    }
  }
  for (const auto& m : curves.items()) d.add(m.loc, m.message);
  if (!(b.spacing > 0.0 && b.spacing < 5.0))
    d.add(b.loc, what + ".buffers.spacing must be in (0, 5) m, got " + formatNumber(b.spacing));
  if (!(b.height > 0.0 && b.height < 5.0))
    d.add(b.loc, what + ".buffers.height must be in (0, 5) m, got " + formatNumber(b.height));
  if (!(b.friction >= 0.0 && b.friction <= 1.0))
    d.add(b.loc, what + ".buffers.friction must be in [0, 1], got " + formatNumber(b.friction));
}

// The axial law's keys, shared by the draw gear and the coupler (`block`: what.draw_gear or
// what.coupler).
template <class Axial>
void validateAxial(const Axial& g, const std::string& block, Diagnostics& d) {
  if (!(g.stiffness > 0.0 && std::isfinite(g.stiffness)))
    d.add(g.loc,
          block + ".stiffness must be positive and finite, got " + formatNumber(g.stiffness));
  if (!(g.slack >= 0.0 && g.slack < 1.0))
    d.add(g.loc, block + ".slack must be in [0, 1) m, got " + formatNumber(g.slack));
  if (!(g.friction >= 0.0 && g.friction < 1.0))
    d.add(g.loc, block + ".friction must be in [0, 1), got " + formatNumber(g.friction));
  if (!(g.height > 0.0 && g.height < 5.0))
    d.add(g.loc, block + ".height must be in (0, 5) m, got " + formatNumber(g.height));
}

void validateCoupler(const CouplerSpec& c, const std::string& what, Diagnostics& d) {
  validateAxial(c, what + ".coupler", d);
  if (!(c.pivot > 0.0 && c.pivot < 5.0))
    d.add(c.loc, what + ".coupler.pivot must be in (0, 5) m, got " + formatNumber(c.pivot));
  if (!(c.angle_stop > 0.0 && c.angle_stop < 1.0))
    d.add(c.loc,
          what + ".coupler.angle_stop must be in (0, 1) rad, got " + formatNumber(c.angle_stop));
  if (!(c.stop_stiffness >= 0.0 && std::isfinite(c.stop_stiffness)))
    d.add(c.loc, what + ".coupler.stop_stiffness must be non-negative and finite, got " +
                     formatNumber(c.stop_stiffness));
}

// The draw gear's law in tension: k (e - slack) (1 + f tanh(e_dot / v_reg)) past the slack.
double tensionLaw(double stiffness, double slack, double friction, double e, double e_dot) {
  if (e <= slack) return 0.0;
  return stiffness * (e - slack) * (1.0 + friction * std::tanh(e_dot / kRegularisingSpeed));
}

// Global position and velocity of the point u (attachment frame) of a body.
struct PointMotion {
  Eigen::Vector3d au, r, v;
};
PointMotion pointMotion(const vehicle::BodyKinematics& k, const Eigen::Vector3d& u) {
  PointMotion p;
  p.au = k.attach.A * u;
  p.r = k.tf.R + k.tf.A * (k.rbar + p.au);
  p.v = k.tf.A * vehicle::pointVelocity(k, p.au);
  return p;
}

}  // namespace

void validateConnection(const ConnectionSpec& c, Diagnostics& d) {
  const std::string what = "train.connections '" + c.front + "-" + c.rear + "'";
  if (!(c.front_end < 0.0 && c.front_end > -50.0))
    d.add(c.loc, what +
                     ": front_end (the front vehicle's rear headstock, x from its car body's "
                     "centre) must be in (-50, 0) m, got " +
                     formatNumber(c.front_end));
  if (!(c.rear_end > 0.0 && c.rear_end < 50.0))
    d.add(c.loc, what +
                     ": rear_end (the rear vehicle's front headstock) must be in (0, 50) m, "
                     "got " +
                     formatNumber(c.rear_end));
  if (!c.buffers && !c.draw_gear && !c.coupler)
    d.add(c.loc, what +
                     ": give buffers, a draw_gear or a coupler (a connection without any "
                     "transmits nothing)");
  if (c.draw_gear && c.coupler)
    d.add(c.loc, what + ": give a draw_gear or a coupler, not both (each is the tension link)");
  if (c.buffers) validateBuffers(*c.buffers, what, d);
  if (c.draw_gear) validateAxial(*c.draw_gear, what + ".draw_gear", d);
  if (c.coupler) {
    validateCoupler(*c.coupler, what, d);
    if (c.coupler->pivot >= std::min(-c.front_end, c.rear_end))
      d.add(c.coupler->loc, what + ".coupler.pivot (" + formatNumber(c.coupler->pivot) +
                                " m) must lie inside both car bodies: less than -front_end and "
                                "rear_end");
  }
}

double curveForce(const std::vector<double>& stroke, const std::vector<double>& force, double x) {
  if (x <= 0.0) return 0.0;
  const std::size_t n = stroke.size();
  std::size_t i = 1;
  while (i + 1 < n && x > stroke[i]) ++i;
  const double slope = (force[i] - force[i - 1]) / (stroke[i] - stroke[i - 1]);
  return force[i - 1] + slope * (x - stroke[i - 1]);
}

double bufferPairForce(const BufferSpec& b, double c, double c_dot) {
  if (c <= 0.0) return 0.0;
  const double x = 0.5 * c;  // two identical buffers in series share the compression
  const double w = 0.5 * (1.0 + std::tanh(c_dot / kRegularisingSpeed));
  return w * curveForce(b.load_stroke, b.load_force, x) +
         (1.0 - w) * curveForce(b.unload_stroke, b.unload_force, x);
}

double drawGearForce(const DrawGearSpec& g, double gap, double gap_dot) {
  return tensionLaw(g.stiffness, g.slack, g.friction, gap, gap_dot);
}

double couplerForce(const CouplerSpec& c, double e, double e_dot) {
  if (e >= 0.0 || !c.compression) return tensionLaw(c.stiffness, c.slack, c.friction, e, e_dot);
  return -tensionLaw(c.stiffness, c.slack, c.friction, -e, -e_dot);  // the mirror law, pressed
}

double stopTorque(const CouplerSpec& c, double theta) {
  const double past = std::abs(theta) - c.angle_stop;
  if (past <= 0.0) return 0.0;
  return -std::copysign(c.stop_stiffness * past, theta);
}

void connectionForces(const ConnectionSpec& c, const vehicle::BodyKinematics& kf, int bf, double hf,
                      const vehicle::BodyKinematics& kr, int br, double hr, ConnectionState& out) {
  out.on_front.clear();
  out.on_rear.clear();
  out.buffer_left = out.buffer_right = out.draw_gear = 0.0;
  const Eigen::Vector3d xf = kf.rotation().col(0), xr = kr.rotation().col(0);
  out.axis = (xf + xr).normalized();
  const Eigen::Vector3d& e = out.axis;
  Eigen::Vector3d total_front = Eigen::Vector3d::Zero();
  // A force F on the front body at its point uf and -F on the rear body at ur.
  const auto apply = [&](const Eigen::Vector3d& uf, const Eigen::Vector3d& ur,
                         const Eigen::Vector3d& F) {
    out.on_front.push_back({bf, uf, F});
    out.on_rear.push_back({br, ur, -F});
    total_front += F;
  };
  if (c.buffers) {
    const BufferSpec& b = *c.buffers;
    for (int side = 0; side < 2; ++side) {
      const double y = (side == 0 ? 0.5 : -0.5) * b.spacing;  // left (+y) first
      const Eigen::Vector3d uf(c.front_end, y, b.height - hf), ur(c.rear_end, y, b.height - hr);
      const PointMotion P = pointMotion(kf, uf), Q = pointMotion(kr, ur);
      const Eigen::Vector3d dv = P.v - Q.v;
      const double comp = -(P.r - Q.r).dot(e);
      const double force = bufferPairForce(b, comp, -dv.dot(e));
      (side == 0 ? out.buffer_left : out.buffer_right) = force;
      if (force <= 0.0) continue;
      Eigen::Vector3d F = force * e;
      if (b.friction > 0.0) {
        const Eigen::Vector3d vt = dv - dv.dot(e) * e;  // the heads' sliding velocity
        F -= b.friction * force * vt /
             std::sqrt(vt.squaredNorm() + kRegularisingSpeed * kRegularisingSpeed);
      }
      apply(uf, ur, F);
    }
  }
  const double h = c.draw_gear ? c.draw_gear->height
                   : c.coupler ? c.coupler->height
                   : c.buffers ? c.buffers->height
                               : 1.0;
  {
    const Eigen::Vector3d uf(c.front_end, 0.0, h - hf), ur(c.rear_end, 0.0, h - hr);
    const PointMotion P = pointMotion(kf, uf), Q = pointMotion(kr, ur);
    out.gap = (P.r - Q.r).dot(e);
    if (c.draw_gear) {
      out.draw_gear = drawGearForce(*c.draw_gear, out.gap, (P.v - Q.v).dot(e));
      if (out.draw_gear > 0.0) apply(uf, ur, -out.draw_gear * e);
    }
  }
  out.angle_front = out.angle_rear = 0.0;
  if (c.coupler) {
    const CouplerSpec& g = *c.coupler;
    const Eigen::Vector3d uf(c.front_end + g.pivot, 0.0, h - hf),
        ur(c.rear_end - g.pivot, 0.0, h - hr);
    const PointMotion P = pointMotion(kf, uf), Q = pointMotion(kr, ur);
    const Eigen::Vector3d r = P.r - Q.r;
    const double length = r.norm();
    const Eigen::Vector3d d = r / length;  // from the rear pivot to the front one
    const Eigen::Matrix3d Rf = kf.rotation(), Rr = kr.rotation();
    out.angle_front = std::atan2(d.dot(Rf.col(1)), d.dot(Rf.col(0)));
    out.angle_rear = std::atan2(d.dot(Rr.col(1)), d.dot(Rr.col(0)));
    out.draw_gear = couplerForce(g, length - 2.0 * g.pivot, (P.v - Q.v).dot(d));
    // The stops' torques on the link about the vertical, and the lateral pair s n at the pivots
    // (on the link: +s n at the front pivot) that balances them: r x (s n) = s |r| z.
    const Eigen::Vector3d z = (Rf.col(2) + Rr.col(2)).normalized();
    const Eigen::Vector3d n = z.cross(d).normalized();
    const double tau_f = stopTorque(g, out.angle_front), tau_r = stopTorque(g, out.angle_rear);
    const double s = -(tau_f + tau_r) / length;
    // On the bodies: the link's axial force (tension pulls the front body back) and the pair's
    // reaction, then each stop's reaction torque -tau as a couple of forces 2a apart.
    if (out.draw_gear != 0.0 || s != 0.0) apply(uf, ur, -out.draw_gear * d - s * n);
    constexpr double a = 0.5;  // [m] half the couple's arm
    const auto couple = [&](std::vector<vehicle::AppliedLoad>& on, int body,
                            const Eigen::Vector3d& u, const Eigen::Vector3d& x_body,
                            double torque) {
      if (torque == 0.0) return;
      const Eigen::Vector3d x_flat = (x_body - x_body.dot(z) * z).normalized();
      const Eigen::Vector3d F = torque / (2.0 * a) * z.cross(x_flat);
      on.push_back({body, u + Eigen::Vector3d(a, 0.0, 0.0), F});
      on.push_back({body, u - Eigen::Vector3d(a, 0.0, 0.0), -F});
    };
    couple(out.on_front, bf, uf, Rf.col(0), -tau_f);
    couple(out.on_rear, br, ur, Rr.col(0), -tau_r);
  }
  out.longitudinal = out.draw_gear - out.buffer_left - out.buffer_right;
  out.lateral_front = kf.tf.A.col(1).dot(total_front);
  out.lateral_rear = -kr.tf.A.col(1).dot(total_front);
}

}  // namespace rb::train
