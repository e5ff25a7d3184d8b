#pragma once
// Difference-quotient Jacobians df/dy that use the model's structure (JacobianPattern): columns
// that share no row are perturbed together in one evaluation of f (Curtis, Powell and Reid, J.
// Inst. Maths Applics 13, 1974). Every entry is the quotient the column-by-column difference
// gives: within a group the other columns do not enter the rows of a column, so only the number
// of evaluations changes.
#include <Eigen/Dense>
#include <vector>

#include "workbench/integrators/ode.hpp"

namespace rb::integ {

// Greedy grouping of the columns (largest row count first): no two columns of a group share a
// row. Without a pattern: one column each.
std::vector<std::vector<int>> groupColumns(long n, const JacobianPattern& pattern);

class GroupedDifferences {
 public:
  GroupedDifferences(long n, JacobianPattern pattern);
  long size() const { return n_; }
  long groups() const { return static_cast<long>(groups_.size()); }
  const JacobianPattern& pattern() const { return pattern_; }

  // Forward differences J(i, j) = (f_i(y + sum_g inc_j e_j) - f0_i) / inc_j, one evaluation
  // rhs(y, ftemp) per group; J is overwritten (entries outside the pattern zero). y is restored
  // on return. Returns 0, or the first non-zero return code of rhs.
  template <class Rhs>
  int forward(Rhs&& rhs, double* y, const double* f0, const double* inc, double* ftemp,
              Eigen::Ref<Eigen::MatrixXd> jac) const {
    jac.setZero();
    for (const std::vector<int>& g : groups_) {
      perturb(g, y, inc, 1.0);
      const int rc = rhs(y, ftemp);
      restore(g, y);
      if (rc != 0) return rc;
      for (const int j : g) scatterForward(j, ftemp, f0, inc[j], jac);
    }
    return 0;
  }

  // Central differences J(i, j) = (f_i(y + d) - f_i(y - d)) / (2 inc_j), two evaluations per
  // group. Same contract as forward().
  template <class Rhs>
  int central(Rhs&& rhs, double* y, const double* inc, double* fp, double* fm,
              Eigen::Ref<Eigen::MatrixXd> jac) const {
    jac.setZero();
    for (const std::vector<int>& g : groups_) {
      perturb(g, y, inc, 1.0);
      int rc = rhs(y, fp);
      restore(g, y);
      perturb(g, y, inc, -1.0);
      if (rc == 0) rc = rhs(y, fm);
      restore(g, y);
      if (rc != 0) return rc;
      for (const int j : g) scatterCentral(j, fp, fm, 2.0 * inc[j], jac);
    }
    return 0;
  }

 private:
  // y_j += sign inc_j over the group, saving y_j; restore() puts the saved values back.
  void perturb(const std::vector<int>& g, double* y, const double* inc, double sign) const;
  void restore(const std::vector<int>& g, double* y) const;
  // J(i, j) = fa_i / step - fb_i / step (forward, SUNDIALS' form) or (fa_i - fb_i) / step
  // (central) over the difference rows of column j.
  void scatterForward(int j, const double* fa, const double* fb, double step,
                      Eigen::Ref<Eigen::MatrixXd> jac) const;
  void scatterCentral(int j, const double* fa, const double* fb, double step,
                      Eigen::Ref<Eigen::MatrixXd> jac) const;

  long n_;
  JacobianPattern pattern_;
  std::vector<std::vector<int>> groups_;
  std::vector<std::vector<int>> rows_;  // rows of each column
  mutable std::vector<double> saved_;   // y_j before the perturbation
};

}  // namespace rb::integ
