#include <ida/ida.h>
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

// What IDA integrates: a DaeSystem, or an OdeSystem as F = y' - f(t, y).
class ResidualModel {
 public:
  virtual ~ResidualModel() = default;
  virtual int residual(double t, const double* y, const double* yp, double* r) = 0;
  virtual bool isDifferential(int i) const = 0;
  virtual std::string componentName(int i) const = 0;
  virtual std::string lastError() const = 0;
  virtual ModelFailure lastFailure() const { return {}; }
  virtual const char* callName() const = 0;      // "residual", "right-hand side"
  virtual const char* residualName() const = 0;  // what a NaN/Inf is in: "residual", "derivative"
  virtual bool hasJacobian() const { return false; }
  // dF/dy + c_j dF/dy'
  virtual int jacobian(double, double, const double*, const double*, const double*,
                       Eigen::Ref<Eigen::MatrixXd>) {
    return -1;
  }
  // JacobianPattern::copy_of of the system (empty: none).
  virtual std::vector<int> copyRows() const { return {}; }
  // The solver memory and error-weight vector a difference Jacobian of ours reads, and the
  // evaluations it spent.
  virtual void attach(void* /*ida_mem*/, N_Vector /*ewt*/) {}
  virtual long jacobianEvaluations() const { return 0; }
};

class DaeModel final : public ResidualModel {
 public:
  explicit DaeModel(DaeSystem& s) : s_(s) {}
  int residual(double t, const double* y, const double* yp, double* r) override {
    return s_.residual(t, y, yp, r);
  }
  bool isDifferential(int i) const override { return s_.isDifferential(i); }
  std::string componentName(int i) const override { return s_.componentName(i); }
  std::string lastError() const override { return s_.lastError(); }
  const char* callName() const override { return "residual"; }
  const char* residualName() const override { return "residual"; }

 private:
  DaeSystem& s_;
};

class OdeModel final : public ResidualModel {
 public:
  OdeModel(OdeSystem& s, bool use_jacobian)
      : s_(s), use_jac_(use_jacobian), f_(s.size()), y_(s.size()), ft_(s.size()), inc_(s.size()) {
    JacobianPattern p = s.jacobianPattern();
    copy_of_ = p.copy_of;
    if (!use_jac_ && !p.empty()) grouped_.emplace(s.size(), std::move(p));
  }
  int residual(double t, const double* y, const double* yp, double* r) override {
    const int rc = s_.rhs(t, y, r);
    if (rc != 0) return rc;
    for (long i = 0; i < f_.size(); ++i) r[i] = yp[i] - r[i];
    return 0;
  }
  bool isDifferential(int) const override { return true; }
  std::string componentName(int i) const override { return s_.componentName(i); }
  std::string lastError() const override { return s_.lastError(); }
  ModelFailure lastFailure() const override { return s_.lastFailure(); }
  const char* callName() const override { return "right-hand side"; }
  const char* residualName() const override { return "derivative"; }
  bool hasJacobian() const override { return use_jac_ || grouped_.has_value(); }
  int jacobian(double t, double cj, const double* y, const double* yp, const double* r,
               Eigen::Ref<Eigen::MatrixXd> J) override {
    for (long i = 0; i < f_.size(); ++i) f_[i] = yp[i] - r[i];  // f = y' - F
    const int rc = use_jac_ ? s_.jacobian(t, y, f_.data(), J) : differences(t, y, yp, J);
    if (rc != 0) return rc;
    J *= -1.0;
    J.diagonal().array() += cj;
    return 0;
  }
  std::vector<int> copyRows() const override { return copy_of_; }
  void attach(void* ida_mem, N_Vector ewt) override {
    mem_ = ida_mem;
    ewt_ = ewt;
  }
  long jacobianEvaluations() const override { return evaluations_; }

 private:
  // df/dy by grouped forward differences with the increments of IDA's own dense difference
  // quotient (idaLsDenseDQJac: inc_j = max(sqrt(u) max(|y_j|, |h y'_j|), 1 / w_j), signed like
  // h y'_j), at f_ = f(t, y).
  int differences(double t, const double* y, const double* yp, Eigen::Ref<Eigen::MatrixXd> J) {
    double hh = 0.0;
    if (IDAGetCurrentStep(mem_, &hh) != IDA_SUCCESS || IDAGetErrWeights(mem_, ewt_) != IDA_SUCCESS)
      return -1;
    const double srur = std::sqrt(DBL_EPSILON);
    const double* w = detail::data(ewt_);
    for (long j = 0; j < y_.size(); ++j) {
      y_[j] = y[j];
      double inc = std::max(srur * std::max(std::abs(y[j]), std::abs(hh * yp[j])), 1.0 / w[j]);
      if (hh * yp[j] < 0.0) inc = -inc;
      inc_[j] = (y[j] + inc) - y[j];
    }
    const auto rhs = [&](double* yv, double* f) {
      ++evaluations_;
      return s_.rhs(t, yv, f);
    };
    return grouped_->forward(rhs, y_.data(), f_.data(), inc_.data(), ft_.data(), J);
  }

