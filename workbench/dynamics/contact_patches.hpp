#pragma once
// Stage 5 of a ContactVehicleOde evaluation (contact_stages.hpp): the contact patches of a
// wheelset, their generalised force directions, creepages and Hertz data, and the generalised
// directions N of the normal-force multipliers. Compiled per contact method and creep law (the
// registry creep_laws.hpp; no per-patch branch on the law). Internal to workbench/dynamics.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "workbench/creep/creepages.hpp"
#include "workbench/creep/hertz.hpp"
#include "workbench/creep/polach.hpp"
#include "workbench/dynamics/contact_stages.hpp"
#include "workbench/dynamics/creep_laws.hpp"
#include "workbench/vehicle/kinematics.hpp"

namespace rb::dynamics::internal {

inline constexpr double kSplitWeight = 1e-9;  // KEC weights closer to 0 or 1: no split

// Rotation about X by the cross-level angle delta of the rail irregularity (Eq. 5).
// (c, s) = cos, sin of delta, taken once per wheelset and evaluation.
inline Eigen::Vector3d rotX(double c, double s, double ny, double nz) {
  return {0.0, c * ny - s * nz, s * ny + c * nz};
}

// Where a patch is and what its curvatures are (from the KEC or LUT table).
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

inline WheelsetFrame wheelsetFrame(const vehicle::BodyKinematics& kin,
                                   const vehicle::Vector6d& qd) {
  WheelsetFrame f;
  f.kin = &kin;
  f.axle = kin.attach.A.col(1);
  f.BG.noalias() = kin.body.A * kin.body.G;
  f.omega.noalias() = kin.body.A * kin.omega_b;
  // cos, sin of the yaw: the first column of A_wI = Rz(psi) Rx(phi) is (cos psi, sin psi, 0).
  f.cps = kin.attach.A(0, 0);
  f.sps = kin.attach.A(1, 0);
  f.spin_rate = qd[vehicle::kPitch];
  return f;
}

// Generalised force (y, z, phi, theta, psi) of a force F (track comps) on the wheel material point
// at au (track comps, relative to the CoM): L_P^T F of the attachment point plus the spin column
// (axle x au) . F. (J_P = pointJacobian + the spin column, never formed.)
// Always inlined: whether GCC inlines it otherwise depends on how many creep laws the translation
// unit instantiates, and adding a law must not change the code of the others (creep_laws.hpp).
[[gnu::always_inline]] inline Vec5 wheelPointForce(const WheelsetFrame& f,
                                                   const Eigen::Vector3d& au,
                                                   const Eigen::Vector3d& sp,
                                                   const Eigen::Vector3d& F) {
  const vehicle::BodyKinematics& k = *f.kin;
  const Eigen::Vector3d rot = k.AG.transpose() * au.cross(F);
  Vec5 g;
  g << F.y(), F.z(), rot(0), rot(1) + sp.dot(F), rot(2);
  return g;
}

// Relative curvatures, Hertz shape and load-independent patch constants of a patch, recomputed
// only when its curvatures change.
inline void updatePatchConstants(Patch& p, const PatchGeometry& g, const ContactModel& c) {
  if (p.k_key[0] == g.k_w_long && p.k_key[1] == g.k_w_trans && p.k_key[2] == g.k_r_trans) return;
  p.k = creep::relativeCurvatures(g.k_w_long, g.k_w_trans, 0.0, g.k_r_trans);
  p.k.A = std::max(p.k.A, c.min_relative_curvature);
  p.k.B = std::max(p.k.B, c.min_relative_curvature);
  p.shape = c.hertz_shapes->shape(p.k.A, p.k.B);
  p.pc = creep::patchConstants(c.material, p.k, p.shape);
  p.k_key[0] = g.k_w_long;
  p.k_key[1] = g.k_w_trans;
  p.k_key[2] = g.k_r_trans;
}

// Where a patch is: active, on the flange side of the profile's tread/flange split or not, its
// profile parameters, contact angle and rolling radius (every contact method).
[[gnu::always_inline]] inline void placePatch(Patch& p, double s_w, double s_r, double gamma,
                                              double radius, double sigma, const ContactModel& c) {
  p.active = true;
  p.on_flange = sigma * s_w < sigma * c.flange_boundary[sigma > 0 ? 0 : 1];
  p.s_w = s_w;
  p.s_r = s_r;
  p.gamma = gamma;
  p.radius = radius;
}

// Kinematics of a patch: generalised directions, creepages, Hertz shape.
template <class Law>
void setupPatch(Patch& p, const PatchGeometry& g, double sigma, const ContactModel& c,
                const WheelsetFrame& f, double V) {
  placePatch(p, g.s_w, g.s_r, g.gamma, g.radius, sigma, c);
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
    updatePatchConstants(p, g, c);
  }
}

