#include "workbench/assessment/wear.hpp"

#include <algorithm>
#include <cmath>

#include "workbench/core/error.hpp"

namespace rb::assessment::wear {

double tGamma(const PatchCreep& p) {
  return std::fabs(p.fx * p.nux) + std::fabs(p.fy * p.nuy) + std::fabs(p.mz * p.phi);
}

double frictionalPower(const PatchCreep& p, double speed) {
  return tGamma(p) * std::fabs(speed);
}

void tGammaSeries(std::span<const double> fx, std::span<const double> fy,
                  std::span<const double> mz, std::span<const double> nux,
                  std::span<const double> nuy, std::span<const double> phi, std::span<double> out) {
  const std::size_t n = out.size();
  RB_CHECK(fx.size() == n && fy.size() == n && nux.size() == n && nuy.size() == n,
           "creep forces, creepages and output differ in length");
  const bool spin = !mz.empty();
  RB_CHECK(!spin || (mz.size() == n && phi.size() == n),
           "spin moment and spin creepage must both have the output's length");
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = tGamma({fx[i], fy[i], spin ? mz[i] : 0.0, nux[i], nuy[i], spin ? phi[i] : 0.0});
  }
}

void addPatch(std::span<double> wheel_total, std::span<const double> patch) {
  RB_CHECK(wheel_total.size() == patch.size(), "patch and wheel series differ in length");
  for (std::size_t i = 0; i < patch.size(); ++i) wheel_total[i] += patch[i];
}

WearSummary summarize(std::span<const double> tgamma, std::span<const double> s) {
  RB_CHECK(tgamma.size() == s.size() && !s.empty(), "T gamma and distance differ in length");
  WearSummary w;
  double sum = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    sum += tgamma[i];
    w.max = std::max(w.max, tgamma[i]);
    if (i > 0) w.energy += 0.5 * (tgamma[i] + tgamma[i - 1]) * (s[i] - s[i - 1]);
  }
  w.mean = sum / static_cast<double>(s.size());
  return w;
}

}  // namespace rb::assessment::wear
