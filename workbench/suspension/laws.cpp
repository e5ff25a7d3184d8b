#include "workbench/suspension/laws.hpp"

#include <cmath>

namespace rb::suspension {

Deformation axialDeformation(const Eigen::Vector3d& delta, const Eigen::Vector3d& delta_dot,
                             double l0) {
  Deformation out;
  const double len = delta.norm();
  out.d = len - l0;
  if (len > 0.0) {
    out.grad = delta / len;
    out.d_dot = out.grad.dot(delta_dot);
  }
  return out;
}

RelativeRotation relativeRotation(const Eigen::Matrix3d& R) {
  RelativeRotation out;
  out.theta = 0.5 * Eigen::Vector3d(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1));
  const double tr = R.trace();
  out.T1 = 0.5 * (tr * Eigen::Matrix3d::Identity() - R);
  out.T2 = 0.5 * (tr * Eigen::Matrix3d::Identity() - R.transpose());
  return out;
}

double seriesDamperConstantRate(double Ks, double D, double f0, double v, double t) {
  return D * v + (f0 - D * v) * std::exp(-Ks * t / D);
}

double seriesDamperStep(double Ks, double D, double f0, double h, double t) {
  return (f0 + Ks * h) * std::exp(-Ks * t / D);
}

}  // namespace rb::suspension
