#pragma once
// Internal helper: uniform grids aligned on multiples of ds (so s = 0 is a knot) for sampling
// profiles. Knots are s0 + i ds, exactly as rb::SplineGrid::uniform computes them.
#include <cmath>
#include <cstddef>

#include "workbench/core/error.hpp"

namespace rb::profiles {

struct UniformGrid {
  double s0 = 0.0;
  double ds = 0.0;
  std::size_t n = 0;
  double at(std::size_t i) const { return s0 + static_cast<double>(i) * ds; }
  double back() const { return at(n - 1); }
};

// The knots k ds inside [a, b] (a grid point within 1e-9 ds of an end counts as inside).
inline UniformGrid alignedGrid(double a, double b, double ds) {
  RB_CHECK(ds > 0.0 && b > a, "alignedGrid needs b > a and ds > 0");
  const double tol = 1e-9;
  const double k0 = std::ceil(a / ds - tol);
  const double k1 = std::floor(b / ds + tol);
  RB_CHECK(k1 - k0 >= 3.0, "profile domain too short for the grid step");
  return {k0 * ds, ds, static_cast<std::size_t>(k1 - k0) + 1};
}

}  // namespace rb::profiles
