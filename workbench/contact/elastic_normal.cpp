#include "workbench/contact/elastic_normal.hpp"

#include <algorithm>
#include <cmath>

namespace rb::contact {

double smoothCurvatureFloor(double x, double m) {
  if (!(m > 0.0)) return x;
  if (x >= 2.0 * m) return x;
  if (x <= 0.0) return m;
  return m + x * x / (4.0 * m);
}

creep::RelativeCurvatures policyCurvatures(const ElasticPatchGeometry& g,
                                           const ElasticNormalSpec& spec, bool* B_floored) {
  const double A = std::max(g.A, spec.min_curvature);
  const double B0 = spec.span_curvature ? g.B_span : g.B;
  const double B = smoothCurvatureFloor(B0, spec.min_ratio * A);
  if (B_floored) *B_floored = B != B0;
  return {A, B};
}

ElasticPatchNormal elasticNormal(const ElasticPatchGeometry& g, const ElasticNormalSpec& spec) {
  ElasticPatchNormal r;
  const creep::RelativeCurvatures k = policyCurvatures(g, spec, &r.B_floored);
  r.A = k.A;
  r.B = k.B;
  const creep::HertzShape shape = creep::hertzShape(k.A, k.B);
  r.k_hertz = creep::hertzStiffness(spec.material, k, shape);
  const double d = std::max(g.approach, 0.0);
  r.N = r.k_hertz * d * std::sqrt(d);
  if (r.N > 0.0) {
    const creep::HertzContact h = creep::hertz(spec.material, k, shape, r.N);
    r.a = h.a;
    r.b = h.b;
    r.p0 = h.p0;
  }
  return r;
}

void elasticWheelContact(const ElasticContactSearch& search, const ElasticPose& pose,
                         const ElasticNormalSpec& spec, ElasticWheelContact& out,
                         ElasticSearchWorkspace& ws, const ElasticWheelGeometry* seed) {
  search.search(pose, out.geometry, ws, seed);
  out.force_y = out.force_z = out.normal_sum = 0.0;
  for (int i = 0; i < out.geometry.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const ElasticPatchGeometry& g = out.geometry.patch[k];
    out.normal[k] = elasticNormal(g, spec);
    out.force_y += out.normal[k].N * g.n_y;
    out.force_z += out.normal[k].N * g.n_z;
    out.normal_sum += out.normal[k].N;
  }
}

WheelLoadSolution solveWheelLoad(const ElasticContactSearch& search, const ElasticPose& pose,
                                 const ElasticNormalSpec& spec, double target, WheelLoad mode,
                                 double rel_tol) {
  WheelLoadSolution sol;
  ElasticSearchWorkspace ws;
  ElasticPose p = pose;
  // g(z) = F^(2/3) - target^(2/3): nearly linear in z for Hertz patches (F ~ delta^1.5).
  auto eval = [&](double z) {
    p.z = z;
    elasticWheelContact(search, p, spec, sol.contact, ws);
    ++sol.iterations;
    const double f = mode == WheelLoad::Vertical ? sol.contact.force_z : sol.contact.normal_sum;
    return std::cbrt(f * f) - std::cbrt(target * target);
  };
  // Upper end: just touching (the sampled gap is about vertical on a tread).
  double z_hi = pose.z;
  double g_hi = eval(z_hi);
  for (int k = 0; k < 60 && g_hi >= 0.0; ++k) {
    z_hi += std::max(std::abs(sol.contact.geometry.min_gap), 1e-4);
    g_hi = eval(z_hi);
  }
  if (g_hi >= 0.0) return sol;
  if (std::isfinite(sol.contact.geometry.min_gap) && sol.contact.geometry.min_gap > 0.0) {
    z_hi -= sol.contact.geometry.min_gap;  // the first touch
    g_hi = eval(z_hi);
  }
  double step = 1e-5, z_lo = z_hi - step, g_lo = eval(z_lo);
  for (int k = 0; k < 60 && g_lo < 0.0; ++k) {
    z_hi = z_lo;
    g_hi = g_lo;
    step *= 2.0;
    z_lo -= step;
    g_lo = eval(z_lo);
  }
  if (g_lo < 0.0) return sol;
  // Illinois regula falsi on [z_lo, z_hi] (g_lo >= 0 > g_hi).
  int side = 0;
  for (int it = 0; it < 100; ++it) {
    double z = z_lo - g_lo * (z_hi - z_lo) / (g_hi - g_lo);
    if (!(z > std::min(z_lo, z_hi) && z < std::max(z_lo, z_hi))) z = 0.5 * (z_lo + z_hi);
    const double g = eval(z);
    const double f = mode == WheelLoad::Vertical ? sol.contact.force_z : sol.contact.normal_sum;
    if (std::abs(f - target) <= rel_tol * target || std::abs(z_hi - z_lo) < 1e-15) {
      sol.converged = true;
      sol.z = z;
      return sol;
    }
    if (g >= 0.0) {
      z_lo = z;
      g_lo = g;
      if (side == -1) g_hi *= 0.5;
      side = -1;
    } else {
      z_hi = z;
      g_hi = g;
      if (side == 1) g_lo *= 0.5;
      side = 1;
    }
  }
  return sol;
}

WheelsetLoadSolution solveWheelsetLoad(const ElasticContactSearch& left,
                                       const ElasticContactSearch& right, const ElasticPose& pose,
                                       const ElasticNormalSpec& spec, double target_left,
                                       double target_right, WheelLoad mode, double z_tol) {
  WheelsetLoadSolution sol;
  ElasticPose p = pose;
  // Height difference of the two single-wheel solutions at roll phi (NaN when one failed).
  auto diff = [&](double phi) {
    p.phi = phi;
    sol.left = solveWheelLoad(left, p, spec, target_left, mode);
    sol.right = solveWheelLoad(right, p, spec, target_right, mode);
    ++sol.iterations;
    if (!sol.left.converged || !sol.right.converged) return std::nan("");
    return sol.left.z - sol.right.z;
  };
  // Raising the left wheel by dz at fixed z needs phi ~ dz / (2 Lw): the first secant step.
  const double span = 2.0 * left.pair().wheel_lw;
  double phi0 = pose.phi, d0 = diff(phi0);
  if (!std::isfinite(d0)) return sol;
  double phi1 = phi0 + d0 / span, d1 = diff(phi1);
  for (int it = 0; it < 40 && std::isfinite(d1); ++it) {
    if (std::abs(d1) <= z_tol) {
      sol.converged = true;
      sol.phi = phi1;
      sol.z = 0.5 * (sol.left.z + sol.right.z);
      return sol;
    }
    const double slope = (d1 - d0) / (phi1 - phi0);
    double next = slope != 0.0 && std::isfinite(slope) ? phi1 - d1 / slope : phi1 + d1 / span;
    // A contact-point jump makes z(phi) kinked: limit the step to 2 mrad.
    next = std::clamp(next, phi1 - 2e-3, phi1 + 2e-3);
    phi0 = phi1;
    d0 = d1;
    phi1 = next;
    d1 = diff(phi1);
  }
  return sol;
}

}  // namespace rb::contact
