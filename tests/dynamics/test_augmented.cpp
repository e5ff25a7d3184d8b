// The wheelset's augmented-system solver (dynamics/augmented.hpp) against a dense pivoted LU of
// the full 7x7 system, free and with the spin pinned.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "workbench/dynamics/augmented.hpp"

namespace rb::dynamics {
namespace {

using Mat5 = Eigen::Matrix<double, 5, 5>;
using Mat7 = Eigen::Matrix<double, 7, 7>;
using Vec7 = Eigen::Matrix<double, 7, 1>;

// A wheelset-like SPD mass matrix (1813 kg, inertias 1120 / 112 kg m^2 with couplings).
Mat5 massMatrix() {
  Mat5 A = Mat5::Random();
  Mat5 M = A * A.transpose() * 10.0;
  M.diagonal() += Eigen::Matrix<double, 5, 1>(1813, 1813, 1120, 112, 1120);
  return M;
}

TEST(AugmentedSolver, Cholesky5SolvesAndRejectsIndefinite) {
  const Mat5 M = massMatrix();
  Cholesky5 ch;
  ASSERT_TRUE(ch.factor(M));
  const Eigen::Matrix<double, 5, 1> b = Eigen::Matrix<double, 5, 1>::Random();
  EXPECT_LT((M * ch.solve(b) - b).norm(), 1e-12 * b.norm() * M.norm());
  Mat5 bad = M;
  bad(2, 2) = -1.0;
  EXPECT_FALSE(ch.factor(bad));
}

TEST(AugmentedSolver, MatchesDenseLuFreeAndPinned) {
  const Mat5 M = massMatrix();
  Eigen::Matrix<double, 5, 2> N = Eigen::Matrix<double, 5, 2>::Random();
  Eigen::Matrix<double, 2, 5> G = Eigen::Matrix<double, 2, 5>::Zero();
  G << -0.05, 1, 0, 0, 0, -0.07, 0, 1, 0, 0;
  const Vec7 r = Vec7::Random() * 1e4;
  AugmentedSolver s;
  // Free: [M -N; G 0] x = r.
  ASSERT_TRUE(s.factor(M, N, G, false, 0.0));
  Mat7 K = Mat7::Zero();
  K.block<5, 5>(0, 0) = M;
  K.block<5, 2>(0, 5) = -N;
  K.block<2, 5>(5, 0) = G;
  const Vec7 x = K.partialPivLu().solve(r);
  EXPECT_LT((s.solve(r) - x).norm(), 1e-10 * x.norm());
  // Pinned spin: row 3 replaced by theta_ddot = 2.5; r(3) is ignored (a reaction).
  ASSERT_TRUE(s.factor(M, N, G, true, 2.5));
  Mat7 Kp = K;
  Kp.row(3).setZero();
  Kp(3, 3) = 1.0;
  Vec7 rp = r;
  rp(3) = 2.5;
  const Vec7 xp = Kp.partialPivLu().solve(rp);
  Vec7 r_other = r;
  r_other(3) = -1e6;  // must not matter
  EXPECT_LT((s.solve(r_other) - xp).norm(), 1e-10 * xp.norm());
  EXPECT_DOUBLE_EQ(s.solve(r)(3), 2.5);
}

}  // namespace
}  // namespace rb::dynamics
