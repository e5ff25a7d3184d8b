#pragma once
// Solver of one wheelset's augmented system (paper Eq. 16, 24; docs/contact_dynamics.md section
// 3), used by ContactVehicleOde and timed separately by bench/bench_wagon.cpp.
#include <Eigen/Dense>
#include <cmath>

namespace rb::dynamics {

// Cholesky factorisation M = L L^T of a symmetric positive definite 5x5 matrix, written out for
// the fixed size (Eigen's LLT runs its generic blocked loops for it: ~4x slower at this size).
// factor() returns false unless M is numerically positive definite (every pivot > 0 and finite).
class Cholesky5 {
 public:
  using Mat = Eigen::Matrix<double, 5, 5>;
  using Vec = Eigen::Matrix<double, 5, 1>;
  bool factor(const Mat& M) {
    for (int j = 0; j < 5; ++j) {
      double d = M(j, j);
      for (int k = 0; k < j; ++k) d -= L_(j, k) * L_(j, k);
      if (!(d > 0.0) || !std::isfinite(d)) return false;
      const double ljj = std::sqrt(d);
      L_(j, j) = ljj;
      inv_diag_[j] = 1.0 / ljj;
      for (int i = j + 1; i < 5; ++i) {
        double v = M(i, j);
        for (int k = 0; k < j; ++k) v -= L_(i, k) * L_(j, k);
        L_(i, j) = v * inv_diag_[j];
      }
    }
    return true;
  }
  template <class Rhs>
  Vec solve(const Rhs& b) const {
    Vec x;
    for (int i = 0; i < 5; ++i) {  // L y = b
      double v = b(i);
      for (int k = 0; k < i; ++k) v -= L_(i, k) * x(k);
      x(i) = v * inv_diag_[i];
    }
    for (int i = 4; i >= 0; --i) {  // L^T x = y
      double v = x(i);
      for (int k = i + 1; k < 5; ++k) v -= L_(k, i) * x(k);
      x(i) = v * inv_diag_[i];
    }
    return x;
  }

 private:
  Mat L_ = Mat::Zero();
  double inv_diag_[5] = {0, 0, 0, 0, 0};
};

// Prescribed spin (theta_ddot = thdd given): row and column 3 (the spin) of the wheelset's mass
// matrix M become the identity, and the right-hand side b of M qddot = b loses the coupling
// M_{q,theta} thdd (m3 = the original column 3 of M) and gets thdd as its spin row. The spin row's
// own reaction (spin torque) drops out.
inline void pinSpinMass(Eigen::Matrix<double, 5, 5>& M) {
  M.row(3).setZero();
  M.col(3).setZero();
  M(3, 3) = 1.0;
}
inline void pinSpinRhs(const Eigen::Matrix<double, 5, 1>& m3, double thdd,
                       Eigen::Matrix<double, 5, 1>& b) {
  b -= m3 * thdd;
  b(3) = thdd;
}

// The wheelset's augmented system [M -N; G 0] [qddot; lambda] = [r_q; r_lambda] (Eq. 16, 24) by
// its Schur complement: M is the symmetric positive definite 5x5 mass matrix, so with
// X = M^-1 N and S = G X, lambda = S^-1 (r_lambda - G M^-1 r_q) and qddot = M^-1 r_q + X lambda.
// One 5x5 Cholesky and a 2x2 inverse per evaluation, then two 5x5 triangular solves per right-hand
// side (the consistent coupling solves several), instead of a 7x7 pivoted LU.
// Prescribed spin (pin = true): theta_ddot = thdd is given; row and column 3 of M become the
// identity, its coupling M_{q,theta} theta_ddot moves to the right-hand side, and r_q(3) (spin
// torque of the applied and creep forces) and row 3 of N (that of the normal forces) are dropped:
// they are the constraint reaction. G has no theta column.
class AugmentedSolver {
 public:
  bool factor(const Eigen::Matrix<double, 5, 5>& M, const Eigen::Matrix<double, 5, 2>& N,
              const Eigen::Matrix<double, 2, 5>& G, bool pin, double thdd) {
    pin_ = pin;
    thdd_ = thdd;
    G_ = G;
    Eigen::Matrix<double, 5, 5> Mf = M;
    Eigen::Matrix<double, 5, 2> Nf = N;
    if (pin) {
      m3_ = M.col(3);
      pinSpinMass(Mf);
      Nf.row(3).setZero();
    }
    if (!llt_.factor(Mf)) return false;
    X_.col(0) = llt_.solve(Nf.col(0));
    X_.col(1) = llt_.solve(Nf.col(1));
    Sinv_ = (G_ * X_).inverse();
    return true;
  }
  Eigen::Matrix<double, 7, 1> solve(const Eigen::Matrix<double, 7, 1>& r) const {
    Eigen::Matrix<double, 5, 1> b = r.head<5>();
    if (pin_) pinSpinRhs(m3_, thdd_, b);
    const Eigen::Matrix<double, 5, 1> u = llt_.solve(b);
    const Eigen::Vector2d lam = Sinv_ * (r.tail<2>() - G_ * u);
    Eigen::Matrix<double, 7, 1> x;
    x.head<5>() = u + X_ * lam;
    x.tail<2>() = lam;
    return x;
  }

 private:
  Cholesky5 llt_;
  Eigen::Matrix<double, 5, 2> X_;
  Eigen::Matrix<double, 2, 5> G_;
  Eigen::Matrix2d Sinv_;
  Eigen::Matrix<double, 5, 1> m3_ = Eigen::Matrix<double, 5, 1>::Zero();
  double thdd_ = 0.0;
  bool pin_ = false;
};

}  // namespace rb::dynamics
