#include "workbench/integrators/detail.hpp"
#include "workbench/core/strings.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>

namespace rb::integ::detail {

std::vector<int> nonFiniteComponents(const double* v, long n) {
  std::vector<int> out;
  for (long i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) out.push_back(static_cast<int>(i));
  return out;
}

std::string componentList(const std::vector<int>& comps, const NameFn& name) {
  constexpr std::size_t kMax = 8;
  std::string out;
  for (std::size_t i = 0; i < comps.size() && i < kMax; ++i) {
    if (i > 0) out += ", ";
    out += name(comps[i]);
  }
  if (comps.size() > kMax) out += " and " + std::to_string(comps.size() - kMax) + " more";
  return out;
}

std::string RhsRecord::describeCode() const {
  std::string s = what + " returned " + std::to_string(code) +
                  (code > 0 ? " (recoverable)" : " (fatal)") + " at t = " + formatNumber(t, 10);
  if (!model_error.empty()) s += ": " + model_error;
  return s;
}

std::string RhsRecord::describeNonFinite(const NameFn& name) const {
  std::string s = "NaN/Inf in the " + nonfinite_where;
  if (!nonfinite_comps.empty()) s += " of " + componentList(nonfinite_comps, name);
  return s + " at t = " + formatNumber(nonfinite_t, 10);
}

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace rb::integ::detail
