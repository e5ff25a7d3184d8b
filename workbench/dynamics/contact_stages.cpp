#include "workbench/dynamics/contact_stages.hpp"

#include <array>
#include <cmath>
#include <sstream>

namespace rb::dynamics::internal {

namespace {

using vehicle::kPitch;
using vehicle::kRoll;
using vehicle::kS;
using vehicle::kY;
using vehicle::kZ;

constexpr double kPitchLimit = 1.2;  // [rad] Euler-angle guard of free bodies

// One channel of an irregularity array (values, first or second derivatives along s).
double channel(const std::array<double, track::kChannels>& xi, track::Channel c) {
  return xi[static_cast<std::size_t>(c)];
}

// z, phi of a wheelset's centre and their rates (from the contact constraints).
struct DependentCoordinates {
  double z = 0.0, phi = 0.0, z_dot = 0.0, phi_dot = 0.0;
};

// Irregularities at the wheelset's arc length s and the cross-level angle of the rails (Eq. 5).
// Without irregularities they stay zero (delta_irr = 0, cos 1, sin 0).
void updateIrregularities(const track::Irregularities& irr, double s, double lr, WheelsetWork& ww) {
  if (ww.irr_key == s) return;  // the stages of a step at one time share them
  ww.irr = irr.at(s);
  ww.irr_key = s;
  ww.delta_irr = (ww.irr.z_l - ww.irr.z_r) / (2.0 * lr);
  ww.cos_irr = std::cos(ww.delta_irr);
  ww.sin_irr = std::sin(ww.delta_irr);
}

// "wheelset 'ws1' at t = 1.5 s (s = 30 m): " (failure messages of the constraint stage).
void wheelsetAt(std::ostringstream& os, const ContactModels& models, const WheelsetWork& ww,
                double t, double s) {
  os << "wheelset '" << models.vehicle.bodies[ww.body].name << "' at t = " << t << " s (s = " << s
     << " m): ";
}

std::string kecFailure(const contact::KecSolution& sol) {
  return sol.status == contact::KecStatus::OutOfTable
             ? "left the KEC table: s_lk = " + std::to_string(sol.s_lk * 1e3) +
                   " mm, s_rk = " + std::to_string(sol.s_rk * 1e3) + " mm (flange climb?)"
             : "not solved (Newton did not converge, residual " + std::to_string(sol.residual) +
                   ")";
}

// KEC (Eq. 22): x = (z, phi, s_lk, s_rk) = solveKec(p), p = (y, y_lir, y_rir, z_lir, z_rir),
// warm-started from the last solution; xdot = dx_dp pdot, xddot = dx_dp pddot + kecQuadraticTerm.
int kecConstraints(const ContactModels& models, const StageInput& in, WheelsetWork& ww,
                   ContactWorkspace& work, DependentCoordinates& dep) {
  const vehicle::Vector6d& q = work.bodies.q[ww.body];
  const vehicle::Vector6d& qd = work.bodies.qd[ww.body];
  const track::IrregularityPoint& rail = ww.irr;
  const contact::KecInput input{q[kY], rail.y_l, rail.y_r, rail.z_l, rail.z_r};
  const contact::KecSolution sol =
      contact::solveKec(*ww.contact->kec, input, ww.kec_warm ? &ww.kec : nullptr);
  work.stats.kec_iterations += sol.iterations;
  if (sol.status != contact::KecStatus::Ok) {
    std::ostringstream os;
    wheelsetAt(os, models, ww, in.t, q[kS]);
    os << "KEC constraints (Eq. 22) " << kecFailure(sol) << ", y = " << q[kY] * 1e3 << " mm";
    work.fail(sol.status == contact::KecStatus::OutOfTable ? ContactFailure::TableRange
                                                           : ContactFailure::ConstraintSolve,
              models.vehicle.bodies[ww.body].name, os.str());
    ww.kec_warm = false;
    return 1;
  }
  ww.kec = sol;
  ww.kec_warm = true;
  const double V = in.speed, V2 = V * V, acc = in.acceleration;
  Eigen::Matrix<double, 5, 1> p_dot;
  p_dot << qd[kY], V * rail.y_l_s, V * rail.y_r_s, V * rail.z_l_s, V * rail.z_r_s;
  const Eigen::Vector4d x_dot = sol.dx_dp * p_dot;
  const Eigen::Vector4d quad = contact::kecQuadraticTerm(sol, x_dot);
  const double a_ss = channel(rail.xi_ss, track::Channel::Alignment);
  const double v_ss = channel(rail.xi_ss, track::Channel::Vertical);
  const double g_ss = channel(rail.xi_ss, track::Channel::Gauge);
  const double c_ss = channel(rail.xi_ss, track::Channel::CrossLevel);
  Eigen::Vector4d p_ddot;  // pddot without yddot: the rails' irregularities, V^2 p'' + a p'
  p_ddot << V2 * (a_ss + 0.5 * g_ss) + acc * rail.y_l_s,
      V2 * (a_ss - 0.5 * g_ss) + acc * rail.y_r_s, V2 * (v_ss + 0.5 * c_ss) + acc * rail.z_l_s,
      V2 * (v_ss - 0.5 * c_ss) + acc * rail.z_r_s;
  dep = {sol.z, sol.phi, x_dot(0), x_dot(1)};
  ww.G.setZero();
  ww.G(0, 0) = -sol.dx_dp(0, 0);
  ww.G(0, 1) = 1.0;
  ww.G(1, 0) = -sol.dx_dp(1, 0);
  ww.G(1, 2) = 1.0;
  ww.gamma(0) = sol.dx_dp.row(0).tail<4>().dot(p_ddot) + quad(0);
  ww.gamma(1) = sol.dx_dp.row(1).tail<4>().dot(p_ddot) + quad(1);
  return 0;
}

// The irregularities seen by the LUT constraints (Eq. 18): values, first and second derivatives
// along s of alignment, vertical, gauge and cross level.
struct RailChannels {
  double a, v, g, c;              // [m]
  double a_s, v_s, g_s, c_s;      // [-]
  double a_ss, v_ss, g_ss, c_ss;  // [1/m]
};
RailChannels railChannels(const track::IrregularityPoint& rail) {
  using track::Channel;
  return {channel(rail.xi, Channel::Alignment),    channel(rail.xi, Channel::Vertical),
          channel(rail.xi, Channel::Gauge),        channel(rail.xi, Channel::CrossLevel),
          channel(rail.xi_s, Channel::Alignment),  channel(rail.xi_s, Channel::Vertical),
          channel(rail.xi_s, Channel::Gauge),      channel(rail.xi_s, Channel::CrossLevel),
          channel(rail.xi_ss, Channel::Alignment), channel(rail.xi_ss, Channel::Vertical),
          channel(rail.xi_ss, Channel::Gauge),     channel(rail.xi_ss, Channel::CrossLevel)};
}

// Second time derivative of a LUT constraint value f(ybar, xi_g) (Eq. 17) without the yddot term
// and without the rail's own term (the caller adds V^2 xi''): the chain rule with the table's first
// and second derivatives.
double lutChainRule(const contact::LutValue& f, const RailChannels& xi, double ybar_dot,
                    double xig_dot, double V2) {
  return -f.dy * V2 * xi.a_ss + f.dyy * ybar_dot * ybar_dot + 2.0 * f.dyxi * ybar_dot * xig_dot +
         f.dxixi * xig_dot * xig_dot + f.dxi * V2 * xi.g_ss;
}

// LUT (Eq. 17-18): z = z_clt(y - xi_a, xi_g) + xi_v, phi = phi_clt(y - xi_a, xi_g) + xi_c/(2 Lr);
// velocities and accelerations by the chain rule with the table's derivatives. Also reads the
// tread contact points and flange indentations the patch stage needs.
int lutConstraints(const ContactModels& models, const StageInput& in, WheelsetWork& ww,
                   ContactWorkspace& work, DependentCoordinates& dep) {
  const contact::LutTable& lut = *ww.contact->lut;
  const double lr = ww.contact->geometry.rail_lr;
  const vehicle::Vector6d& q = work.bodies.q[ww.body];
  const vehicle::Vector6d& qd = work.bodies.qd[ww.body];
  const RailChannels xi = railChannels(ww.irr);
  const double V = in.speed, V2 = V * V, acc = in.acceleration;
  const double ybar = q[kY] - xi.a;  // Eq. (18)
  const double ybar_dot = qd[kY] - V * xi.a_s, xig_dot = V * xi.g_s;
  contact::LutValue zv, pv;
  lut.evalZPhi(ybar, xi.g, zv, pv);
  readTreadsAndFlangeIndentations(lut, ybar, xi.g, ww.lut);
  for (int s = 0; s < 2; ++s) lut.treadBranches(ybar, xi.g, sideOf(s), ww.lut_branches[s]);
  ww.lut_ybar = ybar;
  ww.lut_xig = xi.g;
  if (!zv.inside || !ww.lut.inside) {
    std::ostringstream os;
    wheelsetAt(os, models, ww, in.t, q[kS]);
    os << "the LUT entry (y - xi_a = " << ybar * 1e3 << " mm, xi_g = " << xi.g * 1e3
       << " mm) left the table [" << lut.yGrid().min * 1e3 << ", " << lut.yGrid().max * 1e3
       << "] x [" << lut.gaugeGrid().min * 1e3 << ", " << lut.gaugeGrid().max * 1e3 << "] mm";
    work.fail(ContactFailure::TableRange, models.vehicle.bodies[ww.body].name, os.str());
    return 1;
  }
  ww.ybar_dot = ybar_dot;
  ww.xig_dot = xig_dot;
  ww.zbar_dot = zv.dy * ybar_dot + zv.dxi * xig_dot;
  ww.phibar_dot = pv.dy * ybar_dot + pv.dxi * xig_dot;
  dep = {zv.v + xi.v, pv.v + xi.c / (2.0 * lr), ww.zbar_dot + V * xi.v_s,
         ww.phibar_dot + V * xi.c_s / (2.0 * lr)};
  ww.G.setZero();
  ww.G(0, 0) = -zv.dy;
  ww.G(0, 1) = 1.0;
  ww.G(1, 0) = -pv.dy;
  ww.G(1, 2) = 1.0;
  ww.gamma(0) = lutChainRule(zv, xi, ybar_dot, xig_dot, V2) + V2 * xi.v_ss;
  ww.gamma(1) = lutChainRule(pv, xi, ybar_dot, xig_dot, V2) + V2 * xi.c_ss / (2.0 * lr);
  if (acc != 0.0) {
    // Speed ramp: d2 xi / dt2 = V^2 xi'' + a xi' (the terms above are the V^2 part).
    ww.gamma(0) += acc * (-zv.dy * xi.a_s + zv.dxi * xi.g_s + xi.v_s);
    ww.gamma(1) += acc * (-pv.dy * xi.a_s + pv.dxi * xi.g_s + xi.c_s / (2.0 * lr));
  }
  return 0;
}

// Wheelset w's independent coordinates from the state; the spin rolls at the centred radius
// when it is prescribed (theta_dot = V(t) / r_c).
void setWheelsetCoordinates(const ContactModels& models, const StageInput& in, int w,
                            ContactWorkspace& work) {
  const vehicle::VehicleLayout& l = models.layout;
  const std::size_t b = l.wheelset(w);
  vehicle::Vector6d& q = work.bodies.q[b];
  vehicle::Vector6d& qd = work.bodies.qd[b];
  for (int c = 0; c < vehicle::kWheelsetCoordinates; ++c) {
    const int ip = l.wsPosition(w, c);
    if (ip < 0) continue;
    q[vehicle::kWheelsetCoord[c]] = in.y[ip];
    qd[vehicle::kWheelsetCoord[c]] = in.y[l.wsRate(w, c)];
  }
  if (!l.spinFree()) {
    const double rc = work.wheelset(w).contact->centredRadius();
    q[kPitch] = in.travel / rc;
    qd[kPitch] = in.speed / rc;
  }
}

}  // namespace

int setIndependentCoordinates(const ContactModels& models, const StageInput& in,
                              ContactWorkspace& work) {
  const vehicle::VehicleModel& m = models.vehicle;
  const vehicle::VehicleLayout& l = models.layout;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    vehicle::Vector6d& q = work.bodies.q[b];
    vehicle::Vector6d& qd = work.bodies.qd[b];
    q.setZero();
    qd.setZero();
    q[kS] = m.bodySAt(b, in.travel);
    qd[kS] = in.speed;
    const int k = l.freeSlot(b);
    if (k < 0) continue;
    for (int c = 0; c < vehicle::kFreeBodyDof; ++c) {
      q[1 + c] = in.y[l.position(k, c)];
      qd[1 + c] = in.y[l.rate(k, c)];
    }
    if (!(std::abs(q[kPitch]) < kPitchLimit)) {
      work.fail(ContactFailure::BodyRotation, m.bodies[b].name,
                "body '" + m.bodies[b].name + "': pitch angle " + std::to_string(q[kPitch]) +
                    " rad reached the Euler-angle guard at t = " + std::to_string(in.t) + " s");
      return 1;
    }
  }
  for (int w = 0; w < l.n_ws; ++w) setWheelsetCoordinates(models, in, w, work);
  return 0;
}

