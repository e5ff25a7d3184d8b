#pragma once
// Complete elliptic integrals of the first and second kind by the arithmetic-geometric mean
// (DLMF 19.8.1 and 19.8.6; Abramowitz & Stegun 17.6.1-17.6.4):
//
//   K(k) = int_0^{pi/2} dt / sqrt(1 - k^2 sin^2 t) = pi / (2 M(1, k')),   k' = sqrt(1 - k^2)
//   E(k) = int_0^{pi/2} sqrt(1 - k^2 sin^2 t) dt  = K(k) (1 - S),
//   S    = sum_{n >= 0} 2^(n-1) c_n^2,  c_0 = k,  c_{n+1} = c_n^2 / (4 a_{n+1})
//
// with a_{n+1} = (a_n + b_n)/2, b_{n+1} = sqrt(a_n b_n), a_0 = 1, b_0 = k'. For k' < 1e-4, where
// 1 - S ~ 1/K would cancel, E comes from its expansion at k -> 1 (DLMF 19.12.2). The argument is
// the MODULUS k (not the parameter m = k^2 used by some libraries). The iteration converges
// quadratically (at most 6 steps for k' >= 1e-16); the result is accurate to a few ulp
// (measured against 30-digit references: relative error < 4e-16, see tests/creep).
//
// S = (K - E)/K is returned as well: it is obtained without the cancellation of K - E near k = 0,
// which the Hertz ellipse solver (hertz.hpp) needs for nearly circular contacts.
// Allocation-free, no exceptions.

namespace rb::creep {

struct EllipticKE {
  double K = 0.0;  // K(k)
  double E = 0.0;  // E(k)
  double S = 0.0;  // 1 - E/K, in [0, 1]
};

// Modulus k in [0, 1] (|k| is used). k = 1 gives K = +inf, E = 1, S = 1.
EllipticKE ellipticKE(double k);

// The same from the complementary modulus kp = k' = sqrt(1 - k^2) in [0, 1]. Use it when k is
// close to 1: there k' carries the information and 1 - k^2 would lose digits.
EllipticKE ellipticKEComplementary(double kp);

inline double ellipticK(double k) {
  return ellipticKE(k).K;
}
inline double ellipticE(double k) {
  return ellipticKE(k).E;
}

}  // namespace rb::creep
