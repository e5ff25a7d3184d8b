#include "workbench/vehicle/guided.hpp"

#include <cmath>
#include <sstream>

namespace rb::vehicle {

namespace {
constexpr const char* kCoordName[5] = {"y", "z", "phi", "theta", "psi"};
constexpr double kPitchLimit = 1.2;  // [rad] Euler-angle guard (singular at pi/2)
}  // namespace

GuidedLayout guidedLayout(const VehicleModel& m) {
  GuidedLayout l;
  l.slot.assign(m.bodies.size(), -1);
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const BodyKind k = m.bodies[b].kind;
    if (k == BodyKind::CarBody || k == BodyKind::Bogie) {
      l.slot[b] = static_cast<int>(l.free_bodies.size());
      l.free_bodies.push_back(static_cast<int>(b));
    }
  }
  l.n_free = static_cast<int>(l.free_bodies.size());
  l.n_series = static_cast<int>(m.series_dampers.size());
  l.size = 10 * l.n_free + l.n_series;
  return l;
}

void guidedCoordinates(const VehicleModel& m, const GuidedLayout& l, double t, const double* y,
                       Workspace& ws) {
  const double V = m.speedAt(t);
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    Vector6d& q = ws.q[b];
    Vector6d& qd = ws.qd[b];
    q.setZero();
    qd.setZero();
    q[kS] = m.bodyS(static_cast<int>(b), t);
    qd[kS] = V;
    const int k = l.slot[b];
    if (k >= 0) {
      for (int c = 0; c < 5; ++c) {
        q[1 + c] = y[l.position(k, c)];
        qd[1 + c] = y[l.rate(k, c)];
      }
    } else if (m.bodies[b].kind == BodyKind::Wheelset) {
      // Rolling without slip on r0: theta = travel / r0, theta_dot = V(t) / r0.
      q[kPitch] = m.travel(t) / m.wheel_radius;
      qd[kPitch] = V / m.wheel_radius;
    }
  }
}

int guidedRhs(const VehicleModel& m, const GuidedLayout& l, double t, const double* y, double* ydot,
              Workspace& ws) {
  guidedCoordinates(m, l, t, y, ws);
  for (int k = 0; k < l.n_free; ++k)
    if (!(std::abs(y[l.position(k, kPitch - 1)]) < kPitchLimit)) return 1;
  evaluate(m, l.n_series > 0 ? y + l.series(0) : nullptr, ws);
  for (int k = 0; k < l.n_free; ++k) {
    const auto b = static_cast<std::size_t>(l.free_bodies[static_cast<std::size_t>(k)]);
    const Matrix6d& M = ws.mass[b];
    // s is imposed with sddot = a: M_pp pddot = Q_p - M_ps a (the inertia of the prescribed
    // longitudinal acceleration, e.g. pitch of a braked car; on a curve it includes the frame's
    // angular acceleration kappa a through the s column of Lv, Lw).
    const Eigen::Matrix<double, 5, 5> Mpp = M.block<5, 5>(1, 1);
    const Eigen::LLT<Eigen::Matrix<double, 5, 5>> llt(Mpp);
    if (llt.info() != Eigen::Success) return 1;
    const Eigen::Matrix<double, 5, 1> acc =
        llt.solve(ws.force[b].segment<5>(1) - M.block<5, 1>(1, kS) * m.acceleration);
    for (int c = 0; c < 5; ++c) {
      ydot[l.position(k, c)] = y[l.rate(k, c)];
      ydot[l.rate(k, c)] = acc[c];
    }
  }
  for (int e = 0; e < l.n_series; ++e)
    ydot[l.series(e)] = ws.series_rate[static_cast<std::size_t>(e)];
  return 0;
}

GuidedVehicleOde::GuidedVehicleOde(const VehicleModel& model)
    : model_(&model), layout_(guidedLayout(model)), ws_(makeWorkspace(model)) {
  scratch_.assign(static_cast<std::size_t>(layout_.size), 0.0);
}

int GuidedVehicleOde::rhs(double t, const double* y, double* ydot) {
  const int rc = guidedRhs(*model_, layout_, t, y, ydot, ws_);
  if (rc != 0) {
    last_error_ =
        "a free body's pitch angle reached the Euler-angle guard |theta| >= 1.2 rad, or "
        "a mass matrix is not positive definite";
  }
  return rc;
}

std::string GuidedVehicleOde::componentName(int i) const {
  const GuidedLayout& l = layout_;
  if (i < 0 || i >= l.size) return "y[" + std::to_string(i) + "]";
  if (i >= l.series(0) && l.n_series > 0)
    return "series[" + std::to_string(i - l.series(0)) + "].f";
  const bool rate = i >= 5 * l.n_free;
  const int j = rate ? i - 5 * l.n_free : i;
  const int k = j / 5, c = j % 5;
  const std::string& body =
      model_->bodies[static_cast<std::size_t>(l.free_bodies[static_cast<std::size_t>(k)])].name;
  return body + "." + kCoordName[c] + (rate ? "_dot" : "");
}

