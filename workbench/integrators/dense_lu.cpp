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

namespace {

// y_i -= alpha x_i, i < m: the element update of DGEFA/DGESL (one multiply, one subtract). A plain
// loop over raw columns: the columns are short (n <= 100), where a generic expression's set-up
// costs as much as the arithmetic.
inline void subtractScaled(double alpha, const double* __restrict x, double* __restrict y,
                           Eigen::Index m) {
  for (Eigen::Index i = 0; i < m; ++i) y[i] -= alpha * x[i];
}

}  // namespace

long DenseLu::factor(Eigen::Ref<Eigen::MatrixXd> a) {
  const Eigen::Index n = a.cols();
  const Eigen::Index ld = a.outerStride();
  double* base = a.data();
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index l = pivotRow(a, k);
    pivots_[static_cast<std::size_t>(k)] = static_cast<long>(l);
    if (a(l, k) == 0.0) return static_cast<long>(k) + 1;
    if (l != k) a.row(k).swap(a.row(l));  // whole rows, so the multipliers of L follow
    const Eigen::Index m = n - k - 1;     // rows (and columns) below (right of) the pivot
    // Multipliers l_ik = a_ik / a_kk, formed as a_ik * (1 / a_kk) like DGEFA.
    double* lk = base + k * ld + k + 1;
    const double mult = 1.0 / a(k, k);
    for (Eigen::Index i = 0; i < m; ++i) lk[i] *= mult;
    // Rank-1 update of the trailing block, one column at a time: a_ij -= a_kj l_ik.
    for (Eigen::Index j = k + 1; j < n; ++j) {
      double* aj = base + j * ld;
      const double a_kj = aj[k];
      if (a_kj != 0.0) subtractScaled(a_kj, lk, aj + k + 1, m);
    }
  }
  return 0;
}

void DenseLu::solve(const Eigen::Ref<const Eigen::MatrixXd>& lu,
                    Eigen::Ref<Eigen::VectorXd> b) const {
  const Eigen::Index n = lu.cols();
  const Eigen::Index ld = lu.outerStride();
  const double* base = lu.data();
  double* x = b.data();
  // b := P b, the interchanges in the order of the factorisation.
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto pk = static_cast<Eigen::Index>(pivots_[static_cast<std::size_t>(k)]);
    if (pk != k) std::swap(x[k], x[pk]);
  }
  // L y = b (unit diagonal), column-oriented forward substitution.
  for (Eigen::Index k = 0; k + 1 < n; ++k)
    subtractScaled(x[k], base + k * ld + k + 1, x + k + 1, n - k - 1);
  // U x = y, column-oriented back substitution.
  for (Eigen::Index k = n - 1; k > 0; --k) {
    x[k] /= base[k * ld + k];
    subtractScaled(x[k], base + k * ld, x, k);
  }
  if (n > 0) x[0] /= base[0];
}

CopyRowElimination::CopyRowElimination(long n, const std::vector<int>& copy_of) : lu_(0) {
  const auto size = static_cast<std::size_t>(n);
  std::vector<bool> is_copy(size, false);
  if (copy_of.size() == size) {
    for (std::size_t p = 0; p < size; ++p) {
      const int k = copy_of[p];
      if (k >= 0 && k < n && copy_of[static_cast<std::size_t>(k)] < 0 &&
          static_cast<std::size_t>(k) != p)
        is_copy[p] = true;
    }
  }
  kept_slot_.assign(size, -1);
  for (std::size_t i = 0; i < size; ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    if (is_copy[i]) {
      copy_rows_.push_back(row);
      targets_.push_back(copy_of[i]);
    } else {
      kept_slot_[i] = static_cast<Eigen::Index>(kept_.size());
      kept_.push_back(row);
    }
  }
  const auto m = static_cast<Eigen::Index>(kept_.size());
  const auto np = static_cast<Eigen::Index>(copy_rows_.size());
  leading_ = np > 0 && copy_rows_.back() == np - 1;  // copy rows 0 .. np-1, kept rows after
  reduced_.resize(m, m);
  coupling_.resize(m, np);
  diagonal_.resize(np);
  target_entry_.resize(np);
  rhs_.resize(m);
  copy_rhs_.resize(np);
  lu_ = DenseLu(m);
}

