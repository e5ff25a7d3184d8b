// Mode labels from the kinetic-energy shares of the body coordinates (stability.hpp, labelMode).
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "workbench/stability/stability.hpp"
#include "workbench/vehicle/kinematics.hpp"
#include "workbench/vehicle/spec.hpp"

namespace rb::stability {

namespace {

using vehicle::BodyKind;

// Groups of coordinates an engineer names a mode by.
enum Group : int {
  kWsLateral,  // wheelset y + yaw
  kWsSpin,     // wheelset spin
  kBogieLateral,
  kBogieBounce,
  kBogiePitch,
  kBogieRoll,
  kCarSway,  // car y + roll
  kCarYaw,
  kCarBounce,
  kCarPitch,
  kGroups
};

int wheelsetGroup(int coord) {
  if (coord == vehicle::kPitch) return kWsSpin;
  return kWsLateral;
}

int bogieGroup(int coord) {
  switch (coord) {
    case vehicle::kZ:
      return kBogieBounce;
    case vehicle::kPitch:
      return kBogiePitch;
    case vehicle::kRoll:
      return kBogieRoll;
    default:
      return kBogieLateral;  // y, yaw
  }
}

int carGroup(int coord) {
  switch (coord) {
    case vehicle::kZ:
      return kCarBounce;
    case vehicle::kPitch:
      return kCarPitch;
    case vehicle::kYaw:
      return kCarYaw;
    default:
      return kCarSway;  // y, roll
  }
}

int groupOf(const Coordinate& c) {
  switch (static_cast<BodyKind>(c.kind)) {
    case BodyKind::Wheelset:
      return wheelsetGroup(c.coord);
    case BodyKind::Bogie:
      return bogieGroup(c.coord);
    default:
      return carGroup(c.coord);
  }
}

// Wheelset and bogie lateral/yaw modes by the shares W (wheelsets) and B (bogie frames).
std::string lateralLabel(double w, double b, bool oscillatory) {
  if (!oscillatory) return w >= b ? "wheelset lateral/yaw (creep)" : "bogie yaw (creep)";
  if (b < 0.25 * (w + b)) return "wheelset hunting";
  if (w < 0.2 * (w + b)) return "bogie yaw/lateral";
  return "bogie hunting";
}

}  // namespace

void labelMode(Mode& m, const std::vector<Coordinate>& coords, std::complex<double> car_y,
               std::complex<double> car_roll) {
  std::array<double, kGroups> share{};
  double best = -1.0;
  for (std::size_t i = 0; i < coords.size(); ++i) {
    share[static_cast<std::size_t>(groupOf(coords[i]))] += m.participation[i];
    if (m.participation[i] > best) {
      best = m.participation[i];
      m.dominant = coords[i].name;
    }
  }
  m.hunting = false;
  if (m.series_share > 0.5) {
    m.label = "series-damper relaxation";
    return;
  }
  const auto g = static_cast<int>(std::max_element(share.begin(), share.end()) - share.begin());
  const bool osc = m.oscillatory;
  switch (g) {
    case kWsLateral:
    case kBogieLateral:
      m.label = lateralLabel(share[kWsLateral], share[kBogieLateral], osc);
      m.hunting = osc;
      return;
    case kWsSpin:
      m.label = "wheelset spin (creep)";
      return;
    case kCarSway: {
      // A point at height h above the CoM moves laterally by y - h phi (roll positive about the
      // forward x axis, y to the left, z up): it stands still at h = y / phi, the roll centre.
      // Below the CoM: lower sway (mostly lateral); above: upper sway (mostly roll).
      m.roll_centre = std::abs(car_roll) > 0.0 ? (car_y / car_roll).real() : 0.0;
      m.label = m.roll_centre < 0.0 ? "car body lower sway" : "car body upper sway";
      break;
    }
    case kBogieBounce:
      m.label = "bogie bounce";
      break;
    case kBogiePitch:
      m.label = "bogie pitch";
      break;
    case kBogieRoll:
      m.label = "bogie roll";
      break;
    case kCarYaw:
      m.label = "car body yaw";
      break;
    case kCarBounce:
      m.label = "car body bounce";
      break;
    default:
      m.label = "car body pitch";
      break;
  }
  if (!osc) m.label += " (aperiodic)";
}

}  // namespace rb::stability