int solveConstraints(const ContactModels& models, const StageInput& in, ContactWorkspace& work) {
  const bool kec = models.contact.method == ContactMethod::Kec;
  const bool elastic = models.contact.method == ContactMethod::Elastic;
  for (WheelsetWork& ww : work.wheelsets) {
    vehicle::Vector6d& q = work.bodies.q[ww.body];
    vehicle::Vector6d& qd = work.bodies.qd[ww.body];
    if (models.irregularities)
      updateIrregularities(*models.irregularities, q[kS], ww.contact->geometry.rail_lr, ww);
    if (elastic) continue;  // z and phi are states (setIndependentCoordinates)
    DependentCoordinates dep;
    const int rc =
        kec ? kecConstraints(models, in, ww, work, dep) : lutConstraints(models, in, ww, work, dep);
    if (rc != 0) return rc;
    q[kZ] = dep.z - ww.height;
    q[kRoll] = dep.phi;
    qd[kZ] = dep.z_dot;
    qd[kRoll] = dep.phi_dot;
  }
  return 0;
}

int freeBodyAccelerations(const ContactModels& models, const StageInput& in, double* ydot,
                          ContactWorkspace& work) {
  const vehicle::VehicleLayout& l = models.layout;
  const double acc = in.acceleration;
  for (int k = 0; k < l.n_free; ++k) {
    const std::size_t b = l.freeBody(k);
    const vehicle::Matrix6d& mass = work.bodies.mass[b];
    Cholesky5 llt;
    if (!llt.factor(mass.block<5, 5>(1, 1))) {
      work.fail(ContactFailure::Singular, models.vehicle.bodies[b].name,
                "body '" + models.vehicle.bodies[b].name +
                    "': mass matrix not positive definite at t = " + std::to_string(in.t) + " s");
      return 1;
    }
    const Vec5 pdd = llt.solve(work.bodies.force[b].segment<5>(1) - mass.block<5, 1>(1, kS) * acc);
    if (fillsOutputs(in.mode)) {
      work.qdd[b].setZero();
      work.qdd[b](kS) = acc;
      work.qdd[b].segment<5>(1) = pdd;
    }
    for (int c = 0; c < vehicle::kFreeBodyDof; ++c) {
      ydot[l.position(k, c)] = in.y[l.rate(k, c)];
      ydot[l.rate(k, c)] = pdd[c];
    }
  }
  return 0;
}

