#pragma once
// The model's outputs at one observed state (t, y), shared by everything that samples it: the
// output series and the assessment's signals observe the same step ends, and each would otherwise
// ask the model for its own evaluation of the same state. Here each state costs at most one model
// evaluation on wheel/rail contact (wheel and patch outputs and body accelerations come from the
// same one, ContactVehicleOde::outputs) and one per kind for a guided vehicle; the element values
// come with either (or cost one of their own when neither was asked).
//
// Why sharing changes no result: an output evaluation leaves what the integration depends on
// unchanged (the normal-force memory is kept), and evaluating the same state again gives the same
// bits (the KEC solve warm-started at its own solution takes no Newton step). So only the count
// of model evaluations (/stats/model_evaluations) and of coupling iterations changes.
#include <Eigen/Dense>
#include <span>
#include <vector>

#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::run {

class StateOutputs {
 public:
  // contact: the same model as ode when the vehicle runs on wheel/rail contact, else null (no
  // wheel outputs). Both must outlive this object.
  StateOutputs(vehicle::VehicleOde& ode, dynamics::ContactVehicleOde* contact);

  // The state the next requests are about. What was evaluated at another state is forgotten; the
  // same (t, y) again keeps it.
  void at(double t, const double* y);

  // Accelerations of every body (VehicleOde::bodyAccelerations); the workspace then holds the
  // body kinematics of the state. False when the evaluation failed.
  bool accelerations();
  const std::vector<vehicle::Vector6d>& qdd() const { return qdd_; }

  // Wheel and patch outputs, two per wheelset ([2w] left, [2w + 1] right). False when the
  // evaluation failed or the vehicle has no wheel/rail contact.
  bool wheels();
  const std::vector<dynamics::WheelOutput>& wheelOutputs() const { return wheels_; }

  // Values of the elements ids at the state, as VehicleOde::elementOutputs gives them.
  void elements(std::span<const vehicle::ElementId> ids, std::span<vehicle::ElementValue> out);

  // The vehicle workspace of the state's last evaluation (body kinematics, element values).
  const vehicle::Workspace& workspace() const { return ode_.workspace(); }

  // Model evaluations asked of the model through this object (each on-demand output call is one).
  long evaluations() const { return evaluations_; }

 private:
  enum class Done : unsigned char { No, Ok, Failed };
  void contactOutputs();

  vehicle::VehicleOde& ode_;
  dynamics::ContactVehicleOde* contact_;
  double t_ = 0.0;
  std::vector<double> y_;
  bool valid_ = false;  // t_, y_ name a state
  Done acc_ = Done::No, wheels_done_ = Done::No;
  std::vector<vehicle::Vector6d> qdd_;
  std::vector<dynamics::WheelOutput> wheels_;
  long evaluations_ = 0;
};

}  // namespace rb::run
