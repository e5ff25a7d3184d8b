#include "workbench/integrators/dense_lu.hpp"

#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <memory>
#include <utility>

namespace rb::integ::detail {
namespace {

// First row l >= k with the largest |a_lk| (strict comparison: ties keep the upper row, a NaN
// candidate is never chosen; the rule of SUNDIALS' denseGETRF).
Eigen::Index pivotRow(const Eigen::Ref<Eigen::MatrixXd>& a, Eigen::Index k) {
  Eigen::Index l = k;
  double best = std::abs(a(k, k));
  for (Eigen::Index i = k + 1; i < a.rows(); ++i) {
    const double v = std::abs(a(i, k));
    if (v > best) {
      best = v;
      l = i;
    }
  }
  return l;
}

}  // namespace

long DenseLu::factor(Eigen::Ref<Eigen::MatrixXd> a) {
  const Eigen::Index n = a.cols();
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index l = pivotRow(a, k);
    pivots_[static_cast<std::size_t>(k)] = static_cast<long>(l);
    if (a(l, k) == 0.0) return static_cast<long>(k) + 1;
    if (l != k) a.row(k).swap(a.row(l));  // whole rows, so the multipliers of L follow
    const Eigen::Index m = n - k - 1;     // rows (and columns) below (right of) the pivot
    // Multipliers l_ik = a_ik / a_kk, formed as a_ik * (1 / a_kk) like DGEFA.
    const double mult = 1.0 / a(k, k);
    a.col(k).tail(m) *= mult;
    // Rank-1 update of the trailing block, one column at a time: a_ij -= a_kj l_ik.
    for (Eigen::Index j = k + 1; j < n; ++j) {
      const double a_kj = a(k, j);
      if (a_kj != 0.0) a.col(j).tail(m) -= a_kj * a.col(k).tail(m);
    }
  }
  return 0;
}

void DenseLu::solve(const Eigen::Ref<const Eigen::MatrixXd>& lu,
                    Eigen::Ref<Eigen::VectorXd> b) const {
  const Eigen::Index n = lu.cols();
  // b := P b, the interchanges in the order of the factorisation.
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto pk = static_cast<Eigen::Index>(pivots_[static_cast<std::size_t>(k)]);
    if (pk != k) std::swap(b(k), b(pk));
  }
  // L y = b (unit diagonal), column-oriented forward substitution.
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    const Eigen::Index m = n - k - 1;
    b.tail(m) -= b(k) * lu.col(k).tail(m);
  }
  // U x = y, column-oriented back substitution.
  for (Eigen::Index k = n - 1; k > 0; --k) {
    b(k) /= lu(k, k);
    b.head(k) -= b(k) * lu.col(k).head(k);
  }
  if (n > 0) b(0) /= lu(0, 0);
}

