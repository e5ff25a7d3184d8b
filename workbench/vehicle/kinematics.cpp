#include "workbench/vehicle/kinematics.hpp"

#include <cmath>

namespace rb::vehicle {

namespace {
// Each angle's sincos is taken once per evaluation and shared by the rotation, G and, for
// wheelsets, the intermediate frame.
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

// The compositions of the elementary rotations written out entry by entry. Every product of the
// matrix product that meets a zero or a one of an elementary rotation is exact, and the remaining
// terms are summed in the product's order: the entries are the numbers of rz() * ry() * rx() etc.
// (tests/vehicle/test_shared.cpp) without their multiplications by 0 and 1.
// Rz(psi) Ry(theta) Rx(phi): car bodies, bogies, frames.
void yawPitchRoll(const AngleTrig& t, Eigen::Matrix3d& A) {
  const double p00 = t.cps * t.cth, p02 = t.cps * t.sth;  // Rz Ry
  const double p10 = t.sps * t.cth, p12 = t.sps * t.sth;
  const double p01 = -t.sps, p11 = t.cps, p20 = -t.sth, p22 = t.cth;
  A << p00, p01 * t.cph + p02 * t.sph, p01 * -t.sph + p02 * t.cph,  //
      p10, p11 * t.cph + p12 * t.sph, p11 * -t.sph + p12 * t.cph,   //
      p20, p22 * t.sph, p22 * t.cph;
}
// Rz(psi) Rx(phi): the wheelset intermediate frame wI.
void yawRoll(const AngleTrig& t, Eigen::Matrix3d& A) {
  A << t.cps, -t.sps * t.cph, -t.sps * -t.sph,  //
      t.sps, t.cps * t.cph, t.cps * -t.sph,     //
      0.0, t.sph, t.cph;
}
// B Ry(theta) for a rotation B: the wheelset body frame wI Ry(theta).
void timesRy(const Eigen::Matrix3d& B, double cth, double sth, Eigen::Matrix3d& A) {
  for (int r = 0; r < 3; ++r) {
    A(r, 0) = B(r, 0) * cth + B(r, 2) * -sth;
    A(r, 1) = B(r, 1);
    A(r, 2) = B(r, 0) * sth + B(r, 2) * cth;
  }
}

// Intermediate frame wI = Rz(psi) Rx(phi) of a wheelset; omega_wI = (dph, sph dps, cph dps).
void intermediateFrom(const AngleTrig& t, const Eigen::Vector3d& rates, EulerKinematics& k) {
  const double dph = rates[0], dps = rates[2];
  yawRoll(t, k.A);
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
    yawPitchRoll(t, k.A);
    k.G << 1, 0, -sth, 0, cph, cth * sph, 0, -sph, cth * cph;
    k.Gdot_rates << -dps * dth * cth, -dth * dph * sph + dps * (-dth * sth * sph + dph * cth * cph),
        -dth * dph * cph + dps * (-dth * sth * cph - dph * cth * sph);
  } else {
    // omega_b = (cth dph - sth cph dps, dth + sph dps, sth dph + cth cph dps)
    if (inter) {
      timesRy(inter->A, cth, sth, k.A);
    } else {
      Eigen::Matrix3d wI;
      yawRoll(t, wI);
      timesRy(wI, cth, sth, k.A);
    }
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
  // Lv, Lw: the entries not written here are zero from construction (BodyKinematics).
  out.Lv.col(kS) = Eigen::Vector3d::UnitX() + w.cross(out.rbar);
  out.Lv(1, kY) = 1.0;
  out.Lv(2, kZ) = 1.0;
  out.v = out.Lv.col(kS) * sd + rbar_dot;
  out.omega_att = w * sd + out.omega_rel;
  out.gamma_v = sd * sd * w_s.cross(out.rbar) + sd * w.cross(rbar_dot) + sd * w.cross(out.v);

  // Rotation: omega_b = Abar^T w sdot + G alpha_dot (body comps).
  const Eigen::Vector3d wb = out.body.A.transpose() * w;
  const Eigen::Vector3d omega_rel = out.body.G * rates;
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