namespace {

// lutNormalMap with a wheel whose tread force is split over the two branches of a contact-point
// jump (lutTreadPatches): three or four tread patches share the reaction. Their unit normal
// forces' (y, z, roll) components A must reproduce those of N lambda for every lambda, A Q =
// N_yzphi, the y row included (the two-patch map of lutNormalMap cannot hold it: there the
// interpolated constraint slope and the points' normals disagree, and the lateral force the rails
// were reported to exert was not the one applied). Three patches: the unique solution; four (both
// wheels split): the least-norm one. False when A is singular.
bool lutBranchNormalMap(WheelsetWork& ww) {
  std::array<Patch*, 4> p{};
  int k = 0;
  for (int s = 0; s < 2; ++s) {
    p[static_cast<std::size_t>(k++)] = &ww.patch[s][0];
    if (ww.lut_split[s]) p[static_cast<std::size_t>(k++)] = &ww.patch[s][1];
  }
  const Eigen::Matrix<double, 3, 2> rhs = ww.N.topRows<3>();
  if (k == 3) {
    Eigen::Matrix3d A;
    for (int m = 0; m < 3; ++m) A.col(m) = p[static_cast<std::size_t>(m)]->gn.head<3>();
    const double det = A.determinant();
    if (!(std::abs(det) > 1e-12)) return false;
    const Eigen::Matrix<double, 3, 2> Q = A.inverse() * rhs;
    for (int m = 0; m < 3; ++m) p[static_cast<std::size_t>(m)]->ql = Q.row(m).transpose();
    return true;
  }
  Eigen::Matrix<double, 3, 4> A;
  for (int m = 0; m < 4; ++m) A.col(m) = p[static_cast<std::size_t>(m)]->gn.head<3>();
  const Eigen::Matrix3d AAt = A * A.transpose();
  const double det = AAt.determinant();
  if (!(std::abs(det) > 1e-24)) return false;
  const Eigen::Matrix<double, 4, 2> Q = A.transpose() * (AAt.inverse() * rhs);
  for (int m = 0; m < 4; ++m) p[static_cast<std::size_t>(m)]->ql = Q.row(m).transpose();
  return true;
}

}  // namespace

