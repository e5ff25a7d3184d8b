#pragma once
// Stage 7 of a ContactVehicleOde evaluation (contact_stages.hpp): the coupling of the normal and
// tangential contact forces of a wheelset (paper section 2.5) and the augmented solve. The creep
// forces depend on the normal forces, which the augmented system gives:
//   Lagged      creep forces at the normal forces of the previous evaluation (NormalForceMemory),
//               one augmented solve (the paper);
//   Consistent  lambda = Phi(lambda), Phi = the normal forces that the creep forces at lambda
//               produce: plain fixed-point steps while they contract well, Newton with a
//               finite-difference 2x2 Jacobian otherwise.
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

// Newton step on lambda - Phi(lambda) = 0 with a finite-difference Jacobian; f0 = Phi(lambda) -
// lambda. Falls back to the fixed-point step when the Jacobian is singular.
template <class Phi>
Eigen::Vector2d newtonStep(Phi& phi, const Eigen::Vector2d& lambda, const Eigen::Vector2d& f0) {
  Eigen::Matrix2d jac;
  for (int j = 0; j < 2; ++j) {
    Eigen::Vector2d lp = lambda;
    const double h = 1e-6 * (std::abs(lambda(j)) + 1.0);
    lp(j) += h;
    jac.col(j) = (phi(lp) - lp - f0) / h;
  }
  Eigen::Vector2d step = jac.partialPivLu().solve(-f0);
  if (!step.allFinite()) step = f0;
  return step;
}

// Consistent: fixed-point iteration on the normal forces, from the remembered ones or from the
// solution without tangential forces. x is the solution of the last Phi evaluation.
template <class Law>
int consistentCoupling(const ContactModels& models, const StageInput& in,
                       const AugmentedSystem& system, WheelsetWork& ww, ContactWorkspace& work,
                       Vec7& x) {
  const ContactModel& c = models.contact;
  Eigen::Vector2d lambda;
  if (ww.memory.valid) {
    lambda = ww.memory.lambda;
  } else {
    x = system.solver.solve(system.rhs0);
    lambda = x.tail<2>();
  }
  // Phi(lambda): plain fixed-point steps while they contract well (the usual case: the creep
  // forces change the normal forces little), Newton otherwise (large creepages with the unbounded
  // linear Kalker law, flange contact).
  int it = 0;
  const auto phi = [&](const Eigen::Vector2d& lambda_in) -> Eigen::Vector2d {
    ++it;
    x = solveWithCreepAt<Law>(c, system, ww, lambda_in);
    return x.tail<2>();
  };
  bool converged = false, newton = false;
  double last_step = std::numeric_limits<double>::infinity();
  while (it < c.consistent_max_iter) {
    const Eigen::Vector2d f0 = phi(lambda) - lambda;
    const double step = f0.cwiseAbs().maxCoeff();
    if (step <= c.consistent_tol * ((lambda + f0).cwiseAbs().maxCoeff() + 1.0)) {
      lambda += f0;
      converged = true;
      break;
    }
    if (!newton && step > 0.5 * last_step) newton = true;
    last_step = step;
    lambda += newton ? newtonStep(phi, lambda, f0) : f0;
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
    work.error = os.str();
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
      laggedCoupling<Law>(models.contact, system, ww, work.stats, x);
    } else if (const int rc = consistentCoupling<Law>(models, in, system, ww, work, x); rc != 0) {
      return rc;
    }
    if (in.mode != EvalMode::Output) ww.memory.remember(ww.lambda);
    return 0;
  }
}

}  // namespace rb::dynamics::internal
