#pragma once
// Variable-step integrators through SUNDIALS 6: dopri5 (ARKODE ERKStep), bdf (CVODE), ida (IDA).
// All three: scalar rtol/atol, optional initial step (spec.step, 0 = solver's estimate), maximum
// step (0 = unlimited), at most spec.max_steps internal steps per output interval (0 = the
// SUNDIALS default 500), dense output at the requested times (outputs never force steps: no stop
// time is set), SUNDIALS' error printing redirected into our failure message.
#include "workbench/integrators/integrator.hpp"

namespace rb::integ {

// Dormand-Prince 5(4) with ARKODE's built-in table ARKODE_DORMAND_PRINCE_7_4_5 (7 stages, order 5
// propagated, order-4 embedding) and ARKODE's default PID step controller.
// Dense output: cubic Hermite interpolation from y and f at both ends of the step, which costs no
// rhs evaluation, so the number of output times never changes the work. ARKODE's default for a
// 5th-order method (degree 4) needs one extra rhs evaluation per output time. The price: between
// steps the output carries an interpolation error O(h^4) (measured on x'' = -x, 1000 outputs:
// max error 9e-6 at rtol = atol = 1e-6, 1.1e-7 at 1e-8; degree 4: 1.8e-6, 7.6e-9); the steps
// and the solution at step points are unaffected. ode45 uses a free 4th-order continuous
// extension of the Dormand-Prince stages, which ERKStep does not expose.
// Differences to Matlab's ode45 (same tableau, both use FSAL: 6 rhs evaluations per accepted
// step): the error norm is the weighted RMS norm with weights 1 / (rtol |y_i| + atol) (ode45: a
// max norm of |err_i| / max(|y_i|, atol / rtol) times rtol); the step controller is PID (ode45:
// I-controller with other safety factors); the initial step estimate differs; ode45's default
// tolerances are rtol 1e-3, atol 1e-6.
// The run is driven in ARK_ONE_STEP mode and the output times are interpolated with
// ERKStepGetDky: the same steps and the same interpolant as ARK_NORMAL mode (which steps past
// tout and interpolates), but we know the last accepted time exactly, which the recovery below
// needs (after a failure ERKStep reports the failing stage's time, not the last accepted one).
// Recoverable rhs returns (> 0, also NaN/Inf in y or ydot): ERKStep itself cannot recover from
// them (ARK_UNREC_RHSFUNC_ERR), so the driver resets ERKStep to the last accepted state
// (ERKStepReset, counters kept) with an initial step of 1/4 of the failed one, like CVODE's
// reaction to a recoverable failure; at most kMaxRecoveries times without an accepted step in
// between and kMaxRecoveriesPerOutput times per output interval, then the run fails.
class Dopri5Integrator final : public Integrator {
 public:
  static constexpr int kMaxRecoveries = 10;
  static constexpr int kMaxRecoveriesPerOutput = 50;
  explicit Dopri5Integrator(SolverSpec spec) : Integrator(std::move(spec)) {}
  std::string_view name() const override { return kDopri5; }
  bool isFixedStep() const override { return false; }

 protected:
  RunResult runOde(OdeSystem& sys, double t0, const Eigen::VectorXd& y0,
                   const std::vector<double>& output_times, const Observer& observer,
                   const Progress& progress) override;
};

// Variable-order (1..spec.max_order) variable-step BDF through CVODE (CV_BDF, Newton iteration,
// dense SUNMatrix and LU solver of dense_lu.hpp: SUNDIALS' dense algorithms compiled with our
// flags, bit-identical to SUNMatrix_Dense + SUNLinSol_Dense). Jacobian: the model's analytic one
// when sys.hasJacobian() and spec.jacobian == "auto", else CVODE's internal difference-quotient
// Jacobian, whose rhs evaluations are counted in Stats::rhs_evals_jac (CVodeGetNumLinRhsEvals),
// not in Stats::rhs_evals.
//
// NOT Matlab's ode15s. ode15s (the paper's stiff solver) uses by default the numerical
// differentiation formulas NDF1..NDF5: BDFs whose corrector gets an extra term kappa * gamma_k *
// (y_n+1 - y^(0)_n+1) (Klopfenstein/Shampine), which at orders 1-4 has a smaller error constant
// at a small loss of stability angle (orders 3, 4); NDF5 is BDF5 (kappa = 0, ode15s's maximum
// order is 5). Shampine & Reichelt (1997) report up to about 26 % larger steps for the same
// accuracy at orders 1-4 (less at order 4).
// CVODE has no NDF option: with the same tolerances CVODE's BDF takes somewhat smaller steps at
// low orders, i.e. more steps/rhs evaluations/Jacobians than ode15s. Step/order selection,
// Jacobian reuse (CVODE re-evaluates at most every 51 steps or on convergence trouble; ode15s
// keeps it until convergence fails) and error norms (CVODE: WRMS; Matlab: max norm) differ too.
// Tolerances: Matlab's defaults are rtol 1e-3, atol 1e-6; the paper sets rtol = atol (1e-6 in
// Sect. 5.4, varied in the cost tables of Sect. 5.3) and a maximum step of 1 ms, i.e. railbench's
// defaults (1e-6 / 1e-6) plus max_step = 1e-3. Therefore step
// and evaluation counts and CPU times of bdf are not expected to match the paper's ode15s columns;
// only the solution (within tolerances) and the qualitative ranking are comparable.
class BdfIntegrator final : public Integrator {
 public:
  explicit BdfIntegrator(SolverSpec spec) : Integrator(std::move(spec)) {}
  std::string_view name() const override { return kBdf; }
  bool isFixedStep() const override { return false; }

 protected:
  RunResult runOde(OdeSystem& sys, double t0, const Eigen::VectorXd& y0,
                   const std::vector<double>& output_times, const Observer& observer,
                   const Progress& progress) override;
};

// IDA (variable-order BDF for F(t, y, y') = 0) with the dense matrix and LU solver of
// dense_lu.hpp and IDA's finite-difference Jacobian. DAEs: IDACalcIC(IDA_YA_YDP_INIT) with
// DaeSystem::isDifferential makes the initial values consistent. ODEs are run as F = y' - f(t, y)
// (y'(t0) = f(t0, y0), no IDACalcIC); for them the model's analytic Jacobian is used (J = c_j I -
// df/dy) under the same rule as bdf. Residual evaluations are counted as Stats::rhs_evals /
// rhs_evals_jac.
class IdaIntegrator final : public Integrator {
 public:
  explicit IdaIntegrator(SolverSpec spec) : Integrator(std::move(spec)) {}
  std::string_view name() const override { return kIda; }
  bool isFixedStep() const override { return false; }
  bool supportsDae() const override { return true; }

 protected:
  RunResult runOde(OdeSystem& sys, double t0, const Eigen::VectorXd& y0,
                   const std::vector<double>& output_times, const Observer& observer,
                   const Progress& progress) override;
  RunResult runDae(DaeSystem& sys, double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0,
                   const std::vector<double>& output_times, const Observer& observer,
                   const Progress& progress) override;
};

}  // namespace rb::integ
