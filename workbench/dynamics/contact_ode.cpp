#include "workbench/dynamics/contact_ode.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "workbench/creep/creepages.hpp"
#include "workbench/creep/hertz.hpp"
#include "workbench/creep/polach.hpp"
#include "workbench/dynamics/augmented.hpp"
#include "workbench/vehicle/kinematics.hpp"

namespace rb::dynamics {

namespace {

using Vec5 = Eigen::Matrix<double, 5, 1>;
using Vec7 = Eigen::Matrix<double, 7, 1>;
using vehicle::kPitch;
using vehicle::kRoll;
using vehicle::kS;
using vehicle::kY;
using vehicle::kYaw;
using vehicle::kZ;

constexpr const char* kCoordName[5] = {"y", "z", "phi", "theta", "psi"};
constexpr const char* kWsCoordName[3] = {"y", "theta", "psi"};
constexpr int kWsCoord[3] = {kY, kPitch, kYaw};  // wheelset state c -> body coordinate
constexpr double kPitchLimit = 1.2;              // [rad] Euler-angle guard of free bodies
constexpr double kSplitWeight = 1e-9;            // KEC weights closer to 0 or 1: no split

// Tangential force laws, chosen once per model (template parameter of the evaluation).
struct PolachLaw {
  static constexpr bool kCreep = true;
  static void apply(const ContactModel& m, const creep::ContactPatch& p, const creep::Creepages& c,
                    double& fx, double& fy, double& mz) {
    const creep::CreepForce f = creep::polachForce(m.creep_params, p, c);
    fx = f.fx;
    fy = f.fy;
    mz = 0.0;
  }
};
struct KalkerLaw {
  static constexpr bool kCreep = true;
  static void apply(const ContactModel& m, const creep::ContactPatch& p, const creep::Creepages& c,
                    double& fx, double& fy, double& mz) {
    const creep::LinearCreepForce f = creep::kalkerLinearForce(m.creep_params.G, p, c);
    fx = f.fx;
    fy = f.fy;
    mz = f.mz;
  }
};
struct NoCreep {
  static constexpr bool kCreep = false;
  static void apply(const ContactModel&, const creep::ContactPatch&, const creep::Creepages&,
                    double& fx, double& fy, double& mz) {
    fx = fy = mz = 0.0;
  }
};

// Rotation about X by the cross-level angle delta of the rail irregularity (Eq. 5).
// (c, s) = cos, sin of delta, taken once per wheelset and evaluation.
Eigen::Vector3d rotX(double c, double s, double ny, double nz) {
  return {0.0, c * ny - s * nz, s * ny + c * nz};
}

}  // namespace

namespace internal {

// One contact patch of a wheel during an evaluation.
struct Patch {
  bool active = false;
  bool on_flange = false;  // wheel point in the flange window
  double q0 = 0.0;         // normal force Q = q0 + ql . lambda
  Eigen::Vector2d ql = Eigen::Vector2d::Zero();
  double s_w = 0.0, s_r = 0.0, gamma = 0.0, radius = 0.0;
  Eigen::Vector3d n = Eigen::Vector3d::UnitZ();   // rail normal into the wheel (track comps)
  Eigen::Vector3d ex = Eigen::Vector3d::UnitX();  // rolling direction (wheel x, yawed)
  Eigen::Vector3d ey = Eigen::Vector3d::UnitY();  // lateral tangent n x e_x
  Vec5 gn = Vec5::Zero();  // generalised direction of a unit normal force (y, z, phi, theta, psi)
  Vec5 gx = Vec5::Zero(), gy = Vec5::Zero(), gm = Vec5::Zero();  // creep fx, fy, spin moment
  creep::Creepages cr;
  creep::RelativeCurvatures k;
  creep::HertzShape shape;
  creep::PatchConstants pc;  // load-independent patch data, once per setupPatch (not per Q)
  // The curvatures (wheel long., wheel trans., rail trans.) k, shape and pc were computed from;
  // k, shape, pc are functions of them alone (the KEC transition-band points repeat them).
  double k_key[3] = {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0};
  double Q = 0.0, fx = 0.0, fy = 0.0, mz = 0.0, a = 0.0, b = 0.0;
};

}  // namespace internal
using internal::Patch;

struct ContactVehicleOde::WheelsetWork {
  int body = 0;
  double height = 0.0;  // nominal centre height h (body z = contact z - h)
  // Contact constraints at this evaluation.
  contact::KecSolution kec;
  bool kec_warm = false;
  contact::LutSample lut;
  double delta_irr = 0.0;               // cross-level angle of the irregular rails [rad]
  double cos_irr = 1.0, sin_irr = 0.0;  // its cosine and sine
  // Irregularities at s = irr_key (the stages of a step at one time share them).
  track::IrregularityPoint irr;
  double irr_key = std::numeric_limits<double>::quiet_NaN();
  double ybar_dot = 0.0, xig_dot = 0.0, zbar_dot = 0.0, phibar_dot = 0.0;  // LUT rates
  double lut_ybar = 0.0, lut_xig = 0.0;                                    // the LUT entry of `lut`
  // KEC transition bands: the real contact points A, B [side][0 A, 1 B] of the last describe()
  // and its inputs. Inside one transition A and B are the fixed end points of the band (the
  // table's Hermite data of SwA ... SrB are constant there), so successive evaluations mostly ask
  // for the same points again; equal inputs give equal outputs, so the reuse changes nothing.
  struct Described {
    double s_w = std::numeric_limits<double>::quiet_NaN(), s_r = 0.0;
    contact::ContactPoint p;
  };
  Described described[2][2];
  Eigen::Matrix<double, 2, 5> G = Eigen::Matrix<double, 2, 5>::Zero();
  Eigen::Vector2d gamma = Eigen::Vector2d::Zero();
  // Patches [side][0 tread / A, 1 flange / B] and per-wheel data.
  Patch patch[2][2];
  int regime[2] = {0, 0};
  double weight[2] = {0.0, 0.0};
  double fl_delta[2] = {0.0, 0.0}, fl_force[2] = {0.0, 0.0};
  Vec5 q_flange = Vec5::Zero();  // LUT: generalised Hertz flange forces (Eq. 20)
  Eigen::Matrix<double, 5, 2> N = Eigen::Matrix<double, 5, 2>::Zero();
  // Normal-force multipliers: the last solution and the memory of the Lagged coupling.
  Eigen::Vector2d lambda = Eigen::Vector2d::Zero();
  Eigen::Vector2d lambda_prev = Eigen::Vector2d::Zero();
  bool has_prev = false;
};

ContactLayout contactLayout(const vehicle::VehicleModel& m, WheelsetSpin spin) {
  ContactLayout l;
  l.ws_dof = spin == WheelsetSpin::Prescribed ? 2 : 3;
  l.slot.assign(m.bodies.size(), -1);
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const vehicle::BodyKind k = m.bodies[b].kind;
    if (k == vehicle::BodyKind::CarBody || k == vehicle::BodyKind::Bogie) {
      l.slot[b] = static_cast<int>(l.free_bodies.size());
      l.free_bodies.push_back(static_cast<int>(b));
    } else if (k == vehicle::BodyKind::Wheelset) {
      l.slot[b] = static_cast<int>(l.wheelsets.size());
      l.wheelsets.push_back(static_cast<int>(b));
    }
  }
  l.n_free = static_cast<int>(l.free_bodies.size());
  l.n_ws = static_cast<int>(l.wheelsets.size());
  l.n_series = static_cast<int>(m.series_dampers.size());
  l.size = 10 * l.n_free + 2 * l.ws_dof * l.n_ws + l.n_series;
  return l;
}

