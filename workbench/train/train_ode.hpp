#pragma once
// The vehicles of one run as one ODE: the state is the vehicles' states one after the other
// (vehicle k's components start at offset(k)), then, when the motion along the track is a state
// (longitudinal.hpp), each vehicle's distance travelled and speed. The right-hand side first
// evaluates the connections between the vehicles (connection.hpp) on their car bodies and each
// vehicle's longitudinal acceleration (prepare()), hands each vehicle its forward motion and the
// connections' forces as applied loads, then evaluates every vehicle on its own part.
// Vehicles without connections and with a prescribed motion move independently, so the system is
// block-diagonal and a fixed-step method integrates each vehicle exactly as it would alone (every
// update of a fixed-step method is component-wise). A train of one vehicle is that vehicle's
// ODE with unchanged component names.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "workbench/integrators/ode.hpp"
#include "workbench/train/connection.hpp"
#include "workbench/train/longitudinal.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::train {

// A connection between two neighbouring vehicles of a run, by their places in the run's list
// (front one first) and their car bodies' indices.
struct Connection {
  std::string name;  // "<front>-<rear>"
  int front = 0, rear = 1;
  int front_body = 0, rear_body = 0;
  ConnectionSpec spec;
};

// The longitudinal motion of every vehicle (longitudinal.hpp): off, the prescribed V0 + a t.
struct Longitudinal {
  LongitudinalSpec spec;
  std::vector<TractionSpec> traction;      // per vehicle
  std::vector<ResistanceSpec> resistance;  // per vehicle
};

// The longitudinal motion of vehicle k at the last prepare().
struct VehicleMotion {
  double travel = 0.0, speed = 0.0, acceleration = 0.0;
  double traction = 0.0, resistance = 0.0, grade = 0.0, connections = 0.0;  // [N] forces
  // [N] the wheel/rail contact forces along the track (traction at the wheelsets: what carries
  // the traction there).
  double rail = 0.0;
  double mass = 0.0;       // [kg] of the longitudinal equation (longitudinalMass)
  double body_mass = 0.0;  // [kg] the bodies' alone: what the slope pulls on
};

// The mass of a vehicle's longitudinal equation: its bodies', plus the rotating-mass allowance of
// its wheelsets, sum I_yy / r0^2, when their spin follows the travel (guided, prescribed spin, or
// traction applied to the vehicle). A free spin whose creep forces enter the equation brings its
// own inertia: its creep forces are the rotating mass's share.
double longitudinalMass(const vehicle::VehicleModel& m, bool rotating = true);

class TrainOde final : public integ::OdeSystem {
 public:
  // One ODE per vehicle with the name its state components carry ("wagon2.ws1.y"); the name of
  // the only vehicle of a run is empty. Throws std::logic_error when a connection joins vehicles
  // that are not neighbours or bodies that are not car bodies or bogies.
  struct Part {
    std::string name;
    std::unique_ptr<vehicle::VehicleOde> ode;
  };
  explicit TrainOde(std::vector<Part> parts, std::vector<Connection> connections = {},
                    Longitudinal longitudinal = {});

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

  // Sets every vehicle's forward motion and the connections' loads at (t, y): what rhs() does
  // first, and what the outputs of a state need before they evaluate the vehicles. Returns
  // non-zero (lastError()) when a vehicle is slower than longitudinal.min_speed.
  int prepare(double t, const double* y);
  bool longitudinal() const { return longitudinal_.spec.on; }
  // The state components of vehicle k's distance travelled and speed (longitudinal() only).
  int travelIndex(int k) const { return longitudinal_offset_ + 2 * k; }
  int speedIndex(int k) const { return longitudinal_offset_ + 2 * k + 1; }
  // Vehicle k's longitudinal state and the force balance of the last prepare().
  const VehicleMotion& motion(int k) const { return motion_[static_cast<std::size_t>(k)]; }
  const std::vector<Connection>& connections() const { return connections_; }
  const ConnectionState& connectionState(int i) const {
    return states_[static_cast<std::size_t>(i)];
  }
  // The start state of the longitudinal components: travel 0 and each vehicle's speed V0.
  void initialLongitudinal(Eigen::VectorXd& y) const;
  // With the traction at the wheelsets: every vehicle's acceleration from the contact forces of
  // its last evaluation (rhs() calls it after the vehicles; the outputs after evaluating them).
  void updateAccelerations();

 private:
  void addConnectionPattern(integ::JacobianPattern& out) const;
  // The track's gradient under vehicle k's slope body at its travel (the connection end's track
  // frame of this evaluation when one computed it).
  double slopeUnder(int k, double travel) const;
  void addLongitudinalPattern(integ::JacobianPattern& out) const;

  std::vector<Part> parts_;
  std::vector<int> offsets_;
  std::vector<Connection> connections_;
  Longitudinal longitudinal_;
  int longitudinal_offset_ = 0;
  int size_ = 0;
  int failed_ = -1;    // the vehicle whose rhs returned non-zero last, -1: none
  std::string error_;  // the train's own failure (a vehicle too slow)
  std::vector<VehicleMotion> motion_;
  std::vector<ConnectionState> states_;
  std::vector<vehicle::BodyKinematics> kin_;  // per connection end: 2 i (front), 2 i + 1 (rear)
  std::vector<std::vector<vehicle::AppliedLoad>> loads_;      // per vehicle
  std::vector<std::vector<vehicle::AppliedMoment>> moments_;  // per vehicle
  // Per vehicle, its wheelsets and the bodies their brake or traction torques react on.
  std::vector<std::vector<std::array<int, 2>>> drives_;
  // Per vehicle, the body its slope is read under (its first car body, else its first body) and
  // the kin_ slot of a connection end on that body, -1 if none.
  std::vector<int> slope_body_, slope_kin_;
};

}  // namespace rb::train
