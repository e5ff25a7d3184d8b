#include "workbench/core/spline.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "workbench/core/error.hpp"

namespace rb {
namespace {

// Solves a tridiagonal system in place with partial pivoting (the algorithm of LAPACK dgtsv):
// dl sub-diagonal (n-1), d diagonal (n), du super-diagonal (n-1), b right-hand side -> solution.
void solveTridiagonal(std::vector<double> dl, std::vector<double> d, std::vector<double> du,
                      std::vector<double>& b) {
  const std::size_t n = d.size();
  auto eliminate = [&](std::size_t i, bool has_next_super) {
    if (std::abs(d[i]) >= std::abs(dl[i])) {
      RB_CHECK(d[i] != 0.0, "singular spline system");
      const double fact = dl[i] / d[i];
      d[i + 1] -= fact * du[i];
      b[i + 1] -= fact * b[i];
      dl[i] = 0.0;  // dl[i] now holds the second super-diagonal of U
    } else {
      const double fact = d[i] / dl[i];
      d[i] = dl[i];
      double temp = d[i + 1];
      d[i + 1] = du[i] - fact * temp;
      if (has_next_super) {
        dl[i] = du[i + 1];
        du[i + 1] = -fact * dl[i];
      } else {
        dl[i] = 0.0;
      }
      du[i] = temp;
      temp = b[i];
      b[i] = b[i + 1];
      b[i + 1] = temp - fact * b[i + 1];
    }
  };
  for (std::size_t i = 0; i + 2 < n; ++i) eliminate(i, true);
  if (n > 1) eliminate(n - 2, false);
  RB_CHECK(d[n - 1] != 0.0, "singular spline system");
  b[n - 1] /= d[n - 1];
  if (n > 1) b[n - 2] = (b[n - 2] - du[n - 2] * b[n - 1]) / d[n - 2];
  for (std::size_t i = n - 2; i-- > 0;) {
    b[i] = (b[i] - du[i] * b[i + 1] - dl[i] * b[i + 2]) / d[i];
  }
}

// Knot slopes k_i = y'(x_i) of the interpolating cubic spline.
std::vector<double> knotSlopes(const std::vector<double>& x, const std::vector<double>& y,
                               SplineEnd end) {
  const std::size_t n = x.size();
  std::vector<double> dx(n - 1), m(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    dx[i] = x[i + 1] - x[i];
    m[i] = (y[i + 1] - y[i]) / dx[i];
  }
  if (n == 2) return {m[0], m[0]};
  if (n == 3 && end == SplineEnd::NotAKnot) {
    // Not-a-knot on 3 points: the interpolating parabola.
    const double c = (m[1] - m[0]) / (x[2] - x[0]);
    return {m[0] - c * dx[0], m[0] + c * dx[0], m[0] + c * (dx[0] + 2.0 * dx[1])};
  }
  std::vector<double> dl(n - 1), d(n), du(n - 1), b(n);
  // Interior rows: continuity of y'' at x_i.
  for (std::size_t i = 1; i + 1 < n; ++i) {
    dl[i - 1] = dx[i];
    d[i] = 2.0 * (dx[i - 1] + dx[i]);
    du[i] = dx[i - 1];
    b[i] = 3.0 * (dx[i] * m[i - 1] + dx[i - 1] * m[i]);
  }
  if (end == SplineEnd::Natural) {
    d[0] = 2.0;
    du[0] = 1.0;
    b[0] = 3.0 * m[0];
    dl[n - 2] = 1.0;
    d[n - 1] = 2.0;
    b[n - 1] = 3.0 * m[n - 2];
  } else {
    // Not-a-knot: y''' continuous at x_1 and x_{n-2}, written in slope form (de Boor).
    const double d0 = x[2] - x[0];
    d[0] = dx[1];
    du[0] = d0;
    b[0] = ((dx[0] + 2.0 * d0) * dx[1] * m[0] + dx[0] * dx[0] * m[1]) / d0;
    const double dn = x[n - 1] - x[n - 3];
    dl[n - 2] = dn;
    d[n - 1] = dx[n - 3];
    b[n - 1] =
        (dx[n - 2] * dx[n - 2] * m[n - 3] + (2.0 * dn + dx[n - 2]) * dx[n - 3] * m[n - 2]) / dn;
  }
  solveTridiagonal(std::move(dl), std::move(d), std::move(du), b);
  return b;
}

}  // namespace

SplineGrid::SplineGrid(std::vector<double> x) : x_(std::move(x)) {
  RB_CHECK(x_.size() >= 2, "a spline needs at least 2 knots");
  for (std::size_t i = 0; i < x_.size(); ++i) {
    RB_CHECK(std::isfinite(x_[i]), "spline knot is not finite");
    if (i > 0) RB_CHECK(x_[i] > x_[i - 1], "spline knots must be strictly increasing");
  }
  // Uniform when every knot is within a few ulps of x0 + i h.
  const std::size_t n = x_.size();
  const double h = (x_.back() - x_.front()) / static_cast<double>(n - 1);
  const double tol = 1e-12 * std::max({std::abs(x_.front()), std::abs(x_.back()), h});
  uniform_ = true;
  for (std::size_t i = 0; i < n && uniform_; ++i) {
    uniform_ = std::abs(x_[i] - (x_.front() + static_cast<double>(i) * h)) <= tol;
  }
  inv_h_ = 1.0 / h;
}

SplineGrid SplineGrid::uniform(double x0, double h, std::size_t n) {
  RB_CHECK(n >= 2 && h > 0.0, "uniform grid needs n >= 2 and h > 0");
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = x0 + static_cast<double>(i) * h;
  return SplineGrid(std::move(x));
}

std::size_t SplineGrid::searchInterval(double x) const {
  // First knot > x, minus one, clamped to [0, n-2].
  const auto it = std::upper_bound(x_.begin() + 1, x_.end() - 1, x);
  return static_cast<std::size_t>(it - x_.begin()) - 1;
}

CubicSplineSet::CubicSplineSet(SplineGrid grid, const std::vector<std::vector<double>>& ys,
                               SplineEnd end)
    : grid_(std::move(grid)), m_(ys.size()) {
  const std::size_t n = grid_.size();
  RB_CHECK(n >= 2, "spline grid is empty");
  coef_.assign((n - 1) * m_ * 4, 0.0);
  const auto& x = grid_.knots();
  for (std::size_t c = 0; c < m_; ++c) {
    const auto& y = ys[c];
    RB_CHECK(y.size() == n, "spline channel " + std::to_string(c) + " has " +
                                std::to_string(y.size()) + " values for " + std::to_string(n) +
                                " knots");
    const std::vector<double> k = knotSlopes(x, y, end);
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const double h = x[i + 1] - x[i];
      const double slope = (y[i + 1] - y[i]) / h;
      double* p = &coef_[(i * m_ + c) * 4];
      p[0] = y[i];
      p[1] = k[i];
      p[2] = (3.0 * slope - 2.0 * k[i] - k[i + 1]) / h;
      p[3] = (k[i] + k[i + 1] - 2.0 * slope) / (h * h);
    }
  }
}

CubicSpline::CubicSpline(std::vector<double> x, const std::vector<double>& y, SplineEnd end)
    : CubicSpline(SplineGrid(std::move(x)), y, end) {}

CubicSpline::CubicSpline(SplineGrid grid, const std::vector<double>& y, SplineEnd end)
    : set_(std::move(grid), std::vector<std::vector<double>>{y}, end) {}

}  // namespace rb
