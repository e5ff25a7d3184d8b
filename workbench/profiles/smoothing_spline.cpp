#include "workbench/profiles/smoothing_spline.hpp"

#include <cmath>
#include <utility>

#include "workbench/core/error.hpp"

namespace rb::profiles {
namespace {

// Solves the symmetric positive definite pentadiagonal system A x = b in place, A given by its
// diagonal d, first super-diagonal e and second super-diagonal f (LDL^T without pivoting).
void solvePentadiagonalSpd(std::vector<double> d, std::vector<double> e, std::vector<double> f,
                           std::vector<double>& b) {
  const std::size_t m = d.size();
  // Factorisation: A = L D L^T with L unit lower triangular of bandwidth 2; l1 (sub-diagonal) and
  // l2 (second sub-diagonal) overwrite e and f.
  for (std::size_t i = 0; i < m; ++i) {
    if (i >= 1) d[i] -= e[i - 1] * e[i - 1] * d[i - 1];
    if (i >= 2) d[i] -= f[i - 2] * f[i - 2] * d[i - 2];
    RB_CHECK(d[i] > 0.0, "smoothing spline system is not positive definite");
    if (i + 1 < m) {
      double v = e[i];
      if (i >= 1) v -= e[i - 1] * f[i - 1] * d[i - 1];
      e[i] = v / d[i];
    }
    if (i + 2 < m) f[i] /= d[i];
  }
  // Forward substitution L z = b, then D, then L^T x = z.
  for (std::size_t i = 0; i < m; ++i) {
    if (i >= 1) b[i] -= e[i - 1] * b[i - 1];
    if (i >= 2) b[i] -= f[i - 2] * b[i - 2];
  }
  for (std::size_t i = 0; i < m; ++i) b[i] /= d[i];
  for (std::size_t i = m; i-- > 0;) {
    if (i + 1 < m) b[i] -= e[i] * b[i + 1];
    if (i + 2 < m) b[i] -= f[i] * b[i + 2];
  }
}

// Smoothing-spline values f = y - lambda W^-1 Q gamma (Reinsch): gamma, the second derivatives at
// the interior knots, solves (R + lambda Q^T W^-1 Q) gamma = Q^T y; `fitted` holds y on entry.
void subtractPenaltyCorrection(const std::vector<double>& x, const std::vector<double>& y,
                               const std::vector<double>& w, double lambda,
                               std::vector<double>& fitted) {
  const std::size_t n = x.size();
  const std::size_t m = n - 2;  // unknowns: second derivatives at the interior knots
  std::vector<double> h(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) h[i] = x[i + 1] - x[i];
  // Column c of Q (interior knot j = c + 1) has entries at rows j-1, j, j+1.
  auto q = [&](std::size_t c, int k) {  // k = -1, 0, +1
    const std::size_t j = c + 1;
    if (k == -1) return 1.0 / h[j - 1];
    if (k == 0) return -1.0 / h[j - 1] - 1.0 / h[j];
    return 1.0 / h[j];
  };
  std::vector<double> d(m), e(m > 1 ? m - 1 : 0), f(m > 2 ? m - 2 : 0), rhs(m);
  for (std::size_t c = 0; c < m; ++c) {
    const std::size_t j = c + 1;
    // R: (h_{j-1} + h_j)/3 on the diagonal, h_j/6 off the diagonal.
    d[c] = (h[j - 1] + h[j]) / 3.0 +
           lambda * (q(c, -1) * q(c, -1) / w[j - 1] + q(c, 0) * q(c, 0) / w[j] +
                     q(c, 1) * q(c, 1) / w[j + 1]);
    if (c + 1 < m) {
      // Columns c and c+1 share rows j and j+1.
      e[c] =
          h[j] / 6.0 + lambda * (q(c, 0) * q(c + 1, -1) / w[j] + q(c, 1) * q(c + 1, 0) / w[j + 1]);
    }
    if (c + 2 < m) f[c] = lambda * q(c, 1) * q(c + 2, -1) / w[j + 1];
    rhs[c] = q(c, -1) * y[j - 1] + q(c, 0) * y[j] + q(c, 1) * y[j + 1];
  }
  solvePentadiagonalSpd(std::move(d), std::move(e), std::move(f), rhs);
  // f = y - lambda W^-1 Q gamma.
  for (std::size_t c = 0; c < m; ++c) {
    const std::size_t j = c + 1;
    fitted[j - 1] -= lambda * q(c, -1) * rhs[c] / w[j - 1];
    fitted[j] -= lambda * q(c, 0) * rhs[c] / w[j];
    fitted[j + 1] -= lambda * q(c, 1) * rhs[c] / w[j + 1];
  }
}

}  // namespace

double SmoothingSpline::lambdaForLength(const std::vector<double>& x, const std::vector<double>& w,
                                        double length) {
  RB_CHECK(x.size() >= 2 && length >= 0.0, "lambdaForLength needs >= 2 points and length >= 0");
  const double hmean = (x.back() - x.front()) / static_cast<double>(x.size() - 1);
  double wmean = 1.0;
  if (!w.empty()) {
    double sum = 0.0;
    for (const double v : w) sum += v;
    wmean = sum / static_cast<double>(w.size());
  }
  return std::pow(length, 4) * wmean / hmean;
}

SmoothingSpline::SmoothingSpline(std::vector<double> x, const std::vector<double>& y,
                                 std::vector<double> w, double lambda, SplineEnd curve) {
  const std::size_t n = x.size();
  RB_CHECK(n >= 3 && y.size() == n, "a smoothing spline needs >= 3 points and y of equal size");
  if (w.empty()) w.assign(n, 1.0);
  RB_CHECK(w.size() == n, "smoothing spline weights must match the points");
  RB_CHECK(lambda >= 0.0 && std::isfinite(lambda), "smoothing parameter must be >= 0");
  for (std::size_t i = 0; i < n; ++i) {
    RB_CHECK(w[i] > 0.0 && std::isfinite(y[i]), "smoothing spline: weights > 0, finite values");
    if (i > 0) RB_CHECK(x[i] > x[i - 1], "smoothing spline: x must be strictly increasing");
  }
  fitted_ = y;
  if (lambda > 0.0) subtractPenaltyCorrection(x, y, w, lambda, fitted_);
  spline_ = CubicSpline(std::move(x), fitted_, curve);
}

}  // namespace rb::profiles
