// The dense LU linear solver of bdf and ida: solution of known systems, bit-identity with
// SUNDIALS' SUNLinSol_Dense (same algorithm, same operation order), singular matrices reported as
// the recoverable SUNLS_LUFACT_FAIL, and the generic SUNLinearSolver interface.
#include <gtest/gtest.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cstring>
#include <random>
#include <vector>

#include "workbench/integrators/dense_lu.hpp"
#include "workbench/integrators/sundials_common.hpp"

namespace rb::integ::detail {
namespace {

SunMatrix denseMatrix(const Eigen::MatrixXd& m, SUNContext ctx) {
  const auto n = static_cast<sunindextype>(m.rows());
  SunMatrix a(SUNDenseMatrix(n, n, ctx));
  Eigen::Map<Eigen::MatrixXd>(SUNDenseMatrix_Data(a.get()), m.rows(), m.cols()) = m;
  return a;
}

// A well-conditioned random matrix shaped like a Newton matrix I - gamma J.
Eigen::MatrixXd newtonLike(long n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd j(n, n);
  for (long c = 0; c < n; ++c)
    for (long r = 0; r < n; ++r) j(r, c) = u(gen) * (r == c ? 50.0 : 3.0);
  return Eigen::MatrixXd::Identity(n, n) - 0.01 * j;
}

TEST(DenseLu, SolvesKnownSystemNeedingPivoting) {
  // a_00 = 0 forces a row interchange at the first step.
  Eigen::MatrixXd a(3, 3);
  a << 0.0, 2.0, 1.0,  //
      1.0, 1.0, 1.0,   //
      4.0, -1.0, 3.0;
  const Eigen::Vector3d x_exact(1.0, -2.0, 3.0);
  Eigen::VectorXd b = a * x_exact;
  Eigen::MatrixXd lu = a;
  DenseLu solver(3);
  ASSERT_EQ(solver.factor(lu), 0);
  solver.solve(lu, b);
  EXPECT_LT((b - x_exact).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(DenseLu, SolvesIdentityAndOneByOne) {
  DenseLu one(1);
  Eigen::MatrixXd a = Eigen::MatrixXd::Constant(1, 1, 4.0);
  Eigen::VectorXd b = Eigen::VectorXd::Constant(1, 2.0);
  ASSERT_EQ(one.factor(a), 0);
  one.solve(a, b);
  EXPECT_EQ(b(0), 0.5);
}

TEST(DenseLu, SingularMatrixReportsZeroPivotStep) {
  Eigen::MatrixXd a(3, 3);
  a << 1.0, 2.0, 3.0,  //
      2.0, 4.0, 6.0,   //
      0.0, 0.0, 1.0;   // column 1 is twice column 0: after step 0 its candidates are zero
  DenseLu solver(3);
  EXPECT_EQ(solver.factor(a), 2);
  Eigen::MatrixXd z = Eigen::MatrixXd::Zero(3, 3);
  EXPECT_EQ(solver.factor(z), 1);
}

TEST(DenseLuSolver, BitIdenticalToSunLinSolDense) {
  SunContext ctx;
  for (const long n : {1L, 2L, 7L, 70L}) {
    const Eigen::MatrixXd m = newtonLike(n, 17U + static_cast<unsigned>(n));
    const SunMatrix a_ours = denseMatrix(m, ctx);
    const SunMatrix a_ref = denseMatrix(m, ctx);
    const NVector b = makeVector(n, ctx);
    const NVector x_ours = makeVector(n, ctx);
    const NVector x_ref = makeVector(n, ctx);
    for (long i = 0; i < n; ++i) data(b.get())[i] = std::sin(1.0 + static_cast<double>(i));
    const SunLinSol ours(newDenseLuSolver(n, ctx));
    const SunLinSol ref(SUNLinSol_Dense(b.get(), a_ref.get(), ctx));
    ASSERT_TRUE(ours && ref);
    ASSERT_EQ(SUNLinSolInitialize(ours.get()), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolInitialize(ref.get()), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSetup(ours.get(), a_ours.get()), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSetup(ref.get(), a_ref.get()), SUNLS_SUCCESS);
    const auto bytes = static_cast<std::size_t>(n * n) * sizeof(double);
    EXPECT_EQ(
        std::memcmp(SUNDenseMatrix_Data(a_ours.get()), SUNDenseMatrix_Data(a_ref.get()), bytes), 0)
        << "factors differ, n = " << n;
    ASSERT_EQ(SUNLinSolSolve(ours.get(), a_ours.get(), x_ours.get(), b.get(), 0.0), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSolve(ref.get(), a_ref.get(), x_ref.get(), b.get(), 0.0), SUNLS_SUCCESS);
    EXPECT_EQ(std::memcmp(data(x_ours.get()), data(x_ref.get()),
                          static_cast<std::size_t>(n) * sizeof(double)),
              0)
        << "solutions differ, n = " << n;
    const Eigen::VectorXd residual = m * map(x_ours.get(), n) - map(b.get(), n);
    EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(DenseLuSolver, GenericInterface) {
  SunContext ctx;
  const SunLinSol s(newDenseLuSolver(4, ctx));
  ASSERT_TRUE(s);
  EXPECT_EQ(SUNLinSolGetType(s.get()), SUNLINEARSOLVER_DIRECT);
  EXPECT_EQ(SUNLinSolGetID(s.get()), SUNLINEARSOLVER_CUSTOM);
  long lenrw = -1;
  long leniw = -1;
  EXPECT_EQ(SUNLinSolSpace(s.get(), &lenrw, &leniw), SUNLS_SUCCESS);
  EXPECT_EQ(lenrw, 0);
  EXPECT_EQ(leniw, 6);
  // A matrix of the wrong size is an unrecoverable input error.
  const SunMatrix wrong = denseMatrix(Eigen::MatrixXd::Identity(3, 3), ctx);
  EXPECT_EQ(SUNLinSolSetup(s.get(), wrong.get()), SUNLS_ILL_INPUT);
}

TEST(DenseLuSolver, SingularMatrixIsRecoverableFailure) {
  SunContext ctx;
  Eigen::MatrixXd m = newtonLike(5, 3U);
  m.col(3) = 2.0 * m.col(1);  // rank 4
  m.col(4).setZero();
  const SunMatrix a = denseMatrix(m, ctx);
  const SunLinSol s(newDenseLuSolver(5, ctx));
  ASSERT_EQ(SUNLinSolInitialize(s.get()), SUNLS_SUCCESS);
  const int rc = SUNLinSolSetup(s.get(), a.get());
  EXPECT_EQ(rc, SUNLS_LUFACT_FAIL);
  EXPECT_GT(rc, 0);  // > 0: CVODE and IDA treat it as recoverable and retry with a smaller step
  EXPECT_GT(SUNLinSolLastFlag(s.get()), 0);
}

TEST(DenseLuSolver, SolveInPlaceWhenXIsB) {
  SunContext ctx;
  const Eigen::MatrixXd m = newtonLike(6, 5U);
  const SunMatrix a = denseMatrix(m, ctx);
  const NVector x = makeVector(6, ctx);
  const Eigen::VectorXd x_exact = Eigen::VectorXd::LinSpaced(6, -1.0, 2.0);
  map(x.get(), 6) = m * x_exact;
  const SunLinSol s(newDenseLuSolver(6, ctx));
  ASSERT_EQ(SUNLinSolSetup(s.get(), a.get()), SUNLS_SUCCESS);
  ASSERT_EQ(SUNLinSolSolve(s.get(), a.get(), x.get(), x.get(), 0.0), SUNLS_SUCCESS);
  EXPECT_LT((map(x.get(), 6) - x_exact).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(DenseMatrix, OperationsBitIdenticalToSunMatrixDense) {
  SunContext ctx;
  constexpr long n = 9;
  const Eigen::MatrixXd m = newtonLike(n, 11U);
  const SunMatrix ours(newDenseMatrix(n, ctx));
  const SunMatrix ref = denseMatrix(m, ctx);
  ASSERT_TRUE(ours);
  EXPECT_EQ(SUNMatGetID(ours.get()), SUNMATRIX_DENSE);
  ASSERT_EQ(SUNMatCopy(ref.get(), ours.get()), SUNMAT_SUCCESS);  // SUNDIALS' copy into ours
  const SunMatrix saved(SUNMatClone(ours.get()));                // a clone has our operations
  ASSERT_EQ(SUNMatCopy(ours.get(), saved.get()), SUNMAT_SUCCESS);
  ASSERT_EQ(SUNMatScaleAddI(-0.37, saved.get()), SUNMAT_SUCCESS);
  ASSERT_EQ(SUNMatScaleAddI(-0.37, ref.get()), SUNMAT_SUCCESS);
  const auto bytes = static_cast<std::size_t>(n * n) * sizeof(double);
  EXPECT_EQ(std::memcmp(SUNDenseMatrix_Data(saved.get()), SUNDenseMatrix_Data(ref.get()), bytes),
            0);
  ASSERT_EQ(SUNMatZero(saved.get()), SUNMAT_SUCCESS);
  EXPECT_EQ(
      Eigen::Map<Eigen::MatrixXd>(SUNDenseMatrix_Data(saved.get()), n, n).cwiseAbs().maxCoeff(),
      0.0);
  const SunMatrix wrong(newDenseMatrix(n + 1, ctx));
  EXPECT_EQ(SUNMatCopy(ours.get(), wrong.get()), SUNMAT_ILL_INPUT);
}

// A second-order system's Newton matrix M = I - gamma J with copy rows p = first .. first+np-1
// (f_p = y_k, k = the row np further on, cyclically): row p is e_p - gamma e_k.
Eigen::MatrixXd secondOrderNewton(long np, long n, unsigned seed, std::vector<int>& copy_of,
                                  long first = 0) {
  Eigen::MatrixXd m = newtonLike(n, seed);
  copy_of.assign(static_cast<std::size_t>(n), -1);
  for (long p = first; p < first + np; ++p) {
    const long k = (p + np) % n;
    m.row(p).setZero();
    m(p, p) = 1.0;
    m(p, k) = -0.01;
    copy_of[static_cast<std::size_t>(p)] = static_cast<int>(k);
  }
  return m;
}

class CopyRowEliminationAt : public ::testing::TestWithParam<long> {};

// Copy rows first (the vehicle layout) and in the middle of the matrix.
TEST_P(CopyRowEliminationAt, SolvesLikeTheFullFactorisation) {
  std::vector<int> copy_of;
  const long n = 12, np = 5;
  const Eigen::MatrixXd m = secondOrderNewton(np, n, 7, copy_of, GetParam());
  CopyRowElimination e(n, copy_of);
  ASSERT_TRUE(e.active());
  ASSERT_TRUE(e.structured(m));
  ASSERT_EQ(e.factor(m), 0);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd b(n);
  for (long i = 0; i < n; ++i) b(i) = u(gen);
  Eigen::VectorXd x = b;
  e.solve(x);
  EXPECT_LT((m * x - b).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((x - m.partialPivLu().solve(b)).cwiseAbs().maxCoeff(), 1e-13);
}

INSTANTIATE_TEST_SUITE_P(FirstCopyRow, CopyRowEliminationAt, ::testing::Values(0L, 4L));

TEST(CopyRowElimination, DetectsAMatrixWithoutTheStructure) {
  std::vector<int> copy_of;
  Eigen::MatrixXd m = secondOrderNewton(3, 8, 11, copy_of);
  CopyRowElimination e(8, copy_of);
  EXPECT_TRUE(e.structured(m));
  m(1, 6) = 1e-3;  // a copy row with a third entry
  EXPECT_FALSE(e.structured(m));
  EXPECT_FALSE(CopyRowElimination(8, {}).active());
}

TEST(DenseLuSolver, EliminatesCopyRowsAndFallsBackToTheFullMatrix) {
  SunContext ctx;
  std::vector<int> copy_of;
  const long n = 10;
  Eigen::MatrixXd m = secondOrderNewton(4, n, 5, copy_of);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  for (const bool structured : {true, false}) {
    if (!structured) m(2, 9) = 0.05;
    SunLinSol ls(newDenseLuSolver(n, ctx, copy_of));
    SunMatrix a = denseMatrix(m, ctx);
    NVector x = makeVector(n, ctx), rhs = makeVector(n, ctx);
    map(rhs.get(), n) = b;
    ASSERT_EQ(SUNLinSolSetup(ls.get(), a.get()), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSolve(ls.get(), a.get(), x.get(), rhs.get(), 0.0), SUNLS_SUCCESS);
    EXPECT_LT((m * map(x.get(), n) - b).cwiseAbs().maxCoeff(), 1e-13) << structured;
  }
}

}  // namespace
}  // namespace rb::integ::detail
