// "No allocation in the per-step path of RK4/ABM" (and of the dense LU solver of bdf/ida): the
// number of heap allocations of a run must not depend on the number of steps. Counts malloc() calls
// by interposing glibc's malloc (also catches Eigen's allocations, which bypass operator new).
// Skipped with sanitizers, which intercept malloc themselves.
#include <gtest/gtest.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <atomic>
#include <cstddef>

#include "test_systems.hpp"
#include "workbench/integrators/dense_lu.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/integrators/sundials_common.hpp"

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
#define RB_COUNT_MALLOC 1
namespace {
std::atomic<long> g_mallocs{0};
}
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void __libc_free(void*);
void* malloc(std::size_t n) {
  g_mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t s) {
  g_mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(n, s);
}
void* realloc(void* p, std::size_t n) {
  g_mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, n);
}
void free(void* p) {
  __libc_free(p);
}
}
#endif

namespace rb::integ {
namespace {

long mallocsForRun(const std::string& method, long steps) {
#ifdef RB_COUNT_MALLOC
  SolverSpec s;
  s.method = method;
  s.step = 1e-3;
  test::Oscillator sys;
  auto integ = makeIntegrator(s);
  const std::vector<double> out = {1e-3 * static_cast<double>(steps)};
  const Eigen::VectorXd y0 = test::Oscillator::exact(0.0);
  const Observer observer = [](double, const Eigen::VectorXd&) { return true; };
  const long before = g_mallocs.load();
  const RunResult r = integrate(sys, *integ, 0.0, y0, out, observer);
  const long after = g_mallocs.load();
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.stats.steps, steps);
  return after - before;
#else
  (void)method;
  (void)steps;
  return 0;
#endif
}

TEST(FixedStep, NoAllocationPerStep) {
#ifndef RB_COUNT_MALLOC
  GTEST_SKIP() << "malloc counting needs glibc and no sanitizer";
#endif
  for (const std::string m : {"rk4", "abm"}) {
    const long few = mallocsForRun(m, 10);
    const long many = mallocsForRun(m, 20000);
    EXPECT_GT(few, 0) << m;  // the counter works: buffers are allocated once per run
    EXPECT_EQ(few, many) << m;
  }
}

// The dense LU solver of bdf and ida allocates its pivots once: setup (factorisation) and solve
// never allocate.
TEST(DenseLuSolver, NoAllocationInSetupOrSolve) {
#ifndef RB_COUNT_MALLOC
  GTEST_SKIP() << "malloc counting needs glibc and no sanitizer";
#else
  constexpr long n = 70;
  detail::SunContext ctx;
  const detail::SunMatrix a(SUNDenseMatrix(n, n, ctx));
  const detail::NVector b = detail::makeVector(n, ctx);
  const detail::NVector x = detail::makeVector(n, ctx);
  const detail::SunLinSol s(detail::newDenseLuSolver(n, ctx));
  ASSERT_TRUE(a && s);
  const Eigen::MatrixXd m = Eigen::MatrixXd::Identity(n, n) - 0.01 * Eigen::MatrixXd::Ones(n, n);
  detail::map(b.get(), n).setLinSpaced(-1.0, 1.0);
  const long before = g_mallocs.load();
  for (int rep = 0; rep < 10; ++rep) {
    Eigen::Map<Eigen::MatrixXd>(SUNDenseMatrix_Data(a.get()), n, n) = m;
    EXPECT_EQ(SUNLinSolSetup(s.get(), a.get()), SUNLS_SUCCESS);
    for (int k = 0; k < 5; ++k)
      EXPECT_EQ(SUNLinSolSolve(s.get(), a.get(), x.get(), b.get(), 0.0), SUNLS_SUCCESS);
  }
  EXPECT_EQ(g_mallocs.load() - before, 0);
#endif
}

}  // namespace
}  // namespace rb::integ
