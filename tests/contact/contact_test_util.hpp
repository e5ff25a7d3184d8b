#pragma once
// Profiles and configurations for the contact tests: analytic profiles with closed-form contact
// geometry, and S1002 on 60E1 1:40 from workbench/profiles.
#include <cmath>
#include <memory>
#include <vector>

#include "workbench/contact/config.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/profile.hpp"
#include "workbench/profiles/rail60e1.hpp"
#include "workbench/profiles/s1002.hpp"

namespace rbtest {

using rb::profiles::Profile;
using rb::profiles::ProfileKind;
using ProfilePtr = std::shared_ptr<const Profile>;

template <class F>
ProfilePtr sampled(const char* name, ProfileKind kind, double s_min, double s_max, double ds, F f) {
  const auto n = static_cast<std::size_t>(std::llround((s_max - s_min) / ds)) + 1;
  std::vector<double> h(n);
  for (std::size_t i = 0; i < n; ++i) h[i] = f(s_min + static_cast<double>(i) * ds);
  return std::make_shared<const Profile>(name, kind, s_min, ds, h);
}

// LEFT conical wheel of conicity lambda: radius r0 at s = 0, decreasing to the field side.
inline ProfilePtr coneWheel(double r0, double lambda, double half = 0.05, double ds = 1e-4) {
  return sampled("cone", ProfileKind::Wheel, -half, half, ds,
                 [=](double s) { return r0 - lambda * s; });
}
// LEFT wheel whose tread is a circle of radius |rw| centred at s = sc: rw > 0 convex (radius
// largest at s = sc), rw < 0 concave (hollow), plus a cone of conicity lambda.
inline ProfilePtr arcWheel(double r0, double rw, double lambda, double sc = 0.0, double half = 0.04,
                           double ds = 1e-4) {
  return sampled("arc wheel", ProfileKind::Wheel, -half, half, ds, [=](double s) {
    const double u = s - sc;
    const double R = std::abs(rw);
    const double bump = std::sqrt(R * R - u * u) - R;  // <= 0
    return r0 - lambda * s + (rw > 0 ? bump : -bump);
  });
}
// Rail head circle of radius R (crown at s = 0, h(0) = 0).
inline ProfilePtr arcRail(double R, double half = 0.03, double ds = 1e-4) {
  return sampled("arc rail", ProfileKind::Rail, -half, half, ds,
                 [=](double s) { return std::sqrt(R * R - s * s) - R; });
}

inline ProfilePtr mirror(const ProfilePtr& p) {
  return std::make_shared<const Profile>(p->mirrored());
}

inline rb::contact::ContactGeometryConfig symmetricConfig(const ProfilePtr& wheel,
                                                          const ProfilePtr& rail, double lw,
                                                          double lr, double beta) {
  rb::contact::ContactGeometryConfig c;
  c.left_wheel = wheel;
  c.right_wheel = mirror(wheel);
  c.left_rail = rail;
  c.right_rail = mirror(rail);
  c.wheel_lw = lw;
  c.rail_lr = lr;
  c.beta = beta;
  c.r0 = wheel->at(0.0).h;
  return c;
}

// S1002 (r0 = 0.46 m) on 60E1 at 1:40, B = 1360 mm, G = 1435 mm (positioning of
// workbench/profiles).
inline rb::contact::ContactGeometryConfig s1002On60E1(double r0 = 0.46, double beta = 1.0 / 40.0) {
  using rb::profiles::Side;
  const auto pos = rb::profiles::positionS1002On60E1(1.360, 1.435, r0, beta);
  rb::contact::ContactGeometryConfig c;
  c.left_wheel = std::make_shared<const Profile>(rb::profiles::s1002Wheel(r0, Side::Left));
  c.right_wheel = std::make_shared<const Profile>(rb::profiles::s1002Wheel(r0, Side::Right));
  c.left_rail = std::make_shared<const Profile>(rb::profiles::rail60E1(Side::Left));
  c.right_rail = std::make_shared<const Profile>(rb::profiles::rail60E1(Side::Right));
  c.wheel_lw = pos.Lw;
  c.rail_lr = pos.Lr;
  c.beta = pos.beta;
  c.r0 = r0;
  return c;
}

}  // namespace rbtest
