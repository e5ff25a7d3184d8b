#include "workbench/suspension/bumpstop.hpp"

#include <algorithm>
#include <cmath>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"

namespace rb::suspension {

std::vector<std::string> BumpstopLaw::check(const std::vector<double>& d,
                                            const std::vector<double>& f) {
  std::vector<std::string> out;
  if (d.size() != f.size()) {
    out.push_back("table: " + std::to_string(d.size()) + " deformations but " +
                  std::to_string(f.size()) + " forces");
    return out;
  }
  if (d.empty()) {
    out.push_back("table is empty; give at least 2 points {d, F}");
    return out;
  }
  if (d.size() < 2) out.push_back("table needs at least 2 points {d, F}, got 1");
  bool finite = true;
  for (std::size_t k = 0; k < d.size(); ++k)
    finite = finite && std::isfinite(d[k]) && std::isfinite(f[k]);
  if (!finite) {
    out.push_back("table values must be finite numbers");
    return out;
  }
  if (d[0] < 0.0) out.push_back("table: d must be >= 0 m (d[1] = " + formatNumber(d[0]) + ")");
  if (f[0] != 0.0)
    out.push_back(
        "table: the first force must be 0 N so the force is continuous at the clearance (F[1] = " +
        formatNumber(f[0]) + ")");
  bool any_positive = false;
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (f[k] < 0.0)
      out.push_back("table: F must be >= 0 N (F[" + std::to_string(k + 1) +
                    "] = " + formatNumber(f[k]) + ")");
    any_positive = any_positive || f[k] > 0.0;
    if (k == 0) continue;
    if (!(d[k] > d[k - 1]))
      out.push_back("table: d must be strictly increasing (d[" + std::to_string(k) +
                    "] = " + formatNumber(d[k - 1]) + ", d[" + std::to_string(k + 1) +
                    "] = " + formatNumber(d[k]) + ")");
    if (f[k] < f[k - 1])
      out.push_back("table: F must not decrease (F[" + std::to_string(k) +
                    "] = " + formatNumber(f[k - 1]) + ", F[" + std::to_string(k + 1) +
                    "] = " + formatNumber(f[k]) + ")");
  }
  if (!any_positive && d.size() >= 2)
    out.push_back("table: every force is 0, the bumpstop does nothing");
  return out;
}

BumpstopLaw::BumpstopLaw(const std::vector<double>& d, const std::vector<double>& f) {
  RB_CHECK(check(d, f).empty(), "invalid bumpstop table");
  // Drop the leading zero-force points except the last one: that one is the clearance.
  std::size_t first = 0;
  while (first + 1 < d.size() && f[first + 1] == 0.0) ++first;
  c_ = d[first];
  x_.assign(d.begin() + static_cast<long>(first), d.end());
  std::vector<double> y(f.begin() + static_cast<long>(first), f.end());
  const std::size_t n = x_.size();
  RB_CHECK(n >= 2, "bumpstop table reduces to fewer than 2 points");
  std::vector<double> h(n - 1), del(n - 1), m(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = x_[k + 1] - x_[k];
    del[k] = (y[k + 1] - y[k]) / h[k];
  }
  // Fritsch-Carlson / Fritsch-Butland interior slopes (weighted harmonic mean, as scipy PCHIP).
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (del[k - 1] > 0.0 && del[k] > 0.0) {
      const double w1 = 2.0 * h[k] + h[k - 1], w2 = h[k] + 2.0 * h[k - 1];
      m[k] = (w1 + w2) / (w1 / del[k - 1] + w2 / del[k]);
    }
  }
  // Slope 0 at the clearance (C1 with the zero force inside it).
  m[0] = 0.0;
  // End slope: shape-preserving three-point formula.
  if (n == 2) {
    m[n - 1] = del[0];
  } else {
    const std::size_t k = n - 2;
    double s = ((2.0 * h[k] + h[k - 1]) * del[k] - h[k] * del[k - 1]) / (h[k] + h[k - 1]);
    if (s < 0.0 || (del[k] <= 0.0))
      s = 0.0;
    else if (del[k - 1] <= 0.0 && s > 3.0 * del[k])
      s = 3.0 * del[k];
    m[n - 1] = s;
  }
  // A zero-slope start can overshoot into the next interval only if m[1] > 3 del[0]; the
  // harmonic mean is <= 3 min(del), so the interpolant is monotone.
  coef_.resize(4 * (n - 1));
  e_.assign(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double hk = h[k];
    double* c = &coef_[4 * k];
    c[0] = y[k];
    c[1] = m[k];
    c[2] = (3.0 * del[k] - 2.0 * m[k] - m[k + 1]) / hk;
    c[3] = (m[k] + m[k + 1] - 2.0 * del[k]) / (hk * hk);
    e_[k + 1] = e_[k] + hk * (c[0] + hk * (c[1] / 2.0 + hk * (c[2] / 3.0 + hk * c[3] / 4.0)));
  }
  end_slope_ = m[n - 1];
}

std::size_t BumpstopLaw::interval(double a) const {
  const auto it = std::upper_bound(x_.begin(), x_.end(), a);
  std::size_t k = it == x_.begin() ? 0 : static_cast<std::size_t>(it - x_.begin()) - 1;
  return std::min(k, x_.size() - 2);
}

double BumpstopLaw::force(double d) const {
  const double a = std::abs(d);
  if (a <= c_) return 0.0;
  const double sign = d < 0.0 ? -1.0 : 1.0;
  if (a >= x_.back()) {
    const double* c = &coef_[coef_.size() - 4];
    const double h = x_.back() - x_[x_.size() - 2];
    const double fend = c[0] + h * (c[1] + h * (c[2] + h * c[3]));
    return sign * (fend + end_slope_ * (a - x_.back()));
  }
  const std::size_t k = interval(a);
  const double t = a - x_[k];
  const double* c = &coef_[4 * k];
  return sign * (c[0] + t * (c[1] + t * (c[2] + t * c[3])));
}

double BumpstopLaw::stiffness(double d) const {
  const double a = std::abs(d);
  if (a <= c_) return 0.0;
  if (a >= x_.back()) return end_slope_;
  const std::size_t k = interval(a);
  const double t = a - x_[k];
  const double* c = &coef_[4 * k];
  return c[1] + t * (2.0 * c[2] + 3.0 * t * c[3]);
}

double BumpstopLaw::energy(double d) const {
  const double a = std::abs(d);
  if (a <= c_) return 0.0;
  if (a >= x_.back()) {
    const double fend = force(x_.back());
    const double u = a - x_.back();
    return e_.back() + fend * u + 0.5 * end_slope_ * u * u;
  }
  const std::size_t k = interval(a);
  const double t = a - x_[k];
  const double* c = &coef_[4 * k];
  return e_[k] + t * (c[0] + t * (c[1] / 2.0 + t * (c[2] / 3.0 + t * c[3] / 4.0)));
}

}  // namespace rb::suspension
