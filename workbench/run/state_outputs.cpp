#include "workbench/run/state_outputs.hpp"

#include <algorithm>

#include "workbench/core/bits.hpp"
#include "workbench/core/error.hpp"

namespace rb::run {

StateOutputs::StateOutputs(vehicle::VehicleOde& ode, dynamics::ContactVehicleOde* contact)
    : ode_(ode),
      contact_(contact),
      y_(static_cast<std::size_t>(ode.size())),
      qdd_(ode.model().bodies.size(), vehicle::Vector6d::Zero()),
      wheels_(contact ? 2 * contact->contact().wheelsets.size() : 0) {}

void StateOutputs::at(double t, const double* y) {
  if (valid_ && sameState(t, y, t_, y_)) return;
  t_ = t;
  std::copy(y, y + y_.size(), y_.begin());
  valid_ = true;
  acc_ = wheels_done_ = Done::No;
}

// On wheel/rail contact one Output evaluation gives the wheel outputs and the accelerations
// together (ContactVehicleOde::outputs): both are taken from it.
void StateOutputs::contactOutputs() {
  ++evaluations_;
  const Done d = contact_->outputs(t_, y_.data(), wheels_, qdd_) == 0 ? Done::Ok : Done::Failed;
  acc_ = wheels_done_ = d;
}

bool StateOutputs::accelerations() {
  RB_CHECK(valid_, "StateOutputs: no state");
  if (acc_ == Done::No && contact_ != nullptr) contactOutputs();
  if (acc_ == Done::No) {
    ++evaluations_;
    acc_ = ode_.bodyAccelerations(t_, y_.data(), qdd_) == 0 ? Done::Ok : Done::Failed;
  }
  return acc_ == Done::Ok;
}

bool StateOutputs::wheels() {
  RB_CHECK(valid_, "StateOutputs: no state");
  if (contact_ == nullptr) return false;
  if (wheels_done_ == Done::No) contactOutputs();
  return wheels_done_ == Done::Ok;
}

void StateOutputs::elements(std::span<const vehicle::ElementId> ids,
                            std::span<vehicle::ElementValue> out) {
  RB_CHECK(valid_, "StateOutputs: no state");
  if (ids.empty()) return;
  // A successful evaluation of this state left its element values in the workspace (evaluating
  // the same state again gives the same values). Without one, the model's own call decides,
  // including what a failed evaluation gives.
  if (acc_ == Done::Ok || wheels_done_ == Done::Ok) {
    const vehicle::Workspace& ws = ode_.workspace();
    for (std::size_t i = 0; i < ids.size() && i < out.size(); ++i) out[i] = ws.value(ids[i]);
    return;
  }
  ++evaluations_;
  ode_.elementOutputs(t_, y_.data(), ids, out);
}

}  // namespace rb::run