// Patches of a wheelset before its contact method fills them: inactive, no normal force.
inline void resetPatches(WheelsetWork& ww) {
  ww.N.setZero();
  ww.q_flange.setZero();
  for (int s = 0; s < 2; ++s) {
    ww.patch[s][0].active = ww.patch[s][1].active = false;
    ww.patch[s][0].q0 = ww.patch[s][1].q0 = 0.0;
    ww.patch[s][0].ql.setZero();
    ww.patch[s][1].ql.setZero();
    ww.regime[s] = 0;
    ww.weight[s] = 0.0;
    ww.fl_delta[s] = ww.fl_force[s] = 0.0;
  }
}

// ---- KEC ---------------------------------------------------------------------------------------

inline PatchGeometry fromPoint(const contact::ContactPoint& cp, double cd, double sd) {
  return {cp.s_w,           cp.s_r,          cp.gamma,        cp.radius,
          cp.k_wheel_trans, cp.k_wheel_long, cp.k_rail_trans, rotX(cd, sd, cp.n_y, cp.n_z)};
}

// The real contact point (s_w, s_r) of a transition band end (A: ab = 0, B: ab = 1), described
// anew only when it changes.
inline const contact::ContactPoint& describedPoint(const ContactModel& c, WheelsetWork& ww,
                                                   int side, int ab, double s_w, double s_r) {
  DescribedPoint& d = ww.described[side][ab];
  if (!(d.s_w == s_w && d.s_r == s_r)) {
    d.point = c.solver->describe(sideOf(side), contact::WheelsetPose{}, 0.0, s_w, s_r);
    d.s_w = s_w;
    d.s_r = s_r;
  }
  return d.point;
}

// One wheel with the KEC (Eq. 23): the real contact point at the knife s_k; in the regularised
// tread-flange band the normal force at C is split into (1 - w) at A and w at B (Eq. 26).
template <class Law>
void kecWheelPatches(const ContactModel& c, const WheelsetFrame& wf, double V, int side,
                     WheelsetWork& ww) {
  using contact::KecQuantity;
  const double sigma = contact::kSideSign[side];
  contact::KecPoint kp;
  c.kec->evalValues(sideOf(side), side == 0 ? ww.kec.s_lk : ww.kec.s_rk, kp);
  const auto val = [&kp](KecQuantity q) { return kp.value[static_cast<std::size_t>(q)]; };
  const double weight = std::clamp(val(KecQuantity::Weight), 0.0, 1.0);
  const Eigen::Vector2d e_side = side == 0 ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(0, 1);
  Patch(&patch)[2] = ww.patch[side];
  if (weight > kSplitWeight && weight < 1.0 - kSplitWeight) {
    const contact::ContactPoint& pa =
        describedPoint(c, ww, side, 0, val(KecQuantity::SwA), val(KecQuantity::SrA));
    const contact::ContactPoint& pb =
        describedPoint(c, ww, side, 1, val(KecQuantity::SwB), val(KecQuantity::SrB));
    setupPatch<Law>(patch[0], fromPoint(pa, ww.cos_irr, ww.sin_irr), sigma, c, wf, V);
    setupPatch<Law>(patch[1], fromPoint(pb, ww.cos_irr, ww.sin_irr), sigma, c, wf, V);
    patch[0].ql = (1.0 - weight) * e_side;
    patch[1].ql = weight * e_side;
    ww.weight[side] = weight;
  } else {
    const double gamma = val(KecQuantity::Gamma);
    const PatchGeometry g{val(KecQuantity::Sw),
                          val(KecQuantity::Sr),
                          gamma,
                          val(KecQuantity::Radius),
                          val(KecQuantity::KwTrans),
                          val(KecQuantity::KwLong),
                          val(KecQuantity::KrTrans),
                          rotX(ww.cos_irr, ww.sin_irr, -sigma * std::sin(gamma), std::cos(gamma))};
    setupPatch<Law>(patch[0], g, sigma, c, wf, V);
    patch[0].ql = e_side;
  }
  // Eq. (25): the generalised direction of the wheel's normal force.
  for (int p = 0; p < 2; ++p)
    if (patch[p].active) ww.N.col(side) += patch[p].ql(side) * patch[p].gn;
}

