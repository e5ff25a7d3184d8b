#include "workbench/vehicle/kinematics.hpp"

#include <cmath>

namespace rb::vehicle {

namespace {
// Elementary rotations from a precomputed cosine and sine (each angle's sincos is taken once per
// evaluation and shared by the rotation, G and, for wheelsets, the intermediate frame).
Eigen::Matrix3d rx(double c, double s) {
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, c, -s, 0, s, c;
  return m;
}
Eigen::Matrix3d ry(double c, double s) {
  Eigen::Matrix3d m;
  m << c, 0, s, 0, 1, 0, -s, 0, c;
  return m;
}
Eigen::Matrix3d rz(double c, double s) {
  Eigen::Matrix3d m;
  m << c, -s, 0, s, c, 0, 0, 0, 1;
  return m;
}

struct AngleTrig {
  double cph, sph, cth, sth, cps, sps;
  explicit AngleTrig(const Eigen::Vector3d& a)
      : cph(std::cos(a[0])),
        sph(std::sin(a[0])),
        cth(std::cos(a[1])),
        sth(std::sin(a[1])),
        cps(std::cos(a[2])),
        sps(std::sin(a[2])) {}
};

// Intermediate frame wI = Rz(psi) Rx(phi) of a wheelset; omega_wI = (dph, sph dps, cph dps).
void intermediateFrom(const AngleTrig& t, const Eigen::Vector3d& rates, EulerKinematics& k) {
  const double dph = rates[0], dps = rates[2];
  k.A = rz(t.cps, t.sps) * rx(t.cph, t.sph);
  k.G << 1, 0, 0, 0, 0, t.sph, 0, 0, t.cph;
  k.Gdot_rates << 0.0, t.cph * dph * dps, -t.sph * dph * dps;
}

// `inter` (YawRollPitch only): the intermediate frame Rz(psi) Rx(phi), already evaluated.
void eulerFrom(RotationSequence seq, const AngleTrig& t, const Eigen::Vector3d& rates,
               const EulerKinematics* inter, EulerKinematics& k) {
  const double dph = rates[0], dth = rates[1], dps = rates[2];
  const double cph = t.cph, sph = t.sph, cth = t.cth, sth = t.sth;
  if (seq == RotationSequence::YawPitchRoll) {
    // omega_b = (dph - dps sth, dth cph + dps cth sph, -dth sph + dps cth cph)
    k.A = rz(t.cps, t.sps) * ry(cth, sth) * rx(cph, sph);
    k.G << 1, 0, -sth, 0, cph, cth * sph, 0, -sph, cth * cph;
    k.Gdot_rates << -dps * dth * cth, -dth * dph * sph + dps * (-dth * sth * sph + dph * cth * cph),
        -dth * dph * cph + dps * (-dth * sth * cph - dph * cth * sph);
  } else {
    // omega_b = (cth dph - sth cph dps, dth + sph dps, sth dph + cth cph dps)
    if (inter)
      k.A = inter->A * ry(cth, sth);
    else
      k.A = rz(t.cps, t.sps) * rx(cph, sph) * ry(cth, sth);
    k.G << cth, 0, -sth * cph, 0, 1, sph, sth, 0, cth * cph;
    k.Gdot_rates << -sth * dth * dph - (cth * dth * cph - sth * sph * dph) * dps, cph * dph * dps,
        cth * dth * dph + (-sth * dth * cph - cth * sph * dph) * dps;
  }
}
}  // namespace

EulerKinematics eulerKinematics(RotationSequence seq, const Eigen::Vector3d& angles,
                                const Eigen::Vector3d& rates) {
  EulerKinematics k;
  eulerFrom(seq, AngleTrig(angles), rates, nullptr, k);
  return k;
}

EulerKinematics intermediateKinematics(const Eigen::Vector3d& angles,
                                       const Eigen::Vector3d& rates) {
  EulerKinematics k;
  intermediateFrom(AngleTrig(angles), rates, k);
  return k;
}

void bodyKinematics(const track::TrackGeometry& geometry, RotationSequence seq, double height,
                    const Vector6d& q, const Vector6d& qd, BodyKinematics& out) {
  if (!(out.tf_key == q[kS] && out.tf_geometry == &geometry)) {
    out.tf = geometry.at(q[kS]);
    out.tf_key = q[kS];
    out.tf_geometry = &geometry;
    ++out.tf_version;
  }
  const Eigen::Vector3d& w = out.tf.w;
  const Eigen::Vector3d& w_s = out.tf.w_s;
  const double sd = qd[kS];
  const Eigen::Vector3d angles = q.segment<3>(kRoll);
  const Eigen::Vector3d rates = qd.segment<3>(kRoll);
  out.rbar = Eigen::Vector3d(0.0, q[kY], height + q[kZ]);
  const AngleTrig trig(angles);
  if (seq == RotationSequence::YawRollPitch) {
    intermediateFrom(trig, rates, out.attach);
    eulerFrom(seq, trig, rates, &out.attach, out.body);
  } else {
    eulerFrom(seq, trig, rates, nullptr, out.body);
    out.attach = out.body;
  }
  const Eigen::Vector3d rbar_dot(0.0, qd[kY], qd[kZ]);
  out.rbar_dot = rbar_dot;
  out.sd = sd;
  out.AG.noalias() = out.attach.A * out.attach.G;
  out.omega_rel.noalias() = out.AG * rates;

  // Translation: v = (e_x + w x rbar) sdot + rbar_dot (track comps).
  out.Lv.setZero();
  out.Lv.col(kS) = Eigen::Vector3d::UnitX() + w.cross(out.rbar);
  out.Lv(1, kY) = 1.0;
  out.Lv(2, kZ) = 1.0;
  out.v = out.Lv.col(kS) * sd + rbar_dot;
  out.omega_att = w * sd + out.omega_rel;
  out.gamma_v = sd * sd * w_s.cross(out.rbar) + sd * w.cross(rbar_dot) + sd * w.cross(out.v);

  // Rotation: omega_b = Abar^T w sdot + G alpha_dot (body comps).
  const Eigen::Vector3d wb = out.body.A.transpose() * w;
  const Eigen::Vector3d omega_rel = out.body.G * rates;
  out.Lw.setZero();
  out.Lw.col(kS) = wb;
  out.Lw.block<3, 3>(0, kRoll) = out.body.G;
  out.omega_b = wb * sd + omega_rel;
  out.gamma_w =
      out.body.A.transpose() * w_s * (sd * sd) - omega_rel.cross(wb * sd) + out.body.Gdot_rates;
}

Eigen::Vector3d pointPosition(const BodyKinematics& k, const Eigen::Vector3d& u) {
  return k.rbar + k.attach.A * u;
}

Matrix36d pointJacobian(const BodyKinematics& k, const Eigen::Vector3d& u) {
  Matrix36d L = Matrix36d::Zero();
  const Eigen::Vector3d au = k.attach.A * u;
  L.col(kS) = Eigen::Vector3d::UnitX() + k.tf.w.cross(k.rbar + au);
  L(1, kY) = 1.0;
  L(2, kZ) = 1.0;
  // A (G alpha_dot x u) = -A skew(u) G alpha_dot = -skew(A u) (A G) alpha_dot
  for (int c = 0; c < 3; ++c) L.col(kRoll + c) = k.AG.col(c).cross(au);
  return L;
}

Matrix36d attachmentAngularJacobian(const BodyKinematics& k) {
  Matrix36d L = Matrix36d::Zero();
  L.col(kS) = k.tf.w;
  L.block<3, 3>(0, kRoll) = k.AG;
  return L;
}

}  // namespace rb::vehicle
