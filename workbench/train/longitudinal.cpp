#include "workbench/train/longitudinal.hpp"

#include <algorithm>
#include <cmath>

#include "workbench/core/strings.hpp"

namespace rb::train {

void validateTraction(const TractionSpec& t, const std::string& what, Diagnostics& d) {
  if (!t.given()) return;
  const std::string axis = t.by_distance ? "s" : "t";
  if (t.at.size() != t.force.size())
    d.add(t.loc, what + ".traction: " + axis + " and force need the same number of points, got " +
                     std::to_string(t.at.size()) + " and " + std::to_string(t.force.size()));
  for (std::size_t i = 0; i < t.at.size(); ++i)
    if (!std::isfinite(t.at[i]) || t.at[i] < 0.0 || (i > 0 && !(t.at[i] > t.at[i - 1])))
      d.add(t.loc, what + ".traction." + axis +
                       " must be finite, >= 0 and strictly ascending (point " +
                       std::to_string(i + 1) + ")");
  for (std::size_t i = 0; i < t.force.size(); ++i)
    if (!std::isfinite(t.force[i]) || std::abs(t.force[i]) > 1e7)
      d.add(t.loc, what + ".traction.force must be finite and within +-1e7 N (point " +
                       std::to_string(i + 1) + "), got " + formatNumber(t.force[i]));
}

void validateResistance(const ResistanceSpec& r, const std::string& what, Diagnostics& d) {
  for (const auto& [name, v] : {std::pair<const char*, double>{"a", r.a}, {"b", r.b}, {"c", r.c}})
    if (!std::isfinite(v) || v < 0.0)
      d.add(r.loc,
            what + ".resistance." + name + " must be finite and >= 0, got " + formatNumber(v));
}

double tractionForce(const TractionSpec& t, double time, double travel) {
  if (!t.given() || t.at.size() != t.force.size()) return 0.0;
  const double x = t.by_distance ? travel : time;
  if (x <= t.at.front()) return t.force.front();
  if (x >= t.at.back()) return t.force.back();
  std::size_t i = 1;
  while (x > t.at[i]) ++i;
  const double w = (x - t.at[i - 1]) / (t.at[i] - t.at[i - 1]);
  return t.force[i - 1] + w * (t.force[i] - t.force[i - 1]);
}

namespace {

// a at time x, linear between the samples (x inside [t.front(), t.back()]).
double at(const std::vector<double>& t, const std::vector<double>& a, double x) {
  const auto hi = std::upper_bound(t.begin(), t.end(), x);
  if (hi == t.end()) return a.back();
  if (hi == t.begin()) return a.front();
  const auto i = static_cast<std::size_t>(hi - t.begin());
  const double u = (x - t[i - 1]) / (t[i] - t[i - 1]);
  return a[i - 1] + u * (a[i] - a[i - 1]);
}

}  // namespace

std::vector<double> jerk(const std::vector<double>& t, const std::vector<double>& a,
                         double window) {
  const std::size_t n = std::min(t.size(), a.size());
  std::vector<double> j(n, 0.0);
  if (n < 2) return j;
  for (std::size_t i = 0; i < n; ++i) {
    double lo = 0.0, hi = 0.0;
    if (window > 0.0) {
      lo = std::max(t[i] - 0.5 * window, t.front());
      hi = std::min(t[i] + 0.5 * window, t[n - 1]);
    } else {
      lo = t[i == 0 ? 0 : i - 1];
      hi = t[i + 1 == n ? n - 1 : i + 1];
    }
    j[i] = hi > lo ? (at(t, a, hi) - at(t, a, lo)) / (hi - lo) : 0.0;
  }
  return j;
}

}  // namespace rb::train
