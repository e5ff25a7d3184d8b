#include "workbench/contact/config.hpp"

#include <cmath>
#include <cstring>
#include <string>

#include "workbench/core/error.hpp"

namespace rb::contact {

std::size_t GridSpec::count() const {
  if (!(step > 0.0) || !(max >= min) || !std::isfinite(min) || !std::isfinite(max)) return 0;
  const double n = (max - min) / step;
  const double r = std::round(n);
  if (std::abs(n - r) > 1e-6) return 0;
  return static_cast<std::size_t>(r) + 1;
}

GridSpec table10LateralGrid() {
  return {-0.018, 0.018, 0.1e-3};
}
GridSpec table10LateralGridRefined() {
  return {-0.018, 0.018, 0.05e-3};
}
GridSpec table10GaugeGrid() {
  return {-0.005, 0.005, 1.0e-3};
}
GridSpec table9KecGrid() {
  return {-0.0464, 0.0464, 0.2e-3};
}
GridSpec table9KecGridRefined() {
  return {-0.0464, 0.0464, 0.0928 / 5000.0};
}

void ContactGeometryConfig::useRefinedGrids() {
  lut_y = table10LateralGridRefined();
  lut_gauge = table10GaugeGrid();
  kec_s = table9KecGridRefined();
}

void checkConfig(const ContactGeometryConfig& c) {
  Diagnostics d;
  const SourceLoc loc{"contact geometry", 0};
  auto need = [&](const std::shared_ptr<const profiles::Profile>& p, const char* what,
                  profiles::ProfileKind kind) {
    if (!p) {
      d.add(loc, std::string("missing ") + what + " profile");
    } else if (p->kind() != kind) {
      d.add(loc, std::string(what) + " profile '" + p->name() + "' has the wrong kind");
    }
  };
  need(c.left_wheel, "left wheel", profiles::ProfileKind::Wheel);
  need(c.right_wheel, "right wheel", profiles::ProfileKind::Wheel);
  need(c.left_rail, "left rail", profiles::ProfileKind::Rail);
  need(c.right_rail, "right rail", profiles::ProfileKind::Rail);
  auto positive = [&](double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v)) d.add(loc, std::string(what) + " must be positive");
  };
  positive(c.wheel_lw, "Lw");
  positive(c.rail_lr, "Lr");
  positive(c.r0, "r0");
  if (!(std::abs(c.beta) < 0.2)) d.add(loc, "rail inclination beta must satisfy |beta| < 0.2 rad");
  auto grid = [&](const GridSpec& g, const char* what, std::size_t min_n) {
    const std::size_t n = g.count();
    if (n < min_n) {
      d.add(loc, std::string(what) + " grid needs min < max, step > 0, (max - min) a multiple of " +
                     "step and at least " + std::to_string(min_n) + " nodes");
    }
  };
  grid(c.lut_y, "LUT lateral", 4);
  grid(c.lut_gauge, "LUT gauge", 1);
  grid(c.kec_s, "KEC", 4);
  if (c.lut_y.count() >= 4 && !(c.lut_y.min < 0.0 && c.lut_y.max > 0.0)) {
    d.add(loc, "LUT lateral grid must contain y = 0");
  }
  positive(c.kec_dhat, "KEC transition length d_hat");
  positive(c.kec_dbar, "KEC transition length d_bar");
  positive(c.jump_threshold, "jump threshold");
  positive(c.search_step, "search step");
  positive(c.newton_tol, "Newton tolerance");
  if (c.newton_max_iter < 1) d.add(loc, "Newton iteration limit must be >= 1");
  if (!(c.flange_angle > 0.0 && c.flange_angle < 1.5)) {
    d.add(loc, "flange angle must lie in (0, 1.5) rad");
  }
  d.throwIfAny();
}

namespace {
struct Fnv {
  std::uint64_t h = 1469598103934665603ULL;
  void bytes(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
      h ^= b[i];
      h *= 1099511628211ULL;
    }
  }
  void num(double v) {
    if (v == 0.0) v = 0.0;  // -0 == +0
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    bytes(&u, sizeof u);
  }
  void str(const std::string& s) {
    num(static_cast<double>(s.size()));
    bytes(s.data(), s.size());
  }
};
}  // namespace

std::uint64_t configHash(const ContactGeometryConfig& c) {
  Fnv f;
  f.str("railbench contact geometry v1");
  for (const auto* p :
       {c.left_wheel.get(), c.right_wheel.get(), c.left_rail.get(), c.right_rail.get()}) {
    if (!p) {
      f.num(-1.0);
      continue;
    }
    f.num(p->kind() == profiles::ProfileKind::Wheel ? 1.0 : 2.0);
    const std::vector<double> k = p->knots(), v = p->values();
    f.num(static_cast<double>(k.size()));
    for (double x : k) f.num(x);
    for (double x : v) f.num(x);
  }
  for (double x : {c.wheel_lw, c.rail_lr, c.beta, c.r0, c.flange_boundary, c.flange_angle}) {
    f.num(x);
  }
  for (const GridSpec* g : {&c.lut_y, &c.lut_gauge, &c.kec_s}) {
    f.num(g->min);
    f.num(g->max);
    f.num(g->step);
  }
  for (double x : {c.kec_dhat, c.kec_dbar, c.kec_min_transition, c.kec_max_curvature,
                   c.kec_max_map_slope, c.kec_sample_step, c.jump_threshold, c.search_step,
                   c.newton_tol, static_cast<double>(c.newton_max_iter)}) {
    f.num(x);
  }
  if (c.interpolation != TableInterpolation::Cubic) f.str(std::string(nameOf(c.interpolation)));
  return f.h;
}

}  // namespace rb::contact
