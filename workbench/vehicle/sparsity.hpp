#pragma once
// The structural sparsity of the vehicle ODE's Jacobian df/dy (integ::JacobianPattern), from the
// bodies, the suspension elements and the state layout, never from numerical values:
// - a position's derivative is its rate state (f_p = y_k: a copy row, VehicleLayout);
// - a body's accelerations depend on its own coordinates and rates (mass matrix, inertia and
//   gravity forces; for a wheelset its contact: constraints, normal and creep forces), on those
//   of every body an element joins it to (the element's deformation and its rate, Eq. 28-29),
//   and on the Maxwell force of every series damper attached to it;
// - a series damper's force rate depends on its force and on the coordinates and rates of its
//   two bodies (Appendix A).
// Frames (track-fixed bodies) and guided wheelsets have no states. Bodies are not coupled
// otherwise: the car body does not see the wheelsets but through the bogies' elements.
#include "workbench/integrators/ode.hpp"
#include "workbench/vehicle/layout.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::vehicle {

integ::JacobianPattern jacobianPattern(const VehicleModel& model, const VehicleLayout& layout);

}  // namespace rb::vehicle
