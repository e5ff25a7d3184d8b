#include "workbench/integrators/serial_vector_ops.hpp"

#include <nvector/nvector_serial.h>

#include <cmath>

namespace rb::integ::detail {
namespace {

struct Span {
  double* d;
  long n;
};
Span span(N_Vector v) {
  return {NV_DATA_S(v), static_cast<long>(NV_LENGTH_S(v))};
}

// y <- a x + y (SUNDIALS' Vaxpy_Serial).
void axpy(double a, const double* x, double* y, long n) {
  if (a == 1.0) {
    for (long i = 0; i < n; ++i) y[i] += x[i];
  } else if (a == -1.0) {
    for (long i = 0; i < n; ++i) y[i] -= x[i];
  } else {
    for (long i = 0; i < n; ++i) y[i] += a * x[i];
  }
}

// z = c v1 + v2 (VLin1_Serial) or z = c v1 - v2 (VLin2_Serial).
void lin1(double c, const double* v1, const double* v2, double* z, long n) {
  for (long i = 0; i < n; ++i) z[i] = (c * v1[i]) + v2[i];
}
void lin2(double c, const double* v1, const double* v2, double* z, long n) {
  for (long i = 0; i < n; ++i) z[i] = (c * v1[i]) - v2[i];
}

// The cases of N_VLinearSum_Serial with a or b equal to +-1 (after the axpy cases). Returns false
// if neither is.
bool unitCoefficientSum(double a, const double* x, double b, const double* y, double* z, long n) {
  if (a == 1.0 && b == 1.0) {
    for (long i = 0; i < n; ++i) z[i] = x[i] + y[i];
  } else if (a == 1.0 && b == -1.0) {
    for (long i = 0; i < n; ++i) z[i] = x[i] - y[i];
  } else if (a == -1.0 && b == 1.0) {
    for (long i = 0; i < n; ++i) z[i] = y[i] - x[i];
  } else if (a == 1.0) {
    lin1(b, y, x, z, n);
  } else if (b == 1.0) {
    lin1(a, x, y, z, n);
  } else if (a == -1.0) {
    lin2(b, y, x, z, n);
  } else if (b == -1.0) {
    lin2(a, x, y, z, n);
  } else {
    return false;
  }
  return true;
}

}  // namespace

void linearSum(double a, N_Vector x, double b, N_Vector y, N_Vector z) {
  const Span xs = span(x);
  const long n = xs.n;
  double* xd = xs.d;
  double* yd = span(y).d;
  double* zd = span(z).d;
  if (b == 1.0 && z == y) return axpy(a, xd, yd, n);
  if (a == 1.0 && z == x) return axpy(b, yd, xd, n);
  if (unitCoefficientSum(a, xd, b, yd, zd, n)) return;
  if (a == b) {
    for (long i = 0; i < n; ++i) zd[i] = a * (xd[i] + yd[i]);
  } else if (a == -b) {
    for (long i = 0; i < n; ++i) zd[i] = a * (xd[i] - yd[i]);
  } else {
    for (long i = 0; i < n; ++i) zd[i] = (a * xd[i]) + (b * yd[i]);
  }
}

double wrmsNorm(N_Vector x, N_Vector w) {
  const Span xs = span(x);
  const double* wd = span(w).d;
  double sum = 0.0;
  for (long i = 0; i < xs.n; ++i) {  // sequential: the order of SUNDIALS' sum
    const double p = xs.d[i] * wd[i];
    sum += p * p;
  }
  const double mean = sum / static_cast<double>(xs.n);
  return mean <= 0.0 ? 0.0 : std::sqrt(mean);  // SUNRsqrt
}

void useCompiledVectorOps(N_Vector v) {
  v->ops->nvlinearsum = linearSum;
  v->ops->nvwrmsnorm = wrmsNorm;
}

}  // namespace rb::integ::detail