ContactVehicleOde::ContactVehicleOde(const vehicle::VehicleModel& vehicle,
                                     const ContactModel& contact, const track::TrackModel& track)
    : vehicle_(&vehicle),
      contact_(&contact),
      layout_(contactLayout(vehicle, contact.spin)),
      ws_(vehicle::makeWorkspace(vehicle)) {
  RB_CHECK(layout_.n_ws > 0, "ContactVehicleOde: the vehicle has no wheelset");
  RB_CHECK(contact.method == ContactMethod::Kec ? contact.kec != nullptr : contact.lut != nullptr,
           "ContactVehicleOde: the contact model has no table for its method");
  if (track.irregularities()) irr_ = &*track.irregularities();
  scratch_.assign(static_cast<std::size_t>(layout_.size), 0.0);
  work_.resize(static_cast<std::size_t>(layout_.n_ws));
  out_.resize(2 * static_cast<std::size_t>(layout_.n_ws));
  qdd_.assign(vehicle.bodies.size(), vehicle::Vector6d::Zero());
  for (int w = 0; w < layout_.n_ws; ++w) {
    WheelsetWork& W = work_[static_cast<std::size_t>(w)];
    W.body = layout_.wheelsets[static_cast<std::size_t>(w)];
    W.height = vehicle.bodies[static_cast<std::size_t>(W.body)].height;
  }
  const bool kec = contact.method == ContactMethod::Kec;
  switch (contact.creep) {
    case CreepModel::Polach:
      eval_ = kec ? &ContactVehicleOde::evaluateT<ContactMethod::Kec, PolachLaw>
                  : &ContactVehicleOde::evaluateT<ContactMethod::Lut, PolachLaw>;
      break;
    case CreepModel::Kalker:
      eval_ = kec ? &ContactVehicleOde::evaluateT<ContactMethod::Kec, KalkerLaw>
                  : &ContactVehicleOde::evaluateT<ContactMethod::Lut, KalkerLaw>;
      break;
    case CreepModel::None:
      eval_ = kec ? &ContactVehicleOde::evaluateT<ContactMethod::Kec, NoCreep>
                  : &ContactVehicleOde::evaluateT<ContactMethod::Lut, NoCreep>;
      break;
  }
}

ContactVehicleOde::~ContactVehicleOde() = default;
ContactVehicleOde::ContactVehicleOde(ContactVehicleOde&&) noexcept = default;

int ContactVehicleOde::rhs(double t, const double* y, double* ydot) {
  return (this->*eval_)(t, y, ydot, Mode::Rhs);
}

int ContactVehicleOde::evaluate(double t, const double* y, double* ydot, Mode mode) {
  return (this->*eval_)(t, y, ydot, mode);
}

// ---- Coordinates: independent from the state, dependent from the constraints -------------------

