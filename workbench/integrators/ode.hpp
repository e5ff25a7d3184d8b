#pragma once
// The one narrow interface between models and integrators. Integrators see vectors only.
// Return-code contract of the right-hand side follows SUNDIALS: 0 ok, > 0 recoverable (the step is
// retried smaller where the method allows: a contact point outside its table, a Newton iteration
// that did not converge), < 0 fatal.
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace rb::integ {

// Structure of the Jacobian df/dy known from the model, not from numerical values.
//   rows[j]: the rows i whose f_i may depend on y_j, sorted; conservative: a row that might
//     depend on y_j is listed. Empty (no columns) when the model gives no structure (dense).
//   copy_of[i] = k when f_i(t, y) = y_k identically (a position whose derivative is its rate
//     state), -1 otherwise; row i of df/dy is then exactly e_k^T. Empty when unknown.
// Difference-quotient Jacobians perturb columns that share no row in one evaluation (Curtis,
// Powell and Reid, "On the estimation of sparse Jacobian matrices", J. Inst. Maths Applics 13,
// 1974), and the Newton solvers eliminate the copy rows before factoring (dense_lu.hpp).
struct JacobianPattern {
  std::vector<std::vector<int>> rows;
  std::vector<int> copy_of;

  bool empty() const { return rows.empty(); }
};

// Why a model refused its last evaluation, in the model's own terms: a reason from the model's
// name table ("wheel_lift", "table_range") and the body it concerns ("ws1"); empty when it does
// not say.
struct ModelFailure {
  std::string reason, body;
};

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual int size() const = 0;
  // ydot = f(t, y). y and ydot have size() entries; ydot must be fully written on success.
  virtual int rhs(double t, const double* y, double* ydot) = 0;
  // Optional analytic Jacobian J = df/dy (dense, size() x size()).
  virtual bool hasJacobian() const { return false; }
  virtual int jacobian(double /*t*/, const double* /*y*/, const double* /*f*/,
                       Eigen::Ref<Eigen::MatrixXd> /*J*/) {
    return -1;
  }
  // Structural sparsity of df/dy (see JacobianPattern); default: none known (dense).
  virtual JacobianPattern jacobianPattern() const { return {}; }
  // Components whose derivative depends stiffly on the component itself (a large negative
  // diagonal Jacobian entry, e.g. a free wheelset spin rate under its creep forces): the
  // fixed-step methods can integrate them exponentially (exponential.hpp). Default: none.
  virtual std::vector<int> stiffComponents() const { return {}; }
  // Name of state component i for failure messages ("ws1.y"); default "y[i]".
  virtual std::string componentName(int i) const { return "y[" + std::to_string(i) + "]"; }
  // Human-readable reason for the last non-zero return of rhs(); empty if none.
  virtual std::string lastError() const { return {}; }
  // The same as a record (what the result file's failure record holds); default: unknown.
  virtual ModelFailure lastFailure() const { return {}; }
};

// Index-reduced DAE F(t, y, yp) = 0 for IDA (embedding vs. DAE comparisons).
class DaeSystem {
 public:
  virtual ~DaeSystem() = default;
  virtual int size() const = 0;
  virtual int residual(double t, const double* y, const double* yp, double* r) = 0;
  // Which components are differential (true) or algebraic (false); used for consistent ICs.
  virtual bool isDifferential(int i) const = 0;
  virtual std::string componentName(int i) const { return "y[" + std::to_string(i) + "]"; }
  virtual std::string lastError() const { return {}; }
};

}  // namespace rb::integ
