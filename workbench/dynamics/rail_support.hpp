#pragma once
// The track under the rail (docs/track_support.md): the support of the rail mass under a wheel at
// track position s. Points of contact.elastic.rail_support, linear between them in s, the end
// points' values beyond (one point: everywhere).
#include <algorithm>
#include <vector>

#include "workbench/dynamics/spec.hpp"

namespace rb::dynamics {

inline RailSupportPoint railSupportAt(const std::vector<RailSupportPoint>& points, double s) {
  if (points.size() == 1 || s <= points.front().s) return points.front();
  if (s >= points.back().s) return points.back();
  const auto it = std::upper_bound(points.begin(), points.end(), s,
                                   [](double v, const RailSupportPoint& p) { return v < p.s; });
  const RailSupportPoint& b = *it;
  const RailSupportPoint& a = *(it - 1);
  const double t = (s - a.s) / (b.s - a.s);
  RailSupportPoint p = a;
  p.s = s;
  p.mass = a.mass + t * (b.mass - a.mass);
  p.k_y = a.k_y + t * (b.k_y - a.k_y);
  p.c_y = a.c_y + t * (b.c_y - a.c_y);
  p.k_z = a.k_z + t * (b.k_z - a.k_z);
  p.c_z = a.c_z + t * (b.c_z - a.c_z);
  return p;
}

}  // namespace rb::dynamics
