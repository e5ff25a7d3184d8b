#pragma once
// Suspension element laws of the paper's Appendix A and the deformation measures of two-point
// elements (Eq. 28-31), as pure functions of the relative motion of the two attachment points.
// Nothing here knows about bodies, tracks or vehicles: the vehicle module projects the attachment
// points into the master track frame (Eq. 28) and passes their relative position and velocity.
//
// Conventions (docs/vehicle.md, "Suspension elements"):
// - delta = r_Q - r_P is the position of the second attachment point Q ("to") relative to the
//   first P ("from"), in master-frame components; delta_dot its time derivative in the master
//   frame.
// - A scalar deformation d(delta) has the gradient grad = dd/ddelta, so d_dot = grad . delta_dot
//   (Eq. 31). The element force f acts as -f grad on Q and +f grad on P; with the generalised
//   forces Q = -(dd/dq)^T f (Eq. 29 with the sign of a restoring force) an element with
//   f = K d has the potential K d^2 / 2.
// - Axial (Eq. 30): d = |delta| - l0 (> 0 in extension, f > 0 is tension).
// - Directional: d = e_axis . (delta - delta_nominal), the component of the relative
//   displacement of the points from their nominal relative position.
#include <Eigen/Dense>

namespace rb::suspension {

struct Deformation {
  double d = 0.0;                                  // [m] or [rad]
  double d_dot = 0.0;                              // [m/s] or [rad/s]
  Eigen::Vector3d grad = Eigen::Vector3d::Zero();  // dd/ddelta (unit vector for the cases here)
};

// Eq. (30): d = |delta| - l0. |delta| must be > 0 (the direction of a zero-length element is
// undefined); for |delta| == 0 grad is zero and d = -l0.
Deformation axialDeformation(const Eigen::Vector3d& delta, const Eigen::Vector3d& delta_dot,
                             double l0);

// d = e_axis . (delta - delta_nominal), axis 0 = x, 1 = y, 2 = z of the master track frame.
// Inline: it runs for most suspension elements in every evaluation.
inline Deformation directionalDeformation(const Eigen::Vector3d& delta,
                                          const Eigen::Vector3d& delta_dot,
                                          const Eigen::Vector3d& delta_nominal, int axis) {
  Deformation out;
  out.grad = Eigen::Vector3d::Unit(axis);
  out.d = delta[axis] - delta_nominal[axis];
  out.d_dot = delta_dot[axis];
  return out;
}

// Relative rotation of two frames for bending springs. R = B_j B_i^T is the rotation of the second
// attachment frame relative to the first, both given by their rotations B relative to the master
// frame (components in the master frame). The measure is theta = vee((R - R^T) / 2), which is
// sin(angle) * axis: the rotation vector to first order and exactly zero for R = I. If a and b are
// the angular velocities of the second and the first frame relative to the master frame (master
// components), theta_dot = T1 a - T2 b with T1 = (tr(R) I - R) / 2 and T2 = (tr(R) I - R^T) / 2.
struct RelativeRotation {
  Eigen::Vector3d theta = Eigen::Vector3d::Zero();
  Eigen::Matrix3d T1 = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d T2 = Eigen::Matrix3d::Identity();
};
RelativeRotation relativeRotation(const Eigen::Matrix3d& R);

// ---- Force laws (Appendix A). preload is the force at zero deformation. ----

// Spring-damper in parallel: f = preload + K d + D d_dot.
inline double springDamperForce(double K, double D, double preload, double d, double d_dot) {
  return preload + K * d + D * d_dot;
}

// Spring-damper in series (Maxwell element): the damper force f is a state obeying
// f_dot + (Ks / D) f = Ks d_dot (Appendix A). Returns f_dot.
inline double seriesDamperRate(double Ks, double D, double f, double d_dot) {
  return Ks * (d_dot - f / D);
}
// Total force of a series damper that also has a parallel spring K (Table 4: a vertical spring
// in parallel with a damper D that has the series stiffness Ks): preload + K d + f.
inline double seriesDamperForce(double K, double preload, double d, double f) {
  return preload + K * d + f;
}
// Analytic solutions of the Appendix A ODE (tests, docs), tau = D / Ks:
// constant deformation rate v from f(0) = f0: f(t) = D v + (f0 - D v) exp(-t / tau);
double seriesDamperConstantRate(double Ks, double D, double f0, double v, double t);
// a deformation step of size h at t = 0 (d_dot = h delta(t)): f(t) = (f0 + Ks h) exp(-t / tau).
double seriesDamperStep(double Ks, double D, double f0, double h, double t);

// Shear spring: f = preload + K_shear d (d a transverse component of the relative displacement).
inline double shearSpringForce(double K, double preload, double d) {
  return preload + K * d;
}

// Bending spring: M = preload + K_bend theta (theta the relative rotation about its axis).
inline double bendingSpringMoment(double K, double preload, double theta) {
  return preload + K * theta;
}

}  // namespace rb::suspension