namespace {

struct DenseLuContent {
  explicit DenseLuContent(long n) : lu(n) {}
  DenseLu lu;
  long last_flag = 0;
};

DenseLuContent* content(SUNLinearSolver s) {
  return static_cast<DenseLuContent*>(s->content);
}

Eigen::Map<Eigen::MatrixXd> denseMap(SUNMatrix a) {
  return {SUNDenseMatrix_Data(a), static_cast<Eigen::Index>(SUNDenseMatrix_Rows(a)),
          static_cast<Eigen::Index>(SUNDenseMatrix_Columns(a))};
}

bool fits(SUNMatrix a, long n) {
  return a != nullptr && SUNMatGetID(a) == SUNMATRIX_DENSE && SUNDenseMatrix_Rows(a) == n &&
         SUNDenseMatrix_Columns(a) == n;
}

SUNLinearSolver_Type getType(SUNLinearSolver) {
  return SUNLINEARSOLVER_DIRECT;
}

SUNLinearSolver_ID getId(SUNLinearSolver) {
  return SUNLINEARSOLVER_CUSTOM;
}

int initialize(SUNLinearSolver s) {
  content(s)->last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

int setup(SUNLinearSolver s, SUNMatrix a) {
  DenseLuContent* c = content(s);
  if (!fits(a, c->lu.size())) {
    c->last_flag = SUNLS_ILL_INPUT;
    return SUNLS_ILL_INPUT;
  }
  const long zero_pivot = c->lu.factor(denseMap(a));
  c->last_flag = zero_pivot;  // like SUNLinSol_Dense: the 1-based step of the zero pivot
  return zero_pivot > 0 ? SUNLS_LUFACT_FAIL : SUNLS_SUCCESS;
}

int solve(SUNLinearSolver s, SUNMatrix a, N_Vector x, N_Vector b, double /*tol*/) {
  DenseLuContent* c = content(s);
  const long n = c->lu.size();
  double* xd = N_VGetArrayPointer(x);
  const double* bd = N_VGetArrayPointer(b);
  if (!fits(a, n) || xd == nullptr || bd == nullptr) {
    c->last_flag = SUNLS_ILL_INPUT;
    return SUNLS_ILL_INPUT;
  }
  Eigen::Map<Eigen::VectorXd> xv(xd, n);
  if (xd != bd) xv = Eigen::Map<const Eigen::VectorXd>(bd, n);
  c->lu.solve(denseMap(a), xv);
  c->last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

sunindextype lastFlag(SUNLinearSolver s) {
  return content(s)->last_flag;
}

int space(SUNLinearSolver s, long* lenrw, long* leniw) {
  *lenrw = 0;
  *leniw = 2 + content(s)->lu.size();
  return SUNLS_SUCCESS;
}

int freeSolver(SUNLinearSolver s) {
  if (s == nullptr) return SUNLS_SUCCESS;
  delete content(s);
  s->content = nullptr;
  SUNLinSolFreeEmpty(s);
  return SUNLS_SUCCESS;
}

// Dense matrix operations. SUNDIALS' checks: both matrices dense and of the same shape.
bool sameShape(SUNMatrix a, SUNMatrix b) {
  return SUNMatGetID(a) == SUNMATRIX_DENSE && SUNMatGetID(b) == SUNMATRIX_DENSE &&
         SUNDenseMatrix_Rows(a) == SUNDenseMatrix_Rows(b) &&
         SUNDenseMatrix_Columns(a) == SUNDenseMatrix_Columns(b);
}

int matCopy(SUNMatrix a, SUNMatrix b) {  // b := a
  if (!sameShape(a, b)) return SUNMAT_ILL_INPUT;
  denseMap(b) = denseMap(a);
  return SUNMAT_SUCCESS;
}

int matScaleAddI(double c, SUNMatrix a) {  // a := c a + I
  if (SUNMatGetID(a) != SUNMATRIX_DENSE) return SUNMAT_ILL_INPUT;
  auto m = denseMap(a);
  m *= c;
  m.diagonal().array() += 1.0;
  return SUNMAT_SUCCESS;
}

int matZero(SUNMatrix a) {
  denseMap(a).setZero();
  return SUNMAT_SUCCESS;
}

SUNMatrix withOurOps(SUNMatrix a);

SUNMatrix matClone(SUNMatrix a) {
  return withOurOps(SUNDenseMatrix(SUNDenseMatrix_Rows(a), SUNDenseMatrix_Columns(a), a->sunctx));
}

SUNMatrix withOurOps(SUNMatrix a) {
  if (a == nullptr) return nullptr;
  a->ops->copy = matCopy;
  a->ops->scaleaddi = matScaleAddI;
  a->ops->zero = matZero;
  a->ops->clone = matClone;
  return a;
}

}  // namespace

SUNMatrix newDenseMatrix(long n, SUNContext ctx) {
  return withOurOps(SUNDenseMatrix(n, n, ctx));
}

SUNLinearSolver newDenseLuSolver(long n, SUNContext ctx) {
  auto c = std::make_unique<DenseLuContent>(n);
  SUNLinearSolver s = SUNLinSolNewEmpty(ctx);
  if (s == nullptr) return nullptr;
  s->content = c.release();
  s->ops->gettype = getType;
  s->ops->getid = getId;
  s->ops->initialize = initialize;
  s->ops->setup = setup;
  s->ops->solve = solve;
  s->ops->lastflag = lastFlag;
  s->ops->space = space;
  s->ops->free = freeSolver;
  return s;
}

}  // namespace rb::integ::detail