  OdeSystem& s_;
  bool use_jac_;
  Eigen::VectorXd f_, y_, ft_, inc_;
  std::vector<int> copy_of_;
  std::optional<GroupedDifferences> grouped_;
  void* mem_ = nullptr;
  N_Vector ewt_ = nullptr;
  long evaluations_ = 0;
};

struct DaeCallbackData {
  ResidualModel* model = nullptr;
  long n = 0;
  detail::RhsRecord rec;
};

int idaRes(double t, N_Vector y, N_Vector yp, N_Vector r, void* user_data) {
  auto* d = static_cast<DaeCallbackData*>(user_data);
  try {
    const double* yv = detail::data(y);
    const double* ypv = detail::data(yp);
    double* rv = detail::data(r);
    if (!detail::allFinite(yv, d->n)) {
      d->rec.recordNonFinite(t, "state", yv, d->n);
      ++d->rec.recoverable;
      return 1;
    }
    if (!detail::allFinite(ypv, d->n)) {
      d->rec.recordNonFinite(t, "state derivative", ypv, d->n);
      ++d->rec.recoverable;
      return 1;
    }
    const int rc = d->model->residual(t, yv, ypv, rv);
    if (rc != 0) {
      d->rec.recordCode(rc, t, d->model->callName(), d->model->lastError(),
                        d->model->lastFailure());
      if (rc > 0) ++d->rec.recoverable;
      return rc;
    }
    if (!detail::allFinite(rv, d->n)) {
      d->rec.recordNonFinite(t, d->model->residualName(), rv, d->n);
      ++d->rec.recoverable;
      return 1;
    }
    return 0;
  } catch (...) {
    d->rec.exception = std::current_exception();
    return -1;
  }
}

int idaJac(double t, double cj, N_Vector y, N_Vector yp, N_Vector r, SUNMatrix J, void* user_data,
           N_Vector, N_Vector, N_Vector) {
  auto* d = static_cast<DaeCallbackData*>(user_data);
  try {
    SUNMatZero(J);
    Eigen::Map<Eigen::MatrixXd> jm(SUNDenseMatrix_Data(J), d->n, d->n);
    const int rc =
        d->model->jacobian(t, cj, detail::data(y), detail::data(yp), detail::data(r), jm);
    if (rc != 0) {
      d->rec.recordCode(rc, t, "Jacobian", d->model->lastError(), d->model->lastFailure());
      if (rc > 0) ++d->rec.recoverable;
      return rc;
    }
    if (!detail::allFinite(jm.data(), d->n * d->n)) {
      d->rec.recordNonFinite(t, "Jacobian", jm.data(), d->n * d->n);
      d->rec.nonfinite_comps.clear();
      ++d->rec.recoverable;
      return 1;
    }
    return 0;
  } catch (...) {
    d->rec.exception = std::current_exception();
    return -1;
  }
}

std::string flagName(int flag) {
  return detail::takeFlagName(IDAGetReturnFlagName(flag));
}

std::string reasonFor(int flag, long max_steps, double tout, bool& rhs_related) {
  rhs_related = false;
  switch (flag) {
    case IDA_TOO_MUCH_WORK:
      return "too much work: " + std::to_string(max_steps) +
             " internal steps in one output interval without reaching t = " +
             formatNumber(tout, 10) + " (raise solver.max_steps)";
    case IDA_TOO_MUCH_ACC:
      return "the tolerances are too small for the machine precision";
    case IDA_ERR_FAIL:
      return "the error test failed repeatedly or with |h| = hmin";
    case IDA_CONV_FAIL:
      rhs_related = true;
      return "the Newton iteration failed to converge repeatedly or with |h| = hmin";
    case IDA_LSETUP_FAIL:
      rhs_related = true;
      return "the linear solver setup failed (Jacobian failure or singular iteration matrix)";
    case IDA_LSOLVE_FAIL:
      return "the linear solve failed";
    case IDA_RES_FAIL:
      rhs_related = true;
      return "the residual failed unrecoverably";
    case IDA_FIRST_RES_FAIL:
      rhs_related = true;
      return "the residual failed recoverably at its first call";
    case IDA_REP_RES_ERR:
      rhs_related = true;
      return "the residual failed recoverably too many times in a row";
    case IDA_NO_RECOVERY:
      rhs_related = true;
      return "the residual or linear solver failed recoverably and no recovery was possible";
    case IDA_LINESEARCH_FAIL:
      return "the line search of the initial-condition computation failed";
    case IDA_CONSTR_FAIL:
      return "the inequality constraints could not be met";
    default:
      return "IDA failed";
  }
}

