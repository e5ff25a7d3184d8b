// Body kinematics in track-frame coordinates against finite differences of the global position and
// rotation, on a curved, canted and sloped track (transition: every track angle and its rates
// vary).
#include <gtest/gtest.h>

#include <cmath>

#include "fixtures.hpp"
#include "workbench/vehicle/kinematics.hpp"

namespace rb::vehicle {
namespace {

Eigen::Vector3d vee(const Eigen::Matrix3d& S) {
  return 0.5 * Eigen::Vector3d(S(2, 1) - S(1, 2), S(0, 2) - S(2, 0), S(1, 0) - S(0, 1));
}

struct Motion {
  // Smooth coordinates q(t) with nonzero s-acceleration.
  Vector6d q(double t) const {
    Vector6d v;
    v << 45.0 + 17.0 * t + 3.0 * t * t, 0.02 * std::sin(3 * t), -0.03 + 0.01 * std::cos(2 * t),
        0.05 * std::sin(1.7 * t), 0.3 + 4.0 * t, -0.04 * std::cos(2.3 * t);
    return v;
  }
  Vector6d qd(double t) const {
    Vector6d v;
    v << 17.0 + 6.0 * t, 0.06 * std::cos(3 * t), -0.02 * std::sin(2 * t), 0.085 * std::cos(1.7 * t),
        4.0, 0.092 * std::sin(2.3 * t);
    return v;
  }
  Vector6d qdd(double t) const {
    Vector6d v;
    v << 6.0, -0.18 * std::sin(3 * t), -0.04 * std::cos(2 * t), -0.1445 * std::sin(1.7 * t), 0.0,
        0.2116 * std::cos(2.3 * t);
    return v;
  }
};

class KinematicsFD : public ::testing::TestWithParam<RotationSequence> {};

TEST_P(KinematicsFD, VelocityAndAccelerationIncludeTrackFrameMotion) {
  // Right-hand clothoid with cant and a gradient ramp over [40, 100] m.
  const track::TrackModel tm = track::compileTrack(
      rbtest::curveTrack(track::Side::Right, 300.0, 0.15, 40.0, 60.0, 100.0, 0.02));
  const track::TrackGeometry& g = tm.geometry();
  const RotationSequence seq = GetParam();
  const double height = 0.8;
  const Motion mo;
  const Eigen::Vector3d u(0.7, -1.1, 0.25);
  const auto kinAt = [&](double t) {
    BodyKinematics k;
    bodyKinematics(g, seq, height, mo.q(t), mo.qd(t), k);
    return k;
  };
  for (double t : {0.0, 0.8, 1.6}) {  // s from 45 to ~80 m: inside the transition
    const BodyKinematics k = kinAt(t);
    const double h = 1e-5;
    const BodyKinematics kp = kinAt(t + h), km = kinAt(t - h);
    // Velocity of the CoM.
    const Eigen::Vector3d v_fd = (kp.position() - km.position()) / (2 * h);
    EXPECT_LT((k.tf.A * k.v - v_fd).norm(), 1e-7) << t;
    EXPECT_LT((k.tf.A * (k.Lv * mo.qd(t)) - v_fd).norm(), 1e-7) << t;
    // Angular velocity: Adot A^T = skew(omega_global).
    const Eigen::Matrix3d Adot = (kp.rotation() - km.rotation()) / (2 * h);
    const Eigen::Vector3d w_fd = vee(Adot * k.rotation().transpose());
    EXPECT_LT((k.rotation() * k.omega_b - w_fd).norm(), 1e-7) << t;
    EXPECT_LT((k.Lw * mo.qd(t) - k.omega_b).norm(), 1e-12) << t;
    // Accelerations: a = Lv qdd + gamma_v (track comps), alpha_b = Lw qdd + gamma_w (body comps).
    const Eigen::Vector3d a_fd = (kp.tf.A * kp.v - km.tf.A * km.v) / (2 * h);
    EXPECT_LT((k.tf.A * (k.Lv * mo.qdd(t) + k.gamma_v) - a_fd).norm(), 1e-6) << t;
    const Eigen::Vector3d al_fd = (kp.omega_b - km.omega_b) / (2 * h);
    EXPECT_LT((k.Lw * mo.qdd(t) + k.gamma_w - al_fd).norm(), 1e-6) << t;
    // A point of the attachment frame (wheelset: the non-spinning axle-box frame).
    const auto pointGlobal = [&](const BodyKinematics& kk) {
      return Eigen::Vector3d(kk.tf.R + kk.tf.A * pointPosition(kk, u));
    };
    const Eigen::Vector3d vp_fd = (pointGlobal(kp) - pointGlobal(km)) / (2 * h);
    EXPECT_LT((k.tf.A * (pointJacobian(k, u) * mo.qd(t)) - vp_fd).norm(), 1e-7) << t;
    // pointVelocity (v + omega_att x au, no Jacobian) is the Jacobian's velocity.
    EXPECT_LT((pointVelocity(k, k.attach.A * u) - pointJacobian(k, u) * mo.qd(t)).norm(), 1e-12)
        << t;
    const Eigen::Matrix3d Aa = k.tf.A * k.attach.A;
    const Eigen::Matrix3d Aa_dot = (kp.tf.A * kp.attach.A - km.tf.A * km.attach.A) / (2 * h);
    const Eigen::Vector3d wa_fd = vee(Aa_dot * Aa.transpose());
    EXPECT_LT((k.tf.A * (attachmentAngularJacobian(k) * mo.qd(t)) - wa_fd).norm(), 1e-7) << t;
  }
}

INSTANTIATE_TEST_SUITE_P(Sequences, KinematicsFD,
                         ::testing::Values(RotationSequence::YawPitchRoll,
                                           RotationSequence::YawRollPitch));

TEST(Kinematics, WheelsetIntermediateFrameHasNoPitchAndEq9IsItsLinearisation) {
  const Eigen::Vector3d ang(0.01, 1.3, -0.02);  // roll, pitch (spin), yaw
  const EulerKinematics w =
      eulerKinematics(RotationSequence::YawRollPitch, ang, Eigen::Vector3d::Zero());
  const EulerKinematics wi = intermediateKinematics(ang, Eigen::Vector3d::Zero());
  // Eq. (8): A_wt,w = A_wt,wI A_wI,w with A_wI,w = Ry(theta).
  const Eigen::Matrix3d Ry = Eigen::AngleAxisd(1.3, Eigen::Vector3d::UnitY()).toRotationMatrix();
  EXPECT_LT((w.A - wi.A * Ry).norm(), 1e-15);
  // Eq. (9): A_wt,wI = [[1, -psi, 0], [psi, 1, -phi], [0, phi, 1]] to first order.
  Eigen::Matrix3d eq9;
  eq9 << 1, 0.02, 0, -0.02, 1, -0.01, 0, 0.01, 1;
  EXPECT_LT((wi.A - eq9).cwiseAbs().maxCoeff(), 3e-4);  // second-order terms only (<= 2.5e-4)
}

TEST(Kinematics, StraightLevelTrackIsTheNominalConfiguration) {
  const track::TrackModel tm = track::compileTrack(rbtest::tangentTrack(100.0));
  BodyKinematics k;
  Vector6d q = Vector6d::Zero(), qd = Vector6d::Zero();
  q[kS] = 30.0;
  qd[kS] = 20.0;
  bodyKinematics(tm.geometry(), RotationSequence::YawPitchRoll, 1.8, q, qd, k);
  EXPECT_LT((k.position() - Eigen::Vector3d(30.0, 0.0, 1.8)).norm(), 1e-9);
  EXPECT_LT((k.v - Eigen::Vector3d(20.0, 0.0, 0.0)).norm(), 1e-12);
  EXPECT_LT(k.gamma_v.norm() + k.gamma_w.norm(), 1e-12);
}

}  // namespace
}  // namespace rb::vehicle