int ContactVehicleOde::setCoordinates(double t, const double* y) {
  const vehicle::VehicleModel& m = *vehicle_;
  const ContactModel& c = *contact_;
  const ContactLayout& l = layout_;
  const double V = m.speedAt(t), acc = m.acceleration;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    vehicle::Vector6d& q = ws_.q[b];
    vehicle::Vector6d& qd = ws_.qd[b];
    q.setZero();
    qd.setZero();
    q[kS] = m.bodyS(static_cast<int>(b), t);
    qd[kS] = V;
    const vehicle::BodyKind kind = m.bodies[b].kind;
    const int k = l.slot[b];
    if (kind == vehicle::BodyKind::CarBody || kind == vehicle::BodyKind::Bogie) {
      for (int cc = 0; cc < 5; ++cc) {
        q[1 + cc] = y[l.position(k, cc)];
        qd[1 + cc] = y[l.rate(k, cc)];
      }
      if (!(std::abs(q[kPitch]) < kPitchLimit)) {
        last_error_ = "body '" + m.bodies[b].name + "': pitch angle " + std::to_string(q[kPitch]) +
                      " rad reached the Euler-angle guard at t = " + std::to_string(t) + " s";
        return 1;
      }
    }
  }
  const double lr = c.geometry.rail_lr;
  for (int w = 0; w < l.n_ws; ++w) {
    WheelsetWork& W = work_[static_cast<std::size_t>(w)];
    const auto b = static_cast<std::size_t>(W.body);
    vehicle::Vector6d& q = ws_.q[b];
    vehicle::Vector6d& qd = ws_.qd[b];
    for (int cc = 0; cc < 3; ++cc) {
      const int ip = l.wsPosition(w, cc);
      if (ip < 0) continue;
      q[kWsCoord[cc]] = y[ip];
      qd[kWsCoord[cc]] = y[l.wsRate(w, cc)];
    }
    if (!l.spinFree()) {
      // Prescribed spin: rolling at the centred radius, theta_dot = V(t) / r_c.
      const double rc = c.centredRadius();
      q[kPitch] = m.travel(t) / rc;
      qd[kPitch] = V / rc;
    }
    const double yy = q[kY], yd = qd[kY];
    if (irr_ && !(W.irr_key == q[kS])) {
      W.irr = irr_->at(q[kS]);
      W.irr_key = q[kS];
      // With the irregularities: the cross-level angle changes only with them. (Without: 0, the
      // initial values delta_irr = 0, cos 1, sin 0.)
      W.delta_irr = (W.irr.z_l - W.irr.z_r) / (2.0 * lr);
      W.cos_irr = std::cos(W.delta_irr);
      W.sin_irr = std::sin(W.delta_irr);
    }
    const track::IrregularityPoint& ip = W.irr;
    double z = 0.0, phi = 0.0, zd = 0.0, phid = 0.0;
    const auto& xi_ss = ip.xi_ss;
    const double a_ss = xi_ss[static_cast<std::size_t>(track::Channel::Alignment)];
    const double v_ss = xi_ss[static_cast<std::size_t>(track::Channel::Vertical)];
    const double g_ss = xi_ss[static_cast<std::size_t>(track::Channel::Gauge)];
    const double c_ss = xi_ss[static_cast<std::size_t>(track::Channel::CrossLevel)];
    const double V2 = V * V;
    if (c.method == ContactMethod::Kec) {
      const contact::KecInput in{yy, ip.y_l, ip.y_r, ip.z_l, ip.z_r};
      const contact::KecSolution sol = contact::solveKec(*c.kec, in, W.kec_warm ? &W.kec : nullptr);
      stats_.kec_iterations += sol.iterations;
      if (sol.status != contact::KecStatus::Ok) {
        std::ostringstream os;
        os << "wheelset '" << m.bodies[b].name << "' at t = " << t << " s (s = " << q[kS]
           << " m): KEC constraints (Eq. 22) "
           << (sol.status == contact::KecStatus::OutOfTable
                   ? "left the KEC table: s_lk = " + std::to_string(sol.s_lk * 1e3) +
                         " mm, s_rk = " + std::to_string(sol.s_rk * 1e3) + " mm (flange climb?)"
                   : "not solved (Newton did not converge, residual " +
                         std::to_string(sol.residual) + ")")
           << ", y = " << yy * 1e3 << " mm";
        last_error_ = os.str();
        W.kec_warm = false;
        return 1;
      }
      W.kec = sol;
      W.kec_warm = true;
      Eigen::Matrix<double, 5, 1> pd;
      pd << yd, V * ip.y_l_s, V * ip.y_r_s, V * ip.z_l_s, V * ip.z_r_s;
      const Eigen::Vector4d xd = sol.dx_dp * pd;
      const Eigen::Vector4d quad = contact::kecQuadraticTerm(sol, xd);
      Eigen::Vector4d pdd;  // pddot without yddot: the rails' irregularities, V^2 p'' + a p'
      pdd << V2 * (a_ss + 0.5 * g_ss) + acc * ip.y_l_s, V2 * (a_ss - 0.5 * g_ss) + acc * ip.y_r_s,
          V2 * (v_ss + 0.5 * c_ss) + acc * ip.z_l_s, V2 * (v_ss - 0.5 * c_ss) + acc * ip.z_r_s;
      z = sol.z;
      phi = sol.phi;
      zd = xd(0);
      phid = xd(1);
      W.G.setZero();
      W.G(0, 0) = -sol.dx_dp(0, 0);
      W.G(0, 1) = 1.0;
      W.G(1, 0) = -sol.dx_dp(1, 0);
      W.G(1, 2) = 1.0;
      W.gamma(0) = sol.dx_dp.row(0).tail<4>().dot(pdd) + quad(0);
      W.gamma(1) = sol.dx_dp.row(1).tail<4>().dot(pdd) + quad(1);
    } else {
      const double xa = ip.xi[static_cast<std::size_t>(track::Channel::Alignment)];
      const double xv = ip.xi[static_cast<std::size_t>(track::Channel::Vertical)];
      const double xg = ip.xi[static_cast<std::size_t>(track::Channel::Gauge)];
      const double xc = ip.xi[static_cast<std::size_t>(track::Channel::CrossLevel)];
      const auto& xs = ip.xi_s;
      const double xa_s = xs[static_cast<std::size_t>(track::Channel::Alignment)];
      const double xv_s = xs[static_cast<std::size_t>(track::Channel::Vertical)];
      const double xg_s = xs[static_cast<std::size_t>(track::Channel::Gauge)];
      const double xc_s = xs[static_cast<std::size_t>(track::Channel::CrossLevel)];
      const double ybar = yy - xa;  // Eq. (18)
      const double ybd = yd - V * xa_s, xgd = V * xg_s;
      contact::LutValue zv, pv;
      c.lut->evalZPhi(ybar, xg, zv, pv);
      // Values only (no derivatives needed) of the tread channels and the flange indentations;
      // the other flange channels of a side only when it indents (below).
      c.lut->evalValues(
          ybar, xg, W.lut, contact::lutChannel(contact::Side::Left, contact::TreadQuantity::Sw),
          contact::lutChannel(contact::Side::Left, contact::FlangeQuantity::Delta) + 1);
      c.lut->evalValues(
          ybar, xg, W.lut,
          contact::lutChannel(contact::Side::Right, contact::FlangeQuantity::Delta),
          contact::lutChannel(contact::Side::Right, contact::FlangeQuantity::Delta) + 1);
      W.lut_ybar = ybar;
      W.lut_xig = xg;
      if (!zv.inside || !W.lut.inside) {
        std::ostringstream os;
        os << "wheelset '" << m.bodies[b].name << "' at t = " << t << " s (s = " << q[kS]
           << " m): the LUT entry (y - xi_a = " << ybar * 1e3 << " mm, xi_g = " << xg * 1e3
           << " mm) left the table [" << c.lut->yGrid().min * 1e3 << ", "
           << c.lut->yGrid().max * 1e3 << "] x [" << c.lut->gaugeGrid().min * 1e3 << ", "
           << c.lut->gaugeGrid().max * 1e3 << "] mm";
        last_error_ = os.str();
        return 1;
      }
      z = zv.v + xv;
      phi = pv.v + xc / (2.0 * lr);
      W.ybar_dot = ybd;
      W.xig_dot = xgd;
      W.zbar_dot = zv.dy * ybd + zv.dxi * xgd;
      W.phibar_dot = pv.dy * ybd + pv.dxi * xgd;
      zd = W.zbar_dot + V * xv_s;
      phid = W.phibar_dot + V * xc_s / (2.0 * lr);
      W.G.setZero();
      W.G(0, 0) = -zv.dy;
      W.G(0, 1) = 1.0;
      W.G(1, 0) = -pv.dy;
      W.G(1, 2) = 1.0;
      W.gamma(0) = -zv.dy * V2 * a_ss + zv.dyy * ybd * ybd + 2.0 * zv.dyxi * ybd * xgd +
                   zv.dxixi * xgd * xgd + zv.dxi * V2 * g_ss + V2 * v_ss;
      W.gamma(1) = -pv.dy * V2 * a_ss + pv.dyy * ybd * ybd + 2.0 * pv.dyxi * ybd * xgd +
                   pv.dxixi * xgd * xgd + pv.dxi * V2 * g_ss + V2 * c_ss / (2.0 * lr);
      if (acc != 0.0) {
        // Speed ramp: d2 xi / dt2 = V^2 xi'' + a xi' (the terms above are the V^2 part).
        W.gamma(0) += acc * (-zv.dy * xa_s + zv.dxi * xg_s + xv_s);
        W.gamma(1) += acc * (-pv.dy * xa_s + pv.dxi * xg_s + xc_s / (2.0 * lr));
      }
    }
    q[kZ] = z - W.height;
    q[kRoll] = phi;
    qd[kZ] = zd;
    qd[kRoll] = phid;
  }
  return 0;
}

