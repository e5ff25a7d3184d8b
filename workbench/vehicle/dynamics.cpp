#include "workbench/vehicle/dynamics.hpp"

#include "workbench/suspension/external_force.hpp"
#include "workbench/suspension/laws.hpp"

namespace rb::vehicle {

namespace {

// Eq. (28) for the points u1 of body i and u2 of body j (PointPairMotion). The Jacobians
// J_i = -L_P - (w_i x delta) e_s^T, J_j = A_ij L_Q are never formed: velocities and generalised
// forces go through pointVelocity and the point resultants (a few cross products each).
void motionOf(const PointPair& d, const Workspace& ws, PointPairMotion& p) {
  const BodyKinematics& ki = ws.kin[static_cast<std::size_t>(d.body1)];
  const BodyKinematics& kj = ws.kin[static_cast<std::size_t>(d.body2)];
  const Eigen::Matrix3d& Aij = ws.pair_A[static_cast<std::size_t>(d.pair)];
  const Eigen::Vector3d& Rij = ws.pair_R[static_cast<std::size_t>(d.pair)];
  p.aui.noalias() = ki.attach.A * d.u1;
  p.auj.noalias() = kj.attach.A * d.u2;
  p.delta = Rij + Aij * (kj.rbar + p.auj) - (ki.rbar + p.aui);
  p.w_delta = ki.tf.w.cross(p.delta);
  p.delta_dot = Aij * pointVelocity(kj, p.auj) - pointVelocity(ki, p.aui) - ki.sd * p.w_delta;
}

// Generalised forces Q = -(dd/dq)^T f on both bodies (Eq. 29): the force F = grad f (master
// comps) acts at P, -A_ij^T F (body j's track comps) at Q; -J_i^T F = L_P^T F + ((w_i x delta) .
// F) e_s, -J_j^T F = L_Q^T (-A_ij^T F). L_P^T F is linear in (F, au x F): the point forces of a
// body are summed into its resultant force and moment about the CoM (susp_force, susp_moment,
// outputs as well) and projected once per body (pointResultantsToQ); only the master's extra
// s term is added per element.
void applyForce(const ElementGeometry& g, const PointPairMotion& p, const Eigen::Matrix3d& Aij,
                const Eigen::Vector3d& grad, double f, Workspace& ws) {
  const auto i = static_cast<std::size_t>(g.body1), j = static_cast<std::size_t>(g.body2);
  const Eigen::Vector3d Fi = grad * f;
  const Eigen::Vector3d Fj = -(Aij.transpose() * Fi);
  ws.force[i][kS] += p.w_delta.dot(Fi);
  ws.susp_force[i] += Fi;
  ws.susp_moment[i] += p.aui.cross(Fi);
  ws.susp_force[j] += Fj;
  ws.susp_moment[j] += p.auj.cross(Fj);
}

// applyForce for a directional element, grad = e_a: F_i = f e_a, so every product with F_i keeps
// one term (the others are exact zeros, whose sums change nothing: the same numbers as
// applyForce), and au x (f e_a) has the components au[a+2] f at a+1 and -au[a+1] f at a+2.
// (Inlined into the element loops: it runs for most elements in every evaluation.)
[[gnu::always_inline]] inline void applyAxisForce(const ElementGeometry& g,
                                                  const PointPairMotion& p,
                                                  const Eigen::Matrix3d& Aij, double f,
                                                  Workspace& ws) {
  const auto i = static_cast<std::size_t>(g.body1), j = static_cast<std::size_t>(g.body2);
  const int a = g.axis, a1 = a == 2 ? 0 : a + 1, a2 = a == 0 ? 2 : a - 1;
  const Eigen::Vector3d Fj(-(Aij(a, 0) * f), -(Aij(a, 1) * f), -(Aij(a, 2) * f));
  ws.force[i][kS] += p.w_delta[a] * f;
  Eigen::Vector3d& Fi_sum = ws.susp_force[i];
  Eigen::Vector3d& Mi_sum = ws.susp_moment[i];
  Fi_sum[a] += f;
  Mi_sum[a1] += p.aui[a2] * f;
  Mi_sum[a2] -= p.aui[a1] * f;
  ws.susp_force[j] += Fj;
  ws.susp_moment[j] += p.auj.cross(Fj);
}

// Deformation of a point-based element from its point pair's motion, its force f = law(d, d_dot)
// and the generalised forces; returns the element's output value.
template <class Law>
ElementValue pointElement(const ElementGeometry& g, Workspace& ws, Law law) {
  const PointPairMotion& p = ws.point_motion[static_cast<std::size_t>(g.point_pair)];
  const Eigen::Matrix3d& Aij = ws.pair_A[static_cast<std::size_t>(g.pair)];
  if (g.axis < 0) {
    const suspension::Deformation d = suspension::axialDeformation(p.delta, p.delta_dot, g.length0);
    const double f = law(d.d, d.d_dot);
    applyForce(g, p, Aij, d.grad, f, ws);
    return {d.d, d.d_dot, f};
  }
  const suspension::Deformation d =
      suspension::directionalDeformation(p.delta, p.delta_dot, g.delta_nominal, g.axis);
  const double f = law(d.d, d.d_dot);
  applyAxisForce(g, p, Aij, f, ws);
  return {d.d, d.d_dot, f};
}

// Sum of L_P^T F over the point forces of a body from their resultant F and moment M = sum au x F:
// s: F.x + (w x rbar) . F + w . M (as (w x au) . F = w . (au x F)), y: F.y, z: F.z, angles: AG^T M.
void pointResultantsToQ(const BodyKinematics& k, const Eigen::Vector3d& F, const Eigen::Vector3d& M,
                        Vector6d& Q) {
  Q[kS] += F.x() + k.tf.w.cross(k.rbar).dot(F) + k.tf.w.dot(M);
  Q[kY] += F.y();
  Q[kZ] += F.z();
  Q.segment<3>(kRoll).noalias() += k.AG.transpose() * M;
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

PointPairMotion pointPairMotion(const ElementGeometry& g, const Workspace& ws) {
  PointPairMotion p;
  motionOf({g.body1, g.body2, g.pair, g.u1, g.u2}, ws, p);
  return p;
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
  ws.pair_A.assign(m.body_pairs.size(), Eigen::Matrix3d::Identity());
  ws.pair_R.assign(m.body_pairs.size(), Eigen::Vector3d::Zero());
  // tf_version starts at 0 and is >= 1 once a frame is evaluated: no pair matches before that.
  ws.pair_version.assign(m.body_pairs.size(), {0, 0});
  ws.point_motion.resize(m.point_pairs.size());
  return ws;
}

void evaluate(const VehicleModel& m, double t, const double* series_f, Workspace& ws) {
  // Bodies: kinematics, mass matrix, quadratic-velocity inertia forces, gravity. With
  // Lv = [c_s, e_y, e_z, 0] (c_s = e_x + w x rbar) and Lw = [wb, 0, 0, G] the products
  // M = m Lv^T Lv + Lw^T J Lw and Q = Lv^T f_lin + Lw^T f_rot are written out by blocks (the
  // zero columns are known; a generic 6x6 product would spend 3/4 of its work on them).
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const Body& body = m.bodies[b];
    BodyKinematics& k = ws.kin[b];
    bodyKinematics(m.geometry, body.rotation, body.height, ws.q[b], ws.qd[b], k);
    const Eigen::Vector3d& J = body.inertia;
    const double mass = body.mass;
    const Eigen::Vector3d cs = k.Lv.col(kS);
    const Eigen::Vector3d wb = k.Lw.col(kS);
    const Eigen::Matrix3d& G = k.body.G;
    const Eigen::Vector3d Jwb = J.cwiseProduct(wb);
    const Eigen::Matrix3d JG = J.asDiagonal() * G;
    Matrix6d& M = ws.mass[b];
    M(kS, kS) = mass * cs.squaredNorm() + wb.dot(Jwb);
    M(kS, kY) = M(kY, kS) = mass * cs.y();
    M(kS, kZ) = M(kZ, kS) = mass * cs.z();
    M(kY, kY) = M(kZ, kZ) = mass;
    M(kY, kZ) = M(kZ, kY) = 0.0;
    const Eigen::RowVector3d msr = Jwb.transpose() * G;
    M.block<1, 3>(kS, kRoll) = msr;
    M.block<3, 1>(kRoll, kS) = msr.transpose();
    M.block<2, 3>(kY, kRoll).setZero();
    M.block<3, 2>(kRoll, kY).setZero();
    M.block<3, 3>(kRoll, kRoll).noalias() = G.transpose() * JG;
    const Eigen::Vector3d Jw = J.cwiseProduct(k.omega_b);
    const Eigen::Vector3d g_track = k.tf.A.transpose() * Eigen::Vector3d(0.0, 0.0, -m.gravity);
    const Eigen::Vector3d f_lin = mass * (g_track - k.gamma_v);
    const Eigen::Vector3d f_rot = -(J.cwiseProduct(k.gamma_w) + k.omega_b.cross(Jw));
    Vector6d& Q = ws.force[b];
    Q[kS] = cs.dot(f_lin) + wb.dot(f_rot);
    Q[kY] = f_lin.y();
    Q[kZ] = f_lin.z();
    Q.segment<3>(kRoll).noalias() = G.transpose() * f_rot;
    ws.susp_force[b].setZero();
    ws.susp_moment[b].setZero();
  }
  // Relative placement of the track frames of each element body pair (Eq. 28).
  // Recomputed only when a track frame changed (not between the stages at one time).
  for (std::size_t pr = 0; pr < m.body_pairs.size(); ++pr) {
    const BodyKinematics& ki = ws.kin[static_cast<std::size_t>(m.body_pairs[pr][0])];
    const BodyKinematics& kj = ws.kin[static_cast<std::size_t>(m.body_pairs[pr][1])];
    const std::array<std::uint64_t, 2> version{ki.tf_version, kj.tf_version};
    if (version == ws.pair_version[pr]) continue;
    ws.pair_version[pr] = version;
    ws.pair_A[pr].noalias() = ki.tf.A.transpose() * kj.tf.A;
    ws.pair_R[pr].noalias() = ki.tf.A.transpose() * (kj.tf.R - ki.tf.R);
  }

  // Relative motion of every point pair, shared by the elements at those points.
  for (std::size_t pp = 0; pp < m.point_pairs.size(); ++pp) {
    motionOf(m.point_pairs[pp], ws, ws.point_motion[pp]);
  }
  // Spring-dampers in parallel.
  for (std::size_t e = 0; e < m.spring_dampers.size(); ++e) {
    const SpringDamperElement& el = m.spring_dampers[e];
    ws.spring_damper[e] = pointElement(el.g, ws, [&](double d, double d_dot) {
      return suspension::springDamperForce(el.stiffness, el.damping, el.preload, d, d_dot);
    });
  }
  // Spring-dampers in series (the Maxwell force is a state).
  for (std::size_t e = 0; e < m.series_dampers.size(); ++e) {
    const SeriesDamperElement& el = m.series_dampers[e];
    const double fs = series_f[e];
    ws.series_damper[e] = pointElement(el.g, ws, [&](double d, double d_dot) {
      ws.series_rate[e] = suspension::seriesDamperRate(el.series_stiffness, el.damping, fs, d_dot);
      return suspension::seriesDamperForce(el.stiffness, el.preload, d, fs);
    });
  }
  // Shear springs (directional by validation).
  for (std::size_t e = 0; e < m.shear_springs.size(); ++e) {
    const ShearSpringElement& el = m.shear_springs[e];
    ws.shear_spring[e] = pointElement(el.g, ws, [&](double d, double /*d_dot*/) {
      return suspension::shearSpringForce(el.stiffness, el.preload, d);
    });
  }
  // Bumpstops.
  for (std::size_t e = 0; e < m.bumpstops.size(); ++e) {
    const BumpstopElement& el = m.bumpstops[e];
    ws.bumpstop[e] =
        pointElement(el.g, ws, [&](double d, double /*d_dot*/) { return el.law.force(d); });
  }
  for (std::size_t b = 0; b < m.bodies.size(); ++b)
    pointResultantsToQ(ws.kin[b], ws.susp_force[b], ws.susp_moment[b], ws.force[b]);
  // Forces from outside the vehicle (a train's buffers and couplers), at their points.
  for (const AppliedLoad& a : ws.applied) {
    const BodyKinematics& k = ws.kin[static_cast<std::size_t>(a.body)];
    addPointForce(k, k.attach.A * a.u, k.tf.A.transpose() * a.force,
                  ws.force[static_cast<std::size_t>(a.body)]);
  }
  // External forces: F(t, s) along a direction of the body's track frame or of the body, at a
  // point of the body, so that its moment about the CoM acts too (addPointForce).
  for (const ExternalForce& e : m.external_forces) {
    const auto b = static_cast<std::size_t>(e.body);
    const BodyKinematics& k = ws.kin[b];
    const double f = suspension::forceAt(e.law, t, ws.q[b][kS]);
    const Eigen::Vector3d along =
        e.frame == ForceFrame::Body ? Eigen::Vector3d(k.attach.A * e.direction) : e.direction;
    addPointForce(k, k.attach.A * e.u, f * along, ws.force[b]);
  }
  // Moments: on the angles through the body frame's angular-velocity map, omega (track comps)
  // = Abar G alpha_dot, so Q_alpha = (Abar G)^T M (the spin of a wheelset included).
  for (const AppliedMoment& a : ws.moments) {
    const BodyKinematics& k = ws.kin[static_cast<std::size_t>(a.body)];
    const BodyKinematics& ax = ws.kin[static_cast<std::size_t>(a.axis)];
    const Eigen::Vector3d moment = ax.tf.A * ax.attach.A.col(1) * a.torque;  // global
    ws.force[static_cast<std::size_t>(a.body)].segment<3>(kRoll).noalias() +=
        (k.body.A * k.body.G).transpose() * (k.tf.A.transpose() * moment);
  }

  // Bending springs: relative rotation of the attachment frames in the master track frame.
  // theta_dot = T1 (A_ij omega_j - w_i sdot_i) - T2 (omega_i - w_i sdot_i), omega = absolute
  // angular velocities of the attachment frames in their track-frame components, = w sdot +
  // omega_rel. Row `a` only: with t1 = T1^T e_a, t2 = T2^T e_a, t1j = A_ij^T t1,
  // d theta_a / d qdot_i = (-t1 . w_i, 0, 0, -AG_i^T t2), d theta_a / d qdot_j =
  // (t1j . w_j, 0, 0, AG_j^T t1j).
  for (std::size_t e = 0; e < m.bending_springs.size(); ++e) {
    const BendingSpringElement& el = m.bending_springs[e];
    const auto i = static_cast<std::size_t>(el.g.body1), j = static_cast<std::size_t>(el.g.body2);
    const BodyKinematics& ki = ws.kin[i];
    const BodyKinematics& kj = ws.kin[j];
    const Eigen::Matrix3d& Aij = ws.pair_A[static_cast<std::size_t>(el.g.pair)];
    const Eigen::Matrix3d R = (Aij * kj.attach.A) * ki.attach.A.transpose();
    const suspension::RelativeRotation rr = suspension::relativeRotation(R);
    const int a = el.g.axis;
    const Eigen::Vector3d t1 = rr.T1.row(a).transpose();
    const Eigen::Vector3d t2 = rr.T2.row(a).transpose();
    const Eigen::Vector3d t1j = Aij.transpose() * t1;
    const double th = rr.theta[a];
    const double th_dot = -t1.dot(ki.tf.w) * ki.sd - t2.dot(ki.omega_rel) +
                          t1j.dot(kj.tf.w) * kj.sd + t1j.dot(kj.omega_rel);
    const double M = suspension::bendingSpringMoment(el.stiffness, el.preload, th);
    ws.bending_spring[e] = {th, th_dot, M};
    ws.force[i][kS] += t1.dot(ki.tf.w) * M;
    ws.force[i].segment<3>(kRoll).noalias() += ki.AG.transpose() * (t2 * M);
    ws.force[j][kS] -= t1j.dot(kj.tf.w) * M;
    ws.force[j].segment<3>(kRoll).noalias() -= kj.AG.transpose() * (t1j * M);
    ws.susp_moment[i] += t2 * M;
    ws.susp_moment[j] -= t1j * M;
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
