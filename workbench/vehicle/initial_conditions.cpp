#include "workbench/vehicle/initial_conditions.hpp"

#include <array>
#include <cmath>

#include "workbench/core/error.hpp"

namespace rb::vehicle {

namespace {
constexpr std::array<const char*, 6> kCoordKeys = {"s", "y", "z", "roll", "pitch", "yaw"};
}  // namespace

std::string initialConditionKey(int coord, bool rate) {
  if (coord < kY || coord > kYaw) return "?";
  return std::string(kCoordKeys[static_cast<std::size_t>(coord)]) + (rate ? "_dot" : "");
}

void applyInitialConditions(const VehicleOde& ode, std::span<const InitialCondition> conditions,
                            Eigen::VectorXd& y0) {
  const VehicleModel& m = ode.model();
  for (const InitialCondition& c : conditions) {
    const std::string key =
        "vehicle.initial." + c.body + "." + initialConditionKey(c.coord, c.rate);
    if (!std::isfinite(c.value)) throw InputError(c.loc, key + " must be finite");
    int body = -1;
    for (std::size_t b = 0; b < m.bodies.size(); ++b)
      if (m.bodies[b].name == c.body) body = static_cast<int>(b);
    if (body < 0) throw InputError(c.loc, key + ": no body named '" + c.body + "'");
    const int i = ode.index(body, static_cast<Coord>(c.coord), c.rate);
    if (i < 0)
      throw InputError(c.loc, key +
                                  ": not a state of this model (given by the contact "
                                  "constraints or prescribed)");
    y0[i] += c.value;
  }
}

}  // namespace rb::vehicle
