#include "workbench/vehicle/dynamics.hpp"

#include "workbench/suspension/laws.hpp"

namespace rb::vehicle {

namespace {

// Relative motion of the two attachment points of an element in the master track frame (Eq. 28)
// and its Jacobians: delta_dot = Ji qd_i + Jj qd_j.
struct PointPair {
  Eigen::Matrix3d Aij;  // A_ti^T A_tj
  Eigen::Vector3d delta, delta_dot;
  Matrix36d Ji, Jj;
};

void pointPair(const ElementGeometry& g, const Workspace& ws, PointPair& p) {
  const BodyKinematics& ki = ws.kin[static_cast<std::size_t>(g.body1)];
  const BodyKinematics& kj = ws.kin[static_cast<std::size_t>(g.body2)];
  p.Aij.noalias() = ki.tf.A.transpose() * kj.tf.A;
  const Eigen::Vector3d Rij = ki.tf.A.transpose() * (kj.tf.R - ki.tf.R);
  const Eigen::Vector3d rP = pointPosition(ki, g.u1);
  const Eigen::Vector3d rQ = Rij + p.Aij * pointPosition(kj, g.u2);
  p.delta = rQ - rP;
  // d/dt of master-frame components: A_ij v_Q - v_P - sdot_i w_i x delta.
  p.Ji = -pointJacobian(ki, g.u1);
  p.Ji.col(kS) -= ki.tf.w.cross(p.delta);
  p.Jj.noalias() = p.Aij * pointJacobian(kj, g.u2);
  p.delta_dot.noalias() = p.Ji * ws.qd[static_cast<std::size_t>(g.body1)];
  p.delta_dot.noalias() += p.Jj * ws.qd[static_cast<std::size_t>(g.body2)];
}

suspension::Deformation deformation(const ElementGeometry& g, const PointPair& p) {
  if (g.axis < 0) return suspension::axialDeformation(p.delta, p.delta_dot, g.length0);
  return suspension::directionalDeformation(p.delta, p.delta_dot, g.delta_nominal, g.axis);
}

// Generalised forces Q = -(dd/dq)^T f on both bodies (Eq. 29) and the physical resultants.
void applyForce(const ElementGeometry& g, const PointPair& p, const Eigen::Vector3d& grad, double f,
                Workspace& ws) {
  const auto i = static_cast<std::size_t>(g.body1), j = static_cast<std::size_t>(g.body2);
  ws.force[i].noalias() -= p.Ji.transpose() * (grad * f);
  ws.force[j].noalias() -= p.Jj.transpose() * (grad * f);
  const Eigen::Vector3d Fi = grad * f;
  const Eigen::Vector3d Fj = -(p.Aij.transpose() * Fi);
  ws.susp_force[i] += Fi;
  ws.susp_moment[i] += (ws.kin[i].attach.A * g.u1).cross(Fi);
  ws.susp_force[j] += Fj;
  ws.susp_moment[j] += (ws.kin[j].attach.A * g.u2).cross(Fj);
}

}  // namespace

const ElementValue& Workspace::value(ElementId id) const {
  const auto i = static_cast<std::size_t>(id.index);
  switch (id.kind) {
    case ElementKind::SpringDamper:
      return spring_damper.at(i);
    case ElementKind::SeriesSpringDamper:
      return series_damper.at(i);
    case ElementKind::ShearSpring:
      return shear_spring.at(i);
    case ElementKind::BendingSpring:
      return bending_spring.at(i);
    case ElementKind::Bumpstop:
      return bumpstop.at(i);
  }
  RB_CHECK(false, "unknown element kind");
}

Workspace makeWorkspace(const VehicleModel& m) {
  Workspace ws;
  const std::size_t n = m.bodies.size();
  ws.q.assign(n, Vector6d::Zero());
  ws.qd.assign(n, Vector6d::Zero());
  ws.kin.resize(n);
  ws.mass.assign(n, Matrix6d::Zero());
  ws.force.assign(n, Vector6d::Zero());
  ws.susp_force.assign(n, Eigen::Vector3d::Zero());
  ws.susp_moment.assign(n, Eigen::Vector3d::Zero());
  ws.spring_damper.resize(m.spring_dampers.size());
  ws.series_damper.resize(m.series_dampers.size());
  ws.shear_spring.resize(m.shear_springs.size());
  ws.bending_spring.resize(m.bending_springs.size());
  ws.bumpstop.resize(m.bumpstops.size());
  ws.series_rate.assign(m.series_dampers.size(), 0.0);
  return ws;
}

void evaluate(const VehicleModel& m, const double* series_f, Workspace& ws) {
  // Bodies: kinematics, mass matrix, quadratic-velocity inertia forces, gravity.
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const Body& body = m.bodies[b];
    BodyKinematics& k = ws.kin[b];
    bodyKinematics(m.geometry, body.rotation, body.height, ws.q[b], ws.qd[b], k);
    const Eigen::Vector3d J = body.inertia;
    Matrix6d& M = ws.mass[b];
    M.noalias() = body.mass * k.Lv.transpose() * k.Lv;
    M.noalias() += k.Lw.transpose() * J.asDiagonal() * k.Lw;
    const Eigen::Vector3d Jw = J.cwiseProduct(k.omega_b);
    const Eigen::Vector3d g_track = k.tf.A.transpose() * Eigen::Vector3d(0.0, 0.0, -m.gravity);
    Vector6d& Q = ws.force[b];
    Q.noalias() = k.Lv.transpose() * (body.mass * (g_track - k.gamma_v));
    Q.noalias() -= k.Lw.transpose() * (J.cwiseProduct(k.gamma_w) + k.omega_b.cross(Jw));
    ws.susp_force[b].setZero();
    ws.susp_moment[b].setZero();
  }

