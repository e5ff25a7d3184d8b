// The compiled N_Vector operations of bdf and ida are bit-identical to SUNDIALS' serial ones in
// every case of N_VLinearSum_Serial (coefficients +-1, a == b, a == -b, general; z aliasing x or
// y) and for the weighted RMS norm.
#include <gtest/gtest.h>
#include <nvector/nvector_serial.h>

#include <cstring>
#include <vector>

#include "workbench/integrators/serial_vector_ops.hpp"
#include "workbench/integrators/sundials_common.hpp"

namespace rb::integ::detail {
namespace {

constexpr long kN = 13;

void fill(N_Vector v, double seed) {
  double* d = data(v);
  for (long i = 0; i < kN; ++i) d[i] = std::sin(seed + 0.7 * static_cast<double>(i)) * 1e3;
  d[0] = 0.0;  // signed zeros: -y - x and -(x + y) differ in the sign of a zero result
  d[1] = -0.0;
}

bool sameBits(N_Vector u, N_Vector v) {
  return std::memcmp(data(u), data(v), static_cast<std::size_t>(kN) * sizeof(double)) == 0;
}

TEST(SerialVectorOps, LinearSumBitIdenticalInEveryCase) {
  SunContext ctx;
  const std::vector<double> coefficients = {1.0, -1.0, 0.0, 0.37, -0.37, 2.5, 1e-300};
  const NVector x = makeVector(kN, ctx), y = makeVector(kN, ctx);
  const NVector z1 = makeVector(kN, ctx), z2 = makeVector(kN, ctx);
  const NVector x2 = makeVector(kN, ctx), y2 = makeVector(kN, ctx);
  for (const double a : coefficients) {
    for (const double b : coefficients) {
      fill(x.get(), 1.0);
      fill(y.get(), 2.0);
      linearSum(a, x.get(), b, y.get(), z1.get());
      N_VLinearSum_Serial(a, x.get(), b, y.get(), z2.get());
      EXPECT_TRUE(sameBits(z1.get(), z2.get())) << "a = " << a << ", b = " << b;
      // z == y and z == x (the axpy cases and in-place general cases)
      fill(x2.get(), 1.0);
      fill(y2.get(), 2.0);
      linearSum(a, x.get(), b, y2.get(), y2.get());
      N_VLinearSum_Serial(a, x.get(), b, y.get(), y.get());
      EXPECT_TRUE(sameBits(y.get(), y2.get())) << "z = y, a = " << a << ", b = " << b;
      fill(y.get(), 2.0);
      linearSum(a, x2.get(), b, y.get(), x2.get());
      N_VLinearSum_Serial(a, x.get(), b, y.get(), x.get());
      EXPECT_TRUE(sameBits(x.get(), x2.get())) << "z = x, a = " << a << ", b = " << b;
    }
  }
}

TEST(SerialVectorOps, WrmsNormBitIdentical) {
  SunContext ctx;
  const NVector x = makeVector(kN, ctx), w = makeVector(kN, ctx);
  fill(x.get(), 0.3);
  for (long i = 0; i < kN; ++i) data(w.get())[i] = 1.0 / (1e-6 + 1e-6 * static_cast<double>(i));
  const double ours = wrmsNorm(x.get(), w.get());
  const double ref = N_VWrmsNorm_Serial(x.get(), w.get());
  EXPECT_EQ(std::memcmp(&ours, &ref, sizeof(double)), 0);
  N_VConst(0.0, x.get());
  EXPECT_EQ(wrmsNorm(x.get(), w.get()), 0.0);
}

TEST(SerialVectorOps, ClonesInheritTheOperations) {
  SunContext ctx;
  const NVector v = makeVector(kN, ctx);
  useCompiledVectorOps(v.get());
  const NVector c(N_VClone(v.get()));
  EXPECT_EQ(c->ops->nvlinearsum, &linearSum);
  EXPECT_EQ(c->ops->nvwrmsnorm, &wrmsNorm);
}

}  // namespace
}  // namespace rb::integ::detail