// ---- Patches -----------------------------------------------------------------------------------

namespace {

struct PatchGeometry {
  double s_w, s_r, gamma, radius, k_w_trans, k_w_long, k_r_trans;
  Eigen::Vector3d n;  // rail normal into the wheel, track comps
};

// Per wheelset and evaluation: what every patch of it needs from the body kinematics.
struct WheelsetFrame {
  const vehicle::BodyKinematics* kin = nullptr;
  Eigen::Vector3d axle;   // wI y axis (the spin axis), track comps: attach.A e_y
  Eigen::Matrix3d BG;     // body.A body.G: Euler rates -> wheel angular velocity (track comps)
  Eigen::Vector3d omega;  // absolute angular velocity of the wheel, track comps
  double cps = 1.0, sps = 0.0;  // cos, sin of the yaw
  double spin_rate = 0.0;       // theta_dot
};

WheelsetFrame wheelsetFrame(const vehicle::BodyKinematics& kin, const vehicle::Vector6d& qd) {
  WheelsetFrame f;
  f.kin = &kin;
  f.axle = kin.attach.A.col(1);
  f.BG.noalias() = kin.body.A * kin.body.G;
  f.omega.noalias() = kin.body.A * kin.omega_b;
  // cos, sin of the yaw: the first column of A_wI = Rz(psi) Rx(phi) is (cos psi, sin psi, 0).
  f.cps = kin.attach.A(0, 0);
  f.sps = kin.attach.A(1, 0);
  f.spin_rate = qd[kPitch];
  return f;
}

// Generalised force (y, z, phi, theta, psi) of a force F (track comps) on the wheel material point
// at au (track comps, relative to the CoM): L_P^T F of the attachment point plus the spin column
// (axle x au) . F. (J_P = pointJacobian + the spin column, never formed.)
Vec5 wheelPointForce(const WheelsetFrame& f, const Eigen::Vector3d& au, const Eigen::Vector3d& sp,
                     const Eigen::Vector3d& F) {
  const vehicle::BodyKinematics& k = *f.kin;
  const Eigen::Vector3d rot = k.AG.transpose() * au.cross(F);
  Vec5 g;
  g << F.y(), F.z(), rot(0), rot(1) + sp.dot(F), rot(2);
  return g;
}

// Kinematics of a patch: generalised directions, creepages, Hertz shape.
template <class Law>
void setupPatch(Patch& p, const PatchGeometry& g, double sigma, const ContactModel& c,
                const WheelsetFrame& f, double V) {
  p.active = true;
  p.on_flange = sigma * g.s_w < sigma * c.flange_boundary[sigma > 0 ? 0 : 1];
  p.s_w = g.s_w;
  p.s_r = g.s_r;
  p.gamma = g.gamma;
  p.radius = g.radius;
  // The planar contact (section 2.2) neglects the yaw for the contact location: the contact
  // picture (normal and contact frame) is the planar one, carried along by the wheelset yaw psi.
  // Rotated with the yaw the normal stays normal to the wheel surface (perpendicular to the
  // wheel's circumferential direction), so the normal force does no work on yaw and spin, as the
  // yaw-independent constraints (Eq. 17, 22) require; the contact frame's x is the wheel's
  // rolling direction.
  const double cps = f.cps, sps = f.sps;
  p.n = Eigen::Vector3d(-sps * g.n.y(), cps * g.n.y(), g.n.z());
  // Wheel material point at the contact: in the wheelset intermediate frame (Eq. 10, s_w2 =
  // pi/2) u = (0, sigma Lw + s_w, -r); its velocity includes the spin about the wI y axis,
  // sp theta_dot with sp = A_wI (e_y x u) = axle x au.
  const Eigen::Vector3d u(0.0, sigma * c.geometry.wheel_lw + g.s_w, -g.radius);
  const Eigen::Vector3d au = f.kin->attach.A * u;
  const Eigen::Vector3d sp = f.axle.cross(au);
  p.gn = wheelPointForce(f, au, sp, p.n);
  if constexpr (Law::kCreep) {
    const Eigen::Vector3d ex(cps, sps, 0.0);
    p.ex = ex;
    p.ey = p.n.cross(ex);
    p.gx = wheelPointForce(f, au, sp, ex);
    p.gy = wheelPointForce(f, au, sp, p.ey);
    // Spin moment about n: the wheel's angular velocity Jacobian is [w, 0, 0, body.A G] (track
    // comps), so its (y..psi) part is (0, 0, (BG^T n)).
    const Eigen::Vector3d bgn = f.BG.transpose() * p.n;
    p.gm << 0.0, 0.0, bgn(0), bgn(1), bgn(2);
    const Eigen::Vector3d v =
        vehicle::pointVelocity(*f.kin, au) + sp * f.spin_rate;  // rail at rest
    p.cr = creep::creepagesFromKinematics(v.dot(ex), v.dot(p.ey), f.omega.dot(p.n), V);
    if (!(p.k_key[0] == g.k_w_long && p.k_key[1] == g.k_w_trans && p.k_key[2] == g.k_r_trans)) {
      p.k = creep::relativeCurvatures(g.k_w_long, g.k_w_trans, 0.0, g.k_r_trans);
      p.k.A = std::max(p.k.A, c.min_relative_curvature);
      p.k.B = std::max(p.k.B, c.min_relative_curvature);
      p.shape = c.hertz_shapes->shape(p.k.A, p.k.B);
      p.pc = creep::patchConstants(c.material, p.k, p.shape);
      p.k_key[0] = g.k_w_long;
      p.k_key[1] = g.k_w_trans;
      p.k_key[2] = g.k_r_trans;
    }
  }
}

// Creep forces of one patch at normal force Q; adds the generalised forces to Qt.
template <class Law>
void creepForce(Patch& p, double Q, const ContactModel& c, Vec5& Qt) {
  p.Q = Q;
  if (!(Q > 0.0)) {
    p.fx = p.fy = p.mz = p.a = p.b = 0.0;
    return;
  }
  const creep::ContactPatch cp = creep::makeContactPatch(p.pc, Q);
  Law::apply(c, cp, p.cr, p.fx, p.fy, p.mz);
  p.a = cp.a;
  p.b = cp.b;
  Qt.noalias() += p.gx * p.fx + p.gy * p.fy + p.gm * p.mz;
}

PatchGeometry fromPoint(const contact::ContactPoint& cp, double cd, double sd) {
  return {cp.s_w,           cp.s_r,          cp.gamma,        cp.radius,
          cp.k_wheel_trans, cp.k_wheel_long, cp.k_rail_trans, rotX(cd, sd, cp.n_y, cp.n_z)};
}

}  // namespace