  PointPair p;
  // Spring-dampers in parallel.
  for (std::size_t e = 0; e < m.spring_dampers.size(); ++e) {
    const SpringDamperElement& el = m.spring_dampers[e];
    pointPair(el.g, ws, p);
    const suspension::Deformation d = deformation(el.g, p);
    const double f =
        suspension::springDamperForce(el.stiffness, el.damping, el.preload, d.d, d.d_dot);
    ws.spring_damper[e] = {d.d, d.d_dot, f};
    applyForce(el.g, p, d.grad, f, ws);
  }
  // Spring-dampers in series (the Maxwell force is a state).
  for (std::size_t e = 0; e < m.series_dampers.size(); ++e) {
    const SeriesDamperElement& el = m.series_dampers[e];
    pointPair(el.g, ws, p);
    const suspension::Deformation d = deformation(el.g, p);
    const double fs = series_f[e];
    const double f = suspension::seriesDamperForce(el.stiffness, el.preload, d.d, fs);
    ws.series_damper[e] = {d.d, d.d_dot, f};
    ws.series_rate[e] = suspension::seriesDamperRate(el.series_stiffness, el.damping, fs, d.d_dot);
    applyForce(el.g, p, d.grad, f, ws);
  }
  // Shear springs (directional by validation).
  for (std::size_t e = 0; e < m.shear_springs.size(); ++e) {
    const ShearSpringElement& el = m.shear_springs[e];
    pointPair(el.g, ws, p);
    const suspension::Deformation d = deformation(el.g, p);
    const double f = suspension::shearSpringForce(el.stiffness, el.preload, d.d);
    ws.shear_spring[e] = {d.d, d.d_dot, f};
    applyForce(el.g, p, d.grad, f, ws);
  }
  // Bumpstops.
  for (std::size_t e = 0; e < m.bumpstops.size(); ++e) {
    const BumpstopElement& el = m.bumpstops[e];
    pointPair(el.g, ws, p);
    const suspension::Deformation d = deformation(el.g, p);
    const double f = el.law.force(d.d);
    ws.bumpstop[e] = {d.d, d.d_dot, f};
    applyForce(el.g, p, d.grad, f, ws);
  }
  // Bending springs: relative rotation of the attachment frames in the master track frame.
  for (std::size_t e = 0; e < m.bending_springs.size(); ++e) {
    const BendingSpringElement& el = m.bending_springs[e];
    const auto i = static_cast<std::size_t>(el.g.body1), j = static_cast<std::size_t>(el.g.body2);
    const BodyKinematics& ki = ws.kin[i];
    const BodyKinematics& kj = ws.kin[j];
    const Eigen::Matrix3d Aij = ki.tf.A.transpose() * kj.tf.A;
    const Eigen::Matrix3d R = (Aij * kj.attach.A) * ki.attach.A.transpose();
    const suspension::RelativeRotation rr = suspension::relativeRotation(R);
    // theta_dot = T1 (A_ij omega_j - w_i sdot_i) - T2 (omega_i - w_i sdot_i), omega = absolute
    // angular velocities of the attachment frames in their track-frame components.
    Matrix36d Ti = -rr.T2 * attachmentAngularJacobian(ki);
    Ti.col(kS) += (rr.T2 - rr.T1) * ki.tf.w;
    const Matrix36d Tj = rr.T1 * Aij * attachmentAngularJacobian(kj);
    const int a = el.g.axis;
    const double th = rr.theta[a];
    const double th_dot = Ti.row(a).dot(ws.qd[i]) + Tj.row(a).dot(ws.qd[j]);
    const double M = suspension::bendingSpringMoment(el.stiffness, el.preload, th);
    ws.bending_spring[e] = {th, th_dot, M};
    ws.force[i].noalias() -= Ti.row(a).transpose() * M;
    ws.force[j].noalias() -= Tj.row(a).transpose() * M;
    const Eigen::Vector3d Mi = rr.T2.row(a).transpose() * M;
    ws.susp_moment[i] += Mi;
    ws.susp_moment[j] -= Aij.transpose() * (rr.T1.row(a).transpose() * M);
  }
}

