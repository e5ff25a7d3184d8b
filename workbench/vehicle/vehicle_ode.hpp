#pragma once
// The vehicle ODE family: one interface for the guided vehicle (GuidedVehicleOde) and the vehicle
// on wheel/rail contact (dynamics::ContactVehicleOde), with one state layout (VehicleLayout) and
// one naming scheme for the states ("car.y", "ws1.theta_dot", "series[3].f").
#include <Eigen/Dense>
#include <algorithm>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "workbench/integrators/ode.hpp"
#include "workbench/vehicle/dynamics.hpp"
#include "workbench/vehicle/layout.hpp"
#include "workbench/vehicle/model.hpp"
#include "workbench/vehicle/sparsity.hpp"
#include "workbench/vehicle/stage_clock.hpp"

namespace rb::vehicle {

class VehicleOde : public integ::OdeSystem {
 public:
  int size() const final { return layout_.size; }
  std::string componentName(int i) const final { return layout_.componentName(i, *model_); }

  const VehicleModel& model() const { return *model_; }
  const VehicleLayout& layout() const { return layout_; }
  // State index of coordinate c of body b (or of its rate); -1 if not a state.
  int index(int body, Coord c, bool rate = false) const { return layout_.index(body, c, rate); }
  int indexOf(const std::string& component) const {  // by componentName(); -1 if none
    return layout_.indexOf(component, *model_);
  }
  // Structural sparsity of df/dy from the bodies, elements and layout (sparsity.hpp).
  integ::JacobianPattern jacobianPattern() const final {
    return vehicle::jacobianPattern(*model_, layout_);
  }
  // The stiff components the fixed-step methods may integrate exponentially: the free wheelset
  // spin rates (creep damping, about -2 f11 r0^2 / (V I_yy), the stiffest mode of the contact
  // vehicle) and the series-damper forces (relaxation rate -K_series / D, Appendix A).
  std::vector<int> stiffComponents() const final {
    std::vector<int> out;
    if (layout_.spinFree())
      for (int w = 0; w < layout_.n_ws; ++w) out.push_back(layout_.wsRate(w, 1));
    for (int e = 0; e < layout_.n_series; ++e) out.push_back(layout_.series(e));
    return out;
  }

  // State at rest at t0: car bodies and bogies in static (on a curve: quasi-static) equilibrium
  // on their suspension (solveStaticEquilibrium), rates zero (wheelset spin: rolling), series
  // forces zero. Throws rb::InputError at the vehicle's loc when no equilibrium is found.
  virtual Eigen::VectorXd initialState(double t0) = 0;

  // Outputs at (t, y), evaluated on demand. Return 0, or the rhs error code.
  // Full coordinates (s, y, z, roll, pitch, yaw) of every body, q.size() == bodies.
  virtual int bodyCoordinates(double t, const double* y, std::span<Vector6d> q) = 0;
  // Accelerations (sddot = a, y, z, roll, pitch, yaw) of every body, qdd.size() == bodies; the
  // workspace then holds the body kinematics at (t, y) (absolute acceleration Lv qdd + gamma_v).
  virtual int bodyAccelerations(double t, const double* y, std::span<Vector6d> qdd) = 0;
  // Values of the suspension elements ids at (t, y).
  virtual int elementOutputs(double t, const double* y, std::span<const ElementId> ids,
                             std::span<ElementValue> out) = 0;
  // The vehicle workspace of the last evaluation (element values, forces, body kinematics).
  virtual const Workspace& workspace() const = 0;

  // Inputs a train sets before every evaluation (train/train_ode.hpp): the forward motion that
  // replaces the prescribed one, and the forces of the neighbouring vehicles' buffers and
  // couplers. A vehicle alone has neither. Allocation-free once the loads' count is reached.
  void setForwardMotion(const ForwardMotion& motion) {
    Workspace& ws = bodyWorkspace();
    if (ws.motion && *ws.motion == motion) return;
    ws.motion = motion;
    inputsChanged();
  }
  void setAppliedLoads(std::span<const AppliedLoad> loads,
                       std::span<const AppliedMoment> moments = {}) {
    Workspace& ws = bodyWorkspace();
    if (std::equal(loads.begin(), loads.end(), ws.applied.begin(), ws.applied.end()) &&
        std::equal(moments.begin(), moments.end(), ws.moments.begin(), ws.moments.end()))
      return;
    ws.applied.assign(loads.begin(), loads.end());
    ws.moments.assign(moments.begin(), moments.end());
    inputsChanged();
  }

  // The wheel/rail contact forces along the track of the last evaluation with a forward motion
  // set [N]; 0 for a vehicle without contact (guided wheelsets follow the track).
  virtual double railForce() const { return 0.0; }

  // Sampled timing of the rhs stages (stage_clock.hpp): rhs() evaluations only, not the outputs
  // and initial-state evaluations. setStageSampling(0) turns it off.
  const StageClock& stageClock() const { return stages_; }
  void setStageSampling(unsigned period) { stages_.setPeriod(period); }

 protected:
  // The workspace the evaluations read the train's inputs from.
  virtual Workspace& bodyWorkspace() = 0;
  // Called when those inputs change: what was computed for the old ones is stale.
  virtual void inputsChanged() {}

  VehicleOde(const VehicleModel& model, VehicleLayout layout)
      : model_(&model), layout_(std::move(layout)) {}

  const VehicleModel* model_;
  VehicleLayout layout_;
  StageClock stages_;
};

}  // namespace rb::vehicle
