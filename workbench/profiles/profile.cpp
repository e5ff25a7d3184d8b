#include "workbench/profiles/profile.hpp"

#include <cmath>
#include <utility>

#include "workbench/core/error.hpp"

namespace rb::profiles {

Profile::Profile(std::string name, ProfileKind kind, double s_min, double ds,
                 const std::vector<double>& h)
    : name_(std::move(name)),
      kind_(kind),
      ds_(ds),
      spline_(SplineGrid::uniform(s_min, ds, h.size()), std::vector<std::vector<double>>{h}) {
  RB_CHECK(h.size() >= 4 && ds > 0, "a profile needs >= 4 samples and a positive step");
}

ProfilePoint Profile::at(double s) const {
  // Mirror image: h_m(s) = h(-s), h_m'(s) = -h'(-s), h_m''(s) = h''(-s). Negation is exact.
  const double x = mirror_ ? -s : s;
  double v = 0.0, d1 = 0.0, d2 = 0.0;
  spline_.eval(x, {&v, 1}, {&d1, 1}, {&d2, 1});
  return {v, mirror_ ? -d1 : d1, d2};
}

Profile Profile::mirrored() const {
  return mirrored(name_ + " (mirrored)");
}

Profile Profile::mirrored(std::string name) const {
  Profile m = *this;
  m.name_ = std::move(name);
  m.mirror_ = !mirror_;
  return m;
}

double Profile::curvature(double s) const {
  ProfilePoint p = at(s);
  return p.d2h / std::pow(1.0 + p.dh * p.dh, 1.5);
}

std::vector<double> Profile::knots() const {
  std::vector<double> k;
  const auto& g = spline_.grid();
  k.reserve(g.size());
  if (mirror_) {
    for (std::size_t i = g.size(); i-- > 0;) k.push_back(-g[i]);
  } else {
    for (std::size_t i = 0; i < g.size(); ++i) k.push_back(g[i]);
  }
  return k;
}

std::vector<double> Profile::values() const {
  std::vector<double> v;
  const auto& g = spline_.grid();
  v.reserve(g.size());
  if (mirror_) {
    for (std::size_t i = g.size(); i-- > 0;) v.push_back(spline_.value(0, g[i]));
  } else {
    for (std::size_t i = 0; i < g.size(); ++i) v.push_back(spline_.value(0, g[i]));
  }
  return v;
}

}  // namespace rb::profiles
