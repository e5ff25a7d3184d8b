#include <arkode/arkode_erkstep.h>

#include "workbench/core/strings.hpp"
#include "workbench/integrators/sundials_common.hpp"
#include "workbench/integrators/sundials_integrators.hpp"

namespace rb::integ {
namespace {

constexpr long kDefaultMaxSteps = 500;  // ARKODE's default mxstep
// Cubic Hermite dense output from y and f at both ends of the step: no extra rhs evaluations.
// ARKODE's default for a 5th-order method is degree 4, which costs one rhs evaluation per output
// time (measured: 10 000 outputs over 55 steps = 10 000 extra evaluations).
constexpr int kInterpolantDegree = 3;

std::string flagName(int flag) {
  return detail::takeFlagName(ERKStepGetReturnFlagName(flag));
}

std::string reasonFor(int flag, bool& rhs_related) {
  rhs_related = false;
  switch (flag) {
    case ARK_TOO_MUCH_ACC:
      return "the tolerances are too small for the machine precision";
    case ARK_ERR_FAILURE:
      return "the error test failed repeatedly or with |h| = hmin";
    case ARK_RHSFUNC_FAIL:
      rhs_related = true;
      return "the right-hand side failed unrecoverably";
    case ARK_FIRST_RHSFUNC_ERR:
      rhs_related = true;
      return "the right-hand side failed at its first call";
    case ARK_REPTD_RHSFUNC_ERR:
    case ARK_UNREC_RHSFUNC_ERR:
      rhs_related = true;
      return "the right-hand side kept failing recoverably (restarts with smaller steps "
             "exhausted)";
    case ARK_TOO_CLOSE:
      return "the output time is too close to t0";
    default:
      return "ERKStep failed";
  }
}

// The method, the tolerances and the step options of ERKStep; false (res holds the failure)
// when SUNDIALS refuses one of them.
bool configure(void* mem, const SolverSpec& sp, detail::OdeCallbackData& cb,
               detail::SundialsMessages& msgs, RunResult& res, std::string_view method, double t0) {
  const auto setup = [&](int flag, const char* call) {
    return flag == ARK_SUCCESS || detail::setupFailed(res, method, t0, call, flagName(flag), msgs);
  };
  return setup(ERKStepSetErrHandlerFn(mem, detail::captureMessage, &msgs),
               "ERKStepSetErrHandlerFn") &&
         setup(ERKStepSetUserData(mem, &cb), "ERKStepSetUserData") &&
         setup(ERKStepSetTableNum(mem, ARKODE_DORMAND_PRINCE_7_4_5), "ERKStepSetTableNum") &&
         setup(ERKStepSetInterpolantDegree(mem, kInterpolantDegree),
               "ERKStepSetInterpolantDegree") &&
         setup(ERKStepSStolerances(mem, sp.rtol, sp.atol), "ERKStepSStolerances") &&
         (sp.max_step <= 0 || setup(ERKStepSetMaxStep(mem, sp.max_step), "ERKStepSetMaxStep")) &&
         (sp.step <= 0 || setup(ERKStepSetInitStep(mem, sp.step), "ERKStepSetInitStep"));
}

// After a recoverable rhs failure inside a step: restart from the last accepted state tn, yacc
// with a quarter of the step. False when the step cannot shrink further or SUNDIALS refuses.
bool retryQuarterStep(void* mem, double tn, N_Vector yacc) {
  double hcur = 0.0;
  ERKStepGetCurrentStep(mem, &hcur);
  const double hnew = 0.25 * hcur;
  return hnew != 0.0 && tn + hnew != tn && ERKStepReset(mem, tn, yacc) == ARK_SUCCESS &&
         ERKStepSetInitStep(mem, hnew) == ARK_SUCCESS;
}

}  // namespace

RunResult Dopri5Integrator::runOde(OdeSystem& sys, double t0, const Eigen::VectorXd& y0,
                                   const std::vector<double>& output_times,
                                   const Observer& observer, const Progress& progress) {
  const long n = sys.size();
  const SolverSpec& sp = spec();
  const auto names = [&sys](int i) { return sys.componentName(i); };
  detail::SunContext ctx;
  detail::OdeCallbackData cb;
  cb.sys = &sys;
  cb.n = n;
  detail::SundialsMessages msgs;
  detail::NVector y = detail::makeVector(n, ctx);
  detail::NVector yacc = detail::makeVector(n, ctx);  // state at the last accepted step
  detail::NVector ytmp = detail::makeVector(n, ctx);
  detail::NVector ytmp2 = detail::makeVector(n, ctx);
  detail::map(y.get(), n) = y0;
  detail::map(yacc.get(), n) = y0;
  Eigen::VectorXd yout(n);

  RunResult res;
  res.t_reached = t0;
  detail::SolverMem mem(ERKStepCreate(detail::odeRhs, t0, y.get(), ctx), ERKStepFree);
  if (!mem) throw std::bad_alloc();
  if (!configure(mem, sp, cb, msgs, res, name(), t0)) return res;
  const long max_steps = sp.max_steps > 0 ? sp.max_steps : kDefaultMaxSteps;

  const auto collect = [&] {
    long nst = 0, nfe = 0, natt = 0;
    ERKStepGetNumSteps(mem, &nst);
    ERKStepGetNumRhsEvals(mem, &nfe);
    ERKStepGetNumStepAttempts(mem, &natt);
    res.stats.steps = nst;
    res.stats.rhs_evals = nfe;
    res.stats.rejected_steps = natt - nst;
    res.stats.recoverable_rhs_failures = cb.rec.recoverable;
  };
  const auto fail = [&](detail::FailureReport f, bool local_errors) {
    f.method = name();
    f.t_reached = res.t_reached;
    f.sundials_text = msgs.last_error;
    if (local_errors && ERKStepGetErrWeights(mem, ytmp.get()) == ARK_SUCCESS &&
        ERKStepGetEstLocalErrors(mem, ytmp2.get()) == ARK_SUCCESS)
      f.weighted_errors = detail::largestWeightedErrors(ytmp2.get(), ytmp.get(), n);
    detail::reportFailure(f, cb.rec, names, res);
    res.ok = false;
    res.t_fail = res.t_reached;
    collect();
    return res;
  };

  if (!observer(t0, y0)) {
    res.ok = res.stopped_by_observer = true;
    res.message = "dopri5: stopped by the observer at t = " + formatNumber(t0, 10);
    return res;
  }
  double tn = t0;
  std::size_t k = 0;
  long steps_in_interval = 0;
  int streak = 0;       // recoveries since the last accepted step
  int in_interval = 0;  // recoveries in this output interval
  while (k < output_times.size()) {
    // Dense output at every output time the last step passed.
    while (k < output_times.size() && output_times[k] <= tn) {
      const int flag = ERKStepGetDky(mem, output_times[k], 0, ytmp.get());
      if (flag != ARK_SUCCESS) {
        detail::FailureReport f;
        f.reason = "dense output at t = " + formatNumber(output_times[k], 10) + " failed";
        f.flag_name = flagName(flag);
        return fail(f, false);
      }
      yout = detail::map(ytmp.get(), n);
      collect();
      res.t_reached = output_times[k];
      if (!observer(output_times[k], yout)) {
        res.ok = res.stopped_by_observer = true;
        res.message = "dopri5: stopped by the observer at t = " + formatNumber(res.t_reached, 10);
        return res;
      }
      if (progress) progress(output_times[k], res.stats);
      ++k;
      steps_in_interval = 0;
      in_interval = 0;
    }
    if (k == output_times.size()) break;
    res.t_reached = tn;
    if (steps_in_interval >= max_steps) {
      detail::FailureReport f;
      f.reason = "too much work: " + std::to_string(max_steps) +
                 " internal steps in one output interval without reaching t = " +
                 formatNumber(output_times[k], 10) +
                 " (raise solver.max_steps; if the problem is stiff use bdf)";
      f.flag_name = "ARK_TOO_MUCH_WORK";
      return fail(f, true);
    }
    const long recoverable_before = cb.rec.recoverable;
    double tret = tn;
    const int flag = ERKStepEvolve(mem, output_times[k], y.get(), &tret, ARK_ONE_STEP);
    if (cb.rec.exception) std::rethrow_exception(cb.rec.exception);
    if (flag < 0) {
      const bool recoverable_cause =
          (flag == ARK_UNREC_RHSFUNC_ERR || flag == ARK_FIRST_RHSFUNC_ERR ||
           flag == ARK_REPTD_RHSFUNC_ERR) &&
          cb.rec.recoverable > recoverable_before;
      if (recoverable_cause && streak < kMaxRecoveries && in_interval < kMaxRecoveriesPerOutput &&
          retryQuarterStep(mem, tn, yacc.get())) {
        ++streak;
        ++in_interval;
        continue;
      }
      detail::FailureReport f;
      bool rhs_related = false;
      f.reason = reasonFor(flag, rhs_related);
      f.rhs_related = rhs_related;
      f.flag_name = flagName(flag);
      return fail(f, flag == ARK_ERR_FAILURE || flag == ARK_TOO_MUCH_ACC);
    }
    tn = tret;
    N_VScale(1.0, y.get(), yacc.get());
    ++steps_in_interval;
    streak = 0;
  }
  collect();
  res.ok = true;
  res.t_reached = output_times.empty() ? t0 : output_times.back();
  return res;
}

}  // namespace rb::integ
