#include "workbench/run/start_state.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/vehicle/initial_conditions.hpp"

namespace rb::run {

namespace {
constexpr double kSettleStep = 2.5e-4;  // [m] or [rad]
}  // namespace

void startWithInitialConditions(vehicle::VehicleOde& ode,
                                std::span<const vehicle::InitialCondition> initial,
                                Eigen::VectorXd& y) {
  std::vector<vehicle::InitialCondition> positions, rates;
  for (const vehicle::InitialCondition& c : initial) (c.rate ? rates : positions).push_back(c);
  const Eigen::VectorXd equilibrium = y;
  vehicle::applyInitialConditions(ode, positions, y);
  // The rates enter after the settling: a damper's force from a kick's velocity is part of the
  // kick, not something for the positions to balance at t = 0.
  auto* contact = dynamic_cast<dynamics::ContactVehicleOde*>(&ode);
  if (contact != nullptr && !positions.empty()) {
    std::vector<int> held;
    double largest = 0.0;
    for (int i = 0; i < y.size(); ++i)
      if (y[i] != equilibrium[i]) {
        held.push_back(i);
        largest = std::max(largest, std::abs(y[i] - equilibrium[i]));
      }
    // In steps of at most 0.25 mm (or mrad): a wheelset moved by millimetres at once has one
    // wheel in its rail and the other in the air, where the equilibrium's Newton iteration on the
    // elastic approaches has no stiffness to work with; a small step keeps every tread patch.
    // Offsets of zero hold nothing: the start stays the equilibrium, bit for bit.
    if (!held.empty()) {
      const int steps = std::clamp(static_cast<int>(std::ceil(largest / kSettleStep)), 1, 200);
      const Eigen::VectorXd target = y;
      y = equilibrium;
      for (int k = 1; k <= steps; ++k) {
        const double f = static_cast<double>(k) / steps;
        for (const int i : held) y[i] = equilibrium[i] + f * (target[i] - equilibrium[i]);
        contact->settle(0.0, y, held);
      }
    }
  }
  vehicle::applyInitialConditions(ode, rates, y);
}

}  // namespace rb::run