bool CopyRowElimination::structured(const Eigen::Ref<const Eigen::MatrixXd>& a) const {
  // Column by column (contiguous): the copy rows hold no entry but M_pp and M_pk.
  for (Eigen::Index j = 0; j < a.cols(); ++j) {
    const double* col = a.data() + j * a.outerStride();
    for (std::size_t c = 0; c < copy_rows_.size(); ++c) {
      const Eigen::Index p = copy_rows_[c];
      const bool allowed = j == p || j == targets_[c];
      if (col[p] == 0.0 ? (j == p) : !allowed) return false;
    }
  }
  return true;
}

long CopyRowElimination::factor(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  const auto m = static_cast<Eigen::Index>(kept_.size());
  if (leading_) {
    reduced_ = a.bottomRightCorner(m, m);
  } else {
    for (Eigen::Index jj = 0; jj < m; ++jj) {
      const auto col = a.col(kept_[static_cast<std::size_t>(jj)]);
      for (Eigen::Index ii = 0; ii < m; ++ii)
        reduced_(ii, jj) = col(kept_[static_cast<std::size_t>(ii)]);
    }
  }
  // C_ip = M_ip / M_pp, then M'_ik -= C_ip M_pk over the kept rows i.
  for (std::size_t c = 0; c < copy_rows_.size(); ++c) {
    const Eigen::Index p = copy_rows_[c], k = targets_[c];
    const auto cc = static_cast<Eigen::Index>(c);
    const auto col = a.col(p);
    const double inv = 1.0 / a(p, p);
    if (leading_) {
      coupling_.col(cc) = col.tail(m) * inv;
    } else {
      for (Eigen::Index ii = 0; ii < m; ++ii)
        coupling_(ii, cc) = col(kept_[static_cast<std::size_t>(ii)]) * inv;
    }
    diagonal_(cc) = a(p, p);
    target_entry_(cc) = a(p, k);
    reduced_.col(kept_slot_[static_cast<std::size_t>(k)]) -= a(p, k) * coupling_.col(cc);
  }
  return lu_.factor(reduced_);
}

void CopyRowElimination::solve(Eigen::Ref<Eigen::VectorXd> b) {
  const auto m = static_cast<Eigen::Index>(kept_.size());
  const auto np = static_cast<Eigen::Index>(copy_rows_.size());
  if (leading_) {
    copy_rhs_ = b.head(np);
    rhs_ = b.tail(m);
  } else {
    for (Eigen::Index ii = 0; ii < m; ++ii) rhs_(ii) = b(kept_[static_cast<std::size_t>(ii)]);
    for (Eigen::Index c = 0; c < np; ++c) copy_rhs_(c) = b(copy_rows_[static_cast<std::size_t>(c)]);
  }
  // b'_i = b_i - sum_p C_ip b_p
  rhs_.noalias() -= coupling_ * copy_rhs_;
  lu_.solve(reduced_, rhs_);
  if (leading_) {
    b.tail(m) = rhs_;
  } else {
    for (Eigen::Index ii = 0; ii < m; ++ii) b(kept_[static_cast<std::size_t>(ii)]) = rhs_(ii);
  }
  // x_p = (b_p - M_pk x_k) / M_pp
  for (Eigen::Index c = 0; c < np; ++c) {
    const auto cs = static_cast<std::size_t>(c);
    b(copy_rows_[cs]) = (copy_rhs_(c) - target_entry_(c) * b(targets_[cs])) / diagonal_(c);
  }
}

namespace {

struct DenseLuContent {
  DenseLuContent(long n, const std::vector<int>& copy_of) : lu(n), elimination(n, copy_of) {}
  DenseLu lu;
  CopyRowElimination elimination;
  bool reduced = false;  // the last setup factored the reduced matrix
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
  const auto m = denseMap(a);
  c->reduced = c->elimination.active() && c->elimination.structured(m);
  const long zero_pivot = c->reduced ? c->elimination.factor(m) : c->lu.factor(m);
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
  if (c->reduced)
    c->elimination.solve(xv);
  else
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

SUNLinearSolver newDenseLuSolver(long n, SUNContext ctx, const std::vector<int>& copy_of) {
  auto c = std::make_unique<DenseLuContent>(n, copy_of);
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