RunResult runIda(std::string_view method, const SolverSpec& sp, ResidualModel& model, long n,
                 double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0, bool calc_ic,
                 long extra_rhs_evals, const std::vector<double>& output_times,
                 const Observer& observer, const Progress& progress) {
  const auto names = [&model](int i) { return model.componentName(i); };
  detail::SunContext ctx;
  DaeCallbackData cb;
  cb.model = &model;
  cb.n = n;
  detail::SundialsMessages msgs;
  detail::NVector yy = detail::makeVector(n, ctx);
  detail::NVector yp = detail::makeVector(n, ctx);
  detail::NVector id = detail::makeVector(n, ctx);
  detail::NVector ewt = detail::makeVector(n, ctx);
  detail::NVector ele = detail::makeVector(n, ctx);
  detail::map(yy.get(), n) = y0;
  detail::map(yp.get(), n) = yp0;
  detail::useCompiledVectorOps(yy.get());  // IDA's internal vectors are clones of yy
  detail::useCompiledVectorOps(yp.get());
  for (long i = 0; i < n; ++i)
    detail::data(id.get())[i] = model.isDifferential(static_cast<int>(i)) ? 1.0 : 0.0;
  Eigen::VectorXd yout(n);
  detail::SunMatrix A(detail::newDenseMatrix(n, ctx));
  detail::SunLinSol LS(detail::newDenseLuSolver(n, ctx, model.copyRows()));
  if (!A || !LS) throw std::bad_alloc();

  RunResult res;
  res.t_reached = t0;
  detail::SolverMem mem(IDACreate(ctx), IDAFree);
  if (!mem) throw std::bad_alloc();
  detail::NVector jac_ewt = detail::makeVector(n, ctx);
  model.attach(mem, jac_ewt.get());
  const auto setup = [&](int flag, const char* call) {
    return flag == IDA_SUCCESS || detail::setupFailed(res, method, t0, call, flagName(flag), msgs);
  };
  if (!setup(IDASetErrHandlerFn(mem, detail::captureMessage, &msgs), "IDASetErrHandlerFn") ||
      !setup(IDAInit(mem, idaRes, t0, yy.get(), yp.get()), "IDAInit") ||
      !setup(IDASetUserData(mem, &cb), "IDASetUserData") ||
      !setup(IDASStolerances(mem, sp.rtol, sp.atol), "IDASStolerances") ||
      !setup(IDASetLinearSolver(mem, LS.get(), A.get()), "IDASetLinearSolver") ||
      (model.hasJacobian() && !setup(IDASetJacFn(mem, idaJac), "IDASetJacFn")) ||
      !setup(IDASetMaxOrd(mem, sp.max_order), "IDASetMaxOrd") ||
      (sp.max_step > 0 && !setup(IDASetMaxStep(mem, sp.max_step), "IDASetMaxStep")) ||
      (sp.step > 0 && !setup(IDASetInitStep(mem, sp.step), "IDASetInitStep")) ||
      (sp.max_steps > 0 && !setup(IDASetMaxNumSteps(mem, sp.max_steps), "IDASetMaxNumSteps")) ||
      !setup(IDASetId(mem, id.get()), "IDASetId"))
    return res;

  const auto collect = [&] {
    Stats& s = res.stats;
    long netf = 0, nsf = 0;
    IDAGetNumSteps(mem, &s.steps);
    IDAGetNumResEvals(mem, &s.rhs_evals);
    s.rhs_evals += extra_rhs_evals;
    IDAGetNumLinResEvals(mem, &s.rhs_evals_jac);
    s.rhs_evals_jac += model.jacobianEvaluations();
    IDAGetNumJacEvals(mem, &s.jacobian_evals);
    IDAGetNumNonlinSolvIters(mem, &s.nonlinear_iters);
    IDAGetNumNonlinSolvConvFails(mem, &s.nonlinear_conv_fails);
    IDAGetNumErrTestFails(mem, &netf);
    IDAGetNumStepSolveFails(mem, &nsf);
    s.rejected_steps = netf + nsf;
    s.recoverable_rhs_failures = cb.rec.recoverable;
  };
  const long max_steps = sp.max_steps > 0 ? sp.max_steps : 500;
  const auto fail = [&](int flag, double tout, std::string prefix) {
    detail::FailureReport f;
    f.method = std::string(method);
    f.t_reached = res.t_reached;
    bool rhs_related = false;
    f.reason = prefix + reasonFor(flag, max_steps, tout, rhs_related);
    f.rhs_related = rhs_related;
    f.flag_name = flagName(flag);
    f.sundials_text = msgs.last_error;
    if ((flag == IDA_TOO_MUCH_WORK || flag == IDA_ERR_FAIL || flag == IDA_CONV_FAIL ||
         flag == IDA_TOO_MUCH_ACC) &&
        IDAGetErrWeights(mem, ewt.get()) == IDA_SUCCESS &&
        IDAGetEstLocalErrors(mem, ele.get()) == IDA_SUCCESS)
      f.weighted_errors = detail::largestWeightedErrors(ele.get(), ewt.get(), n);
    detail::reportFailure(f, cb.rec, names, res);
    res.ok = false;
    res.t_fail = res.t_reached;
    collect();
    return res;
  };

  if (calc_ic) {
    const double tout1 = output_times.empty() ? t0 + 1.0 : output_times.front();
    const int flag = IDACalcIC(mem, IDA_YA_YDP_INIT, tout1);
    if (cb.rec.exception) std::rethrow_exception(cb.rec.exception);
    if (flag < 0) return fail(flag, tout1, "consistent initial values (IDACalcIC) failed: ");
    IDAGetConsistentIC(mem, yy.get(), yp.get());
  }
  yout = detail::map(yy.get(), n);
  if (!observer(t0, yout)) {
    res.ok = res.stopped_by_observer = true;
    res.message = std::string(method) + ": stopped by the observer at t = " + formatNumber(t0, 10);
    return res;
  }
  for (double tout : output_times) {
    double tret = tout;
    const int flag = IDASolve(mem, tout, &tret, yy.get(), yp.get(), IDA_NORMAL);
    if (cb.rec.exception) std::rethrow_exception(cb.rec.exception);
    if (flag < 0) {
      double tcur = res.t_reached;
      IDAGetCurrentTime(mem, &tcur);  // last accepted step
      res.t_reached = tcur;
      return fail(flag, tout, "");
    }
    collect();
    yout = detail::map(yy.get(), n);
    res.t_reached = tout;
    if (!observer(tout, yout)) {
      res.ok = res.stopped_by_observer = true;
      res.message =
          std::string(method) + ": stopped by the observer at t = " + formatNumber(tout, 10);
      return res;
    }
    if (progress) progress(tout, res.stats);
  }
  collect();
  res.ok = true;
  return res;
}

}  // namespace

