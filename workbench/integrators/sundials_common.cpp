#include "workbench/integrators/sundials_common.hpp"
#include "workbench/core/strings.hpp"

#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace rb::integ::detail {

SunContext::SunContext() {
  if (SUNContext_Create(nullptr, &ctx_) != 0 || ctx_ == nullptr)
    throw std::runtime_error("SUNContext_Create failed");
}

SunContext::~SunContext() {
  if (ctx_) SUNContext_Free(&ctx_);
}

NVector makeVector(long n, SUNContext ctx) {
  NVector v(N_VNew_Serial(static_cast<sunindextype>(n), ctx));
  if (!v) throw std::bad_alloc();
  N_VConst(0.0, v.get());
  return v;
}

void captureMessage(int error_code, const char* /*module*/, const char* function, char* msg,
                    void* eh_data) {
  auto* m = static_cast<SundialsMessages*>(eh_data);
  if (!m) return;
  try {
    std::string text = std::string(function ? function : "") + ": " + (msg ? msg : "");
    if (error_code < 0) {
      m->last_error = std::move(text);
    } else {
      ++m->warnings;
      m->last_warning = std::move(text);
    }
  } catch (...) {
    // Never let an exception cross the C boundary.
  }
}

int odeRhs(double t, N_Vector y, N_Vector ydot, void* user_data) {
  auto* d = static_cast<OdeCallbackData*>(user_data);
  try {
    const double* yv = data(y);
    double* dv = data(ydot);
    if (!allFinite(yv, d->n)) {
      d->rec.recordNonFinite(t, "state", yv, d->n);
      ++d->rec.recoverable;
      return 1;
    }
    const int rc = d->sys->rhs(t, yv, dv);
    if (rc != 0) {
      d->rec.recordCode(rc, t, "right-hand side", d->sys->lastError(), d->sys->lastFailure());
      if (rc > 0) ++d->rec.recoverable;
      return rc;
    }
    if (!allFinite(dv, d->n)) {
      d->rec.recordNonFinite(t, "derivative", dv, d->n);
      ++d->rec.recoverable;
      return 1;
    }
    return 0;
  } catch (...) {
    d->rec.exception = std::current_exception();
    return -1;
  }
}

int odeJac(double t, N_Vector y, N_Vector fy, SUNMatrix J, void* user_data, N_Vector, N_Vector,
           N_Vector) {
  auto* d = static_cast<OdeCallbackData*>(user_data);
  try {
    SUNMatZero(J);
    Eigen::Map<Eigen::MatrixXd> jm(SUNDenseMatrix_Data(J), d->n, d->n);  // column-major
    const int rc = d->sys->jacobian(t, data(y), data(fy), jm);
    if (rc != 0) {
      d->rec.recordCode(rc, t, "Jacobian", d->sys->lastError(), d->sys->lastFailure());
      if (rc > 0) ++d->rec.recoverable;
      return rc;
    }
    if (!allFinite(jm.data(), d->n * d->n)) {
      d->rec.recordNonFinite(t, "Jacobian", jm.data(), d->n * d->n);
      d->rec.nonfinite_comps.clear();  // matrix entries are not state components
      ++d->rec.recoverable;
      return 1;
    }
    return 0;
  } catch (...) {
    d->rec.exception = std::current_exception();
    return -1;
  }
}

std::vector<std::pair<int, double>> largestWeightedErrors(N_Vector ele, N_Vector ewt, long n,
                                                          int count) {
  std::vector<std::pair<int, double>> w;
  const double* e = data(ele);
  const double* s = data(ewt);
  for (long i = 0; i < n; ++i) {
    const double v = std::abs(e[i] * s[i]);
    if (v > 0.0 && std::isfinite(v)) w.emplace_back(static_cast<int>(i), v);
  }
  const auto k = std::min<std::size_t>(w.size(), static_cast<std::size_t>(count));
  std::partial_sort(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(k), w.end(),
                    [](const auto& a, const auto& b) { return a.second > b.second; });
  w.resize(k);
  return w;
}

namespace {

// The kind of a failure that is not a non-finite value the solver gave up on: the model's
// refusal, else the SUNDIALS flag's.
FailureKind flagKind(const FailureReport& f, const RhsRecord& rec) {
  if (f.rhs_related && rec.code != 0) return FailureKind::Model;
  // SUNDIALS' flag names are the same for CVODE (CV_), ARKODE (ARK_) and IDA (IDA_) after the
  // prefix: the kind follows the flag, never the text of a message.
  const std::string& n = f.flag_name;
  auto is = [&n](std::string_view suffix) {
    return n.size() >= suffix.size() &&
           n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (is("_TOO_MUCH_WORK")) return FailureKind::TooMuchWork;
  if (is("_ERR_FAILURE") || is("_ERR_FAIL") || is("_TOO_CLOSE") || is("_TOO_MUCH_ACC"))
    return FailureKind::StepSize;
  if (is("_CONV_FAILURE") || is("_CONV_FAIL") || is("_LSETUP_FAIL") || is("_LSOLVE_FAIL"))
    return FailureKind::Convergence;
  return FailureKind::Solver;
}

}  // namespace

void reportFailure(const FailureReport& f, const RhsRecord& rec, const NameFn& name,
                   RunResult& res) {
  std::string m = f.method + ": failed at t = " + formatNumber(f.t_reached, 10) + ": ";
  const double tol = 1e-12 * std::max(1.0, std::abs(f.t_reached));
  const bool blame_nonfinite = rec.nonfinite && rec.nonfinite_t >= f.t_reached - tol;
  res.failure = blame_nonfinite ? FailureKind::NonFinite : flagKind(f, rec);
  if (res.failure == FailureKind::Model) res.cause = rec.model_failure;
  std::vector<int>& offending = res.offending_components;
  offending.clear();
  if (blame_nonfinite) {
    m += rec.describeNonFinite(name) + " (the solver shrank the step and gave up: " + f.reason +
         ") [" + f.flag_name + "]";
    offending = rec.nonfinite_comps;
  } else {
    m += f.reason + " [" + f.flag_name + "]";
    if (f.rhs_related && rec.code != 0 && rec.t >= f.t_reached - tol)
      m += "; " + rec.describeCode();
  }
  if (!f.sundials_text.empty()) m += "; SUNDIALS: " + f.sundials_text;
  if (!blame_nonfinite && !f.weighted_errors.empty()) {
    m += "; largest weighted local errors: ";
    for (std::size_t i = 0; i < f.weighted_errors.size(); ++i) {
      if (i > 0) m += ", ";
      m += name(f.weighted_errors[i].first) + " (" + formatNumber(f.weighted_errors[i].second, 10) +
           ")";
    }
    for (const auto& [i, v] : f.weighted_errors) offending.push_back(i);
  }
  res.message = std::move(m);
}

std::string takeFlagName(char* name) {
  if (!name) return "unknown flag";
  std::string s(name);
  std::free(name);
  return s;
}

bool setupFailed(RunResult& res, std::string_view method, double t0, const char* call,
                 const std::string& flag_name, const SundialsMessages& msgs) {
  res.ok = false;
  res.failure = FailureKind::Setup;
  res.t_reached = res.t_fail = t0;
  res.message = std::string(method) + ": failed at t = " + formatNumber(t0, 10) +
                ": solver setup " + call + " returned " + flag_name;
  if (!msgs.last_error.empty()) res.message += "; SUNDIALS: " + msgs.last_error;
  return false;
}

}  // namespace rb::integ::detail