int lutNormalMap(const ContactModels& models, const StageInput& in, WheelsetWork& ww,
                 ContactWorkspace& work) {
  ww.N = -ww.G.transpose();
  if (ww.lut_split[0] || ww.lut_split[1]) {
    if (lutBranchNormalMap(ww)) return 0;
    work.fail(ContactFailure::Singular, models.vehicle.bodies[ww.body].name,
              "wheelset '" + models.vehicle.bodies[ww.body].name +
                  "': the tread normal directions on both sides of a contact-point jump do not "
                  "span lateral, vertical and roll at t = " +
                  std::to_string(in.t) + " s");
    return 1;
  }
  Eigen::Matrix2d A;
  for (int s = 0; s < 2; ++s) {
    A(0, s) = ww.patch[s][0].gn(1);  // z component of the unit normal force
    A(1, s) = ww.patch[s][0].gn(2);  // roll component
  }
  const double det = A.determinant();
  if (!(std::abs(det) > 1e-12)) {
    work.fail(ContactFailure::Singular, models.vehicle.bodies[ww.body].name,
              "wheelset '" + models.vehicle.bodies[ww.body].name +
                  "': the tread normal directions do not span vertical and roll at t = " +
                  std::to_string(in.t) + " s");
    return 1;
  }
  const Eigen::Matrix2d T = A.inverse() * ww.N.block<2, 2>(1, 0);
  ww.patch[0][0].ql = T.row(0).transpose();
  ww.patch[1][0].ql = T.row(1).transpose();
  return 0;
}

