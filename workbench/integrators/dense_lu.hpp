#pragma once
// Dense LU factorisation with partial pivoting for the Newton iteration matrices of bdf (CVODE,
// M = I - gamma J) and ida (IDA, J = dF/dy + c_j dF/dy'), and the SUNDIALS linear solver built on
// it, so that the cost of the linear algebra depends on our compiler flags and not on how the
// system's SUNDIALS library was built.
//
// The elimination is the right-looking column-oriented Gaussian elimination with row
// interchanges of LINPACK DGEFA/DGESL (Dongarra et al., LINPACK Users' Guide, 1979, ch. 1), the
// algorithm of SUNDIALS' own dense solver (denseGETRF/denseGETRS): the same pivot choice (first
// row of largest |a_ik|), the same operation per matrix element and the same order of operations.
// Every element update is one IEEE multiply and one subtract, whether or not the column loop is
// vectorised, so without fused multiply-add contraction the factors and solutions are
// bit-identical to SUNLinSol_Dense; only the speed changes.
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <Eigen/Dense>
#include <vector>

namespace rb::integ::detail {

class DenseLu {
 public:
  // Pivot storage for n x n matrices, allocated once.
  explicit DenseLu(long n) : pivots_(static_cast<std::size_t>(n), 0) {}
  long size() const { return static_cast<long>(pivots_.size()); }

  // Factors the column-major n x n matrix `a` in place: P A = L U with unit lower L below the
  // diagonal and U on and above it. Returns 0, or k + 1 if the pivot candidates of step k are all
  // exactly zero (the matrix is singular; `a` is then only partly factored).
  long factor(Eigen::Ref<Eigen::MatrixXd> a);
  // Solves A x = b in place (b becomes x) with the factors of the last successful factor(a).
  void solve(const Eigen::Ref<const Eigen::MatrixXd>& lu, Eigen::Ref<Eigen::VectorXd> b) const;

 private:
  std::vector<long> pivots_;  // row interchanged with row k at step k
};

// Newton matrices M = I - gamma J (bdf) or c_j I - df/dy (ida) of a system with copy rows
// (JacobianPattern::copy_of[p] = k: f_p = y_k identically, the positions of a second-order
// system) have in row p only M_pp and M_pk. Eliminating x_p = (b_p - M_pk x_k) / M_pp from the
// other rows leaves the system of the remaining m = n - |copy rows| unknowns
//   M'_ik = M_ik - M_ip M_pk / M_pp,   b'_i = b_i - M_ip b_p / M_pp,
// the Newton matrix I - gamma B - gamma^2 A of the second-order form (Hairer and Wanner, Solving
// ODEs II, section IV.8, "second order systems"), factored with DenseLu in (m/n)^3 of the work.
class CopyRowElimination {
 public:
  // copy_of: JacobianPattern::copy_of (empty: no copy rows). A target that is itself a copy row
  // is not eliminated (its row stays in the reduced system).
  CopyRowElimination(long n, const std::vector<int>& copy_of);
  bool active() const { return !copy_rows_.empty(); }
  // Whether every copy row p of a has no non-zero entry but M_pp != 0 and M_pk.
  bool structured(const Eigen::Ref<const Eigen::MatrixXd>& a) const;
  // Forms and factors the reduced matrix of a (a is not changed). Returns 0, or the 1-based step
  // of a zero pivot of the reduced matrix.
  long factor(const Eigen::Ref<const Eigen::MatrixXd>& a);
  // Solves a x = b in place with the factors of the last factor(a).
  void solve(Eigen::Ref<Eigen::VectorXd> b);

 private:
  std::vector<Eigen::Index> copy_rows_, targets_;  // p and k = copy_of[p]
  std::vector<Eigen::Index> kept_;                 // the other rows, ascending
  std::vector<Eigen::Index> kept_slot_;            // per row: its place in kept_, or -1
  bool leading_ = false;      // the copy rows are the first ones (the vehicle layout)
  Eigen::MatrixXd reduced_;   // M', then its LU factors
  Eigen::MatrixXd coupling_;  // C_ip = M_ip / M_pp over the kept rows i and copy rows p
  Eigen::VectorXd diagonal_, target_entry_;  // M_pp, M_pk per copy row
  Eigen::VectorXd rhs_, copy_rhs_;
  DenseLu lu_;
};

// A SUNLinearSolver of type SUNLINEARSOLVER_DIRECT (id SUNLINEARSOLVER_CUSTOM) for n x n
// SUNDenseMatrix systems. Setup factors the matrix in place, like SUNLinSol_Dense, and returns
// SUNLS_LUFACT_FAIL (> 0: recoverable, CVODE and IDA retry with a smaller step) for a singular
// matrix; solve copies b into x and applies the factors. Neither allocates. Returns nullptr if the
// solver cannot be created; free it with SUNLinSolFree.
// With copy rows (copy_of non-empty) setup eliminates them (CopyRowElimination) whenever the
// matrix has their structure, and factors the whole matrix otherwise.
SUNLinearSolver newDenseLuSolver(long n, SUNContext ctx, const std::vector<int>& copy_of = {});

// An n x n SUNDenseMatrix (SUNDIALS' column-major content, id SUNMATRIX_DENSE, so CVODE's and
// IDA's difference-quotient Jacobians fill it as usual) whose operations used once per linear
// solver setup are ours: copy (the saved Jacobian into the Newton matrix and back), scale-add-I
// (M = I - gamma J), zero, and clone (so the saved Jacobian CVODE clones from it gets the same
// operations). Each computes the same element operations as SUNDIALS' dense versions, so the
// results are bit-identical. Returns nullptr if the matrix cannot be created; free it with
// SUNMatDestroy.
SUNMatrix newDenseMatrix(long n, SUNContext ctx);

}  // namespace rb::integ::detail