Energy energy(const VehicleModel& m, const double* series_f, const Workspace& ws) {
  Energy E;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const Body& body = m.bodies[b];
    if (body.kind == BodyKind::Frame) continue;
    const BodyKinematics& k = ws.kin[b];
    E.kinetic += 0.5 * body.mass * k.v.squaredNorm() +
                 0.5 * k.omega_b.dot(body.inertia.cwiseProduct(k.omega_b));
    E.gravity += body.mass * m.gravity * k.position().z();
  }
  const auto spring = [](double K, double preload, double d) {
    return 0.5 * K * d * d + preload * d;
  };
  for (std::size_t e = 0; e < m.spring_dampers.size(); ++e)
    E.elastic +=
        spring(m.spring_dampers[e].stiffness, m.spring_dampers[e].preload, ws.spring_damper[e].d);
  for (std::size_t e = 0; e < m.series_dampers.size(); ++e) {
    const SeriesDamperElement& el = m.series_dampers[e];
    E.elastic += spring(el.stiffness, el.preload, ws.series_damper[e].d) +
                 series_f[e] * series_f[e] / (2.0 * el.series_stiffness);
  }
  for (std::size_t e = 0; e < m.shear_springs.size(); ++e)
    E.elastic +=
        spring(m.shear_springs[e].stiffness, m.shear_springs[e].preload, ws.shear_spring[e].d);
  for (std::size_t e = 0; e < m.bending_springs.size(); ++e)
    E.elastic += spring(m.bending_springs[e].stiffness, m.bending_springs[e].preload,
                        ws.bending_spring[e].d);
  for (std::size_t e = 0; e < m.bumpstops.size(); ++e)
    E.elastic += m.bumpstops[e].law.energy(ws.bumpstop[e].d);
  return E;
}

}  // namespace rb::vehicle
