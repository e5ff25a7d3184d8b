#pragma once
// The two N_Vector operations that dominate the vector work of CVODE's and IDA's steps (about
// 10 % of the instructions of a bdf run on the contact vehicle when taken from a SUNDIALS built
// without optimisation): the linear sum z = a x + b y (predictor, corrector updates, error
// estimates) and the weighted RMS norm (every convergence and error test). They replace the
// serial vector's operations with versions compiled with our flags that do the same
// floating-point operations in the same order as SUNDIALS' N_VLinearSum_Serial (including its
// special cases such as z = a (x + y) for a == b) and N_VWrmsNorm_Serial (sequential sum), so
// the results are bit-identical.
#include <sundials/sundials_nvector.h>

namespace rb::integ::detail {

// Installs the operations in v's operation table. Vectors that CVODE and IDA clone from v
// (N_VClone copies the table) use them too.
void useCompiledVectorOps(N_Vector v);

// The operations themselves (exposed for tests).
void linearSum(double a, N_Vector x, double b, N_Vector y, N_Vector z);
double wrmsNorm(N_Vector x, N_Vector w);

}  // namespace rb::integ::detail
