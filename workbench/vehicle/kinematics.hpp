#pragma once
// Kinematics of a rigid body in track-frame coordinates (paper Eq. 1-3, 7-10, 27-28; Recuero,
// Escalona, Chamorro 2012). docs/vehicle.md derives every expression used here.
//
// Coordinates of body i relative to its body track frame <O_ti; X_ti, Y_ti, Z_ti> at arc length s:
//   q = (s, y, z, phi, theta, psi)  (indices kS .. kYaw)
// - centre of mass:  R = R_t(s) + A_t(s) rbar,  rbar = (0, y, h + z), h = nominal CoM height above
//   the top-of-rail plane (z = 0 is the nominal height);
// - orientation:     A = A_t(s) Abar(phi, theta, psi).
//   Car bodies, bogies, frames: Abar = Rz(psi) Ry(theta) Rx(phi), the same yaw-pitch-roll sequence
//   as the track frame of Eq. (1) (exact trigonometry, no linearisation).
//   Wheelsets: Abar = A_wt,wI A_wI,w = [Rz(psi) Rx(phi)] Ry(theta) (Eq. 8): the intermediate frame
//   wI = Rz(psi) Rx(phi) has no pitch; Eq. (9) is its first-order form, used here exactly. The
//   pitch theta is the spin angle.
// - Attachment frame: suspension elements attach to the body frame (car, bogie, frame) or to the
//   intermediate frame wI of a wheelset (the axle boxes do not spin).
//
// Velocities are linear in the coordinate rates: v = Lv qdot (CoM, track-frame components),
// omega_b = Lw qdot (body-frame components), and accelerations are a = Lv qddot + gamma_v,
// alpha_b = Lw qddot + gamma_w, including the motion of the track frame itself (w = angular rate of
// the track frame per metre, w_s its s-derivative, from TrackGeometry::at()).
#include <Eigen/Dense>
#include <cstdint>
#include <limits>

#include "workbench/track/geometry.hpp"

namespace rb::vehicle {

enum Coord : int { kS = 0, kY = 1, kZ = 2, kRoll = 3, kPitch = 4, kYaw = 5 };
inline constexpr int kCoords = 6;

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Matrix36d = Eigen::Matrix<double, 3, 6>;

enum class RotationSequence {
  YawPitchRoll,  // Rz(psi) Ry(theta) Rx(phi): car bodies, bogies, frames
  YawRollPitch,  // Rz(psi) Rx(phi) Ry(theta): wheelsets (pitch = spin last), Eq. (8)-(9)
};

// Relative rotation Abar and the angular-velocity map of an Euler sequence: the angular velocity
// relative to the track frame in the rotated frame's own components is G * (phi_dot, theta_dot,
// psi_dot); Gdot_rates = (dG/dt) * (phi_dot, theta_dot, psi_dot).
struct EulerKinematics {
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d G = Eigen::Matrix3d::Identity();
  Eigen::Vector3d Gdot_rates = Eigen::Vector3d::Zero();
};
EulerKinematics eulerKinematics(RotationSequence seq, const Eigen::Vector3d& angles,
                                const Eigen::Vector3d& rates);
// Wheelset intermediate frame wI = Rz(psi) Rx(phi) (no pitch); G acts on (phi, theta, psi) rates
// with a zero theta column.
EulerKinematics intermediateKinematics(const Eigen::Vector3d& angles, const Eigen::Vector3d& rates);

struct BodyKinematics {
  track::TrackFrame tf;                               // body track frame at s
  Eigen::Vector3d rbar = Eigen::Vector3d::Zero();     // CoM in track-frame components
  EulerKinematics body;                               // body frame relative to the track frame
  EulerKinematics attach;                             // attachment frame (== body, or wI)
  Eigen::Vector3d v = Eigen::Vector3d::Zero();        // absolute CoM velocity, track comps
  Eigen::Vector3d omega_b = Eigen::Vector3d::Zero();  // absolute angular velocity, body comps
  // dv/dqdot and domega_b/dqdot. Their constant zero blocks (the y, z columns of Lw, the angle
  // columns of Lv) are set here and never written by bodyKinematics.
  Matrix36d Lv = Matrix36d::Zero();
  Matrix36d Lw = Matrix36d::Zero();
  Eigen::Vector3d gamma_v = Eigen::Vector3d::Zero();  // a - Lv qddot (track comps)
  Eigen::Vector3d gamma_w = Eigen::Vector3d::Zero();  // alpha_b - Lw qddot (body comps)
  // Per-evaluation constants of the attachment frame, so that a point force or a point velocity
  // costs a few cross products instead of a 3x6 Jacobian (pointVelocity, addPointForce):
  Eigen::Matrix3d AG = Eigen::Matrix3d::Identity();     // attach.A attach.G (track comps)
  Eigen::Vector3d omega_rel = Eigen::Vector3d::Zero();  // AG alpha_dot: attachment frame's
                                                        // angular velocity rel. to the track frame
  Eigen::Vector3d rbar_dot = Eigen::Vector3d::Zero();   // (0, ydot, zdot)
  double sd = 0.0;                                      // sdot
  // w sdot + omega_rel: angular velocity of the attachment frame (track comps, the track frame's
  // rotation included), so that pointVelocity is v + omega_att x au (one cross product; it runs
  // twice per suspension element and evaluation).
  Eigen::Vector3d omega_att = Eigen::Vector3d::Zero();
  // The track frame tf was evaluated at s = tf_key on tf_geometry: an evaluation at the same s
  // (the stages of a multistage method at one time, ABM predictor and corrector) reuses it.
  double tf_key = std::numeric_limits<double>::quiet_NaN();
  const track::TrackGeometry* tf_geometry = nullptr;
  std::uint64_t tf_version = 0;  // incremented whenever tf is evaluated anew (caches key on it)

