#include "workbench/profiles/positioning.hpp"

#include <cmath>

#include "workbench/core/error.hpp"
#include "workbench/profiles/rail60e1.hpp"

namespace rb::profiles {

double railFrameAngle(RailSide side, double beta, double delta) {
  return (side == RailSide::Left ? beta : -beta) + delta;
}

PlanePoint rotatedPoint(const Profile& rail, double s, double angle) {
  const double h = rail.at(s).h;
  const double c = std::cos(angle), sn = std::sin(angle);
  return {s * c - h * sn, s * sn + h * c};
}

std::vector<PlanePoint> rotatedPoints(const Profile& rail, double angle) {
  std::vector<PlanePoint> out;
  for (const double s : rail.knots()) out.push_back(rotatedPoint(rail, s, angle));
  return out;
}

TopPoint highestPoint(const Profile& rail, double angle) {
  // z(s) = s sin a + h(s) cos a; scan the knots for the maximum, then refine z'(s) = 0 by
  // bisection on the bracketing intervals.
  const std::vector<double> k = rail.knots();
  const double c = std::cos(angle), sn = std::sin(angle);
  auto z = [&](double s) { return s * sn + rail.at(s).h * c; };
  auto dz = [&](double s) { return sn + rail.at(s).dh * c; };
  std::size_t best = 0;
  for (std::size_t i = 1; i < k.size(); ++i) {
    if (z(k[i]) > z(k[best])) best = i;
  }
  double a = k[best > 0 ? best - 1 : 0], b = k[best + 1 < k.size() ? best + 1 : best];
  if (dz(a) > 0.0 && dz(b) < 0.0) {
    for (int it = 0; it < 100 && b - a > 1e-15; ++it) {
      const double m = 0.5 * (a + b);
      (dz(m) > 0.0 ? a : b) = m;
    }
  } else {
    a = b = k[best];  // maximum at the domain end
  }
  const double s = 0.5 * (a + b);
  return {s, rotatedPoint(rail, s, angle)};
}

namespace {

// Lateral offset of the midpoint of the head's chord `depth` below the top from the top, in the
// frame rotated by `angle`; nullopt when the profile ends before the chord.
std::optional<double> chordOffset(const Profile& rail, double angle, double depth) {
  const TopPoint top = highestPoint(rail, angle);
  const double target = top.p.z - depth;
  const double c = std::cos(angle), sn = std::sin(angle);
  auto z = [&](double s) { return s * sn + rail.at(s).h * c; };
  auto y = [&](double s) { return s * c - rail.at(s).h * sn; };
  constexpr double kWalk = 1e-4;  // [m] below the knot spacing of any usable rail head
  auto side = [&](double dir) -> std::optional<double> {
    double inside = top.s;
    for (double s = top.s + dir * kWalk; rail.inside(s); s += dir * kWalk) {
      if (z(s) < target) {
        double a = inside, b = s;  // z(a) >= target > z(b)
        for (int it = 0; it < 60; ++it) {
          const double m = 0.5 * (a + b);
          (z(m) >= target ? a : b) = m;
        }
        return y(0.5 * (a + b));
      }
      inside = s;
    }
    return std::nullopt;
  };
  const auto lo = side(-1.0), hi = side(1.0);
  if (!lo || !hi) return std::nullopt;
  return 0.5 * (*lo + *hi) - top.p.y;
}

}  // namespace

std::optional<double> drawnInclination(const Profile& rail, double depth) {
  constexpr double kRange = 0.06;  // [rad] well beyond any rail inclination in use (1:20 = 0.05)
  double a = -kRange, b = kRange;
  auto fa = chordOffset(rail, a, depth), fb = chordOffset(rail, b, depth);
  if (!fa || !fb || (*fa > 0.0) == (*fb > 0.0)) return std::nullopt;
  for (int it = 0; it < 50; ++it) {
    const double m = 0.5 * (a + b);
    const auto fm = chordOffset(rail, m, depth);
    if (!fm) return std::nullopt;
    if ((*fm > 0.0) == (*fa > 0.0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  // The angle that makes the head symmetric undoes the inclination it is drawn with.
  return -0.5 * (a + b);
}

PlanePoint gaugePoint(const Profile& rail, RailSide side, double angle, double depth,
                      double* s_out) {
  const TopPoint top = highestPoint(rail, angle);
  const double target = top.p.z - depth;
  const double c = std::cos(angle), sn = std::sin(angle);
  auto z = [&](double s) { return s * sn + rail.at(s).h * c; };
  // Walk from the top toward the gauge side until z drops below the target, then bisect.
  const double dir = side == RailSide::Left ? -1.0 : 1.0;
  const double end = side == RailSide::Left ? rail.sMin() : rail.sMax();
  const double step = rail.step();
  double a = top.s, b = top.s;
  bool found = false;
  while (dir * (end - b) > 0.0) {
    a = b;
    b = dir > 0 ? std::min(b + step, end) : std::max(b - step, end);
    if (z(b) <= target) {
      found = true;
      break;
    }
  }
  RB_CHECK(found, "gauge point: the rail profile does not reach " + std::to_string(depth) +
                      " m below its highest point on the gauge side");
  for (int it = 0; it < 100 && std::abs(b - a) > 1e-15; ++it) {
    const double m = 0.5 * (a + b);
    (z(m) > target ? a : b) = m;
  }
  const double s = 0.5 * (a + b);
  if (s_out) *s_out = s;
  return rotatedPoint(rail, s, angle);
}

ProfilePositioning positionProfiles(double backToBack, double gauge, double r0, double beta,
                                    double flangeBackDistance, double gaugePointOffset) {
  return {0.5 * backToBack + flangeBackDistance, 0.5 * gauge + gaugePointOffset, r0, beta};
}

double rail60E1GaugePointOffset(double beta, double depth) {
  const Profile rail = rail60E1(RailSide::Left);
  return std::abs(gaugePoint(rail, RailSide::Left, beta, depth).y);
}

ProfilePositioning positionS1002On60E1(double backToBack, double gauge, double r0, double beta) {
  return positionProfiles(backToBack, gauge, r0, beta, kS1002FlangeBackDistance,
                          rail60E1GaugePointOffset(beta));
}

WheelLandmarks wheelLandmarks(const ProfilePositioning& pos, WheelSide side,
                              double flangeBackDistance) {
  const double sign = side == WheelSide::Left ? 1.0 : -1.0;
  return {sign * pos.Lw, sign * (pos.Lw - flangeBackDistance)};
}

}  // namespace rb::profiles
