#pragma once
// Dynamics of the vehicle in full track-frame coordinates (Model -> Workspace): for given
// coordinates q_i, rates qd_i of EVERY body (6 each: s, y, z, phi, theta, psi) and the series
// damper forces, evaluate() computes for each body the 6x6 mass matrix M_i and the generalised
// force vector Q_i = Q_applied (gravity, suspension elements, Eq. 29, external forces) + Q_v
// (quadratic-velocity inertia forces, Newton-Euler), so that M_i qddot_i = Q_i + (constraint
// reactions). Each body's inertia couples only its own coordinates (block-diagonal M; each body has
// its own track frame). The series damper force rates f_dot (Appendix A ODE) are computed too.
//
// The ODE adapters (guided.hpp, later the contact models) decide which coordinates are
// prescribed and which are free. evaluate() is allocation-free.
#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "workbench/vehicle/kinematics.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::vehicle {

// Deformation d [m or rad], its rate, and the element force f [N] (moment [N m] for bending
// springs; total force including a parallel spring for series dampers), as defined in
// suspension/laws.hpp and docs/vehicle.md.
struct ElementValue {
  double d = 0.0;
  double d_dot = 0.0;
  double force = 0.0;
};

// Relative motion of the two attachment points of a point pair (VehicleModel::point_pairs) in the
// master track frame, Eq. (28): delta = R_ij + A_ij (rbar_j + A_a,j u_Q) - (rbar_i + A_a,i u_P),
// delta_dot = A_ij v_Q - v_P - sdot_i (w_i x delta) (docs/vehicle.md).
struct PointPairMotion {
  Eigen::Vector3d aui = Eigen::Vector3d::Zero();  // A_a,i u_P: point P rel. to CoM i (track comps)
  Eigen::Vector3d auj = Eigen::Vector3d::Zero();  // A_a,j u_Q: point Q rel. to CoM j (track comps)
  Eigen::Vector3d delta = Eigen::Vector3d::Zero();
  Eigen::Vector3d delta_dot = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_delta = Eigen::Vector3d::Zero();  // w_i x delta (the s column of J_i)
};

// The motion of a vehicle along the track when a train computes it (its longitudinal equation,
// train/train_ode.hpp) instead of the model's prescribed V(t) = V0 + a t: the distance travelled
// from vehicle.start, the speed and the acceleration, shared by every body of the vehicle.
struct ForwardMotion {
  double travel = 0.0;        // [m]
  double speed = 0.0;         // [m/s]
  double acceleration = 0.0;  // [m/s^2]
  bool operator==(const ForwardMotion&) const = default;
};

// A force on a body from outside the vehicle (a buffer or coupler of the next vehicle): applied at
// the point u of the body's attachment frame (relative to its CoM), global components.
struct AppliedLoad {
  int body = 0;
  Eigen::Vector3d u = Eigen::Vector3d::Zero();      // [m]
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // [N]
  bool operator==(const AppliedLoad&) const = default;
};

// A moment on a body from outside its suspension: `torque` about the y axis of the attachment
// frame of body `axis` (a wheelset's axle), so that a wheelset's brake or traction torque and its
// reaction on the bogie act about one axis and balance exactly.
struct AppliedMoment {
  int body = 0;
  int axis = 0;
  double torque = 0.0;  // [N m]
  bool operator==(const AppliedMoment&) const = default;
};

struct Workspace {
  // Inputs: full coordinates and rates of every body (set by the ODE adapter).
  std::vector<Vector6d> q, qd;
  // Inputs set by a train (none for a vehicle alone): the forward motion that replaces the
  // model's prescribed one, and the forces from the vehicles next to it, added to Q by
  // evaluate() as point forces (addPointForce).
  std::optional<ForwardMotion> motion;
  std::vector<AppliedLoad> applied;
  std::vector<AppliedMoment> moments;
  // Outputs of evaluate():
  std::vector<BodyKinematics> kin;
  std::vector<Matrix6d> mass;   // M_i
  std::vector<Vector6d> force;  // Q_i = Q_applied + Q_v
  // Resultant of the suspension elements on each body: force and moment about the CoM, in the
  // body's track-frame components.
  std::vector<Eigen::Vector3d> susp_force, susp_moment;
  std::vector<ElementValue> spring_damper, series_damper, shear_spring, bending_spring, bumpstop;
  std::vector<double> series_rate;  // f_dot of each series damper
  // Per body pair (VehicleModel::body_pairs): A_ij = A_ti^T A_tj, R_ij = A_ti^T (R_tj - R_ti).
  std::vector<Eigen::Matrix3d> pair_A;
  std::vector<Eigen::Vector3d> pair_R;
  // The BodyKinematics::tf_version of both bodies pair_A, pair_R were computed from: they depend
  // on the track frames alone, which stay the same for the stages at one time.
  std::vector<std::array<std::uint64_t, 2>> pair_version;
  // Per point pair (VehicleModel::point_pairs), shared by the elements at those points.
  std::vector<PointPairMotion> point_motion;

  const ElementValue& value(ElementId id) const;
};

Workspace makeWorkspace(const VehicleModel& model);

// The forward motion at t: the train's when it set one (ws.motion), else the model's prescribed
// travel(t), speedAt(t), acceleration.
inline ForwardMotion forwardMotion(const VehicleModel& m, const Workspace& ws, double t) {
  if (ws.motion) return *ws.motion;
  return {m.travel(t), m.speedAt(t), m.acceleration};
}

// The relative motion of the attachment points of element g computed from the element's own
// geometry, at the body kinematics and body-pair placements of the last evaluate(): equal to
// ws.point_motion[g.point_pair] (tests; bending springs included).
PointPairMotion pointPairMotion(const ElementGeometry& g, const Workspace& ws);

// Evaluates everything at time t, ws.q, ws.qd and the series damper forces series_f (one per
// series damper; may be null if there are none). t enters only through the laws of the external
// forces (VehicleModel::external_forces).
void evaluate(const VehicleModel& model, double t, const double* series_f, Workspace& ws);

struct Energy {
  double kinetic = 0.0;  // [J] sum of m v^2 / 2 + omega^T J omega / 2
  double gravity = 0.0;  // [J] sum of m g Z_cg (global Z)
  double elastic = 0.0;  // [J] springs (K d^2/2 + preload d), bumpstops, series springs f^2/(2 Ks)
  double total() const { return kinetic + gravity + elastic; }
};
// Mechanical energy of the state last passed to evaluate().
Energy energy(const VehicleModel& model, const double* series_f, const Workspace& ws);

}  // namespace rb::vehicle
