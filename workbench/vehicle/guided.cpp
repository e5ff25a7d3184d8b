#include "workbench/vehicle/guided.hpp"

#include <cmath>
#include <sstream>

#include "workbench/vehicle/equilibrium.hpp"

namespace rb::vehicle {

namespace {
constexpr double kPitchLimit = 1.2;  // [rad] Euler-angle guard (singular at pi/2)
}  // namespace

VehicleLayout guidedLayout(const VehicleModel& m) {
  return vehicleLayout(m, kGuidedWheelsetDof);
}

void guidedCoordinates(const VehicleModel& m, const VehicleLayout& l, double t, const double* y,
                       Workspace& ws) {
  const ForwardMotion fm = forwardMotion(m, ws, t);
  const double V = fm.speed;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    Vector6d& q = ws.q[b];
    Vector6d& qd = ws.qd[b];
    q.setZero();
    qd.setZero();
    q[kS] = m.bodySAt(b, fm.travel);
    qd[kS] = V;
    const int k = l.freeSlot(b);
    if (k >= 0) {
      for (int c = 0; c < 5; ++c) {
        q[1 + c] = y[l.position(k, c)];
        qd[1 + c] = y[l.rate(k, c)];
      }
    } else if (m.bodies[b].kind == BodyKind::Wheelset) {
      // Rolling without slip on r0: theta = travel / r0, theta_dot = V(t) / r0.
      q[kPitch] = fm.travel / m.wheel_radius;
      qd[kPitch] = V / m.wheel_radius;
    }
  }
}

int guidedRhs(const VehicleModel& m, const VehicleLayout& l, double t, const double* y,
              double* ydot, Workspace& ws, StageClock* clock) {
  guidedCoordinates(m, l, t, y, ws);
  for (int k = 0; k < l.n_free; ++k)
    if (!(std::abs(y[l.position(k, kPitch - 1)]) < kPitchLimit)) return 1;
  if (clock) clock->mark(Stage::Coordinates);
  evaluate(m, t, l.n_series > 0 ? y + l.series(0) : nullptr, ws);
  if (clock) clock->mark(Stage::VehicleForces);
  const double acceleration = forwardMotion(m, ws, t).acceleration;
  for (int k = 0; k < l.n_free; ++k) {
    const std::size_t b = l.freeBody(k);
    const Matrix6d& M = ws.mass[b];
    // s is imposed with sddot = a: M_pp pddot = Q_p - M_ps a (the inertia of the prescribed
    // longitudinal acceleration, e.g. pitch of a braked car; on a curve it includes the frame's
    // angular acceleration kappa a through the s column of Lv, Lw).
    const Eigen::Matrix<double, 5, 5> Mpp = M.block<5, 5>(1, 1);
    const Eigen::LLT<Eigen::Matrix<double, 5, 5>> llt(Mpp);
    if (llt.info() != Eigen::Success) return 1;
    const Eigen::Matrix<double, 5, 1> acc =
        llt.solve(ws.force[b].segment<5>(1) - M.block<5, 1>(1, kS) * acceleration);
    for (int c = 0; c < 5; ++c) {
      ydot[l.position(k, c)] = y[l.rate(k, c)];
      ydot[l.rate(k, c)] = acc[c];
    }
  }
  if (clock) clock->mark(Stage::FreeBodies);
  for (int e = 0; e < l.n_series; ++e)
    ydot[l.series(e)] = ws.series_rate[static_cast<std::size_t>(e)];
  if (clock) {
    clock->mark(Stage::SeriesRates);
    clock->finish();
  }
  return 0;
}

GuidedVehicleOde::GuidedVehicleOde(const VehicleModel& model)
    : VehicleOde(model, guidedLayout(model)), ws_(makeWorkspace(model)) {
  scratch_.assign(static_cast<std::size_t>(layout_.size), 0.0);
  stages_.use({Stage::Coordinates, Stage::VehicleForces, Stage::FreeBodies, Stage::SeriesRates});
}

int GuidedVehicleOde::rhs(double t, const double* y, double* ydot) {
  const int rc = guidedRhs(*model_, layout_, t, y, ydot, ws_, stages_.start() ? &stages_ : nullptr);
  if (rc != 0) {
    last_error_ =
        "a free body's pitch angle reached the Euler-angle guard |theta| >= 1.2 rad, or "
        "a mass matrix is not positive definite";
  }
  return rc;
}

Eigen::VectorXd GuidedVehicleOde::initialState(double t0) {
  const VehicleLayout& l = layout_;
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
  const EquilibriumResult eq =
      solveStaticEquilibrium(y, n, residual, [this](int i) { return componentName(i); });
  if (eq.status == EquilibriumResult::Status::Singular)
    throw InputError(model_->loc,
                     "vehicle '" + model_->name +
                         "': no static equilibrium: a free body coordinate is not restrained by "
                         "any suspension element (singular stiffness)" +
                         (eq.unrestrained.empty() ? std::string() : ":" + eq.unrestrained));
  if (eq.status == EquilibriumResult::Status::NotConverged) {
    std::ostringstream os;
    os << "vehicle '" << model_->name
       << "': static equilibrium did not converge (|acceleration| = " << eq.residual
       << " after 50 Newton iterations)";
    throw InputError(model_->loc, os.str());
  }
  return y;
}

int GuidedVehicleOde::bodyCoordinates(double t, const double* y, std::span<Vector6d> q) {
  guidedCoordinates(*model_, layout_, t, y, ws_);
  for (std::size_t b = 0; b < q.size() && b < ws_.q.size(); ++b) q[b] = ws_.q[b];
  return 0;
}

Vector6d GuidedVehicleOde::accelerationOf(std::size_t b) const {
  Vector6d qdd = Vector6d::Zero();
  const double a = ws_.motion ? ws_.motion->acceleration : model_->acceleration;
  qdd[kS] = a;
  if (model_->bodies[b].kind == BodyKind::Wheelset) qdd[kPitch] = a / model_->wheel_radius;
  const int k = layout_.freeSlot(b);
  if (k >= 0)
    for (int c = 0; c < 5; ++c) qdd[1 + c] = scratch_[static_cast<std::size_t>(layout_.rate(k, c))];
  return qdd;
}

int GuidedVehicleOde::bodyAccelerations(double t, const double* y, std::span<Vector6d> qdd) {
  const int rc = guidedRhs(*model_, layout_, t, y, scratch_.data(), ws_);
  for (std::size_t b = 0; b < qdd.size() && b < ws_.q.size(); ++b) qdd[b] = accelerationOf(b);
  return rc;
}

int GuidedVehicleOde::elementOutputs(double t, const double* y, std::span<const ElementId> ids,
                                     std::span<ElementValue> out) {
  guidedCoordinates(*model_, layout_, t, y, ws_);
  evaluate(*model_, t, layout_.n_series > 0 ? y + layout_.series(0) : nullptr, ws_);
  for (std::size_t i = 0; i < ids.size() && i < out.size(); ++i) out[i] = ws_.value(ids[i]);
  return 0;
}

BodyOutput GuidedVehicleOde::bodyOutput(double t, const double* y, int body) {
  BodyOutput o;
  guidedRhs(*model_, layout_, t, y, scratch_.data(), ws_);
  const auto b = static_cast<std::size_t>(body);
  const Vector6d qdd = accelerationOf(b);
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
  evaluate(*model_, t, f, ws_);
  return vehicle::energy(*model_, f, ws_);
}

}  // namespace rb::vehicle