int augmentedSystem(const ContactModels& models, const StageInput& in, const WheelsetWork& ww,
                    ContactWorkspace& work, AugmentedSystem& system) {
  const bool spin_free = models.layout.spinFree();
  const vehicle::Matrix6d& mass = work.bodies.mass[ww.body];
  // Prescribed spin: the spin row becomes theta_ddot = a / r_c (AugmentedSolver pins it). Its
  // reaction (the spin torque the creep forces and the constraint normal forces would exert) is
  // a constraint reaction and drops out; the other rows keep their M_{q,theta} theta_ddot
  // coupling.
  if (!system.solver.factor(mass.block<5, 5>(1, 1), ww.N, ww.G, !spin_free,
                            spin_free ? 0.0 : in.acceleration / ww.contact->centredRadius())) {
    work.fail(ContactFailure::Singular, models.vehicle.bodies[ww.body].name,
              "wheelset '" + models.vehicle.bodies[ww.body].name +
                  "': mass matrix not positive definite at t = " + std::to_string(in.t) + " s");
    return 1;
  }
  // The prescribed sddot = a enters as -M_qs a (inertia of the speed ramp).
  system.rhs0.head<5>() = work.bodies.force[ww.body].segment<5>(1) -
                          mass.block<5, 1>(1, kS) * in.acceleration + ww.q_flange;
  system.rhs0.tail<2>() = ww.gamma;
  return 0;
}

