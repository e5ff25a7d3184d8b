#include "workbench/profiles/rail60e1.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/profiles/sampling.hpp"

namespace rb::profiles {
namespace {

Rail60E1Geometry makeGeometry() {
  Rail60E1Geometry g;
  // R300 centred at (0, -R1), through the crown top (0, 0).
  const double c1y = 0.0, c1z = -g.crownRadius;
  g.y1 = g.crownHalfWidth;
  g.z1 = c1z + std::sqrt(g.crownRadius * g.crownRadius - g.y1 * g.y1);
  // R80 tangent to R300 at P1: its centre lies on the normal through P1, R80 away from P1.
  g.c2y = g.y1 + (c1y - g.y1) * g.shoulderRadius / g.crownRadius;
  g.c2z = g.z1 + (c1z - g.z1) * g.shoulderRadius / g.crownRadius;
  g.y2 = g.shoulderEnd;
  const double u2 = g.y2 - g.c2y;
  g.z2 = g.c2z + std::sqrt(g.shoulderRadius * g.shoulderRadius - u2 * u2);
  // R13 tangent to R80 at P2.
  g.c3y = g.y2 + (g.c2y - g.y2) * g.cornerRadius / g.shoulderRadius;
  g.c3z = g.z2 + (g.c2z - g.z2) * g.cornerRadius / g.shoulderRadius;
  // End of R13 where dz/dy = -sideSlope: u / sqrt(R^2 - u^2) = k.
  const double k = g.sideSlope;
  const double q = std::sqrt(1.0 + k * k);
  g.y3 = g.c3y + g.cornerRadius * k / q;
  g.z3 = g.c3z + g.cornerRadius / q;
  return g;
}

double arcZ(double cy, double cz, double R, double y) {
  const double u = y - cy;
  return cz + std::sqrt(std::max(0.0, R * R - u * u));
}
double arcDZ(double cy, double R, double y) {
  const double u = y - cy;
  return -u / std::sqrt(std::max(1e-300, R * R - u * u));
}

}  // namespace

const Rail60E1Geometry& rail60E1Geometry() {
  static const Rail60E1Geometry g = makeGeometry();
  return g;
}

double rail60E1Z(double y) {
  const auto& g = rail60E1Geometry();
  const double a = std::abs(y);
  if (a <= g.y1) return arcZ(0.0, -g.crownRadius, g.crownRadius, a);
  if (a <= g.y2) return arcZ(g.c2y, g.c2z, g.shoulderRadius, a);
  if (a <= g.y3) return arcZ(g.c3y, g.c3z, g.cornerRadius, a);
  return g.z3 - g.sideSlope * (a - g.y3);
}

double rail60E1dZ(double y) {
  const auto& g = rail60E1Geometry();
  const double a = std::abs(y);
  const double sign = y < 0.0 ? -1.0 : 1.0;
  double d = 0.0;
  if (a <= g.y1) {
    d = arcDZ(0.0, g.crownRadius, a);
  } else if (a <= g.y2) {
    d = arcDZ(g.c2y, g.shoulderRadius, a);
  } else if (a <= g.y3) {
    d = arcDZ(g.c3y, g.cornerRadius, a);
  } else {
    d = -g.sideSlope;
  }
  return sign * d;
}

Profile rail60E1(RailSide side, double ds) {
  RB_CHECK(ds > 0.0, "rail60E1 needs ds > 0");
  const UniformGrid grid = alignedGrid(-kRail60E1HalfWidth, kRail60E1HalfWidth, ds);
  std::vector<double> h(grid.n);
  for (std::size_t i = 0; i < grid.n; ++i) h[i] = 1e-3 * rail60E1Z(1e3 * grid.at(i));
  Profile left("60E1 left rail", ProfileKind::Rail, grid.s0, grid.ds, h);
  if (side == RailSide::Left) return left;
  return left.mirrored("60E1 right rail");
}

}  // namespace rb::profiles
