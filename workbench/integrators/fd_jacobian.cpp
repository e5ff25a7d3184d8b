#include "workbench/integrators/fd_jacobian.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace rb::integ {
namespace {

// Rows of column j: the pattern's, or every row when there is no pattern.
std::vector<std::vector<int>> differenceRows(long n, const JacobianPattern& p) {
  std::vector<std::vector<int>> rows(static_cast<std::size_t>(n));
  for (long j = 0; j < n; ++j) {
    auto& r = rows[static_cast<std::size_t>(j)];
    if (p.empty()) {
      r.resize(static_cast<std::size_t>(n));
      std::iota(r.begin(), r.end(), 0);
      continue;
    }
    r = p.rows[static_cast<std::size_t>(j)];
  }
  return rows;
}

}  // namespace

std::vector<std::vector<int>> groupColumns(long n, const JacobianPattern& pattern) {
  const auto rows = differenceRows(n, pattern);
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  // Columns with more rows first, ties in column order (the order of a stable sort, without its
  // temporary buffer, which GCC 12's libstdc++ frees in a way ASan reports as a mismatch).
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const std::size_t na = rows[static_cast<std::size_t>(a)].size();
    const std::size_t nb = rows[static_cast<std::size_t>(b)].size();
    return na != nb ? na > nb : a < b;
  });
  std::vector<std::vector<int>> groups;
  std::vector<std::vector<bool>> used;  // per group: rows taken
  for (const int j : order) {
    const auto& rj = rows[static_cast<std::size_t>(j)];
    std::size_t g = 0;
    for (; g < groups.size(); ++g) {
      const auto& u = used[g];
      if (std::none_of(rj.begin(), rj.end(), [&](int i) { return u[static_cast<std::size_t>(i)]; }))
        break;
    }
    if (g == groups.size()) {
      groups.emplace_back();
      used.emplace_back(static_cast<std::size_t>(n), false);
    }
    groups[g].push_back(j);
    for (const int i : rj) used[g][static_cast<std::size_t>(i)] = true;
  }
  for (auto& g : groups) std::sort(g.begin(), g.end());
  return groups;
}

GroupedDifferences::GroupedDifferences(long n, JacobianPattern pattern)
    : n_(n),
      pattern_(std::move(pattern)),
      groups_(groupColumns(n, pattern_)),
      rows_(differenceRows(n, pattern_)),
      saved_(static_cast<std::size_t>(n), 0.0) {}

void GroupedDifferences::perturb(const std::vector<int>& g, double* y, const double* inc,
                                 double sign) const {
  for (const int j : g) {
    saved_[static_cast<std::size_t>(j)] = y[j];
    y[j] += sign * inc[j];
  }
}

void GroupedDifferences::restore(const std::vector<int>& g, double* y) const {
  for (const int j : g) y[j] = saved_[static_cast<std::size_t>(j)];
}

void GroupedDifferences::scatterForward(int j, const double* fa, const double* fb, double step,
                                        Eigen::Ref<Eigen::MatrixXd> jac) const {
  const double inv = 1.0 / step;
  for (const int i : rows_[static_cast<std::size_t>(j)]) jac(i, j) = inv * fa[i] - inv * fb[i];
}

void GroupedDifferences::scatterCentral(int j, const double* fa, const double* fb, double step,
                                        Eigen::Ref<Eigen::MatrixXd> jac) const {
  for (const int i : rows_[static_cast<std::size_t>(j)]) jac(i, j) = (fa[i] - fb[i]) / step;
}

}  // namespace rb::integ
