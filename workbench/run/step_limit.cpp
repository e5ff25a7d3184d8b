#include "workbench/run/step_limit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "workbench/core/eigen_decomposition.hpp"
#include "workbench/vehicle/modal.hpp"

namespace rb::run {
namespace {

double rk4Amplification(std::complex<double> z) {
  // R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24 (Horner).
  return std::abs(1.0 + z * (1.0 + z * (0.5 + z * (1.0 / 6.0 + z / 24.0))));
}

// ABM PECE on y' = lambda y (fixed_step.cpp): with f = lambda y and z = h lambda,
//   y* = y_n + z/24 (55 y_n - 59 y_n-1 + 37 y_n-2 - 9 y_n-3)
//   y_n+1 = y_n + z/24 (9 y* + 19 y_n - 5 y_n-1 + y_n-2),
// so y_n = zeta^n solves zeta^4 - c3 zeta^3 - c2 zeta^2 - c1 zeta - c0 = 0 with the coefficients
// below; the step is stable when every root has |zeta| <= 1.
double abmAmplification(std::complex<double> z) {
  const std::complex<double> a = z / 24.0, p = 9.0 * a * a;
  const std::complex<double> c3 = 1.0 + 28.0 * a + 55.0 * p;
  const std::complex<double> c2 = -5.0 * a - 59.0 * p;
  const std::complex<double> c1 = a + 37.0 * p;
  const std::complex<double> c0 = -9.0 * p;
  // The roots are the eigenvalues of the companion matrix C = A + iB; those of the real matrix
  // [A -B; B A] are the roots and their conjugates, of the same moduli. The real eigensolver is
  // compiled once in core (eigen_decomposition.hpp): Eigen's complex solver would cost about 9 s
  // of compile time in this unit alone.
  const std::complex<double> row[4] = {c3, c2, c1, c0};
  Eigen::MatrixXd real = Eigen::MatrixXd::Zero(8, 8);
  for (int j = 0; j < 4; ++j) {
    real(0, j) = real(4, 4 + j) = row[j].real();
    real(4, j) = row[j].imag();
    real(0, 4 + j) = -row[j].imag();
  }
  for (int i = 1; i < 4; ++i) real(i, i - 1) = real(4 + i, 4 + i - 1) = 1.0;
  const EigenDecomposition e = eigenDecomposition(real, false);
  return e.values.cwiseAbs().maxCoeff();
}

// Smallest exit radius of the method's stability region over directions in the left half-plane
// (the regions are symmetric about the real axis): no eigenvalue with h |lambda| below it can
// limit the step, so fixedStepLimit() skips those.
double smallestExitRadius(FixedStepMethod method) {
  double rmin = std::numeric_limits<double>::infinity();
  constexpr int kDirections = 18;
  for (int k = 0; k <= kDirections; ++k) {
    const double theta = 0.5 * M_PI + 0.5 * M_PI * k / kDirections;  // pi/2 .. pi
    const std::complex<double> dir = std::polar(1.0, theta);
    // A direction along the imaginary axis itself has Re = 0: nudge it into the left half-plane.
    rmin = std::min(rmin, stableStep(method, k == 0 ? dir - 1e-9 : dir));
  }
  return rmin;
}

}  // namespace

double amplification(FixedStepMethod method, std::complex<double> z) {
  return method == FixedStepMethod::Rk4 ? rk4Amplification(z) : abmAmplification(z);
}

double stableStep(FixedStepMethod method, std::complex<double> lambda) {
  const double mod = std::abs(lambda);
  if (!(mod > 0.0) || lambda.real() >= 0.0) return std::numeric_limits<double>::infinity();
  const std::complex<double> dir = lambda / mod;
  const auto unstable = [&](double rho) {
    return amplification(method, rho * dir) > 1.0 + kGrowthTolerance;
  };
  // March out along the ray (both regions are bounded by |z| < 3), then bisect the first exit.
  constexpr double kRhoStep = 0.05, kRhoMax = 4.0;
  double lo = 0.0;
  for (double rho = kRhoStep; rho <= kRhoMax; rho += kRhoStep) {
    if (unstable(rho)) {
      double hi = rho;
      for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (unstable(mid) ? hi : lo) = mid;
      }
      return lo / mod;
    }
    lo = rho;
  }
  return std::numeric_limits<double>::infinity();
}

StepLimit fixedStepLimit(integ::OdeSystem& ode, double t0, const Eigen::VectorXd& y0,
                         FixedStepMethod method, std::span<const int> exponential) {
  StepLimit out;
  const int n = ode.size();
  // Central differences with a relative increment of eps^(1/3) (the optimum for a central
  // quotient), at least 1e-8 in the component's unit (m, rad, m/s, N).
  const double rel = std::cbrt(std::numeric_limits<double>::epsilon());
  Eigen::VectorXd steps(n);
  std::vector<int> all(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    steps(j) = rel * std::max(std::abs(y0(j)), 1e-8 / rel);
    all[static_cast<std::size_t>(j)] = j;
  }
  Eigen::MatrixXd jac;
  long evaluations = 0;
  const int failed = vehicle::centralDifferenceJacobian(
      ode, t0, y0, steps, all, vehicle::DifferenceQuotient::NominalStep, jac, evaluations);
  out.evaluations = static_cast<int>(evaluations);
  if (failed >= 0) {
    out.why_not = ode.lastError();
    return out;
  }
  for (const int i : exponential) jac(i, i) = 0.0;
  if (!jac.allFinite()) {
    out.why_not = "non-finite Jacobian";
    return out;
  }
  const EigenDecomposition eig = eigenDecomposition(jac, true);
  if (!eig.ok) {
    out.why_not = "eigenvalues did not converge";
    return out;
  }
  out.computed = true;
  out.h_max = std::numeric_limits<double>::infinity();
  int limiting = -1;
  // Largest moduli first: once a limit is known, an eigenvalue with h_max |lambda| below the
  // region's smallest exit radius cannot lower it (and a conjugate gives the same limit).
  std::vector<int> order(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) order[static_cast<std::size_t>(k)] = k;
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return std::abs(eig.values(a)) > std::abs(eig.values(b)); });
  const double rmin = smallestExitRadius(method);
  for (const int k : order) {
    const std::complex<double> lam = eig.values(k);
    if (lam.real() < 0.0) out.stiffest = std::max(out.stiffest, std::abs(lam));
    if (lam.imag() < 0.0 || out.h_max * std::abs(lam) < rmin) continue;
    const double h = stableStep(method, lam);
    if (h < out.h_max) {
      out.h_max = h;
      out.lambda = lam;
      limiting = k;
    }
  }
  if (limiting >= 0) {
    Eigen::Index i = 0;
    eig.vectors.col(limiting).cwiseAbs().maxCoeff(&i);
    out.mode = ode.componentName(static_cast<int>(i));
  }
  return out;
}

}  // namespace rb::run
