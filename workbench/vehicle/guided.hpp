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
// State layout (size() = 10 nf + ns, nf free bodies in body order, ns series dampers):
//   y[5k + c]          position c of free body k, c = 0..4: y, z, phi, theta, psi
//   y[5 nf + 5k + c]   its rate
//   y[10 nf + e]       force f of series damper e (its Maxwell branch, Appendix A)
// componentName(): "car.y", "bogie1.psi", "car.y_dot", "bogie1.psi_dot", "series[3].f".
//
// rhs() is allocation-free. Output functions (elementOutputs, bodyOutput, energy) evaluate the
// model at the given state on demand: nothing is computed for outputs nobody asked for.
#include <Eigen/Dense>
#include <span>
#include <string>
#include <vector>

#include "workbench/integrators/ode.hpp"
#include "workbench/vehicle/dynamics.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::vehicle {

// Which bodies are free and where their states live.
struct GuidedLayout {
  std::vector<int> free_bodies;  // body indices, in body order
  std::vector<int> slot;         // per body: k (free body number) or -1 (prescribed)
  int n_free = 0;
  int n_series = 0;
  int size = 0;
  int position(int k, int c) const { return 5 * k + c; }  // c = 0..4 (y .. psi)
  int rate(int k, int c) const { return 5 * n_free + 5 * k + c; }
  int series(int e) const { return 10 * n_free + e; }
};
GuidedLayout guidedLayout(const VehicleModel& model);

// Writes the full coordinates of every body at time t from the ODE state y into ws.q, ws.qd.
void guidedCoordinates(const VehicleModel& model, const GuidedLayout& layout, double t,
                       const double* y, Workspace& ws);

// The pure right-hand side: ydot = f(t, y). Returns 0, or 1 (recoverable) if a free body's pitch
// leaves |theta| < 1.2 rad (Euler-angle singularity at 90 deg) or a mass matrix is not positive
// definite. After the call ws holds the evaluated model (forces, element values, series rates).
int guidedRhs(const VehicleModel& model, const GuidedLayout& layout, double t, const double* y,
              double* ydot, Workspace& ws);

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

class GuidedVehicleOde : public integ::OdeSystem {
 public:
  // Keeps a reference: `model` must outlive this object.
  explicit GuidedVehicleOde(const VehicleModel& model);

  int size() const override { return layout_.size; }
  int rhs(double t, const double* y, double* ydot) override;
  std::string componentName(int i) const override;
  std::string lastError() const override { return last_error_; }

  const VehicleModel& model() const { return *model_; }
  const GuidedLayout& layout() const { return layout_; }
  // State index of coordinate c (kY .. kYaw) of body b, or of its rate; -1 if prescribed.
  int index(int body, Coord c, bool rate = false) const;
  // Index of a state by componentName(); -1 if none.
  int indexOf(const std::string& component) const;

  // State at rest: free bodies in static equilibrium (quasi-static on a curve: the accelerations
  // of the imposed motion at time t0 included), rates zero, series forces zero. Newton iteration
  // on the accelerations with a finite-difference Jacobian. Throws rb::InputError at the
  // vehicle's loc if a free body has an unrestrained coordinate (singular Jacobian) or Newton
  // does not converge.
  Eigen::VectorXd staticState(double t0);

  // Outputs at (t, y), evaluated on demand.
  void elementOutputs(double t, const double* y, std::span<const ElementId> ids,
                      std::span<ElementValue> out);
  BodyOutput bodyOutput(double t, const double* y, int body);
  Energy energy(double t, const double* y);
  // The workspace after the last evaluation (rhs or an output function).
  const Workspace& workspace() const { return ws_; }

 private:
  const VehicleModel* model_;
  GuidedLayout layout_;
  Workspace ws_;
  std::vector<double> scratch_;
  std::string last_error_;
};

}  // namespace rb::vehicle
