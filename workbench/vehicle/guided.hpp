#pragma once
// OdeSystem adapter of the guided vehicle: wheelsets follow the track kinematically, all other
// bodies are free in (y, z, phi, theta, psi), series damper forces are states (docs/vehicle.md).
//
// Imposed motion (holonomic, rheonomic constraints):
// - every body: s_i(t) = start + x_i + V0 t + a t^2 / 2 (speed V(t) = V0 + a t, VehicleModel::
//   speedAt; the reaction on s is the traction force, BodyOutput::traction);
// - wheelsets: y = z = phi = psi = 0 relative to their track frame, pitch theta = travel(t) / r0;
// - frames: y = z = phi = theta = psi = 0.
//
// State layout: VehicleLayout with ws_dof = 0 (size() = 10 nf + ns, nf free bodies in body order,
// ns series dampers):
//   y[5k + c]          position c of free body k, c = 0..4: y, z, phi, theta, psi
//   y[5 nf + 5k + c]   its rate
//   y[10 nf + e]       force f of series damper e (its Maxwell branch, Appendix A)
// componentName(): "car.y", "bogie1.psi", "car.y_dot", "bogie1.psi_dot", "series[3].f".
//
// rhs() is allocation-free. Output functions (bodyCoordinates, bodyAccelerations, elementOutputs,
// bodyOutput, energy) evaluate the model at the given state on demand: nothing is computed for
// outputs nobody asked for.
#include <Eigen/Dense>
#include <span>
#include <string>
#include <vector>

#include "workbench/vehicle/dynamics.hpp"
#include "workbench/vehicle/layout.hpp"
#include "workbench/vehicle/model.hpp"
#include "workbench/vehicle/stage_clock.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::vehicle {

// The guided layout: free bodies only, wheelsets without states (ws_dof = 0).
VehicleLayout guidedLayout(const VehicleModel& model);

// Writes the full coordinates of every body at time t from the ODE state y into ws.q, ws.qd.
void guidedCoordinates(const VehicleModel& model, const VehicleLayout& layout, double t,
                       const double* y, Workspace& ws);

// The pure right-hand side: ydot = f(t, y). Returns 0, or 1 (recoverable) if a free body's pitch
// leaves |theta| < 1.2 rad (Euler-angle singularity at 90 deg) or a mass matrix is not positive
// definite. After the call ws holds the evaluated model (forces, element values, series rates).
// With a clock (a timed evaluation, stage_clock.hpp) the end of each stage is marked on it.
int guidedRhs(const VehicleModel& model, const VehicleLayout& layout, double t, const double* y,
              double* ydot, Workspace& ws, StageClock* clock = nullptr);

struct BodyOutput {
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();    // [m/s^2] absolute CoM acceleration,
                                                             // body track-frame components
  Eigen::Vector3d specific_force = Eigen::Vector3d::Zero();  // [m/s^2] acceleration - gravity,
                                                             // track-frame components
  Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();  // [rad/s^2] body components
  Eigen::Vector3d suspension_force = Eigen::Vector3d::Zero();      // [N] resultant of the elements,
                                                                   // track-frame components
  Eigen::Vector3d suspension_moment = Eigen::Vector3d::Zero();  // [N m] about the CoM, track comps
  double traction = 0.0;  // [N] generalised reaction of the imposed s(t) (force the drive applies)
};

class GuidedVehicleOde final : public VehicleOde {
 public:
  // Keeps a reference: `model` must outlive this object.
  explicit GuidedVehicleOde(const VehicleModel& model);

  int rhs(double t, const double* y, double* ydot) override;
  std::string lastError() const override { return last_error_; }

  // State at rest: free bodies in static equilibrium (quasi-static on a curve: the accelerations
  // of the imposed motion at time t0 included), rates zero, series forces zero
  // (solveStaticEquilibrium). Throws rb::InputError at the vehicle's loc if a free body has an
  // unrestrained coordinate (singular Jacobian) or Newton does not converge.
  Eigen::VectorXd initialState(double t0) override;
  // Same as initialState (the name workbench/run/compile.cpp calls).

  // Outputs at (t, y), evaluated on demand.
  int bodyCoordinates(double t, const double* y, std::span<Vector6d> q) override;
  int bodyAccelerations(double t, const double* y, std::span<Vector6d> qdd) override;
  int elementOutputs(double t, const double* y, std::span<const ElementId> ids,
                     std::span<ElementValue> out) override;
  BodyOutput bodyOutput(double t, const double* y, int body);
  Energy energy(double t, const double* y);
  // The workspace after the last evaluation (rhs or an output function).
  const Workspace& workspace() const override { return ws_; }

 protected:
  Workspace& bodyWorkspace() override { return ws_; }

 private:
  // Generalised accelerations of body b after guidedRhs into scratch_.
  Vector6d accelerationOf(std::size_t b) const;

  Workspace ws_;
  std::vector<double> scratch_;
  std::string last_error_;
};

}  // namespace rb::vehicle