  // Global position of the CoM and global rotation of the body.
  Eigen::Vector3d position() const { return tf.R + tf.A * rbar; }
  Eigen::Matrix3d rotation() const { return tf.A * body.A; }
};

// Fills `out` for a body with nominal CoM height `height` at coordinates q, rates qd.
// Allocation-free.
void bodyKinematics(const track::TrackGeometry& geometry, RotationSequence seq, double height,
                    const Vector6d& q, const Vector6d& qd, BodyKinematics& out);

// A point fixed in the attachment frame at u (attachment-frame components, relative to the CoM):
// position in track-frame components, and the Jacobian of its absolute velocity (track comps).
Eigen::Vector3d pointPosition(const BodyKinematics& k, const Eigen::Vector3d& u);
Matrix36d pointJacobian(const BodyKinematics& k, const Eigen::Vector3d& u);

// The same without forming the Jacobian, for the point at au = attach.A u (track comps, relative
// to the CoM): its absolute velocity L_P qdot = (e_x + w x (rbar + au)) sdot + rbar_dot +
// omega_rel x au, and the generalised force L_P^T F of a force F (track comps) applied there:
// (e_x + w x (rbar + au)) . F on s, F_y, F_z on y, z, AG^T (au x F) on the angles
// (L_P's angle block is -A skew(u) G = -skew(au) AG).
inline Eigen::Vector3d pointVelocity(const BodyKinematics& k, const Eigen::Vector3d& au) {
  // (e_x + w x (rbar + au)) sdot + rbar_dot + omega_rel x au regrouped: v + (w sdot + omega_rel) x
  // au (v = CoM velocity).
  return k.v + k.omega_att.cross(au);
}
inline void addPointForce(const BodyKinematics& k, const Eigen::Vector3d& au,
                          const Eigen::Vector3d& F, Vector6d& Q) {
  Q[kS] += F.x() + k.tf.w.cross(k.rbar + au).dot(F);
  Q[kY] += F.y();
  Q[kZ] += F.z();
  Q.segment<3>(kRoll).noalias() += k.AG.transpose() * au.cross(F);
}
// Jacobian of the absolute angular velocity of the attachment frame, track-frame components.
Matrix36d attachmentAngularJacobian(const BodyKinematics& k);

}  // namespace rb::vehicle
