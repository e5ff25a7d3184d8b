#pragma once
// Exponential treatment of stiff diagonal components in the fixed-step methods.
//
// A component i whose own derivative dominates (y_i' = d_i y_i + N_i(t, y) with d_i << 0, e.g. a
// wheelset's spin rate driven by its longitudinal creep force: d = -2 f11 r0^2 / (V I_yy), about
// -2400 1/s at 20 m/s) limits explicit RK4 and ABM to h |d| < 2.79 and 1.28. Exponential time
// differencing integrates the linear part exactly and the remainder N_i = f_i - d_i y_i with the
// method's own polynomial (Cox and Matthews, J. Comput. Phys. 176 (2002) 430-455, for ETDRK4;
// exponential Adams methods: Hochbruck and Ostermann, Acta Numerica 19 (2010) 209-286, section
// 2.5): stable for any h d_i < 0, exact at the fixed point, and equal to the classical method as
// d_i -> 0. d_i is a diagonal Jacobian entry estimated by finite differences during the run; the
// model is unchanged.
#include <array>
#include <cmath>

namespace rb::integ::expo {

// phi_k(z) = sum_j z^j / (j + k)!, k = 0..4 (phi_0 = e^z): by the Taylor series near 0 (where the
// closed forms cancel), by phi_k+1 = (phi_k - 1/k!) / z elsewhere.
inline std::array<double, 5> phi(double z) {
  std::array<double, 5> p{};
  if (std::abs(z) < 0.5) {
    // 20 terms: the remainder is below 0.5^20 / 20! relative, far under double precision.
    for (int k = 0; k < 5; ++k) {
      double term = 1.0, sum = 0.0;
      for (int j = 1; j <= k; ++j) term /= j;  // 1 / k!
      for (int j = 0; j < 20; ++j) {
        sum += term;
        term *= z / (j + k + 1);
      }
      p[static_cast<std::size_t>(k)] = sum;
    }
    return p;
  }
  p[0] = std::exp(z);
  double fact = 1.0;  // 1 / k!
  for (int k = 0; k < 4; ++k) {
    p[static_cast<std::size_t>(k) + 1] = (p[static_cast<std::size_t>(k)] - fact) / z;
    fact /= (k + 1);
  }
  return p;
}

// Weights of one exponential step of a stiff component with z = h d.
struct Weights {
  // ETDRK4 (Cox-Matthews): half-step e^{z/2} and h/2 phi_1(z/2); full step e^z and the weights
  // of N(y_n), N(a) + N(b) and N(c).
  double e_half = 1.0, phi1_half = 1.0;
  double e_full = 1.0, f1 = 1.0 / 6.0, f2 = 1.0 / 6.0, f3 = 1.0 / 6.0;
  // Exponential Adams-Bashforth 4 (predictor) on N_n, N_n-1, N_n-2, N_n-3 and exponential
  // Adams-Moulton 4 (corrector) on N*_n+1, N_n, N_n-1, N_n-2 (multiplied by h). At z = 0 they are
  // (55, -59, 37, -9) / 24 and (9, 19, -5, 1) / 24, the ABM of paper Eq. (32).
  std::array<double, 4> ab{}, am{};
};

inline Weights weights(double z) {
  Weights w;
  const auto ph = phi(0.5 * z);
  w.e_half = ph[0];
  w.phi1_half = ph[1];
  const auto p = phi(z);
  w.e_full = p[0];
  w.f1 = p[1] - 3.0 * p[2] + 4.0 * p[3];
  w.f2 = p[2] - 2.0 * p[3];  // weight of N(a) and of N(b) each
  w.f3 = 4.0 * p[3] - p[2];
  // Backward-difference form: N(t_n + theta h) by Newton's backward interpolation through the
  // nodes, integrated against e^{(1 - theta) z} over theta in [0, 1]:
  //   gamma_m = int e^{(1-theta) z} theta (theta+1) ... (theta+m-1) / m!   (nodes n, n-1, ...)
  //   delta_m = int e^{(1-theta) z} (theta-1) theta ... (theta+m-2) / m!   (nodes n+1, n, ...)
  // with int e^{(1-theta) z} theta^k / k! = phi_k+1(z).
  const double g0 = p[1], g1 = p[2], g2 = p[3] + 0.5 * p[2], g3 = p[4] + p[3] + p[2] / 3.0;
  w.ab = {g0 + g1 + g2 + g3, -(g1 + 2.0 * g2 + 3.0 * g3), g2 + 3.0 * g3, -g3};
  const double d0 = p[1], d1 = p[2] - p[1], d2 = p[3] - 0.5 * p[2], d3 = p[4] - p[2] / 6.0;
  w.am = {d0 + d1 + d2 + d3, -(d1 + 2.0 * d2 + 3.0 * d3), d2 + 3.0 * d3, -d3};
  return w;
}

}  // namespace rb::integ::expo
