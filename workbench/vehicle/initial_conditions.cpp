#include "workbench/vehicle/initial_conditions.hpp"

#include <cmath>

namespace rb::vehicle {

namespace {
int bodyIndex(const VehicleModel& m, const std::string& name) {
  for (std::size_t b = 0; b < m.bodies.size(); ++b)
    if (m.bodies[b].name == name) return static_cast<int>(b);
  return -1;
}

std::string conditionKey(const InitialCondition& c) {
  return "vehicle.initial." + c.body + "." + initialConditionKey(c.coord, c.rate);
}

// Why the coordinate of condition c of body `body` is not a state of `ode` (a frame; a guided
// wheelset; a wheelset's z or roll on contact; the prescribed spin); empty when it is one.
std::string notAStateReason(const VehicleOde& ode, std::size_t body, const InitialCondition& c) {
  const VehicleLayout& layout = ode.layout();
  const int coord = c.coord;
  const std::string& name = c.body;
  if (layout.freeSlot(body) >= 0) return {};
  if (layout.wheelsetSlot(body) < 0)
    return "'" + name + "' is a frame, fixed in its track frame (it has no state)";
  if (layout.ws_dof == kGuidedWheelsetDof)
    return "the wheelsets are guided: they follow the track kinematically (contact.method = "
           "guided), "
           "so '" +
           name + "' has no state";
  if ((coord == kZ || coord == kRoll) && !layout.wheelsetVertical())
    return "the height z and roll of wheelset '" + name +
           "' on wheel/rail contact are given by the contact constraints (KEC Eq. 22, LUT Eq. "
           "17-18); its states are y, yaw and, with a free spin, pitch";
  if (coord == kPitch && !layout.spinFree())
    return "the spin of wheelset '" + name +
           "' is prescribed (contact.wheelset_spin = prescribed: pitch_dot = V / r0)";
  return {};
}

// The problem of one condition on `ode`, empty if none; its state index in `index` otherwise.
std::string conditionProblem(const VehicleOde& ode, const InitialCondition& c, int& index) {
  index = -1;
  if (!std::isfinite(c.value)) return "must be finite";
  if (c.coord < kY || c.coord > kYaw) return "is not a coordinate (y, z, roll, pitch, yaw)";
  const int body = bodyIndex(ode.model(), c.body);
  if (body < 0) return "no body named '" + c.body + "'";
  const std::string why = notAStateReason(ode, static_cast<std::size_t>(body), c);
  if (!why.empty()) return "not a state of this model: " + why;
  index = ode.index(body, static_cast<Coord>(c.coord), c.rate);
  if (index < 0) return "not a state of this model";
  return {};
}

}  // namespace

std::string initialConditionKey(int coord, bool rate) {
  if (coord < kY || coord > kYaw) return "?";
  return std::string(kCoordNames[static_cast<std::size_t>(coord)]) + (rate ? "_dot" : "");
}

void checkInitialConditions(const VehicleOde& ode, std::span<const InitialCondition> conditions,
                            Diagnostics& d) {
  for (const InitialCondition& c : conditions) {
    int index = -1;
    const std::string problem = conditionProblem(ode, c, index);
    if (!problem.empty()) d.add(c.loc, conditionKey(c) + ": " + problem);
  }
}

void applyInitialConditions(const VehicleOde& ode, std::span<const InitialCondition> conditions,
                            Eigen::VectorXd& y0) {
  Diagnostics d;
  checkInitialConditions(ode, conditions, d);
  d.throwIfAny();
  for (const InitialCondition& c : conditions) {
    int index = -1;
    conditionProblem(ode, c, index);
    if (c.value != 0.0) y0[index] += c.value;
  }
}

}  // namespace rb::vehicle
