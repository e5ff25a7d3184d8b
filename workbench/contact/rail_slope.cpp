#include "workbench/contact/rail_slope.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace rb::contact {
namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<std::array<double, 3>, 3>;

Vec3 mul(const Mat3& m, const Vec3& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
          m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}
Vec3 mulT(const Mat3& m, const Vec3& v) {
  return {m[0][0] * v[0] + m[1][0] * v[1] + m[2][0] * v[2],
          m[0][1] * v[0] + m[1][1] * v[1] + m[2][1] * v[2],
          m[0][2] * v[0] + m[1][2] * v[1] + m[2][2] * v[2]};
}
Mat3 mulTm(const Mat3& a, const Mat3& b) {  // a^T b
  Mat3 m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) m[i][j] += a[k][i] * b[k][j];
  return m;
}
// The roll and yaw whose wheelset rotation has axle a (unit): the pose of a body of revolution.
void anglesOfAxle(const Vec3& a, EulerOrder order, double& phi, double& psi) {
  if (order == EulerOrder::RollYaw) {  // a = (-sin psi, cos psi cos phi, cos psi sin phi)
    psi = -std::asin(std::clamp(a[0], -1.0, 1.0));
    phi = std::atan2(a[2], a[1]);
  } else {  // a = (-sin psi cos phi, cos psi cos phi, sin phi)
    phi = std::asin(std::clamp(a[2], -1.0, 1.0));
    psi = std::atan2(-a[0], a[1]);
  }
}

// The rail's frame: R = Rz(psi) Ry(-alpha) Rx(kappa), psi = atan t_y, alpha = atan2(t_z,
// sqrt(1 + t_y^2)), takes e_X to t / |t|. A slice point Q = (0, Y, Z) (relative to the pivot) has
// the coordinates R^T Q across the rail (its projection along t): with kappa = 0 they are
// (cos psi Y, cos alpha Z - sin psi sin alpha Y), a slice sheared by the product of the yaw and the
// pitch; kappa = -atan(tan psi sin alpha) removes that shear from the heights, leaving
// (Y - psi alpha Z, Z) to first order: the heights across the rail are the slice's.
Mat3 railRotation(double t_y, double t_z) {
  const double h = std::sqrt(1.0 + t_y * t_y);
  const double cpsi = 1.0 / h, spsi = t_y / h;
  const double len = std::sqrt(h * h + t_z * t_z);
  const double ca = h / len, sa = t_z / len;
  const double kappa = -std::atan(t_y * sa);
  const double ck = std::cos(kappa), sk = std::sin(kappa);
  // Rz(psi) Ry(-alpha) = [[cpsi ca, -spsi, -cpsi sa], [spsi ca, cpsi, -spsi sa], [sa, 0, ca]],
  // times Rx(kappa) = [[1, 0, 0], [0, ck, -sk], [0, sk, ck]].
  return Mat3{{{cpsi * ca, -spsi * ck - cpsi * sa * sk, spsi * sk - cpsi * sa * ck},
               {spsi * ca, cpsi * ck - spsi * sa * sk, -cpsi * sk - spsi * sa * ck},
               {sa, ca * sk, ca * ck}}};
}

// One search in the frame of a rail along t = (1, t_y, t_z), pivoting at (0, py, pz) (pose
// coordinates); the patches come back to the track frame.
void searchInRailFrame(const ElasticContactSearch& search, const ElasticPose& pose, double t_y,
                       double t_z, double py, double pz, ElasticWheelGeometry& out,
                       ElasticSearchWorkspace& ws) {
  const EulerOrder order = search.spec().angles;
  const Mat3 R = railRotation(t_y, t_z);
  const Vec3 P{0.0, py, pz};
  const Vec3 c = mulT(R, Vec3{0.0, pose.y - py, pose.z - pz});
  const Mat3 Rw = wheelsetRotation(pose.phi, pose.psi, order);
  const Vec3 a = mulT(R, Vec3{Rw[0][1], Rw[1][1], Rw[2][1]});
  ElasticPose q = pose;
  q.y = py + c[1];
  q.z = pz + c[2];
  anglesOfAxle(a, order, q.phi, q.psi);
  search.search(q, out, ws);
  // The searched wheel frame R' and the wheelset's, seen in the rail frame (R^T Rw): they differ by
  // a spin chi about the axle, M = R'^T R^T Rw = Ry(chi), and a wheel point X' of the search is
  // X = M^T X' in the wheelset's frame.
  const Mat3 M = mulTm(wheelsetRotation(q.phi, q.psi, order), mulTm(R, Rw));
  for (int k = 0; k < out.count; ++k) {
    ElasticPatchGeometry& g = out.patch[static_cast<std::size_t>(k)];
    const Vec3 p = mul(R, Vec3{c[0] + g.x, g.y - py, g.z - pz});
    g.x = p[0];
    g.y = P[1] + p[1];
    g.z = P[2] + p[2];
    const Vec3 n = mul(R, Vec3{0.0, g.n_y, g.n_z});
    g.n_x = n[0];
    g.n_y = n[1];
    g.n_z = n[2];
    const double st = std::sin(g.theta), ct = std::cos(g.theta);
    const Vec3 X = mulT(M, Vec3{g.radius * st, 0.0, -g.radius * ct});
    g.x_w = X[0];
    g.theta = std::atan2(X[0], -X[2]);
  }
}

}  // namespace

