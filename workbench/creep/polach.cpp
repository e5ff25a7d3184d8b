#include "workbench/creep/polach.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "workbench/core/error.hpp"

namespace rb::creep {

namespace {

constexpr double kPi = std::numbers::pi;

// sqrt(x^2 + y^2) without overflow or underflow of the squares.
double norm2(double x, double y) {
  const double m = fmaxOf(std::fabs(x), std::fabs(y));
  if (m == 0.0) return 0.0;
  if (m > 1e-150 && m < 1e150) return std::sqrt(x * x + y * y);
  return std::hypot(x, y);
}

// x / (1 + x^2) for x >= 0, also for x beyond sqrt(DBL_MAX).
double ratio(double x) {
  return x < 1e150 ? x / (1.0 + x * x) : 1.0 / x;
}

bool finite(double x) {
  return std::isfinite(x);
}

}  // namespace

std::string creepParamsProblem(const CreepParams& p) {
  if (!(p.mu >= 0.0) || !finite(p.mu)) return "friction coefficient mu must be >= 0";
  if (!(p.G > 0.0) || !finite(p.G)) return "shear modulus G must be > 0";
  if (!(p.k_S > 0.0 && p.k_S <= p.k_A && p.k_A <= 1.0))
    return "Polach reduction factors must satisfy 0 < k_S <= k_A <= 1";
  if (!(p.friction_A >= 0.0 && p.friction_A <= 1.0))
    return "falling friction ratio A = mu_inf/mu_0 must be in [0, 1]";
  if (!(p.friction_B >= 0.0) || !finite(p.friction_B))
    return "falling friction decay B must be >= 0 [s/m]";
  return {};
}

ContactPatch makeContactPatch(const Material& mat, const RelativeCurvatures& k, double N) {
  return makeContactPatch(mat, k, hertzShape(k.A, k.B), N);
}

ContactPatch makeContactPatch(const Material& mat, const RelativeCurvatures& k,
                              const HertzShape& shape, double N) {
  return makeContactPatch(patchConstants(mat, k, shape), N);
}

PatchConstants patchConstants(const Material& mat, const RelativeCurvatures& k,
                              const HertzShape& shape) {
  // The semi-axes of hertz() (same expressions, bit-identical) without its Hertz stiffness and
  // approach, which the creep laws do not use (a cbrt and a sqrt less per patch evaluation).
  // nu = 0.5 (incompressible) is inside the schema's range and Kalker's table; E* and G stay
  // finite up to it.
  RB_CHECK(mat.E > 0.0 && mat.nu > -1.0 && mat.nu <= 0.5, "invalid material");
  PatchConstants pc;
  pc.c = kalkerCoefficients(shape.aOverB(), mat.nu);
  pc.denom = 4.0 * contactModulus(mat) * (k.A + k.B);
  pc.m = shape.m;
  pc.n = shape.n;
  pc.rolling_major = shape.rolling_major;
  pc.km = polachSpinFactor(pc.rolling_major ? pc.m / pc.n : pc.n / pc.m);
  return pc;
}

ContactPatch makeContactPatch(const PatchConstants& pc, double N) {
  ContactPatch patch;
  if (N > 0.0) {
    const double c0 = std::cbrt(3.0 * N / pc.denom);
    const double major = pc.m * c0;
    const double minor = pc.n * c0;
    patch.Q = N;
    patch.a = pc.rolling_major ? major : minor;
    patch.b = pc.rolling_major ? minor : major;
  }
  patch.c11 = pc.c.c11;
  patch.c22 = pc.c.c22;
  patch.c23 = pc.c.c23;
  patch.c33 = pc.c.c33;
  patch.km = pc.km;
  return patch;
}

double polachSpinFactor(double a_over_b) {
  return 1.0 + 6.3 * (1.0 - std::exp(-a_over_b));
}

double frictionCoefficient(const CreepParams& p, double slip_velocity) {
  if (p.friction_A == 1.0) return p.mu;
  const double w = std::fabs(slip_velocity);
  return p.mu * ((1.0 - p.friction_A) * std::exp(-p.friction_B * w) + p.friction_A);
}

CreepForce polachForce(const CreepParams& p, const ContactPatch& patch, const Creepages& s) {
  CreepForce out;
  const double Q = patch.Q;
  const double a = patch.a;
  const double b = patch.b;
  if (!(Q > 0.0) || !(a > 0.0) || !(b > 0.0) || !(p.mu > 0.0)) {
    out.mu = p.mu;
    return out;
  }
  // Spin-corrected lateral creepage (Polach 1999): s_y + phi a at the leading edge when it is the
  // larger one in magnitude.
  const double sy_lead = s.sy + s.phi * a;
  const double syc = std::fabs(sy_lead) > std::fabs(s.sy) ? sy_lead : s.sy;
  const double sc = norm2(s.sx, syc);
  const double mu = frictionCoefficient(p, sc * s.v);
  out.mu = mu;
  if (sc == 0.0 || !(mu > 0.0)) return out;  // no creepage (s_x = s_y = phi = 0): zero force
  const double qmu = Q * mu;

  // Creep part: Kalker's coefficient in the direction of (s_x, s_y).
  const double sn = norm2(s.sx, s.sy);
  double C = patch.c22;  // direction undefined at s = 0 (pure spin): F multiplies s_x = s_y = 0
  if (sn > 0.0) C = norm2(patch.c11 * (s.sx / sn), patch.c22 * (s.sy / sn));
  const double eps = kPi * p.G * a * b * C * sc / (4.0 * qmu);
  const double F = (2.0 * qmu / kPi) * (ratio(p.k_A * eps) + std::atan(p.k_S * eps));  // <= mu Q
  // The creep part's direction is (s_x, s_y); its divisor goes from Polach's s_C while the patch
  // adheres (the linear theory, with the spin in F_yS) to s = |(s_x, s_y)| as the creepage alone
  // saturates the patch, so that full sliding carries F -> mu Q along (s_x, s_y) as in Kalker's
  // exact theory (polach.hpp, "Saturation").
  // The weight is continuous where s_yC switches between s_y and s_y + phi a (s_C = s there).
  const double eps_own = p.k_S * eps * (sn / sc);
  // 1 while the creepage alone leaves the patch adhering, -> 0 as it makes it slide.
  const double adhesion = eps_own < 1e150 ? 1.0 / (1.0 + eps_own * eps_own) : 0.0;
  const double divisor = sn + adhesion * (sc - sn);
  double fx = -F * (s.sx / divisor);
  double fy = -F * (s.sy / divisor);

  // Spin part.
  if (s.phi != 0.0) {
    const double km = patch.km > 0.0 ? patch.km : polachSpinFactor(a / b);
    const double eps_s =
        (8.0 / 3.0) * p.G * b * std::sqrt(a * b) * patch.c23 * std::fabs(syc) / (qmu * km);
    // eps_s / (1 + eps_s^2)^2, written to stay finite for any eps_s >= 0.
    const double shape = eps_s < 1e150 ? ratio(eps_s) / (1.0 + eps_s * eps_s) : 0.0;
    // The spin's own share fades with the same weight: over a patch that the creepage makes
    // slide, the spin's slip (-phi y, phi x) averages out (polach.hpp, "Saturation").
    const double fys = 0.375 * a * qmu * km * shape * (s.phi / sc);  // phi/sc <= 2/a
    fy -= adhesion * fys;
  }

  // Cap the resultant at mu Q (only active at absurd creepages, see the header).
  const double f = norm2(fx, fy);
  if (f > qmu) {
    const double scale = qmu / f;
    fx *= scale;
    fy *= scale;
  }
  out.fx = fx;
  out.fy = fy;
  return out;
}

LinearCreepForce kalkerLinearForce(double G, const ContactPatch& patch, const Creepages& s) {
  const double c2 = patch.a * patch.b;  // c^2
  const double c = std::sqrt(c2);
  const double c3 = c2 * c;
  LinearCreepForce f;
  f.fx = -G * c2 * patch.c11 * s.sx;
  f.fy = -G * c2 * patch.c22 * s.sy - G * c3 * patch.c23 * s.phi;
  f.mz = G * c3 * patch.c23 * s.sy - G * c2 * c2 * patch.c33 * s.phi;
  return f;
}

}  // namespace rb::creep