// ---- LUT ---------------------------------------------------------------------------------------

// A tread patch of one wheel from the LUT (Eq. 17-18) in slot `slot`: tread = the wheel's
// kTreadQuantities tread values (TreadQuantity order) from the table's interpolant, or from one
// branch of a contact-point jump (LutTreadBranches).
template <class Law>
void lutTreadPatch(const ContactModel& c, const WheelsetFrame& wf, double V, int side, int slot,
                   const double* tread, WheelsetWork& ww) {
  using contact::TreadQuantity;
  const double sigma = contact::kSideSign[side];
  const auto value = [tread](TreadQuantity q) { return tread[static_cast<std::size_t>(q)]; };
  const double gamma = value(TreadQuantity::Gamma);
  const PatchGeometry g{value(TreadQuantity::Sw),
                        value(TreadQuantity::Sr),
                        gamma,
                        value(TreadQuantity::Radius),
                        value(TreadQuantity::KwTrans),
                        value(TreadQuantity::KwLong),
                        value(TreadQuantity::KrTrans),
                        rotX(ww.cos_irr, ww.sin_irr, -sigma * std::sin(gamma), std::cos(gamma))};
  setupPatch<Law>(ww.patch[side][slot], g, sigma, c, wf, V);
}

// The tread patches of one wheel. Away from a contact-point jump, the one tread contact of the
// interpolated table. In a table cell that holds a jump of this wheel's contact point, the
// interpolant's point is on neither branch of Eq. (12) (LutTable::treadBranches): the wheel then
// has a tread patch on each branch, slot 0 the one nearer the centred wheelset and slot 1 the
// other, whose normal forces lutNormalMap splits so that together they are the constraint
// reaction -C_q^T lambda (Eq. 19), as the KEC splits its band (Eq. 26). Slot 1 is the Hertz
// flange's when the flange indents (lutFlangePatch, called first): the wheel keeps the one
// interpolated point then.
template <class Law>
void lutTreadPatches(const ContactModel& c, const WheelsetFrame& wf, double V, int side,
                     WheelsetWork& ww) {
  const contact::LutTreadBranches& br = ww.lut_branches[side];
  const bool split = br.split && !ww.patch[side][1].active;
  ww.lut_split[side] = split;
  if (!split) {
    const double* tread =
        &ww.lut.value[contact::lutChannel(sideOf(side), contact::TreadQuantity::Sw)];
    lutTreadPatch<Law>(c, wf, V, side, 0, tread, ww);
    return;
  }
  lutTreadPatch<Law>(c, wf, V, side, 0, br.value[0].data(), ww);
  lutTreadPatch<Law>(c, wf, V, side, 1, br.value[1].data(), ww);
}

