// The contact of a check rail with the back of a wheel's flange (check_rail.hpp) against a
// brute-force search written independently here: the wheel's back as the flat face at the
// flange-back distance up to the profile's first point and the profile's own flange-back branch
// (inverted by bisection) beyond, every check-rail point on a line along the track sampled every
// 0.05 mm across and 0.2 mm along, turned into the wheelset frame by Rz(psi) Rx(phi) written out.
// docs/sliced_rails.md, "Check rails".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "workbench/contact/check_rail.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/rail60e1.hpp"
#include "workbench/profiles/s1002.hpp"

namespace {

using namespace rb::contact;
using rb::profiles::Profile;

constexpr double kFace = -rb::profiles::kS1002FlangeBackDistance;

// The wheel (S1002, r0 = 460 mm) and a 60E1 head as a check rail whose profile origin lies
// `inside` metres toward the track centre from the running rail's (beta = 0).
WheelRailPair pair(Side side, double inside) {
  using namespace rb::profiles;
  const WheelSide ws = side == Side::Left ? WheelSide::Left : WheelSide::Right;
  const RailSide rs = side == Side::Left ? RailSide::Left : RailSide::Right;
  WheelRailPair p;
  p.side = side;
  p.wheel = std::make_shared<const Profile>(s1002Wheel(0.46, ws));
  p.rail = std::make_shared<const Profile>(rail60E1(rs));
  p.wheel_lw = 0.75;
  p.rail_lr = 0.7535 - inside;
  p.beta = 0.0;
  return p;
}

// The left profile's back as (radius, s) pairs every micrometre of s from its first point to the
// flange tip; s_back(rho) by bisection in them, flat below the first.
struct Back {
  std::vector<double> rho, s;
  explicit Back(const Profile& left) {
    for (double x = left.sMin(); x < 0.0; x += 1e-6) {
      const double h = left.at(x).h;
      if (!rho.empty() && h <= rho.back()) break;
      rho.push_back(h);
      s.push_back(x);
    }
  }
  double at(double r) const {
    if (r <= rho.front()) return kFace;
    if (r > rho.back()) return std::numeric_limits<double>::quiet_NaN();  // beyond the tip
    const auto k =
        static_cast<std::size_t>(std::lower_bound(rho.begin(), rho.end(), r) - rho.begin());
    return s[k];
  }
};

struct Deepest {
  double d = -1.0, x = 0.0, s_r = 0.0;
  double centroid = 0.0;  // x of the centroid of the penetration on the flat face, line s_r
  bool flat = false;      // the deepest point is on the flat face
};

// The deepest lateral penetration of the rail points in [s0, s1] (step ds) at x in [x0, x1]
// (step dx).
Deepest scan(const WheelRailPair& p, const ElasticPose& pose, const Back& back, double s0,
             double s1, double ds, double x0, double x1, double dx) {
  const double sigma = p.side == Side::Left ? 1.0 : -1.0;
  const double cp = std::cos(pose.phi), sp = std::sin(pose.phi);
  const double cy = std::cos(pose.psi), sy = std::sin(pose.psi);
  // R = Rz(psi) Rx(phi): wheelset -> track; R^T turns track vectors into the wheelset frame.
  const double R[3][3] = {{cy, -sy * cp, sy * sp}, {sy, cy * cp, -cy * sp}, {0.0, sp, cp}};
  Deepest best;
  const int ns = static_cast<int>(std::floor((s1 - s0) / ds + 1e-9));
  const int nx = static_cast<int>(std::lround((x1 - x0) / dx));
  for (int i = 0; i <= ns; ++i) {
    const double s = s0 + i * ds;
    const double Y = sigma * p.rail_lr + s - pose.y, Z = p.rail->at(s).h - pose.z;
    for (int j = 0; j <= nx; ++j) {
      const double x = x0 + j * dx;
      const double X[3] = {R[0][0] * x + R[1][0] * Y + R[2][0] * Z,
                           R[0][1] * x + R[1][1] * Y + R[2][1] * Z,
                           R[0][2] * x + R[1][2] * Y + R[2][2] * Z};
      const double rho = std::hypot(X[0], X[2]);
      const double b = back.at(rho);
      if (!std::isfinite(b)) continue;
      const double d = sigma * X[1] - p.wheel_lw - b;
      if (d > best.d) best = {d, x, s, 0.0, rho <= back.rho.front()};
    }
  }
  return best;
}

// Every 0.05 mm across and 0.2 mm along the rail, then every 0.2 um across and 20 um along (over
// 50 mm) around the deepest sample.
Deepest bruteForce(const WheelRailPair& p, const ElasticPose& pose) {
  const Back back(p.side == Side::Left ? *p.wheel : p.wheel->mirrored());
  const Deepest c = scan(p, pose, back, p.rail->sMin(), p.rail->sMax(), 0.05e-3, -0.2, 0.2, 0.2e-3);
  Deepest f =
      scan(p, pose, back, std::max(p.rail->sMin(), c.s_r - 0.1e-3),
           std::min(p.rail->sMax(), c.s_r + 0.1e-3), 0.2e-6, c.x - 25e-3, c.x + 25e-3, 20e-6);
  // The penetration along the deepest line over the flat face, every 10 um: its centroid.
  double w = 0.0, wx = 0.0;
  for (int j = -20000; j <= 20000; ++j) {
    const double x = j * 10e-6;
    const Deepest one = scan(p, pose, back, f.s_r, f.s_r, 1.0, x, x, 1.0);
    if (one.d <= 0.0 || !(one.flat)) continue;
    w += one.d;
    wx += one.d * x;
  }
  f.centroid = wx / w;
  return f;
}

TEST(CheckRail, FlangeBackContactAgainstBruteForce) {
  ElasticSearchSpec spec;
  spec.angles = EulerOrder::YawRoll;
  for (Side side : {Side::Left, Side::Right}) {
    const double sigma = side == Side::Left ? 1.0 : -1.0;
    // The check rail's profile origin 115 mm inside the running rail's: its face about 7 mm from
    // the flange back of the centred wheelset.
    const ElasticContactSearch rail(pair(side, 0.115), spec);
    const Profile& wheel = *rail.pair().wheel;
    const FlangeBack back(side == Side::Left ? wheel : wheel.mirrored(), kFace);
    for (double psi : {0.0, 0.005, -0.005, 0.02, -0.03}) {
      for (double phi : {0.0, 0.003}) {
        // The clearance of the centred wheelset, then the wheelset moved toward the check rail
        // by it and 0.5 mm more.
        ElasticWheelGeometry g;
        ElasticPose pose{0.0, 0.46, phi, psi};
        searchCheckRail(rail, back, pose, g);
        ASSERT_EQ(g.count, 0);
        const double clearance = g.min_gap;
        ASSERT_GT(clearance, 1e-3);
        ASSERT_LT(clearance, 15e-3);
        pose.y = -sigma * (clearance + 0.5e-3);
        searchCheckRail(rail, back, pose, g);
        const Deepest ref = bruteForce(rail.pair(), pose);
        ASSERT_EQ(g.count, 1);
        const ElasticPatchGeometry& p = g.patch[0];
        SCOPED_TRACE(testing::Message() << "side " << sigma << " psi " << psi << " phi " << phi);
        EXPECT_NEAR(-g.min_gap, ref.d, 5e-6);  // the deepest lateral penetration
        EXPECT_NEAR(-g.min_gap, 0.5e-3, 0.2e-3);
        EXPECT_NEAR(p.s_r, ref.s_r, 0.3e-3);
        // Along the track: at the centroid of the penetration on the flat face (the face lies
        // along the rail without yaw, and the deepest point is its edge with it).
        EXPECT_NEAR(p.x, ref.centroid, 1e-3);
        // The normal: the axle direction (flat face), pushing the wheel toward its field side.
        EXPECT_GT(sigma * p.n_y, 0.99);
        EXPECT_NEAR(std::hypot(p.n_x, std::hypot(p.n_y, p.n_z)), 1.0, 1e-12);
        EXPECT_NEAR(p.gamma, -M_PI / 2, 0.05);
        EXPECT_NEAR(p.s_w, sigma * kFace, 1e-12);
        EXPECT_GT(p.approach, 0.0);
        EXPECT_GT(p.B, 0.0);
      }
    }
  }
}

}  // namespace