int checkSolution(const ContactModels& models, const StageInput& in, const WheelsetWork& ww,
                  const Vec7& x, ContactWorkspace& work) {
  if (x.allFinite()) return 0;
  work.fail(ContactFailure::NonFinite, models.vehicle.bodies[ww.body].name,
            "wheelset '" + models.vehicle.bodies[ww.body].name +
                "': singular contact equations (augmented system) at t = " + std::to_string(in.t) +
                " s");
  return 1;
}

void writeWheelsetRates(const vehicle::VehicleLayout& l, int w, const double* y, const Vec7& x,
                        double* ydot) {
  if (!ydot) return;
  for (int c = 0; c < vehicle::kWheelsetCoordinates; ++c) {
    const int ip = l.wsPosition(w, c);
    if (ip >= 0) ydot[ip] = y[l.wsRate(w, c)];
  }
  ydot[l.wsRate(w, 0)] = x(0);
  if (l.spinFree()) ydot[l.wsRate(w, 1)] = x(3);
  ydot[l.wsRate(w, 2)] = x(4);
}

int refuseWheelLift(const ContactModels& models, const StageInput& in, const WheelsetWork& ww,
                    int side, double qn, ContactWorkspace& work) {
  const double min_normal = models.contact.min_normal_force;
  std::ostringstream os;
  os << "wheel lift: wheelset '" << models.vehicle.bodies[ww.body].name << "', "
     << (side == 0 ? "left" : "right") << " wheel: constraint normal force " << qn / 1e3
     << " kN < contact.min_normal_force = " << min_normal / 1e3 << " kN at t = " << in.t
     << " s (a constraint contact cannot lift a wheel: the model is not valid past this point)";
  work.fail(ContactFailure::WheelLift, models.vehicle.bodies[ww.body].name, os.str());
  ++work.stats.lift_evaluations;
  return 1;
}

// Output of one patch of the wheel on side sigma; adds its force to the wheel's resultant F
// (track comps). speed: V(t) [m/s], for the dissipated power.
void patchOutput(const Patch& pp, const Eigen::Vector2d& lambda, bool creep, double sigma,
                 double speed, PatchOutput& po, WheelOutput& o, Eigen::Vector3d& F) {
  po.active = true;
  po.on_flange = pp.on_flange;
  po.normal = pp.normalAt(lambda);
  po.s_w = pp.s_w;
  po.s_r = pp.s_r;
  po.gamma = pp.gamma;
  po.radius = pp.radius;
  if (creep) {
    po.fx = pp.fx;
    po.fy = pp.fy;
    po.mz = pp.mz;
    po.sx = pp.cr.sx;
    po.sy = pp.cr.sy;
    po.spin = pp.cr.phi;
    po.a = pp.a;
    po.b = pp.b;
  }
  o.normal += po.normal;
  (pp.on_flange ? o.normal_flange : o.normal_tread) += po.normal;
  o.creep_x += po.fx;
  o.creep_y += po.fy;
  ++o.patch_count;
  const Eigen::Vector3d Fp = po.normal * pp.n + po.fx * pp.ex + po.fy * pp.ey;
  F += Fp;
  po.force = {Fp.x(), -sigma * Fp.y(), Fp.z(), Fp.y()};
  // The normal is the planar one carried by the yaw psi (contact_patches.hpp, setupPatch):
  // (n_x, n_y) = nu (-sin psi, cos psi) with nu = -sigma sin(gamma_track), n_z = cos(gamma_track).
  const double nu = std::copysign(std::hypot(pp.n.x(), pp.n.y()), pp.n.y());
  po.gamma_track = std::atan2(-sigma * nu, pp.n.z());
  // Energy dissipation of the patch (the T gamma wear number): creep forces times creepages.
  po.t_gamma = std::abs(po.fx * po.sx) + std::abs(po.fy * po.sy) + std::abs(po.mz * po.spin);
  po.power = po.t_gamma * speed;
  if (po.normal < 0.0) o.lift = true;
}

