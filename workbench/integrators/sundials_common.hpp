#pragma once
// Internal: RAII for SUNDIALS objects, message capture, callback wrappers and failure reports
// shared by the dopri5 (ARKODE), bdf (CVODE) and ida (IDA) adapters.
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "workbench/integrators/detail.hpp"
#include "workbench/integrators/integrator.hpp"
#include "workbench/integrators/ode.hpp"

namespace rb::integ::detail {

class SunContext {
 public:
  SunContext();
  ~SunContext();
  SunContext(const SunContext&) = delete;
  SunContext& operator=(const SunContext&) = delete;
  operator SUNContext() const { return ctx_; }

 private:
  SUNContext ctx_ = nullptr;
};

struct NVectorFree {
  void operator()(N_Vector v) const { N_VDestroy(v); }
};
struct SunMatrixFree {
  void operator()(SUNMatrix m) const { SUNMatDestroy(m); }
};
struct SunLinSolFree {
  void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); }
};
using NVector = std::unique_ptr<std::remove_pointer_t<N_Vector>, NVectorFree>;
using SunMatrix = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, SunMatrixFree>;
using SunLinSol = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, SunLinSolFree>;

NVector makeVector(long n, SUNContext ctx);
inline double* data(N_Vector v) {
  return N_VGetArrayPointer(v);
}
inline Eigen::Map<Eigen::VectorXd> map(N_Vector v, long n) {
  return {N_VGetArrayPointer(v), n};
}

// Solver memory (CVodeFree, ERKStepFree, IDAFree).
class SolverMem {
 public:
  SolverMem(void* mem, void (*free_fn)(void**)) : mem_(mem), free_(free_fn) {}
  ~SolverMem() {
    if (mem_) free_(&mem_);
  }
  SolverMem(const SolverMem&) = delete;
  SolverMem& operator=(const SolverMem&) = delete;
  operator void*() const { return mem_; }
  explicit operator bool() const { return mem_ != nullptr; }

 private:
  void* mem_;
  void (*free_)(void**);
};

// Messages SUNDIALS would print to stderr, kept for our failure message instead.
struct SundialsMessages {
  std::string last_error;  // "CVode: At t = 0.5, mxstep steps taken before reaching tout."
  long warnings = 0;
  std::string last_warning;
};
// Matches CVErrHandlerFn, ARKErrHandlerFn and IDAErrHandlerFn; eh_data is a SundialsMessages*.
void captureMessage(int error_code, const char* module, const char* function, char* msg,
                    void* eh_data);

// user_data of the ODE callbacks (CVODE and ARKODE share the signatures).
struct OdeCallbackData {
  OdeSystem* sys = nullptr;
  long n = 0;
  RhsRecord rec;
  long jacobian_rhs_evals = 0;    // evaluations of a difference Jacobian of ours
  void* jacobian_data = nullptr;  // what that Jacobian callback needs (bdf.cpp)
};
// CVRhsFn / ARKRhsFn: calls sys->rhs; NaN/Inf in y or ydot is returned as recoverable (1) so the
// solver shrinks the step; exceptions are stored in rec.exception and returned as fatal (-1).
int odeRhs(double t, N_Vector y, N_Vector ydot, void* user_data);
// CVLsJacFn: the model's analytic Jacobian (matrix zeroed first).
int odeJac(double t, N_Vector y, N_Vector fy, SUNMatrix J, void* user_data, N_Vector tmp1,
           N_Vector tmp2, N_Vector tmp3);

// Up to `count` components with the largest |ele_i * ewt_i| (> 0), largest first.
std::vector<std::pair<int, double>> largestWeightedErrors(N_Vector ele, N_Vector ewt, long n,
                                                          int count = 3);

// The common failure message of the SUNDIALS adapters:
//   "<method>: failed at t = <t>: <reason> [<FLAG>]; <rhs/NaN detail>; SUNDIALS: <text>;
//    largest weighted local errors: x1 (3.2), x0 (0.4)"
// The NaN/Inf detail takes precedence when rec saw a non-finite value at or after t_reached
// (offending = the non-finite components, no local errors); otherwise offending = the components
// with the largest weighted local errors, if given.
struct FailureReport {
  std::string method;
  double t_reached = 0.0;
  std::string reason;
  std::string flag_name;
  bool rhs_related = false;  // the flag is about the rhs/residual: add rec's last failure
  std::string sundials_text;
  std::vector<std::pair<int, double>> weighted_errors;
};
// The failure into res: its message, the blamed components, its kind (NonFinite, Model, else by
// the SUNDIALS flag) and, when the model refused, the model's reason.
void reportFailure(const FailureReport& f, const RhsRecord& rec, const NameFn& name,
                   RunResult& res);

// SUNDIALS returns a malloc'ed string for flag names.
std::string takeFlagName(char* name);

// A setup call (XxxInit, XxxSetYyy) returned an error: the run fails at t0 with that call, its flag
// name and SUNDIALS' message. Returns false so callers can write `if (!ok) return res;`.
bool setupFailed(RunResult& res, std::string_view method, double t0, const char* call,
                 const std::string& flag_name, const SundialsMessages& msgs);

}  // namespace rb::integ::detail
