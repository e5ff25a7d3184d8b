#include "workbench/suspension/external_force.hpp"

#include <algorithm>
#include <cmath>

#include "workbench/core/strings.hpp"

namespace rb::suspension {
namespace {

double rampAt(const ForceLaw& l, double t) {
  const double up = t - l.start;  // time since the ramp began
  if (!(up > 0.0)) return l.initial;
  const double delta = l.value - l.initial;
  if (up < l.duration) return l.initial + delta * (up / l.duration);
  // Time since the ramp back began; -inf while an infinite hold lasts.
  const double down = up - l.duration - l.hold;
  if (!(down > 0.0)) return l.value;
  if (down < l.duration) return l.value - delta * (down / l.duration);
  return l.initial;
}

double tableAt(const std::vector<double>& x, const std::vector<double>& f, double a) {
  if (!(a > x.front())) return f.front();
  if (!(a < x.back())) return f.back();
  // x[k - 1] <= a < x[k], 1 <= k < size.
  const auto k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), a) - x.begin());
  const double w = (a - x[k - 1]) / (x[k] - x[k - 1]);
  return f[k - 1] + w * (f[k] - f[k - 1]);
}

void checkRange(const Range& r, double v, const char* key, const char* unit,
                std::vector<std::string>& out) {
  if (!r.contains(v))
    out.push_back(std::string(key) + " must be in " + r.text() + " " + unit + ", got " +
                  formatNumber(v));
}

void checkTable(const ForceLaw& l, std::vector<std::string>& out) {
  const char* x = l.over == ForceAbscissa::Time ? "t" : "s";
  if (l.at.size() != l.force.size()) {
    out.emplace_back("table: as many abscissae as forces");
    return;
  }
  if (l.at.size() < 2) {
    out.emplace_back("table: needs at least 2 points {{" + std::string(x) +
                     ", F}, ...} (a force that does not change is law = \"constant\")");
    return;
  }
  for (std::size_t k = 0; k < l.at.size(); ++k) {
    const std::string at = "[" + std::to_string(k + 1) + "]";
    if (!std::isfinite(l.at[k])) {
      out.push_back("table: " + std::string(x) + at + " must be finite, got " +
                    formatNumber(l.at[k]));
    } else if (k > 0 && std::isfinite(l.at[k - 1]) && !(l.at[k] > l.at[k - 1])) {
      out.push_back("table: " + std::string(x) + " must be strictly increasing (" + x + at + " = " +
                    formatNumber(l.at[k]) + " after " + x + "[" + std::to_string(k) +
                    "] = " + formatNumber(l.at[k - 1]) + ")");
    }
    if (!kForceValueRange.contains(l.force[k]))
      out.push_back("table: F" + at + " must be in " + kForceValueRange.text() + " N, got " +
                    formatNumber(l.force[k]));
  }
}

}  // namespace

std::vector<std::string> checkForceLaw(const ForceLaw& l) {
  std::vector<std::string> out;
  switch (l.kind) {
    case ForceLawKind::Constant:
      checkRange(kForceValueRange, l.value, "value", "N", out);
      break;
    case ForceLawKind::Ramp:
      checkRange(kForceValueRange, l.value, "value", "N", out);
      checkRange(kForceValueRange, l.initial, "initial", "N", out);
      checkRange(kForceStartRange, l.start, "start", "s", out);
      // 0 only for a ramp that does not change the force (a rate over a zero difference).
      if (!(std::isfinite(l.duration) && l.duration >= 0.0) ||
          (l.duration == 0.0 && l.value != l.initial))
        out.push_back("duration must be > 0 s, got " + formatNumber(l.duration));
      if (!(l.hold >= 0.0)) out.push_back("hold must be >= 0 s, got " + formatNumber(l.hold));
      break;
    case ForceLawKind::Table:
      checkTable(l, out);
      break;
  }
  return out;
}

double forceAt(const ForceLaw& l, double t, double s) {
  switch (l.kind) {
    case ForceLawKind::Constant:
      return l.value;
    case ForceLawKind::Ramp:
      return rampAt(l, t);
    case ForceLawKind::Table:
      return tableAt(l.at, l.force, l.over == ForceAbscissa::Time ? t : s);
  }
  return 0.0;
}

}  // namespace rb::suspension
