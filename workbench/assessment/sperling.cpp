#include "workbench/assessment/sperling.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace rb::assessment::sperling {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kLateralFactor = 1.25;  // B_y = 1.25 B_z
constexpr double kGain = 0.588;
// Denominator 1 + d1 p + d2 p^2 + d3 p^3 of H(p), p = j f.
constexpr double kD1 = 1.563;
constexpr double kD2 = 0.277;
constexpr double kD3 = 0.0368;

double directionFactor(Direction d) {
  return d == Direction::Lateral ? kLateralFactor : 1.0;
}

// The denominator as (p - r)(d3 p^2 + q1 p + q0): r its real root (Newton from -0.7; the root is
// -0.7237, the other two a complex pair near -3.40 +- 5.10 j).
struct Factored {
  double r, q1, q0;
};

Factored factorDenominator() {
  double r = -0.7;
  for (int it = 0; it < 50; ++it) {
    const double f = 1.0 + r * (kD1 + r * (kD2 + r * kD3));
    const double df = kD1 + r * (2.0 * kD2 + 3.0 * r * kD3);
    r -= f / df;
  }
  const double q1 = kD2 + r * kD3;
  const double q0 = kD1 + r * q1;
  return {r, q1, q0};
}

}  // namespace

double weighting(double f_hz, Direction d) {
  const double f2 = f_hz * f_hz;
  const double num = 1.911 * f2 + (0.25 * f2) * (0.25 * f2);
  const double re = 1.0 - kD2 * f2;
  const double im = kD1 * f_hz - kD3 * f2 * f_hz;
  return directionFactor(d) * kGain * std::sqrt(num / (re * re + im * im));
}

Cascade weightingFilter(Direction d, double dt) {
  const Factored fd = factorDenominator();
  const double g = directionFactor(d) * kGain;
  const double w = kTwoPi;  // p = s / (2 pi): a coefficient of p^k is divided by w^k
  // Section 1: g (sqrt(1.911) p + 0.25 p^2) / (d3 p^2 + q1 p + q0); section 2: 1 / (p - r).
  const AnalogSection s1{
      0.0, g * std::sqrt(1.911) / w, g * 0.25 / (w * w), fd.q0, fd.q1 / w, kD3 / (w * w)};
  const AnalogSection s2{1.0, 0.0, 0.0, -fd.r, 1.0 / w, 0.0};
  Cascade c;
  c.push(bilinear(s1, dt, std::sqrt(fd.q0 / kD3)));
  c.push(bilinear(s2, dt, -fd.r));
  return c;
}

double indexOfHarmonic(double amplitude, double f_hz, Direction d) {
  return std::pow(100.0 * amplitude * weighting(f_hz, d), 0.3);
}

Check index(std::span<const double> a, double dt, Direction d, double target) {
  std::vector<double> y(a.size());
  applyCascade(weightingFilter(d, dt), a, y);
  double sum = 0.0;
  for (const double v : y) sum += v * v;
  const double rms = y.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(y.size()));
  return check(std::pow(100.0 * std::numbers::sqrt2 * rms, 0.3), target);
}

}  // namespace rb::assessment::sperling
