#include "workbench/assessment/en14363.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "workbench/core/error.hpp"

namespace rb::assessment::en14363 {

namespace {

constexpr double kLiftedWheelForce = 1.0;  // Q floor of the derailment quotient [N]

SlidingAssessment assessSliding(std::span<const double> x, std::span<const double> s,
                                double limit) {
  SlidingAssessment a;
  a.series = slidingMean(x, s, kSlidingWindow, kSlidingStep);
  RB_CHECK(!a.series.value.empty(), "the 2 m sliding mean needs at least 2 m of track");
  a.stats = extremes(a.series.value);
  a.check = check(std::max(std::fabs(a.stats.upper), std::fabs(a.stats.lower)), limit);
  return a;
}

}  // namespace

std::vector<double> lowPassForce(std::span<const double> x, double dt) {
  std::vector<double> y(x.begin(), x.end());
  if (kForceCutoff < 0.4 / dt) applyCascade(butterworthLowPass4(kForceCutoff, dt), y, y);
  return y;
}

Extremes extremes(std::span<const double> x) {
  Extremes e;
  e.upper = percentile(x, kUpperPercentile);
  e.lower = percentile(x, kLowerPercentile);
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  e.min = *lo;
  e.max = *hi;
  e.count = x.size();
  return e;
}

double nadalLimit(double flange_angle, double mu) {
  const double t = std::tan(flange_angle);
  return (t - mu) / (1.0 + mu * t);
}

FilteredWheelForces filterWheelForces(std::span<const double> Y, std::span<const double> Q,
                                      double dt) {
  RB_CHECK(Y.size() == Q.size(), "Y and Q differ in number of samples");
  return {lowPassForce(Y, dt), lowPassForce(Q, dt)};
}

SlidingAssessment derailmentQuotient(const FilteredWheelForces& f, std::span<const double> s,
                                     double limit) {
  std::vector<double> ratio = f.Y;
  for (std::size_t i = 0; i < ratio.size(); ++i) ratio[i] /= std::max(f.Q[i], kLiftedWheelForce);
  return assessSliding(ratio, s, limit);
}

SlidingAssessment derailmentQuotient(std::span<const double> Y, std::span<const double> Q,
                                     std::span<const double> s, double dt, double limit) {
  return derailmentQuotient(filterWheelForces(Y, Q, dt), s, limit);
}

double trackShiftLimit(double static_wheel_force, double alpha) {
  return alpha * (10e3 + 2.0 * static_wheel_force / 3.0);
}

SlidingAssessment trackShiftForce(std::span<const double> Y_left, std::span<const double> Y_right,
                                  std::span<const double> s, double dt, double static_wheel_force,
                                  double alpha) {
  RB_CHECK(Y_left.size() == Y_right.size(), "Y of the two wheels differ in number of samples");
  std::vector<double> sum(Y_left.size());
  for (std::size_t i = 0; i < sum.size(); ++i) sum[i] = Y_left[i] + Y_right[i];
  sum = lowPassForce(sum, dt);
  return assessSliding(sum, s, trackShiftLimit(static_wheel_force, alpha));
}

Check wheelUnloading(const FilteredWheelForces& f, double static_wheel_force, double limit) {
  RB_CHECK(static_wheel_force > 0.0 && !f.Q.empty(), "wheel unloading needs Q0 > 0 and samples");
  const double q_min = *std::min_element(f.Q.begin(), f.Q.end());
  return check((static_wheel_force - q_min) / static_wheel_force, limit);
}

Check wheelUnloading(std::span<const double> Q, double dt, double static_wheel_force,
                     double limit) {
  return wheelUnloading(FilteredWheelForces{{}, lowPassForce(Q, dt)}, static_wheel_force, limit);
}

SectionValues sectionValues(std::span<const double> x, double dt) {
  const std::vector<double> y = lowPassForce(x, dt);
  return {percentile(y, kMedianPercentile), percentile(y, kUpperPercentile),
          percentile(y, kLowerPercentile)};
}

Check quasiStaticGuidingForce(std::span<const double> Y, double dt, double limit) {
  return check(std::fabs(sectionValues(Y, dt).quasi_static), limit);
}

Check quasiStaticWheelForce(std::span<const double> Q, double dt, double limit) {
  return check(sectionValues(Q, dt).quasi_static, limit);
}

Check maximumWheelForce(std::span<const double> Q, double dt, double static_wheel_force) {
  return check(sectionValues(Q, dt).upper, 90e3 + static_wheel_force);
}

Check quasiStaticGuidingForce(const FilteredWheelForces& f, double limit) {
  return check(std::fabs(percentile(f.Y, kMedianPercentile)), limit);
}

Check quasiStaticWheelForce(const FilteredWheelForces& f, double limit) {
  return check(percentile(f.Q, kMedianPercentile), limit);
}

Check maximumWheelForce(const FilteredWheelForces& f, double static_wheel_force) {
  return check(percentile(f.Q, kUpperPercentile), 90e3 + static_wheel_force);
}

double bogieAccelerationLimit(double bogie_mass) {
  return 0.5 * (12.0 - bogie_mass / 1000.0 / 5.0);
}

StabilityAssessment stability(std::span<const double> bogie_lateral_acc, std::span<const double> s,
                              double dt, double f0, double bogie_mass) {
  RB_CHECK(f0 > kStabilityHalfBand,
           "the instability frequency f0 must exceed 2 Hz, got " + std::to_string(f0) + " Hz");
  std::vector<double> a(bogie_lateral_acc.begin(), bogie_lateral_acc.end());
  applyCascade(resonatorBandPass(f0, 2.0 * kStabilityHalfBand, dt), a, a);
  StabilityAssessment r;
  r.series = slidingRms(a, s, kStabilityWindow, kStabilityStep);
  RB_CHECK(!r.series.value.empty(), "the stability criterion needs at least 100 m of track");
  const auto it = std::max_element(r.series.value.begin(), r.series.value.end());
  r.position = r.series.position[static_cast<std::size_t>(it - r.series.value.begin())];
  r.check = check(*it, bogieAccelerationLimit(bogie_mass));
  return r;
}

}  // namespace rb::assessment::en14363