int GuidedVehicleOde::index(int body, Coord c, bool rate) const {
  if (body < 0 || body >= static_cast<int>(layout_.slot.size()) || c == kS) return -1;
  const int k = layout_.slot[static_cast<std::size_t>(body)];
  if (k < 0) return -1;
  return rate ? layout_.rate(k, c - 1) : layout_.position(k, c - 1);
}

int GuidedVehicleOde::indexOf(const std::string& component) const {
  for (int i = 0; i < layout_.size; ++i)
    if (componentName(i) == component) return i;
  return -1;
}

Eigen::VectorXd GuidedVehicleOde::staticState(double t0) {
  const GuidedLayout& l = layout_;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(l.size);
  const int n = 5 * l.n_free;
  if (n == 0) return y;
  Eigen::VectorXd yd(l.size);
  const auto residual = [&](const Eigen::VectorXd& state, Eigen::VectorXd& r) {
    if (guidedRhs(*model_, l, t0, state.data(), yd.data(), ws_) != 0)
      throw InputError(model_->loc, "vehicle '" + model_->name +
                                        "': static equilibrium: a body rotated beyond the "
                                        "Euler-angle guard (is it supported?)");
    r = yd.segment(n, n);
  };
  Eigen::VectorXd r(n), rp(n), rm(n);
  Eigen::MatrixXd J(n, n);
  residual(y, r);
  const double h = 1e-6;
  for (int it = 0; it < 50; ++it) {
    for (int c = 0; c < n; ++c) {
      Eigen::VectorXd yp = y, ym = y;
      yp[c] += h;
      ym[c] -= h;
      residual(yp, rp);
      residual(ym, rm);
      J.col(c) = (rp - rm) / (2.0 * h);
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
    if (lu.rank() < n) {
      std::string which;
      for (int c = 0; c < n; ++c)
        if (J.col(c).norm() < 1e-9 * J.norm()) which += " " + componentName(c);
      throw InputError(model_->loc,
                       "vehicle '" + model_->name +
                           "': no static equilibrium: a free body coordinate is not restrained by "
                           "any suspension element (singular stiffness)" +
                           (which.empty() ? std::string() : ":" + which));
    }
    const Eigen::VectorXd dx = lu.solve(r);
    // Backtracking on |r| (the bumpstops make the problem nonlinear).
    double lambda = 1.0;
    Eigen::VectorXd y_new = y;
    const double r0 = r.norm();
    for (int ls = 0; ls < 30; ++ls) {
      y_new.head(n) = y.head(n) - lambda * dx;
      residual(y_new, rp);
      if (rp.norm() <= r0 || rp.norm() < 1e-12) break;
      lambda *= 0.5;
    }
    y = y_new;
    r = rp;
    if (lambda * dx.lpNorm<Eigen::Infinity>() < 1e-13 || r.lpNorm<Eigen::Infinity>() < 1e-12)
      return y;
  }
  std::ostringstream os;
  os << "vehicle '" << model_->name
     << "': static equilibrium did not converge (|acceleration| = " << r.lpNorm<Eigen::Infinity>()
     << " after 50 Newton iterations)";
  throw InputError(model_->loc, os.str());
}

void GuidedVehicleOde::elementOutputs(double t, const double* y, std::span<const ElementId> ids,
                                      std::span<ElementValue> out) {
  guidedCoordinates(*model_, layout_, t, y, ws_);
  evaluate(*model_, layout_.n_series > 0 ? y + layout_.series(0) : nullptr, ws_);
  for (std::size_t i = 0; i < ids.size() && i < out.size(); ++i) out[i] = ws_.value(ids[i]);
}

BodyOutput GuidedVehicleOde::bodyOutput(double t, const double* y, int body) {
  BodyOutput o;
  guidedRhs(*model_, layout_, t, y, scratch_.data(), ws_);
  const auto b = static_cast<std::size_t>(body);
  Vector6d qdd = Vector6d::Zero();
  qdd[kS] = model_->acceleration;
  if (model_->bodies[b].kind == BodyKind::Wheelset)
    qdd[kPitch] = model_->acceleration / model_->wheel_radius;
  const int k = layout_.slot[b];
  if (k >= 0)
    for (int c = 0; c < 5; ++c) qdd[1 + c] = scratch_[static_cast<std::size_t>(layout_.rate(k, c))];
  const BodyKinematics& kin = ws_.kin[b];
  o.acceleration = kin.Lv * qdd + kin.gamma_v;
  o.angular_acceleration = kin.Lw * qdd + kin.gamma_w;
  o.specific_force =
      o.acceleration - kin.tf.A.transpose() * Eigen::Vector3d(0.0, 0.0, -model_->gravity);
  o.suspension_force = ws_.susp_force[b];
  o.suspension_moment = ws_.susp_moment[b];
  o.traction = ws_.mass[b].row(kS).dot(qdd) - ws_.force[b][kS];
  return o;
}

Energy GuidedVehicleOde::energy(double t, const double* y) {
  guidedCoordinates(*model_, layout_, t, y, ws_);
  const double* f = layout_.n_series > 0 ? y + layout_.series(0) : nullptr;
  evaluate(*model_, f, ws_);
  return vehicle::energy(*model_, f, ws_);
}

}  // namespace rb::vehicle
