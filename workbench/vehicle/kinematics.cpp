#include "workbench/vehicle/kinematics.hpp"

#include <cmath>

namespace rb::vehicle {

namespace {
Eigen::Matrix3d rx(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, c, -s, 0, s, c;
  return m;
}
Eigen::Matrix3d ry(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  m << c, 0, s, 0, 1, 0, -s, 0, c;
  return m;
}
Eigen::Matrix3d rz(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  m << c, -s, 0, s, c, 0, 0, 0, 1;
  return m;
}
Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}
}  // namespace

EulerKinematics eulerKinematics(RotationSequence seq, const Eigen::Vector3d& angles,
                                const Eigen::Vector3d& rates) {
  const double ph = angles[0], th = angles[1], ps = angles[2];
  const double dph = rates[0], dth = rates[1], dps = rates[2];
  const double cph = std::cos(ph), sph = std::sin(ph), cth = std::cos(th), sth = std::sin(th);
  EulerKinematics k;
  if (seq == RotationSequence::YawPitchRoll) {
    // omega_b = (dph - dps sth, dth cph + dps cth sph, -dth sph + dps cth cph)
    k.A = rz(ps) * ry(th) * rx(ph);
    k.G << 1, 0, -sth, 0, cph, cth * sph, 0, -sph, cth * cph;
    k.Gdot_rates << -dps * dth * cth, -dth * dph * sph + dps * (-dth * sth * sph + dph * cth * cph),
        -dth * dph * cph + dps * (-dth * sth * cph - dph * cth * sph);
  } else {
    // omega_b = (cth dph - sth cph dps, dth + sph dps, sth dph + cth cph dps)
    k.A = rz(ps) * rx(ph) * ry(th);
    k.G << cth, 0, -sth * cph, 0, 1, sph, sth, 0, cth * cph;
    k.Gdot_rates << -sth * dth * dph - (cth * dth * cph - sth * sph * dph) * dps, cph * dph * dps,
        cth * dth * dph + (-sth * dth * cph - cth * sph * dph) * dps;
  }
  return k;
}

EulerKinematics intermediateKinematics(const Eigen::Vector3d& angles,
                                       const Eigen::Vector3d& rates) {
  const double ph = angles[0], ps = angles[2];
  const double dph = rates[0], dps = rates[2];
  const double cph = std::cos(ph), sph = std::sin(ph);
  EulerKinematics k;
  // omega_wI = (dph, sph dps, cph dps)
  k.A = rz(ps) * rx(ph);
  k.G << 1, 0, 0, 0, 0, sph, 0, 0, cph;
  k.Gdot_rates << 0.0, cph * dph * dps, -sph * dph * dps;
  return k;
}

void bodyKinematics(const track::TrackGeometry& geometry, RotationSequence seq, double height,
                    const Vector6d& q, const Vector6d& qd, BodyKinematics& out) {
  out.tf = geometry.at(q[kS]);
  const Eigen::Vector3d& w = out.tf.w;
  const Eigen::Vector3d& w_s = out.tf.w_s;
  const double sd = qd[kS];
  const Eigen::Vector3d angles = q.segment<3>(kRoll);
  const Eigen::Vector3d rates = qd.segment<3>(kRoll);
  out.rbar = Eigen::Vector3d(0.0, q[kY], height + q[kZ]);
  out.body = eulerKinematics(seq, angles, rates);
  out.attach =
      seq == RotationSequence::YawRollPitch ? intermediateKinematics(angles, rates) : out.body;
  const Eigen::Vector3d rbar_dot(0.0, qd[kY], qd[kZ]);

  // Translation: v = (e_x + w x rbar) sdot + rbar_dot (track comps).
  out.Lv.setZero();
  out.Lv.col(kS) = Eigen::Vector3d::UnitX() + w.cross(out.rbar);
  out.Lv(1, kY) = 1.0;
  out.Lv(2, kZ) = 1.0;
  out.v = out.Lv.col(kS) * sd + rbar_dot;
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
  // A (G alpha_dot x u) = -A skew(u) G alpha_dot
  L.block<3, 3>(0, kRoll) = -k.attach.A * skew(u) * k.attach.G;
  return L;
}

Matrix36d attachmentAngularJacobian(const BodyKinematics& k) {
  Matrix36d L = Matrix36d::Zero();
  L.col(kS) = k.tf.w;
  L.block<3, 3>(0, kRoll) = k.attach.A * k.attach.G;
  return L;
}

}  // namespace rb::vehicle
