#include "workbench/profiles/profile.hpp"

#include <cmath>

#include "workbench/core/error.hpp"

namespace rb::profiles {

Profile::Profile(std::string name, ProfileKind kind, double s_min, double ds,
                 const std::vector<double>& h)
    : name_(std::move(name)),
      kind_(kind),
      ds_(ds),
      spline_(SplineGrid::uniform(s_min, ds, h.size()), h) {
  RB_CHECK(h.size() >= 4 && ds > 0, "a profile needs >= 4 samples and a positive step");
}

ProfilePoint Profile::at(double s) const {
  return {spline_.value(s), spline_.deriv1(s), spline_.deriv2(s)};
}

Profile Profile::mirrored() const {
  std::vector<double> v = values();
  std::vector<double> m(v.rbegin(), v.rend());
  return Profile(name_ + " (mirrored)", kind_, -sMax(), ds_, m);
}

double Profile::curvature(double s) const {
  ProfilePoint p = at(s);
  return p.d2h / std::pow(1.0 + p.dh * p.dh, 1.5);
}

std::vector<double> Profile::knots() const {
  std::vector<double> k;
  const auto& g = spline_.grid();
  for (std::size_t i = 0; i < g.size(); ++i) k.push_back(g[i]);
  return k;
}

std::vector<double> Profile::values() const {
  std::vector<double> v;
  const auto& g = spline_.grid();
  for (std::size_t i = 0; i < g.size(); ++i) v.push_back(spline_.value(g[i]));
  return v;
}

}  // namespace rb::profiles