// ---- The evaluation ----------------------------------------------------------------------------

template <ContactMethod kMethod, class Law>
int ContactVehicleOde::evaluateT(double t, const double* y, double* ydot, Mode mode) {
  ++stats_.evaluations;
  const vehicle::VehicleModel& m = *vehicle_;
  const ContactModel& c = *contact_;
  const ContactLayout& l = layout_;
  const double V = m.speedAt(t), acc = m.acceleration;
  if (const int rc = setCoordinates(t, y); rc != 0) return rc;
  vehicle::evaluate(m, l.n_series > 0 ? y + l.series(0) : nullptr, ws_);

  // Car bodies and bogies: M_pp pddot = Q_p - M_ps a (s imposed, sddot = a), as the guided model.
  for (int k = 0; k < l.n_free; ++k) {
    const auto b = static_cast<std::size_t>(l.free_bodies[static_cast<std::size_t>(k)]);
    Cholesky5 llt;
    if (!llt.factor(ws_.mass[b].block<5, 5>(1, 1))) {
      last_error_ = "body '" + m.bodies[b].name +
                    "': mass matrix not positive definite at t = " + std::to_string(t) + " s";
      return 1;
    }
    const Vec5 pdd = llt.solve(ws_.force[b].segment<5>(1) - ws_.mass[b].block<5, 1>(1, kS) * acc);
    if (mode == Mode::Output) {
      qdd_[b].setZero();
      qdd_[b](kS) = acc;
      qdd_[b].segment<5>(1) = pdd;
    }
    for (int cc = 0; cc < 5; ++cc) {
      ydot[l.position(k, cc)] = y[l.rate(k, cc)];
      ydot[l.rate(k, cc)] = pdd[cc];
    }
  }

  bool lift = false;
  const bool spin_free = l.spinFree();
  for (int w = 0; w < l.n_ws; ++w) {
    WheelsetWork& W = work_[static_cast<std::size_t>(w)];
    const auto b = static_cast<std::size_t>(W.body);
    const vehicle::BodyKinematics& kin = ws_.kin[b];
    const WheelsetFrame wf = wheelsetFrame(kin, ws_.qd[b]);
    W.N.setZero();
    W.q_flange.setZero();
    for (int s = 0; s < 2; ++s) {
      W.patch[s][0].active = W.patch[s][1].active = false;
      W.patch[s][0].q0 = W.patch[s][1].q0 = 0.0;
      W.patch[s][0].ql.setZero();
      W.patch[s][1].ql.setZero();
      W.regime[s] = 0;
      W.weight[s] = 0.0;
      W.fl_delta[s] = W.fl_force[s] = 0.0;
    }

    if constexpr (kMethod == ContactMethod::Kec) {
      // Real contact points from the KEC table (Eq. 23); in the regularised tread-flange band
      // the normal force at C is split into (1 - w) at A and w at B (Eq. 26).
      const contact::KecTable& tab = *c.kec;
      for (int s = 0; s < 2; ++s) {
        const contact::Side side = s == 0 ? contact::Side::Left : contact::Side::Right;
        const double sigma = contact::kSideSign[s];
        contact::KecPoint kp;
        tab.evalValues(side, s == 0 ? W.kec.s_lk : W.kec.s_rk, kp);
        const auto val = [&kp](contact::KecQuantity qq) {
          return kp.value[static_cast<std::size_t>(qq)];
        };
        const double wgt = std::clamp(val(contact::KecQuantity::Weight), 0.0, 1.0);
        const Eigen::Vector2d e_side = s == 0 ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(0, 1);
        if (wgt > kSplitWeight && wgt < 1.0 - kSplitWeight) {
          const auto describe = [&](int ab, double sw, double sr) -> const contact::ContactPoint& {
            WheelsetWork::Described& d = W.described[s][ab];
            if (!(d.s_w == sw && d.s_r == sr)) {
              d.p = c.solver->describe(side, contact::WheelsetPose{}, 0.0, sw, sr);
              d.s_w = sw;
              d.s_r = sr;
            }
            return d.p;
          };
          const contact::ContactPoint& pa =
              describe(0, val(contact::KecQuantity::SwA), val(contact::KecQuantity::SrA));
          const contact::ContactPoint& pb =
              describe(1, val(contact::KecQuantity::SwB), val(contact::KecQuantity::SrB));
          setupPatch<Law>(W.patch[s][0], fromPoint(pa, W.cos_irr, W.sin_irr), sigma, c, wf, V);
          setupPatch<Law>(W.patch[s][1], fromPoint(pb, W.cos_irr, W.sin_irr), sigma, c, wf, V);
          W.patch[s][0].ql = (1.0 - wgt) * e_side;
          W.patch[s][1].ql = wgt * e_side;
          W.weight[s] = wgt;
        } else {
          const double sw = val(contact::KecQuantity::Sw), gam = val(contact::KecQuantity::Gamma);
          const PatchGeometry g{sw,
                                val(contact::KecQuantity::Sr),
                                gam,
                                val(contact::KecQuantity::Radius),
                                val(contact::KecQuantity::KwTrans),
                                val(contact::KecQuantity::KwLong),
                                val(contact::KecQuantity::KrTrans),
                                rotX(W.cos_irr, W.sin_irr, -sigma * std::sin(gam), std::cos(gam))};
          setupPatch<Law>(W.patch[s][0], g, sigma, c, wf, V);
          W.patch[s][0].ql = e_side;
        }
        for (int p = 0; p < 2; ++p)
          if (W.patch[s][p].active) W.N.col(s) += W.patch[s][p].ql(s) * W.patch[s][p].gn;
      }
    } else {
      // LUT: tread contact points from the table; the flange as an applied Hertz force (Eq. 20)
      // when the indentation is positive.
      const contact::LutSample& ls = W.lut;
      Eigen::Matrix2d A;
      for (int s = 0; s < 2; ++s) {
        const contact::Side side = s == 0 ? contact::Side::Left : contact::Side::Right;
        const double sigma = contact::kSideSign[s];
        const auto tv = [&](contact::TreadQuantity qq) {
          return ls.value[contact::lutChannel(side, qq)];
        };
        const auto fv = [&](contact::FlangeQuantity qq) {
          return ls.value[contact::lutChannel(side, qq)];
        };
        const double gam = tv(contact::TreadQuantity::Gamma);
        const PatchGeometry g{tv(contact::TreadQuantity::Sw),
                              tv(contact::TreadQuantity::Sr),
                              gam,
                              tv(contact::TreadQuantity::Radius),
                              tv(contact::TreadQuantity::KwTrans),
                              tv(contact::TreadQuantity::KwLong),
                              tv(contact::TreadQuantity::KrTrans),
                              rotX(W.cos_irr, W.sin_irr, -sigma * std::sin(gam), std::cos(gam))};
        setupPatch<Law>(W.patch[s][0], g, sigma, c, wf, V);
        A(0, s) = W.patch[s][0].gn(1);  // z component of the unit normal force
        A(1, s) = W.patch[s][0].gn(2);  // roll component
        const double delta = fv(contact::FlangeQuantity::Delta);
        W.fl_delta[s] = delta;
        if (delta > 0.0) {
          c.lut->evalValues(W.lut_ybar, W.lut_xig, W.lut,
                            contact::lutChannel(side, contact::FlangeQuantity::Sw),
                            contact::lutChannel(side, contact::FlangeQuantity::DdeltaDphi) + 1);
          const double ny = fv(contact::FlangeQuantity::Ny), nz = fv(contact::FlangeQuantity::Nz);
          const double dphi = fv(contact::FlangeQuantity::DdeltaDphi);
          // Eq. (21): indentation rate from the partial derivatives (envelope theorem), in the
          // coordinates relative to the irregular rails (Eq. 18); d delta / d xi_g = -sigma ny/2.
          const double delta_dot = ny * W.ybar_dot + nz * W.zbar_dot + dphi * W.phibar_dot -
                                   0.5 * sigma * ny * W.xig_dot;
          const double f = std::max(0.0, c.flange_stiffness * delta * std::sqrt(delta) +
                                             c.flange_damping * delta_dot * delta);
          W.fl_force[s] = f;
          // Eq. (20): Q_fla = -(d delta / d q)^T f (the force pushes the wheel out of the rail).
          W.q_flange(0) -= f * ny;
          W.q_flange(1) -= f * nz;
          W.q_flange(2) -= f * dphi;
          const double fgam = fv(contact::FlangeQuantity::Gamma);
          const PatchGeometry gf{fv(contact::FlangeQuantity::Sw),
                                 fv(contact::FlangeQuantity::Sr),
                                 fgam,
                                 fv(contact::FlangeQuantity::Radius),
                                 fv(contact::FlangeQuantity::KwTrans),
                                 fv(contact::FlangeQuantity::KwLong),
                                 fv(contact::FlangeQuantity::KrTrans),
                                 rotX(W.cos_irr, W.sin_irr, -ny, -nz)};
          setupPatch<Law>(W.patch[s][1], gf, sigma, c, wf, V);
          W.patch[s][1].on_flange = true;  // the flange window of the LUT (Eq. 15)
          W.patch[s][1].q0 = f;
        }
      }
      // Eq. (16), (19): N lambda = -C_q^T lambda. The wheel normal forces N_l, N_r reproduce its
      // vertical and roll components: A (N_l, N_r) = (N lambda)_{z, phi}.
      W.N = -W.G.transpose();
      const double det = A.determinant();
      if (!(std::abs(det) > 1e-12)) {
        last_error_ = "wheelset '" + m.bodies[b].name +
                      "': the tread normal directions do not span vertical and roll at t = " +
                      std::to_string(t) + " s";
        return 1;
      }
      const Eigen::Matrix2d T = A.inverse() * W.N.block<2, 2>(1, 0);
      W.patch[0][0].ql = T.row(0).transpose();
      W.patch[1][0].ql = T.row(1).transpose();
    }

    for (int s = 0; s < 2; ++s) {
      bool tread = false, flange = false;
      for (int p = 0; p < 2; ++p) {
        if (!W.patch[s][p].active) continue;
        (W.patch[s][p].on_flange ? flange : tread) = true;
      }
      W.regime[s] = flange ? (tread ? 1 : 2) : 0;
    }

    // Augmented system [M -N; G 0] [qddot; lambda] = [Q + Q_t; gamma].
    AugmentedSolver lu;
    if (!lu.factor(ws_.mass[b].block<5, 5>(1, 1), W.N, W.G, !spin_free,
                   spin_free ? 0.0 : acc / c.centredRadius())) {
      last_error_ = "wheelset '" + m.bodies[b].name +
                    "': mass matrix not positive definite at t = " + std::to_string(t) + " s";
      return 1;
    }
    Vec7 rhs0;
    // The prescribed sddot = a enters as -M_qs a (inertia of the speed ramp).
    rhs0.head<5>() = ws_.force[b].segment<5>(1) - ws_.mass[b].block<5, 1>(1, kS) * acc + W.q_flange;
    rhs0.tail<2>() = W.gamma;
    // Prescribed spin: the spin row becomes theta_ddot = a / r_c (AugmentedSolver pins it). Its
    // reaction (the spin torque the creep forces and the constraint normal forces would exert) is
    // a constraint reaction and drops out; the other rows keep their M_{q,theta} theta_ddot
    // coupling.
    Vec7 x;
    const auto creepAt = [&](const Eigen::Vector2d& lam, Vec5& Qt) {
      Qt.setZero();
      for (int s = 0; s < 2; ++s)
        for (int p = 0; p < 2; ++p) {
          Patch& pp = W.patch[s][p];
          if (pp.active) creepForce<Law>(pp, pp.q0 + pp.ql.dot(lam), c, Qt);
        }
    };
    if constexpr (!Law::kCreep) {
      x = lu.solve(rhs0);
      W.lambda = x.tail<2>();
    } else {
      Vec5 Qt;
      Vec7 r = rhs0;
      const bool lagged = c.coupling == NormalForceCoupling::Lagged && mode != Mode::Init;
      if (lagged && W.has_prev) {
        // The normal forces of the previous evaluation (the paper: of the last time step).
        creepAt(W.lambda_prev, Qt);
        r.head<5>() += Qt;
        x = lu.solve(r);
        W.lambda = x.tail<2>();
        stats_.max_lagged_change =
            std::max(stats_.max_lagged_change, (W.lambda - W.lambda_prev).cwiseAbs().maxCoeff());
      } else {
        // Fixed-point iteration on the normal forces (from the previous ones, or from the
        // solution without tangential forces).
        Eigen::Vector2d lam;
        if (W.has_prev) {
          lam = W.lambda_prev;
        } else {
          x = lu.solve(rhs0);
          lam = x.tail<2>();
        }
        // Phi(lambda): the normal forces that the creep forces at lambda produce. Plain
        // fixed-point steps while they contract well (the usual case: the creep forces change
        // the normal forces little), Newton with a finite-difference 2x2 Jacobian otherwise
        // (large creepages with the unbounded linear Kalker law, flange contact).
        int it = 0;
        const auto phi = [&](const Eigen::Vector2d& lam_in) -> Eigen::Vector2d {
          ++it;
          creepAt(lam_in, Qt);
          r = rhs0;
          r.head<5>() += Qt;
          x = lu.solve(r);
          return x.tail<2>();
        };
        bool converged = false;
        double last_step = std::numeric_limits<double>::infinity();
        bool newton = false;
        while (it < c.consistent_max_iter) {
          const Eigen::Vector2d f0 = phi(lam) - lam;
          const double step = f0.cwiseAbs().maxCoeff();
          const double tol = c.consistent_tol * ((lam + f0).cwiseAbs().maxCoeff() + 1.0);
          if (step <= tol) {
            lam += f0;
            converged = true;
            break;
          }
          if (!newton && step > 0.5 * last_step) newton = true;
          last_step = step;
          if (!newton) {
            lam += f0;
            continue;
          }
          Eigen::Matrix2d jac;
          for (int j = 0; j < 2; ++j) {
            Eigen::Vector2d lp = lam;
            const double h = 1e-6 * (std::abs(lam(j)) + 1.0);
            lp(j) += h;
            jac.col(j) = (phi(lp) - lp - f0) / h;
          }
          Eigen::Vector2d dl = jac.partialPivLu().solve(-f0);
          if (!dl.allFinite()) dl = f0;
          lam += dl;
        }
        // Patches carry the creep forces of the converged normal forces.
        ++stats_.consistent_solves;
        stats_.consistent_iterations += it;
        stats_.consistent_max_iterations = std::max(stats_.consistent_max_iterations, it);
        if (!converged) {
          std::ostringstream os;
          os << "wheelset '" << m.bodies[b].name << "' at t = " << t
             << " s: normal and tangential forces did not converge in " << it
             << " fixed-point iterations";
          last_error_ = os.str();
          return 1;
        }
        W.lambda = lam;
      }
      if (mode != Mode::Output) {
        W.lambda_prev = W.lambda;
        W.has_prev = true;
      }
    }
    if (!x.allFinite()) {
      last_error_ = "wheelset '" + m.bodies[b].name +
                    "': singular contact equations (augmented system) at t = " + std::to_string(t) +
                    " s";
      return 1;
    }
    if (ydot) {
      for (int cc = 0; cc < 3; ++cc) {
        const int ip = l.wsPosition(w, cc);
        if (ip >= 0) ydot[ip] = y[l.wsRate(w, cc)];
      }
      ydot[l.wsRate(w, 0)] = x(0);
      if (spin_free) ydot[l.wsRate(w, 1)] = x(3);
      ydot[l.wsRate(w, 2)] = x(4);
    }
    // Wheel lift: the constraint normal force of a wheel (KEC: both patches, which share the
    // wheel's lambda, Eq. 26; LUT: the tread patch, the Hertz flange force being applied) below
    // the threshold means the constraint pulls the wheel onto the rail, which no wheel/rail pair
    // can do. The state is refused as recoverable: an adaptive method retries a smaller step, so
    // an overshooting trial step is not taken for a lift, while a real lift stops the run here.
    for (int s = 0; s < 2; ++s) {
      double qn = 0.0;
      bool any = false;
      for (int p = 0; p < (kMethod == ContactMethod::Kec ? 2 : 1); ++p) {
        const Patch& pp = W.patch[s][p];
        if (!pp.active) continue;
        any = true;
        qn += pp.q0 + pp.ql.dot(W.lambda);
      }
      if (!any || qn >= c.min_normal_force) continue;
      lift = true;
      if (mode != Mode::Output) {
        std::ostringstream os;
        os << "wheel lift: wheelset '" << m.bodies[b].name << "', " << (s == 0 ? "left" : "right")
           << " wheel: constraint normal force " << qn / 1e3
           << " kN < contact.min_normal_force = " << c.min_normal_force / 1e3 << " kN at t = " << t
           << " s (a constraint contact cannot lift a wheel: the model is not valid past this "
              "point)";
        last_error_ = os.str();
        ++stats_.lift_evaluations;
        return 1;
      }
    }
    if (mode == Mode::Output) {
      qdd_[b].setZero();
      qdd_[b](kS) = acc;
      qdd_[b].segment<5>(1) = x.head<5>();
      for (int s = 0; s < 2; ++s) {
        WheelOutput& o = out_[2 * static_cast<std::size_t>(w) + static_cast<std::size_t>(s)];
        o = WheelOutput{};
        const double sigma = contact::kSideSign[s];
        Eigen::Vector3d F = Eigen::Vector3d::Zero();
        for (int p = 0; p < 2; ++p) {
          const Patch& pp = W.patch[s][p];
          PatchOutput& po = o.patch[p];
          if (!pp.active) continue;
          po.active = true;
          po.on_flange = pp.on_flange;
          po.normal = pp.q0 + pp.ql.dot(W.lambda);
          po.s_w = pp.s_w;
          po.s_r = pp.s_r;
          po.gamma = pp.gamma;
          po.radius = pp.radius;
          if constexpr (Law::kCreep) {
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
          F += po.normal * pp.n + po.fx * pp.ex + po.fy * pp.ey;
          if (po.normal < 0.0) o.lift = true;
        }
        o.regime = W.regime[s];
        o.weight = W.weight[s];
        if constexpr (kMethod == ContactMethod::Lut) {
          o.flange_indentation = W.fl_delta[s];
          o.flange_force = W.fl_force[s];
        }
        o.force_y = F.y();
        o.force_z = F.z();
        o.y_over_q = std::abs(F.z()) > 0.0 ? -sigma * F.y() / F.z() : 0.0;
      }
    }
  }
  if (lift) ++stats_.lift_evaluations;
  if (ydot)
    for (int e = 0; e < l.n_series; ++e)
      ydot[l.series(e)] = ws_.series_rate[static_cast<std::size_t>(e)];
  return 0;
}

// ---- Names, indices ----------------------------------------------------------------------------

std::string ContactVehicleOde::componentName(int i) const {
  const ContactLayout& l = layout_;
  if (i < 0 || i >= l.size) return "y[" + std::to_string(i) + "]";
  if (l.n_series > 0 && i >= l.series(0))
    return "series[" + std::to_string(i - l.series(0)) + "].f";
  const int half = 5 * l.n_free + l.ws_dof * l.n_ws;
  const bool rate = i >= half;
  const int j = rate ? i - half : i;
  const char* suffix = rate ? "_dot" : "";
  if (j < 5 * l.n_free) {
    const int k = j / 5, cc = j % 5;
    return vehicle_->bodies[static_cast<std::size_t>(l.free_bodies[static_cast<std::size_t>(k)])]
               .name +
           "." + kCoordName[cc] + suffix;
  }
  const int jw = j - 5 * l.n_free;
  const int w = jw / l.ws_dof;
  const int cc = l.spinFree() ? jw % 3 : (jw % 2 == 0 ? 0 : 2);  // prescribed: y, psi
  return vehicle_->bodies[static_cast<std::size_t>(l.wheelsets[static_cast<std::size_t>(w)])].name +
         "." + kWsCoordName[cc] + suffix;
}

std::vector<int> ContactVehicleOde::stiffComponents() const {
  std::vector<int> out;
  if (layout_.spinFree())
    for (int w = 0; w < layout_.n_ws; ++w) out.push_back(layout_.wsRate(w, 1));
  for (int e = 0; e < layout_.n_series; ++e) out.push_back(layout_.series(e));
  return out;
}

int ContactVehicleOde::index(int body, vehicle::Coord c, bool rate) const {
  if (body < 0 || body >= static_cast<int>(layout_.slot.size()) || c == kS) return -1;
  const int k = layout_.slot[static_cast<std::size_t>(body)];
  if (k < 0) return -1;
  const vehicle::BodyKind kind = vehicle_->bodies[static_cast<std::size_t>(body)].kind;
  if (kind == vehicle::BodyKind::Wheelset) {
    for (int cc = 0; cc < 3; ++cc)
      if (kWsCoord[cc] == c)
        return rate ? layout_.wsRate(k, cc) : layout_.wsPosition(k, cc);  // -1: prescribed spin
    return -1;
  }
  return rate ? layout_.rate(k, c - 1) : layout_.position(k, c - 1);
}

int ContactVehicleOde::indexOf(const std::string& component) const {
  for (int i = 0; i < layout_.size; ++i)
    if (componentName(i) == component) return i;
  return -1;
}

// ---- Initial state -----------------------------------------------------------------------------

Eigen::VectorXd ContactVehicleOde::initialState(double t0) {
  const ContactLayout& l = layout_;
  const vehicle::VehicleModel& m = *vehicle_;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(l.size);
  const double spin = m.speedAt(t0) / contact_->centredRadius();
  if (l.spinFree())
    for (int w = 0; w < l.n_ws; ++w) y[l.wsRate(w, 1)] = spin;
  for (WheelsetWork& W : work_) {
    W.has_prev = false;
    W.kec_warm = false;
  }
  Eigen::VectorXd yd(l.size);
  const auto fail = [&](const std::string& why) {
    throw InputError(m.loc, "vehicle '" + m.name + "': initial state: " + why);
  };
  const int n = 5 * l.n_free;
  if (n > 0) {
    // Static equilibrium of the car bodies and bogies with the wheelsets centred on the rails.
    const auto residual = [&](const Eigen::VectorXd& state, Eigen::VectorXd& r) {
      if (evaluate(t0, state.data(), yd.data(), Mode::Init) != 0) fail(last_error_);
      r = yd.segment(l.rate(0, 0), n);
    };
    Eigen::VectorXd r(n), rp(n), rm(n);
    Eigen::MatrixXd J(n, n);
    residual(y, r);
    const double h = 1e-6;
    bool converged = false;
    for (int it = 0; it < 50 && !converged; ++it) {
      for (int cc = 0; cc < n; ++cc) {
        Eigen::VectorXd yp = y, ym = y;
        yp[cc] += h;
        ym[cc] -= h;
        residual(yp, rp);
        residual(ym, rm);
        J.col(cc) = (rp - rm) / (2.0 * h);
      }
      const Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
      if (lu.rank() < n) {
        std::string which;
        for (int cc = 0; cc < n; ++cc)
          if (J.col(cc).norm() < 1e-9 * J.norm()) which += " " + componentName(cc);
        fail(
            "no static equilibrium: a car body or bogie coordinate is not restrained by any "
            "suspension element" +
            (which.empty() ? std::string() : ":" + which));
      }
      const Eigen::VectorXd dx = lu.solve(r);
      double step = 1.0;
      Eigen::VectorXd y_new = y;
      const double r0 = r.norm();
      for (int ls = 0; ls < 30; ++ls) {
        y_new.head(n) = y.head(n) - step * dx;
        residual(y_new, rp);
        if (rp.norm() <= r0 || rp.norm() < 1e-12) break;
        step *= 0.5;
      }
      y = y_new;
      r = rp;
      converged =
          step * dx.lpNorm<Eigen::Infinity>() < 1e-13 || r.lpNorm<Eigen::Infinity>() < 1e-12;
    }
    if (!converged) {
      std::ostringstream os;
      os << "static equilibrium did not converge (|acceleration| = " << r.lpNorm<Eigen::Infinity>()
         << " after 50 Newton iterations)";
      fail(os.str());
    }
  }
  // Normal forces at t0 (consistent), the memory of the Lagged coupling for the first step.
  for (WheelsetWork& W : work_) W.has_prev = false;
  if (evaluate(t0, y.data(), yd.data(), Mode::Init) != 0) fail(last_error_);
  return y;
}

// ---- Outputs -----------------------------------------------------------------------------------

int ContactVehicleOde::bodyCoordinates(double t, const double* y, std::span<vehicle::Vector6d> q) {
  const int rc = setCoordinates(t, y);
  if (rc != 0) return rc;
  for (std::size_t b = 0; b < q.size() && b < ws_.q.size(); ++b) q[b] = ws_.q[b];
  return 0;
}

int ContactVehicleOde::bodyAccelerations(double t, const double* y,
                                         std::span<vehicle::Vector6d> qdd) {
  const int rc = evaluate(t, y, scratch_.data(), Mode::Output);
  if (rc != 0) return rc;
  for (std::size_t b = 0; b < qdd.size() && b < qdd_.size(); ++b) qdd[b] = qdd_[b];
  return 0;
}

int ContactVehicleOde::wheelOutputs(double t, const double* y, std::span<WheelOutput> out) {
  const int rc = evaluate(t, y, scratch_.data(), Mode::Output);
  if (rc != 0) return rc;
  for (std::size_t i = 0; i < out.size() && i < out_.size(); ++i) out[i] = out_[i];
  return 0;
}

}  // namespace rb::dynamics