void wheelsetOutputs(const StageInput& in, int w, const WheelsetWork& ww, const Vec7& x, bool creep,
                     bool lut, ContactWorkspace& work) {
  vehicle::Vector6d& qdd = work.qdd[ww.body];
  qdd.setZero();
  qdd(kS) = in.acceleration;
  qdd.segment<5>(1) = x.head<5>();
  for (int s = 0; s < 2; ++s) {
    WheelOutput& o = work.wheels[2 * static_cast<std::size_t>(w) + static_cast<std::size_t>(s)];
    o = WheelOutput{};
    const double sigma = contact::kSideSign[s];
    Eigen::Vector3d F = Eigen::Vector3d::Zero();
    for (int p = 0; p < 2; ++p)
      if (ww.patch[s][p].active)
        patchOutput(ww.patch[s][p], ww.lambda, creep, sigma, in.speed, o.patch[p], o, F);
    o.regime = ww.regime[s];
    o.weight = ww.weight[s];
    if (lut) {
      o.flange_indentation = ww.fl_delta[s];
      o.flange_force = ww.fl_force[s];
    }
    o.force_y = F.y();
    o.force_z = F.z();
    o.force = {F.x(), -sigma * F.y(), F.z(), F.y()};
    o.y_over_q = std::abs(o.force.Q) > 0.0 ? o.force.Y / o.force.Q : 0.0;
  }
}

void elasticWheelsetOutputs(const StageInput& in, int w, const WheelsetWork& ww, const Vec5& qdd,
                            bool creep, ContactWorkspace& work) {
  vehicle::Vector6d& acc = work.qdd[ww.body];
  acc.setZero();
  acc(kS) = in.acceleration;
  acc.segment<5>(1) = qdd;
  const Eigen::Vector2d none = Eigen::Vector2d::Zero();  // no multipliers: N = q0
  for (int s = 0; s < 2; ++s) {
    WheelOutput& o = work.wheels[2 * static_cast<std::size_t>(w) + static_cast<std::size_t>(s)];
    o = WheelOutput{};
    const double sigma = contact::kSideSign[s];
    const ElasticWheelWork& ew = ww.elastic[s];
    // The strongest tread and flange patches take the two output slots.
    int best[2] = {-1, -1};
    for (int k = 0; k < ew.geometry.count; ++k) {
      const Patch& p = ew.patch[static_cast<std::size_t>(k)];
      int& b = best[p.on_flange ? 1 : 0];
      if (b < 0 || p.q0 > ew.patch[static_cast<std::size_t>(b)].q0) b = k;
    }
    Eigen::Vector3d F = Eigen::Vector3d::Zero();
    for (int k = 0; k < ew.geometry.count; ++k) {
      const Patch& p = ew.patch[static_cast<std::size_t>(k)];
      PatchOutput extra;
      PatchOutput& po = k == best[0] ? o.patch[0] : (k == best[1] ? o.patch[1] : extra);
      patchOutput(p, none, creep, sigma, in.speed, po, o, F);
      // The search's contact point is relative to its rail's displaced origin.
      const auto r = static_cast<std::size_t>(ew.patch_rail[static_cast<std::size_t>(k)]);
      po.y = ew.geometry.patch[static_cast<std::size_t>(k)].y + ew.rail_offset[r].y;
      // Per rail: sums over its patches, and its strongest patch's position and creepages.
      RailContactOutput& rc = o.rail[r];
      if (p.q0 > rc.normal_max) {
        rc.normal_max = p.q0;
        rc.x = ew.geometry.patch[static_cast<std::size_t>(k)].x;
        rc.y = po.y;
        rc.sx = po.sx;
        rc.sy = po.sy;
        rc.spin = po.spin;
      }
      rc.normal += p.q0;
      rc.force.X += po.force.X;
      rc.force.Y += po.force.Y;
      rc.force.Q += po.force.Q;
      rc.force.y_track += po.force.y_track;
      rc.t_gamma += po.t_gamma;
    }
    o.regime = ww.regime[s];
    o.force_y = F.y();
    o.force_z = F.z();
    o.force = {F.x(), -sigma * F.y(), F.z(), F.y()};
    o.y_over_q = std::abs(o.force.Q) > 0.0 ? o.force.Y / o.force.Q : 0.0;
    o.lift = false;
    o.wheel_lift = ew.lift;
    o.derailed = std::abs(ew.lift) > ww.contact->elastic->derailment_lift;
    o.rail_mass_y = ew.rail_q[0];
    o.rail_mass_z = ew.rail_q[1];
    o.support_force_y = ew.support_force[0];
    o.support_force_z = ew.support_force[1];
  }
}

}  // namespace rb::dynamics::internal
