#include "workbench/profiles/dimensions.hpp"

#include <cmath>
#include <functional>
#include <vector>

#include "workbench/core/error.hpp"

namespace rb::profiles {
namespace {

// Highest knot, refined to h'(s) = 0 by bisection.
double maxPoint(const Profile& p) {
  const std::vector<double> k = p.knots();
  const std::vector<double> v = p.values();
  std::size_t best = 0;
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (v[i] > v[best]) best = i;
  }
  if (best == 0 || best + 1 == k.size()) return k[best];
  double a = k[best - 1], b = k[best + 1];
  for (int it = 0; it < 100 && b - a > 1e-15; ++it) {
    const double m = 0.5 * (a + b);
    (p.at(m).dh > 0.0 ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// First s from `from` toward `to` (stepping by the grid step) where f changes sign, bisected.
double firstCrossing(const Profile& p, double from, double to,
                     const std::function<double(double)>& f) {
  const double dir = to > from ? 1.0 : -1.0;
  const double step = p.step();
  double a = from, b = from;
  const double fa0 = f(from);
  bool found = false;
  while (dir * (to - b) > 0.0) {
    a = b;
    b = dir > 0 ? std::min(b + step, to) : std::max(b - step, to);
    if ((f(b) > 0.0) != (fa0 > 0.0)) {
      found = true;
      break;
    }
  }
  RB_CHECK(found, "profile dimension: no crossing found between the given points");
  const bool posA = f(a) > 0.0;
  for (int it = 0; it < 100 && std::abs(b - a) > 1e-15; ++it) {
    const double m = 0.5 * (a + b);
    ((f(m) > 0.0) == posA ? a : b) = m;
  }
  return 0.5 * (a + b);
}

}  // namespace

WheelDimensions wheelDimensions(const Profile& wheel, double flangeBackDistance,
                                double tapeCircleS) {
  RB_CHECK(wheel.inside(tapeCircleS), "tape circle outside the wheel profile");
  WheelDimensions d;
  const double h0 = wheel.at(tapeCircleS).h;
  d.flangeTipS = maxPoint(wheel);
  const double hTip = wheel.at(d.flangeTipS).h;
  d.flangeHeight = hTip - h0;
  RB_CHECK(d.flangeHeight > kSdHeight + kQrBelowTip, "the wheel profile has no flange");
  // Face points: first crossings of the given heights from the tape circle toward the tip.
  d.sdPointS = firstCrossing(wheel, tapeCircleS, d.flangeTipS,
                             [&](double s) { return wheel.at(s).h - (h0 + kSdHeight); });
  d.qrPointS = firstCrossing(wheel, tapeCircleS, d.flangeTipS,
                             [&](double s) { return wheel.at(s).h - (hTip - kQrBelowTip); });
  const double toFlange = d.flangeTipS > tapeCircleS ? 1.0 : -1.0;
  const double flangeBackS = tapeCircleS + toFlange * flangeBackDistance;
  d.flangeThickness = std::abs(d.sdPointS - flangeBackS);
  d.qR = std::abs(d.qrPointS - d.sdPointS);
  return d;
}

std::optional<WheelDimensions> measureWheel(const Profile& wheel, double flangeBackDistance,
                                            double tapeCircleS) {
  // The preconditions of wheelDimensions; with them the face crossings exist (h is continuous
  // from the tape circle, below both heights, to the tip, above both).
  if (!wheel.inside(tapeCircleS)) return std::nullopt;
  const double tip = wheel.at(maxPoint(wheel)).h - wheel.at(tapeCircleS).h;
  if (!(tip > kSdHeight + kQrBelowTip)) return std::nullopt;
  return wheelDimensions(wheel, flangeBackDistance, tapeCircleS);
}

double flangeHeight(const Profile& wheel, double tapeCircleS) {
  return wheelDimensions(wheel, 0.070, tapeCircleS).flangeHeight;
}
double flangeThickness(const Profile& wheel, double flangeBackDistance, double tapeCircleS) {
  return wheelDimensions(wheel, flangeBackDistance, tapeCircleS).flangeThickness;
}
double flangeQR(const Profile& wheel, double tapeCircleS) {
  return wheelDimensions(wheel, 0.070, tapeCircleS).qR;
}

double railHeadWidth(const Profile& rail, double sideSlope) {
  const double top = maxPoint(rail);
  auto f = [&](double s) { return std::abs(rail.at(s).dh) - sideSlope * (1.0 - 1e-6); };
  const double left = firstCrossing(rail, top, rail.sMin(), f);
  const double right = firstCrossing(rail, top, rail.sMax(), f);
  return right - left;
}

}  // namespace rb::profiles