// The Hertz flange contact of one wheel (Eq. 20-21) when its indentation is positive: the applied
// force f = max(0, K delta^1.5 + D delta_dot delta), its generalised force Q_fla and the flange
// patch (normal force f, not a multiplier).
template <class Law>
void lutFlangePatch(const ContactModel& c, const WheelsetFrame& wf, double V, int side,
                    WheelsetWork& ww) {
  using contact::FlangeQuantity;
  const contact::Side sd = sideOf(side);
  const double sigma = contact::kSideSign[side];
  const auto flange = [&](FlangeQuantity q) { return flangeValue(ww.lut, sd, q); };
  const double delta = flange(FlangeQuantity::Delta);
  ww.fl_delta[side] = delta;
  if (!(delta > 0.0)) return;
  readFlangeContact(*c.lut, ww.lut_ybar, ww.lut_xig, sd, ww.lut);
  const double ny = flange(FlangeQuantity::Ny), nz = flange(FlangeQuantity::Nz);
  const double dphi = flange(FlangeQuantity::DdeltaDphi);
  // Eq. (21): indentation rate from the partial derivatives (envelope theorem), in the
  // coordinates relative to the irregular rails (Eq. 18); d delta / d xi_g = -sigma ny/2.
  const double delta_dot =
      ny * ww.ybar_dot + nz * ww.zbar_dot + dphi * ww.phibar_dot - 0.5 * sigma * ny * ww.xig_dot;
  const double f = std::max(
      0.0, c.flange_stiffness * delta * std::sqrt(delta) + c.flange_damping * delta_dot * delta);
  ww.fl_force[side] = f;
  // Eq. (20): Q_fla = -(d delta / d q)^T f (the force pushes the wheel out of the rail).
  ww.q_flange(0) -= f * ny;
  ww.q_flange(1) -= f * nz;
  ww.q_flange(2) -= f * dphi;
  const double gamma = flange(FlangeQuantity::Gamma);
  const PatchGeometry g{flange(FlangeQuantity::Sw),
                        flange(FlangeQuantity::Sr),
                        gamma,
                        flange(FlangeQuantity::Radius),
                        flange(FlangeQuantity::KwTrans),
                        flange(FlangeQuantity::KwLong),
                        flange(FlangeQuantity::KrTrans),
                        rotX(ww.cos_irr, ww.sin_irr, -ny, -nz)};
  Patch& patch = ww.patch[side][1];
  setupPatch<Law>(patch, g, sigma, c, wf, V);
  patch.on_flange = true;  // the flange window of the LUT (Eq. 15)
  patch.q0 = f;
}

// ---- The stage ---------------------------------------------------------------------------------

// 5. Patches of wheelset ww and the generalised directions N of its normal-force multipliers.
template <ContactMethod kMethod, class Law>
int contactPatches(const ContactModels& models, const StageInput& in, WheelsetWork& ww,
                   ContactWorkspace& work) {
  const ContactModel& c = *ww.contact;
  const WheelsetFrame wf = wheelsetFrame(work.bodies.kin[ww.body], work.bodies.qd[ww.body]);
  resetPatches(ww);
  if constexpr (kMethod == ContactMethod::Kec) {
    for (int side = 0; side < 2; ++side) kecWheelPatches<Law>(c, wf, in.speed, side, ww);
  } else {
    for (int side = 0; side < 2; ++side) {
      lutFlangePatch<Law>(c, wf, in.speed, side, ww);
      lutTreadPatches<Law>(c, wf, in.speed, side, ww);
    }
    if (const int rc = lutNormalMap(models, in, ww, work); rc != 0) return rc;
  }
  return 0;
}

// Contact regime of each wheel (ContactRegime).
inline void classifyRegimes(WheelsetWork& ww) {
  for (int s = 0; s < 2; ++s) {
    bool tread = false, flange = false;
    for (const Patch& p : ww.patch[s])
      if (p.active) (p.on_flange ? flange : tread) = true;
    ww.regime[s] = contactRegime(tread, flange);
  }
}

}  // namespace rb::dynamics::internal
