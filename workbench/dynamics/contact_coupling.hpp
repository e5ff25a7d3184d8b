#pragma once
// Stage 7 of a ContactVehicleOde evaluation (contact_stages.hpp): the coupling of the normal and
// tangential contact forces of a wheelset (paper section 2.5) and the augmented solve. The creep
// forces depend on the normal forces, which the augmented system gives:
//   Lagged      creep forces at the normal forces of the previous evaluation (NormalForceMemory),
//               one augmented solve (the paper);
//   Consistent  lambda = Phi(lambda), Phi = the normal forces that the creep forces at lambda
//               produce: quasi-Newton (Broyden) steps with a remembered 2x2 Jacobian of Phi,
//               a finite-difference Jacobian when they do not contract well.
// Compiled per creep law. Internal to workbench/dynamics.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "workbench/dynamics/contact_patches.hpp"

namespace rb::dynamics::internal {

// Creep forces of one patch at normal force Q; adds the generalised forces to Qt.
template <class Law>
void creepForce(Patch& p, double Q, const ContactModel& c, Vec5& Qt) {
  p.Q = Q;
  if (!(Q > 0.0)) {
    p.fx = p.fy = p.mz = p.a = p.b = 0.0;
    return;
  }
  const creep::ContactPatch cp = creep::makeContactPatch(p.pc, Q);
  Law::apply(c, cp, p.cr, p.fx, p.fy, p.mz);
  p.a = cp.a;
  p.b = cp.b;
  Qt.noalias() += p.gx * p.fx + p.gy * p.fy + p.gm * p.mz;
}

// The augmented solve with the creep forces of every active patch at the normal-force multipliers
// lambda: x = (qddot, lambda of the solution).
template <class Law>
Vec7 solveWithCreepAt(const ContactModel& c, const AugmentedSystem& system, WheelsetWork& ww,
                      const Eigen::Vector2d& lambda) {
  Vec5 Qt;
  Qt.setZero();
  for (auto& wheel : ww.patch)
    for (Patch& p : wheel)
      if (p.active) creepForce<Law>(p, p.normalAt(lambda), c, Qt);
  Vec7 r = system.rhs0;
  r.head<5>() += Qt;
  return system.solver.solve(r);
}

// Lagged: the creep forces at the remembered normal forces (the paper: of the last time step).
template <class Law>
void laggedCoupling(const ContactModel& c, const AugmentedSystem& system, WheelsetWork& ww,
                    ContactStats& stats, Vec7& x) {
  const Eigen::Vector2d& previous = ww.memory.lambda;
  x = solveWithCreepAt<Law>(c, system, ww, previous);
  ww.lambda = x.tail<2>();
  stats.max_lagged_change =
      std::max(stats.max_lagged_change, (ww.lambda - previous).cwiseAbs().maxCoeff());
}

// Finite-difference Jacobian d Phi / d lambda at lambda (phi0 = Phi(lambda)): two Phi evaluations.
template <class Phi>
Eigen::Matrix2d finiteDifferenceJacobian(Phi& phi, const Eigen::Vector2d& lambda,
                                         const Eigen::Vector2d& phi0) {
  Eigen::Matrix2d jac;
  for (int j = 0; j < 2; ++j) {
    Eigen::Vector2d lp = lambda;
    const double h = 1e-6 * (std::abs(lambda(j)) + 1.0);
    lp(j) += h;
    jac.col(j) = (phi(lp) - phi0) / h;
  }
  return jac;
}

// Broyden's ("good") rank-one update of the Jacobian estimate J of Phi with the secant pair
// (d_lambda, d_phi): the least change of J that satisfies J d_lambda = d_phi.
inline void broydenUpdate(Eigen::Matrix2d& J, const Eigen::Vector2d& d_lambda,
                          const Eigen::Vector2d& d_phi) {
  const double dd = d_lambda.squaredNorm();
  if (!(dd > 0.0)) return;
  J.noalias() += ((d_phi - J * d_lambda) / dd) * d_lambda.transpose();
}

// Newton step d on r(lambda) = Phi(lambda) - lambda = 0 with the Jacobian estimate J of Phi:
// (I - J) d = r. The plain fixed-point step r when I - J is singular.
inline Eigen::Vector2d quasiNewtonStep(const Eigen::Matrix2d& J, const Eigen::Vector2d& r) {
  const Eigen::Matrix2d A = Eigen::Matrix2d::Identity() - J;
  const double det = A.determinant();
  if (!(std::abs(det) > 0.0)) return r;
  Eigen::Vector2d d(A(1, 1) * r(0) - A(0, 1) * r(1), A(0, 0) * r(1) - A(1, 0) * r(0));
  d /= det;
  return d.allFinite() ? d : r;
}

// Consistent: lambda = Phi(lambda) by a quasi-Newton iteration from the remembered normal forces
// (or the solution without tangential forces). The Jacobian estimate J of Phi starts from the
// remembered one (zero without: the first step is the plain fixed-point step) and follows
// Broyden's updates; when a step does not halve the residual, J is replaced by a
// finite-difference Jacobian (large creepages with the unbounded linear Kalker law, flange
// contact). The test and the returned lambda = Phi(lambda_k) are those of the plain iteration, so
// the accuracy is the same; the near-Newton steps only need fewer Phi evaluations. x is the
// solution of the last Phi evaluation; J is the estimate at the solution.
template <class Law>
int consistentCoupling(const ContactModels& models, const StageInput& in,
                       const AugmentedSystem& system, WheelsetWork& ww, ContactWorkspace& work,
                       Vec7& x, Eigen::Matrix2d& J) {
  const ContactModel& c = *ww.contact;
  Eigen::Vector2d lambda;
  if (ww.memory.valid) {
    lambda = ww.memory.lambda;
  } else {
    x = system.solver.solve(system.rhs0);
    lambda = x.tail<2>();
  }
  J = ww.memory.jacobian_valid ? ww.memory.jacobian : Eigen::Matrix2d::Zero();
  int it = 0;
  const auto phi = [&](const Eigen::Vector2d& lambda_in) -> Eigen::Vector2d {
    ++it;
    x = solveWithCreepAt<Law>(c, system, ww, lambda_in);
    return x.tail<2>();
  };
  bool converged = false, have_previous = false;
  Eigen::Vector2d lambda_prev, phi_prev;
  double last_step = std::numeric_limits<double>::infinity();
  while (it < c.consistent_max_iter) {
    const Eigen::Vector2d phi0 = phi(lambda);
    const Eigen::Vector2d r = phi0 - lambda;
    if (have_previous) broydenUpdate(J, lambda - lambda_prev, phi0 - phi_prev);
    const double step = r.cwiseAbs().maxCoeff();
    if (step <= c.consistent_tol * (phi0.cwiseAbs().maxCoeff() + 1.0)) {
      lambda = phi0;
      converged = true;
      break;
    }
    if (step > 0.5 * last_step) J = finiteDifferenceJacobian(phi, lambda, phi0);
    last_step = step;
    lambda_prev = lambda;
    phi_prev = phi0;
    have_previous = true;
    lambda += quasiNewtonStep(J, r);
  }
  ContactStats& stats = work.stats;
  ++stats.consistent_solves;
  stats.consistent_iterations += it;
  stats.consistent_max_iterations = std::max(stats.consistent_max_iterations, it);
  if (!converged) {
    std::ostringstream os;
    os << "wheelset '" << models.vehicle.bodies[ww.body].name << "' at t = " << in.t
       << " s: normal and tangential forces did not converge in " << it
       << " fixed-point iterations";
    work.fail(ContactFailure::Coupling, models.vehicle.bodies[ww.body].name, os.str());
    return 1;
  }
  ww.lambda = lambda;  // the patches carry the creep forces of the converged normal forces
  return 0;
}

// 7. Normal forces lambda and accelerations x = (qddot, lambda) of wheelset ww, with the creep
// forces of its patches; updates its NormalForceMemory (see there).
template <class Law>
int coupleNormalAndTangential(const ContactModels& models, const StageInput& in,
                              const AugmentedSystem& system, WheelsetWork& ww,
                              ContactWorkspace& work, Vec7& x) {
  if constexpr (!Law::kCreep) {
    x = system.solver.solve(system.rhs0);
    ww.lambda = x.tail<2>();
    return 0;
  } else {
    const bool lagged =
        models.contact.coupling == NormalForceCoupling::Lagged && in.mode != EvalMode::Init;
    if (lagged && ww.memory.valid) {
      laggedCoupling<Law>(*ww.contact, system, ww, work.stats, x);
    } else {
      Eigen::Matrix2d J;
      if (const int rc = consistentCoupling<Law>(models, in, system, ww, work, x, J); rc != 0)
        return rc;
      if (in.mode != EvalMode::Output) ww.memory.rememberJacobian(J);
    }
    if (in.mode != EvalMode::Output) ww.memory.remember(ww.lambda);
    return 0;
  }
}

}  // namespace rb::dynamics::internal
