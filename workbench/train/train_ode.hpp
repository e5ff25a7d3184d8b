#pragma once
// The vehicles of one run as one ODE: the state is the vehicles' states one after the other
// (vehicle k's components start at offset(k)), and the right-hand side is each vehicle's on its
// own part. Vehicles without connections between them move independently, so the system is
// block-diagonal and a fixed-step method integrates each vehicle exactly as it would alone (every
// update of a fixed-step method is component-wise). A train of one vehicle is that vehicle's
// ODE with unchanged component names.
#include <memory>
#include <string>
#include <vector>

#include "workbench/integrators/ode.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::train {

// A force element between two vehicles of a run (buffers, draw gear, couplers) by the vehicles'
// places in the run's list, front one first. The run path has none yet: TrainOde refuses any.
struct Connection {
  int front = 0;
  int rear = 1;
};

class TrainOde final : public integ::OdeSystem {
 public:
  // One ODE per vehicle with the name its state components carry ("wagon2.ws1.y"); the name of
  // the only vehicle of a run is empty. Throws std::logic_error when a connection is given.
  struct Part {
    std::string name;
    std::unique_ptr<vehicle::VehicleOde> ode;
  };
  explicit TrainOde(std::vector<Part> parts, const std::vector<Connection>& connections = {});

  int size() const override { return size_; }
  int rhs(double t, const double* y, double* ydot) override;
  integ::JacobianPattern jacobianPattern() const override;
  std::vector<int> stiffComponents() const override;
  std::string componentName(int i) const override;
  std::string lastError() const override;
  // The failing vehicle's, its body named "<vehicle>.<body>" in a run of several.
  integ::ModelFailure lastFailure() const override;

  int vehicles() const { return static_cast<int>(parts_.size()); }
  vehicle::VehicleOde& vehicle(int k) { return *parts_[static_cast<std::size_t>(k)].ode; }
  const vehicle::VehicleOde& vehicle(int k) const {
    return *parts_[static_cast<std::size_t>(k)].ode;
  }
  const std::string& name(int k) const { return parts_[static_cast<std::size_t>(k)].name; }
  // First state component of vehicle k.
  int offset(int k) const { return offsets_[static_cast<std::size_t>(k)]; }

 private:
  std::vector<Part> parts_;
  std::vector<int> offsets_;
  int size_ = 0;
  int failed_ = -1;  // the vehicle whose rhs returned non-zero last, -1: none
};

}  // namespace rb::train
