#include "workbench/creep/hertz.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "workbench/core/error.hpp"
#include "workbench/creep/elliptic.hpp"

namespace rb::creep {

namespace {

constexpr double kPi = std::numbers::pi;

// ln of the shape function f(g) = g^2 (K - E)/(E - g^2 K) at u = ln g (g < 1), and K, E there.
// (K - E)/(E - g^2 K) = S / (e^2 - S) with S = 1 - E/K.
struct ShapeEval {
  double lnf;
  EllipticKE ke;
};

ShapeEval shapeFunction(double u) {
  const double g = std::exp(u);
  const EllipticKE ke = ellipticKEComplementary(g);
  const double e2 = (1.0 - g) * (1.0 + g);
  return {2.0 * u + std::log(ke.S / (e2 - ke.S)), ke};
}

}  // namespace

HertzShape hertzShape(double A, double B) {
  RB_CHECK(isHertzian({A, B}), "Hertz contact needs relative curvatures A > 0 and B > 0, got A = " +
                                   std::to_string(A) + ", B = " + std::to_string(B));
  HertzShape s;
  s.rolling_major = A <= B;
  const double r = s.rolling_major ? A / B : B / A;  // in (0, 1]
  // Near 1, g = 1 - 2 (1 - r)/3 + ...: treat as circular (error < 1e-12).
  if (r >= 1.0 - 1e-12) {
    s.g = 1.0;
    s.K = s.E = 0.5 * kPi;
    s.m = s.n = 1.0;
    return s;
  }
  const double target = std::log(r);
  // F(u) = ln f(e^u) - ln r is increasing in u, with F(0) = -ln r > 0. Safeguarded secant: the
  // iterate stays inside the bracket [lo, hi] known so far (bisection / unit steps otherwise).
  double lo = -std::numeric_limits<double>::infinity(), hi = 0.0;
  auto F = [&](double x, ShapeEval& ev) {
    ev = shapeFunction(x);
    const double f = ev.lnf - target;
    if (f < 0.0) lo = std::max(lo, x);
    if (f > 0.0) hi = std::min(hi, x);
    return f;
  };
  ShapeEval eb{};
  double ua = (2.0 / 3.0) * target;  // g = (A/B)^(2/3), exact to first order at r -> 1
  double fa = F(ua, eb);
  double ub = ua - fa / 1.5;  // d ln f / d ln g ~ 1.5
  if (!(ub < 0.0)) ub = 0.5 * ua;
  double fb = F(ub, eb);
  int evals = 2;
  while (evals < 100 && fb != 0.0 && fa != fb &&
         std::fabs(ub - ua) > 1e-15 * std::max(1.0, std::fabs(ub))) {
    double u = ub - fb * (ub - ua) / (fb - fa);
    if (!(u > lo && u < hi)) u = std::isfinite(lo) ? 0.5 * (lo + hi) : std::min(ua, ub) - 1.0;
    ua = ub;
    fa = fb;
    ub = u;
    fb = F(ub, eb);
    ++evals;
  }
  RB_CHECK(std::isfinite(ub) && std::fabs(fb) < 1e-10,
           "Hertz shape equation did not converge for A/B = " + std::to_string(r));
  const double u = ub;
  const ShapeEval& eu = eb;
  s.g = std::exp(u);
  s.K = eu.ke.K;
  s.E = eu.ke.E;
  s.m = std::cbrt(2.0 * s.E / (kPi * s.g * s.g));
  s.n = std::cbrt(2.0 * s.E * s.g / kPi);
  s.iterations = evals;
  return s;
}

double hertzStiffness(const Material& mat, const RelativeCurvatures& k, const HertzShape& shape) {
  const double es = contactModulus(mat);
  // delta = lambda N^(2/3), lambda = (3 K / (2 pi E* m)) (4 E* (A + B) / 3)^(1/3); K_H =
  // lambda^-1.5.
  const double lambda =
      3.0 * shape.K / (2.0 * kPi * es * shape.m) * std::cbrt(4.0 * es * (k.A + k.B) / 3.0);
  return 1.0 / (lambda * std::sqrt(lambda));
}

double hertzStiffness(const Material& mat, const RelativeCurvatures& k) {
  return hertzStiffness(mat, k, hertzShape(k.A, k.B));
}

HertzContact hertz(const Material& mat, const RelativeCurvatures& k, double N) {
  return hertz(mat, k, hertzShape(k.A, k.B), N);
}

HertzContact hertz(const Material& mat, const RelativeCurvatures& k, const HertzShape& shape,
                   double N) {
  // nu = 0.5 (incompressible) is inside the schema's range and Kalker's table; E* and G stay
  // finite up to it.
  RB_CHECK(mat.E > 0.0 && mat.nu > -1.0 && mat.nu <= 0.5, "invalid material");
  HertzContact c;
  c.shape = shape;
  c.k_hertz = hertzStiffness(mat, k, c.shape);
  if (!(N > 0.0)) return c;
  const double es = contactModulus(mat);
  const double c0 = std::cbrt(3.0 * N / (4.0 * es * (k.A + k.B)));
  const double major = c.shape.m * c0;
  const double minor = c.shape.n * c0;
  c.a = c.shape.rolling_major ? major : minor;
  c.b = c.shape.rolling_major ? minor : major;
  c.delta = 3.0 * N * c.shape.K / (2.0 * kPi * major * es);
  c.p0 = 3.0 * N / (2.0 * kPi * c.a * c.b);
  return c;
}

}  // namespace rb::creep
