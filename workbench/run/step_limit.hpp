#pragma once
// Linear stability of a fixed-step run: the largest step with which RK4 or ABM (PECE, paper
// Eq. 32) stay stable on the stiffest mode of the model at its initial state.
//
// A fixed-step explicit method is stable on a mode y' = lambda y only while z = h lambda lies in
// its region of absolute stability. Beyond it the mode grows from step to step; in the contact
// vehicle the wheelset spin creep mode (lambda about -2 f11 r0^2 / (V I_yy), thousands of 1/s at
// 10-20 m/s with a free spin) then oscillates from step to step, bounded only by the saturation
// of the creep law, and the run ends without any failure on a wrong answer. The eigenvalues of a
// finite-difference Jacobian at the initial state tell which step keeps every decaying mode
// stable; physically growing modes (Re lambda >= 0, e.g. hunting above the critical speed) are the
// model's behaviour, not a step limit, and are not counted.
#include <complex>
#include <span>
#include <string>

#include <Eigen/Dense>

#include "workbench/integrators/ode.hpp"

namespace rb::run {

enum class FixedStepMethod { Rk4, Abm };

// Largest modulus of the amplification factors of one step at z = h lambda: the stability
// function of RK4, or the largest root of the characteristic polynomial of ABM PECE.
double amplification(FixedStepMethod method, std::complex<double> z);

// Largest h such that h lambda stays in the method's stability region (amplification <= 1 +
// kGrowthTolerance on (0, h]); +infinity when the whole ray is stable (Re lambda >= 0 is not
// asked for).
double stableStep(FixedStepMethod method, std::complex<double> lambda);

// Growth per step tolerated as "stable": near the imaginary axis a 4th-order method's
// amplification exceeds 1 by O(z^5), which is no instability worth a refusal.
inline constexpr double kGrowthTolerance = 1e-3;

struct StepLimit {
  bool computed = false;        // false: the Jacobian could not be formed (rhs failed)
  std::string why_not;          // when !computed: the rhs error
  double h_max = 0.0;           // [s] largest stable step (+inf: no decaying mode limits it)
  std::complex<double> lambda;  // [1/s] the limiting eigenvalue
  std::string mode;             // state component dominating its eigenvector ("ws1.theta_dot")
  double stiffest = 0.0;        // [1/s] largest |lambda| among the decaying modes
  int evaluations = 0;          // rhs evaluations spent
};

// Central-difference Jacobian of ode at (t0, y0), its eigenvalues, and the step limit of the
// method. The diagonal entries of the components in `exponential` are integrated exactly by the
// exponential treatment (integrators/exponential.hpp) and are removed from the Jacobian before
// its eigenvalues are taken: what remains is what the explicit formula must keep stable. Uses
// its own evaluations of ode (rhs memory, if any, is left as the last evaluation set it: call it
// on an ODE object that is not integrated afterwards).
StepLimit fixedStepLimit(integ::OdeSystem& ode, double t0, const Eigen::VectorXd& y0,
                         FixedStepMethod method, std::span<const int> exponential = {});

}  // namespace rb::run
