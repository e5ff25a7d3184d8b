#include <cvode/cvode.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>
#include <utility>

#include "workbench/core/strings.hpp"
#include "workbench/integrators/dense_lu.hpp"
#include "workbench/integrators/fd_jacobian.hpp"
#include "workbench/integrators/serial_vector_ops.hpp"
#include "workbench/integrators/sundials_common.hpp"
#include "workbench/integrators/sundials_integrators.hpp"

namespace rb::integ {
namespace {

std::string flagName(int flag) {
  return detail::takeFlagName(CVodeGetReturnFlagName(flag));
}

std::string reasonFor(int flag, long max_steps, double tout, bool& rhs_related) {
  rhs_related = false;
  switch (flag) {
    case CV_TOO_MUCH_WORK:
      return "too much work: " + std::to_string(max_steps) +
             " internal steps in one output interval without reaching t = " +
             formatNumber(tout, 10) + " (raise solver.max_steps)";
    case CV_TOO_MUCH_ACC:
      return "the tolerances are too small for the machine precision";
    case CV_ERR_FAILURE:
      return "the error test failed repeatedly or with |h| = hmin";
    case CV_CONV_FAILURE:
      rhs_related = true;
      return "the Newton iteration failed to converge repeatedly or with |h| = hmin";
    case CV_LSETUP_FAIL:
      rhs_related = true;
      return "the linear solver setup failed (Jacobian failure or singular iteration matrix)";
    case CV_LSOLVE_FAIL:
      return "the linear solve failed";
    case CV_RHSFUNC_FAIL:
      rhs_related = true;
      return "the right-hand side failed unrecoverably";
    case CV_FIRST_RHSFUNC_ERR:
      rhs_related = true;
      return "the right-hand side failed at its first call";
    case CV_REPTD_RHSFUNC_ERR:
      rhs_related = true;
      return "the right-hand side failed recoverably too many times in a row";
    case CV_UNREC_RHSFUNC_ERR:
      rhs_related = true;
      return "the right-hand side failed recoverably and no recovery was possible";
    case CV_TOO_CLOSE:
      return "the output time is too close to t0";
    default:
      return "CVODE failed";
  }
}

// How long the Newton iteration keeps its Jacobian and its factored iteration matrix (CVODE's
// defaults: 51 and 20 steps). The vehicle's Jacobian changes slowly between contact events, and
// CVODE evaluates it anew after any Newton convergence failure and factors anew when gamma
// changes by more than 30 %. Measured on the wagon (case 3 KEC 1e-6, LUT with the Hertz flange
// 1e-7, the stiff-flange hard case): 4 to 8 times fewer Jacobians, the same Newton iterations and
// steps to within 2 %.
constexpr long kJacobianReuseSteps = 500;
constexpr long kSetupReuseSteps = 40;

// OdeCallbackData::jacobian_data of the grouped difference Jacobian.
struct GroupedJacobianData {
  const GroupedDifferences* grouped = nullptr;
  void* mem = nullptr;
  N_Vector ewt = nullptr;
};

// CVLsJacFn: forward differences over the column groups of the model's JacobianPattern, with the
// increments of CVODE's own dense difference quotient (cvLsDenseDQJac: inc_j = max(sqrt(u)
// |y_j|, min_inc / w_j), min_inc = 1000 |h| u n ||f||_wrms), min_inc at least sqrt(u).
int groupedJac(double t, N_Vector y, N_Vector fy, SUNMatrix J, void* user_data, N_Vector tmp1,
               N_Vector tmp2, N_Vector /*tmp3*/) {
  auto* cb = static_cast<detail::OdeCallbackData*>(user_data);
  const auto* d = static_cast<const GroupedJacobianData*>(cb->jacobian_data);
  const long n = cb->n;
  double h = 0.0;
  if (CVodeGetErrWeights(d->mem, d->ewt) != CV_SUCCESS ||
      CVodeGetCurrentStep(d->mem, &h) != CV_SUCCESS)
    return -1;
  const double uround = DBL_EPSILON;
  const double fnorm = N_VWrmsNorm(fy, d->ewt);
  const double min_inc =
      fnorm != 0.0 ? 1000.0 * std::abs(h) * uround * static_cast<double>(n) * fnorm : 1.0;
  const double srur = std::sqrt(uround);
  double* yv = detail::data(y);
  double* inc = detail::data(tmp2);
  const double* w = detail::data(d->ewt);
  // min_inc is floored at sqrt(u): at the first steps (|h| ~ 1e-13) CVODE's bound gives increments
  // of 1e-20 in the weighted norm, far below the residue of the model's inner iterations (KEC
  // Newton, consistent normal forces: 1e-10 relative), and the quotients are noise that a reused
  // Jacobian would carry for many steps.
  const double inc_floor = std::max(min_inc, srur);
  for (long j = 0; j < n; ++j) inc[j] = std::max(srur * std::abs(yv[j]), inc_floor / w[j]);
  Eigen::Map<Eigen::MatrixXd> jm(SUNDenseMatrix_Data(J), n, n);
  const auto rhs = [&](double* /*yp*/, double* /*f*/) {
    ++cb->jacobian_rhs_evals;
    return detail::odeRhs(t, y, tmp1, cb);
  };
  return d->grouped->forward(rhs, yv, detail::data(fy), inc, detail::data(tmp1), jm);
}

}  // namespace

RunResult BdfIntegrator::runOde(OdeSystem& sys, double t0, const Eigen::VectorXd& y0,
                                const std::vector<double>& output_times, const Observer& observer,
                                const Progress& progress) {
  const long n = sys.size();
  const SolverSpec& sp = spec();
  const auto names = [&sys](int i) { return sys.componentName(i); };
  detail::SunContext ctx;  // declared first: destroyed last
  detail::OdeCallbackData cb;
  GroupedJacobianData jac_data;
  cb.sys = &sys;
  cb.n = n;
  detail::SundialsMessages msgs;
  detail::NVector y = detail::makeVector(n, ctx);
  detail::NVector ewt = detail::makeVector(n, ctx);
  detail::NVector ele = detail::makeVector(n, ctx);
  detail::map(y.get(), n) = y0;
  detail::useCompiledVectorOps(y.get());  // CVODE's internal vectors are clones of y
  Eigen::VectorXd yout(n);
  detail::SunMatrix A(detail::newDenseMatrix(n, ctx));
  const bool analytic = sp.jacobian == "auto" && sys.hasJacobian();
  JacobianPattern pattern = sys.jacobianPattern();
  detail::SunLinSol LS(detail::newDenseLuSolver(n, ctx, pattern.copy_of));
  if (!A || !LS) throw std::bad_alloc();
  const std::optional<GroupedDifferences> grouped =
      analytic || pattern.empty()
          ? std::nullopt
          : std::optional<GroupedDifferences>(std::in_place, n, std::move(pattern));

  RunResult res;
  res.t_reached = t0;
  detail::SolverMem mem(CVodeCreate(CV_BDF, ctx), CVodeFree);  // freed before LS and A
  if (!mem) throw std::bad_alloc();
  const auto setup = [&](int flag, const char* call) {
    return flag == CV_SUCCESS || detail::setupFailed(res, name(), t0, call, flagName(flag), msgs);
  };
  jac_data.grouped = grouped ? &*grouped : nullptr;
  jac_data.mem = mem;
  jac_data.ewt = ewt.get();
  cb.jacobian_data = &jac_data;
  if (!setup(CVodeSetErrHandlerFn(mem, detail::captureMessage, &msgs), "CVodeSetErrHandlerFn") ||
      !setup(CVodeInit(mem, detail::odeRhs, t0, y.get()), "CVodeInit") ||
      !setup(CVodeSetUserData(mem, &cb), "CVodeSetUserData") ||
      !setup(CVodeSStolerances(mem, sp.rtol, sp.atol), "CVodeSStolerances") ||
      !setup(CVodeSetLinearSolver(mem, LS.get(), A.get()), "CVodeSetLinearSolver") ||
      (analytic && !setup(CVodeSetJacFn(mem, detail::odeJac), "CVodeSetJacFn")) ||
      (grouped && !setup(CVodeSetJacFn(mem, groupedJac), "CVodeSetJacFn")) ||
      !setup(CVodeSetMaxOrd(mem, sp.max_order), "CVodeSetMaxOrd") ||
      (sp.max_step > 0 && !setup(CVodeSetMaxStep(mem, sp.max_step), "CVodeSetMaxStep")) ||
      (sp.step > 0 && !setup(CVodeSetInitStep(mem, sp.step), "CVodeSetInitStep")) ||
      (sp.max_steps > 0 && !setup(CVodeSetMaxNumSteps(mem, sp.max_steps), "CVodeSetMaxNumSteps")) ||
      !setup(CVodeSetJacEvalFrequency(mem, kJacobianReuseSteps), "CVodeSetJacEvalFrequency") ||
      !setup(CVodeSetLSetupFrequency(mem, kSetupReuseSteps), "CVodeSetLSetupFrequency"))
    return res;

  const auto collect = [&] {
    Stats& s = res.stats;
    long netf = 0, nsf = 0;
    CVodeGetNumSteps(mem, &s.steps);
    CVodeGetNumRhsEvals(mem, &s.rhs_evals);
    CVodeGetNumLinRhsEvals(mem, &s.rhs_evals_jac);
    s.rhs_evals_jac += cb.jacobian_rhs_evals;
    CVodeGetNumJacEvals(mem, &s.jacobian_evals);
    CVodeGetNumNonlinSolvIters(mem, &s.nonlinear_iters);
    CVodeGetNumNonlinSolvConvFails(mem, &s.nonlinear_conv_fails);
    CVodeGetNumErrTestFails(mem, &netf);
    CVodeGetNumStepSolveFails(mem, &nsf);
    s.rejected_steps = netf + nsf;
    s.recoverable_rhs_failures = cb.rec.recoverable;
  };

  if (!observer(t0, y0)) {
    res.ok = res.stopped_by_observer = true;
    res.message = "bdf: stopped by the observer at t = " + formatNumber(t0, 10);
    return res;
  }
  for (double tout : output_times) {
    double tret = tout;
    const int flag = CVode(mem, tout, y.get(), &tret, CV_NORMAL);
    if (cb.rec.exception) std::rethrow_exception(cb.rec.exception);
    if (flag < 0) {
      double tcur = res.t_reached;
      CVodeGetCurrentTime(mem, &tcur);  // last accepted step (CVODE restores tn on failure)
      res.t_reached = tcur;
      detail::FailureReport f;
      f.method = name();
      f.t_reached = tcur;
      bool rhs_related = false;
      f.reason = reasonFor(flag, sp.max_steps > 0 ? sp.max_steps : 500, tout, rhs_related);
      f.rhs_related = rhs_related;
      f.flag_name = flagName(flag);
      f.sundials_text = msgs.last_error;
      if ((flag == CV_TOO_MUCH_WORK || flag == CV_ERR_FAILURE || flag == CV_CONV_FAILURE ||
           flag == CV_TOO_MUCH_ACC) &&
          CVodeGetErrWeights(mem, ewt.get()) == CV_SUCCESS &&
          CVodeGetEstLocalErrors(mem, ele.get()) == CV_SUCCESS)
        f.weighted_errors = detail::largestWeightedErrors(ele.get(), ewt.get(), n);
      detail::reportFailure(f, cb.rec, names, res);
      res.ok = false;
      res.t_fail = tcur;
      collect();
      return res;
    }
    collect();
    yout = detail::map(y.get(), n);
    res.t_reached = tout;
    if (!observer(tout, yout)) {
      res.ok = res.stopped_by_observer = true;
      res.message = "bdf: stopped by the observer at t = " + formatNumber(tout, 10);
      return res;
    }
    if (progress) progress(tout, res.stats);
  }
  collect();
  res.ok = true;
  return res;
}

}  // namespace rb::integ