RunResult IdaIntegrator::runOde(OdeSystem& sys, double t0, const Eigen::VectorXd& y0,
                                const std::vector<double>& output_times, const Observer& observer,
                                const Progress& progress) {
  OdeModel model(sys, spec().jacobian == "auto" && sys.hasJacobian());
  // y'(t0) = f(t0, y0): consistent by construction, no IDACalcIC. This evaluation is not counted
  // by IDA; runIda adds it to rhs_evals.
  Eigen::VectorXd yp0(sys.size());
  const int rc = sys.rhs(t0, y0.data(), yp0.data());
  if (rc != 0 || !detail::allFinite(yp0.data(), yp0.size())) {
    RunResult res;
    res.ok = false;
    res.t_reached = res.t_fail = t0;
    res.stats.rhs_evals = 1;
    detail::RhsRecord rec;
    if (rc != 0) {
      rec.recordCode(rc, t0, "right-hand side", sys.lastError(), sys.lastFailure());
      res.message = "ida: failed at t = " + formatNumber(t0, 10) + ": " + rec.describeCode();
      res.failure = FailureKind::Model;
      res.cause = rec.model_failure;
    } else {
      res.failure = FailureKind::NonFinite;
      rec.recordNonFinite(t0, "derivative", yp0.data(), yp0.size());
      res.offending_components = rec.nonfinite_comps;
      res.message = "ida: failed at t = " + formatNumber(t0, 10) + ": " +
                    rec.describeNonFinite([&sys](int i) { return sys.componentName(i); });
    }
    return res;
  }
  return runIda(name(), spec(), model, sys.size(), t0, y0, yp0, false, 1, output_times, observer,
                progress);
}

RunResult IdaIntegrator::runDae(DaeSystem& sys, double t0, const Eigen::VectorXd& y0,
                                const Eigen::VectorXd& yp0, const std::vector<double>& output_times,
                                const Observer& observer, const Progress& progress) {
  DaeModel model(sys);
  return runIda(name(), spec(), model, sys.size(), t0, y0, yp0, true, 0, output_times, observer,
                progress);
}

}  // namespace rb::integ
