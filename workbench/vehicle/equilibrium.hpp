#pragma once
// Static (on a curve: quasi-static) equilibrium of the car bodies and bogies on their suspension,
// the initial state of every vehicle ODE (GuidedVehicleOde, dynamics::ContactVehicleOde).
#include <Eigen/Dense>
#include <functional>
#include <string>

namespace rb::vehicle {

// The free-body accelerations (n values) at the state y; may throw.
using AccelerationResidual = std::function<void(const Eigen::VectorXd& y, Eigen::VectorXd& acc)>;

struct EquilibriumResult {
  enum class Status { Converged, Singular, NotConverged };
  Status status = Status::Converged;
  // Singular: the coordinates no suspension element restrains (" car.y bogie1.z"; may be empty
  // when the Jacobian is singular without a zero column).
  std::string unrestrained;
  double residual = 0.0;  // [m/s^2 or rad/s^2] |acceleration|_inf at the last iterate
};

// Newton iteration on the accelerations of the first n states of y (the free-body positions; the
// other states keep their values): central-difference Jacobian (step 1e-6), full-pivot LU,
// backtracking on |acceleration| (the bumpstops make the problem nonlinear), at most 50
// iterations; converged when the step or |acceleration|_inf falls below 1e-13 / 1e-12. y holds the
// last iterate on return. name(i) names state i for EquilibriumResult::unrestrained.
EquilibriumResult solveStaticEquilibrium(Eigen::VectorXd& y, int n,
                                         const AccelerationResidual& residual,
                                         const std::function<std::string(int)>& name);

}  // namespace rb::vehicle