void searchSlopedRail(const ElasticContactSearch& search, const ElasticPose& pose,
                      const RailSlope& slope, ElasticWheelGeometry& out,
                      ElasticSearchWorkspace& first, SlopedSearchWorkspace& sloped) {
  const WheelRailPair& pair = search.pair();
  const double sigma = search.sigma();
  const double sb = sigma * std::sin(pair.beta), cb = std::cos(pair.beta);
  const double oy = sigma * pair.rail_lr + pair.rail_dy, oz = pair.rail_dz;
  const bool blended = pair.rail_next && slope.blend_s != 0.0;
  // The blended rail's rise per unit s at profile parameter u (0 where the slices agree).
  auto rise = [&](double u) {
    return blended ? slope.blend_s * (pair.rail_next->at(u).h - pair.rail->at(u).h) : 0.0;
  };
  // First search: pivot on the rail below the wheel's tape circle, with the blend's slope there.
  double u0 = 0.0, rise0 = 0.0;
  if (blended) {
    u0 = std::clamp(cb * (pose.y + sigma * pair.wheel_lw - oy), search.railMin(), search.railMax());
    rise0 = rise(u0);
  }
  const bool tilted = slope.y_s != 0.0 || slope.z_s != 0.0 || rise0 != 0.0;
  if (tilted) {
    const double h0 = blended ? search.railAt(u0, pose.blend).h : 0.0;
    searchInRailFrame(search, pose, slope.y_s - sb * rise0, slope.z_s + cb * rise0,
                      oy + cb * u0 - sb * h0, oz + sb * u0 + cb * h0, out, first);
  } else {
    search.search(pose, out, first);
  }
  if (out.count == 0) return;
  // Second search: pivot on the deepest patch's rail point (patches are sorted deepest first),
  // carried back to X = 0 along the rail, with the blend's slope there.
  const int count = out.count;
  std::array<double, kMaxElasticPatches> s_r{}, x{}, y{}, z{};
  for (int k = 0; k < count; ++k) {
    const ElasticPatchGeometry& g = out.patch[static_cast<std::size_t>(k)];
    s_r[static_cast<std::size_t>(k)] = g.s_r;
    x[static_cast<std::size_t>(k)] = g.x;
    y[static_cast<std::size_t>(k)] = g.y;
    z[static_cast<std::size_t>(k)] = g.z;
  }
  const double r = rise(s_r[0]);
  if (!tilted && r == 0.0) return;
  auto pivotSearch = [&](std::size_t k, double rk, ElasticWheelGeometry& into,
                         ElasticSearchWorkspace& ws) {
    const double t_y = slope.y_s - sb * rk, t_z = slope.z_s + cb * rk;
    searchInRailFrame(search, pose, t_y, t_z, y[k] - x[k] * t_y, z[k] - x[k] * t_z, into, ws);
  };
  pivotSearch(0, r, out, sloped.second);
  // A further patch on a part of the rail that rises otherwise (a blended slice with two heads: a
  // wing rail falling away beside a rising crossing nose) is searched about its own rail point with
  // its own slope: with the deepest patch's slope its contact would sit r dp behind or ahead of
  // where it is and its gap be off by about r dp^2 / 2 (dp the difference of the slopes). The
  // patch of that search nearest to its rail point replaces the one of the second search.
  constexpr double kSamePatch = 3.0e-3;  // [m] of rail profile parameter
  auto nearest = [&](const ElasticWheelGeometry& g, double u) {
    int best = -1;
    for (int j = 0; j < g.count; ++j) {
      const double d = std::abs(g.patch[static_cast<std::size_t>(j)].s_r - u);
      if (d < kSamePatch &&
          (best < 0 || d < std::abs(g.patch[static_cast<std::size_t>(best)].s_r - u)))
        best = j;
    }
    return best;
  };
  bool replaced = false;
  for (std::size_t k = 1; k < static_cast<std::size_t>(count); ++k) {
    const double rk = rise(s_r[k]);
    if (rk == r) continue;
    ElasticWheelGeometry own;
    pivotSearch(k, rk, own, sloped.further);
    out.newton_iterations += own.newton_iterations;
    const int from = nearest(own, s_r[k]);
    int to = nearest(out, s_r[k]);
    if (from < 0) {  // no longer in contact about its own point
      if (to >= 0) {
        out.patch[static_cast<std::size_t>(to)] =
            out.patch[static_cast<std::size_t>(out.count - 1)];
        --out.count;
      }
    } else {
      if (to < 0 && out.count < kMaxElasticPatches) to = out.count++;
      if (to >= 0)
        out.patch[static_cast<std::size_t>(to)] = own.patch[static_cast<std::size_t>(from)];
    }
    replaced = true;
  }
  if (replaced)
    std::sort(out.patch.begin(), out.patch.begin() + out.count,
              [](const auto& p, const auto& q) { return p.approach > q.approach; });
}

}  // namespace rb::contact
