#include "workbench/vehicle/equilibrium.hpp"

namespace rb::vehicle {

namespace {

constexpr int kMaxIterations = 50;
constexpr int kMaxHalvings = 30;
constexpr double kStep = 1e-6;  // central-difference step of the Jacobian

// Central-difference Jacobian of the accelerations with respect to the first n states.
void accelerationJacobian(const Eigen::VectorXd& y, int n, const AccelerationResidual& residual,
                          Eigen::MatrixXd& jac, Eigen::VectorXd& rp, Eigen::VectorXd& rm) {
  for (int c = 0; c < n; ++c) {
    Eigen::VectorXd yp = y, ym = y;
    yp[c] += kStep;
    ym[c] -= kStep;
    residual(yp, rp);
    residual(ym, rm);
    jac.col(c) = (rp - rm) / (2.0 * kStep);
  }
}

std::string zeroColumns(const Eigen::MatrixXd& jac, const std::function<std::string(int)>& name) {
  std::string which;
  for (int c = 0; c < jac.cols(); ++c)
    if (jac.col(c).norm() < 1e-9 * jac.norm()) which += " " + name(c);
  return which;
}

}  // namespace

EquilibriumResult solveStaticEquilibrium(Eigen::VectorXd& y, int n,
                                         const AccelerationResidual& residual,
                                         const std::function<std::string(int)>& name) {
  EquilibriumResult out;
  Eigen::VectorXd r(n), rp(n), rm(n);
  Eigen::MatrixXd jac(n, n);
  residual(y, r);
  for (int it = 0; it < kMaxIterations; ++it) {
    accelerationJacobian(y, n, residual, jac, rp, rm);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(jac);
    if (lu.rank() < n) {
      out.status = EquilibriumResult::Status::Singular;
      out.unrestrained = zeroColumns(jac, name);
      out.residual = r.lpNorm<Eigen::Infinity>();
      return out;
    }
    const Eigen::VectorXd dx = lu.solve(r);
    // Backtracking on |r|.
    double step = 1.0;
    Eigen::VectorXd y_new = y;
    const double r0 = r.norm();
    for (int ls = 0; ls < kMaxHalvings; ++ls) {
      y_new.head(n) = y.head(n) - step * dx;
      residual(y_new, rp);
      if (rp.norm() <= r0 || rp.norm() < 1e-12) break;
      step *= 0.5;
    }
    y = y_new;
    r = rp;
    if (step * dx.lpNorm<Eigen::Infinity>() < 1e-13 || r.lpNorm<Eigen::Infinity>() < 1e-12) {
      out.residual = r.lpNorm<Eigen::Infinity>();
      return out;
    }
  }
  out.status = EquilibriumResult::Status::NotConverged;
  out.residual = r.lpNorm<Eigen::Infinity>();
  return out;
}

}  // namespace rb::vehicle
