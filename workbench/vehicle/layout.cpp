#include "workbench/vehicle/layout.hpp"

namespace rb::vehicle {

namespace {
constexpr const char* kCoordName[5] = {"y", "z", "phi", "theta", "psi"};
constexpr const char* kWsCoordName[5] = {"y", "theta", "psi", "z", "phi"};
}  // namespace

VehicleLayout vehicleLayout(const VehicleModel& m, int ws_dof) {
  VehicleLayout l;
  l.ws_dof = ws_dof;
  l.slot.assign(m.bodies.size(), -1);
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const BodyKind k = m.bodies[b].kind;
    if (k == BodyKind::CarBody || k == BodyKind::Bogie) {
      l.slot[b] = static_cast<int>(l.free_bodies.size());
      l.free_bodies.push_back(static_cast<int>(b));
    } else if (k == BodyKind::Wheelset) {
      l.slot[b] = static_cast<int>(l.wheelsets.size());
      l.wheelsets.push_back(static_cast<int>(b));
    }
  }
  l.n_free = static_cast<int>(l.free_bodies.size());
  l.n_ws = static_cast<int>(l.wheelsets.size());
  l.n_series = static_cast<int>(m.series_dampers.size());
  l.size = 10 * l.n_free + 2 * l.ws_dof * l.n_ws + l.n_series;
  return l;
}

int VehicleLayout::index(int body, Coord c, bool is_rate) const {
  if (body < 0 || body >= static_cast<int>(slot.size()) || c == kS) return -1;
  const auto b = static_cast<std::size_t>(body);
  if (const int k = freeSlot(b); k >= 0) return is_rate ? rate(k, c - 1) : position(k, c - 1);
  const int w = wheelsetSlot(b);
  if (w < 0) return -1;
  for (int cc = 0; cc < kWheelsetCoordinates; ++cc)
    if (kWheelsetCoord[cc] == c) return is_rate ? wsRate(w, cc) : wsPosition(w, cc);
  return -1;  // z, phi on constraint contact: dependent
}

std::string VehicleLayout::componentName(int i, const VehicleModel& m) const {
  if (i < 0 || i >= size) return "y[" + std::to_string(i) + "]";
  if (rail_masses > 0 && i >= railPosition(0, 0, 0)) {
    const int j = i - railPosition(0, 0, 0);
    const int k = j % (4 * rail_masses);
    return m.bodies[wheelset(k / 4)].name + ((k / 2) % 2 == 0 ? ".rail_left." : ".rail_right.") +
           (k % 2 == 0 ? "y" : "z") + (j >= 4 * rail_masses ? "_dot" : "");
  }
  if (n_series > 0 && i >= series(0)) return "series[" + std::to_string(i - series(0)) + "].f";
  const int half = positions();
  const bool is_rate = i >= half;
  const int j = is_rate ? i - half : i;
  const char* suffix = is_rate ? "_dot" : "";
  if (j < 5 * n_free) return m.bodies[freeBody(j / 5)].name + "." + kCoordName[j % 5] + suffix;
  const int jw = j - 5 * n_free;
  int c = 0;
  while (c + 1 < kWheelsetCoordinates && wsSlot(c) != jw % ws_dof) ++c;
  return m.bodies[wheelset(jw / ws_dof)].name + "." + kWsCoordName[c] + suffix;
}

int VehicleLayout::indexOf(const std::string& component, const VehicleModel& m) const {
  for (int i = 0; i < size; ++i)
    if (componentName(i, m) == component) return i;
  return -1;
}

}  // namespace rb::vehicle
