#include "workbench/creep/elliptic.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace rb::creep {

namespace {

// AGM with both moduli given (k^2 + kp^2 = 1 to rounding; each is used where it is accurate).
EllipticKE agm(double k, double kp) {
  if (kp <= 0.0) return {std::numeric_limits<double>::infinity(), 1.0, 1.0};
  double a = 1.0;
  double b = kp;
  double c = k;
  double pow2 = 0.5;          // 2^(n-1)
  double sum = pow2 * c * c;  // S accumulated from n = 0
  for (int n = 0; n < 64; ++n) {
    const double a_next = 0.5 * (a + b);
    const double b_next = std::sqrt(a * b);
    // c_{n+1} = (a_n - b_n)/2 = c_n^2 / (4 a_{n+1}): no cancellation.
    c = c * c / (4.0 * a_next);
    a = a_next;
    b = b_next;
    pow2 *= 2.0;
    const double term = pow2 * c * c;
    sum += term;
    if (term <= 1e-17 * sum || c <= 1e-300) break;
  }
  const double K = std::numbers::pi / (a + b);  // pi / (2 M), M = (a + b)/2 at convergence
  if (kp < 1e-4) {
    // E = K (1 - S) loses ~log10(K) digits when S -> 1; use the expansion at k -> 1 instead
    // (DLMF 19.12.2): E = 1 + (k'^2 / 2)(ln(4/k') - 1/2) + O(k'^4 ln k'), error < 3e-17 here.
    const double E = 1.0 + 0.5 * kp * kp * (std::log(4.0 / kp) - 0.5);
    return {K, E, 1.0 - E / K};
  }
  return {K, K * (1.0 - sum), sum};
}

}  // namespace

EllipticKE ellipticKE(double k) {
  k = std::fabs(k);
  if (k >= 1.0) return agm(1.0, 0.0);
  return agm(k, std::sqrt((1.0 - k) * (1.0 + k)));
}

EllipticKE ellipticKEComplementary(double kp) {
  kp = std::fabs(kp);
  if (kp >= 1.0) return agm(0.0, 1.0);
  return agm(std::sqrt((1.0 - kp) * (1.0 + kp)), kp);
}

}  // namespace rb::creep
