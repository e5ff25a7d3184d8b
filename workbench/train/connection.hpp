#pragma once
// The connection between two vehicles of a train (Spec -> force law): side buffers and a draw gear
// between the car bodies' headstocks, as in UIC screw-coupled and buffered stock.
//
// Geometry. Each car body carries its headstock plane at x = end (body frame, relative to its
// CoM): the front vehicle's rear end (end < 0) faces the rear vehicle's front end (end > 0). The
// buffers sit at y = +-spacing/2, the draw gear on the centre line, at their heights above the
// top of rail. The connection's axis e is the mean of the two car bodies' longitudinal axes; the
// gap of a pair of points (P on the front body, Q on the rear) is (P - Q) . e, zero when the
// buffer faces touch. Forces act along e at the points (a compressive buffer force pushes the
// front body forward and the rear one back), plus the buffer-head friction across it.
//
// Force laws.
// - A buffer pair (one buffer of each vehicle, face to face, in series): the compression c =
//   max(0, -gap) splits equally between the two identical buffers, so the pair's force is the
//   one buffer's force at c / 2. Loading and unloading curves (force against one buffer's stroke)
//   give the hysteresis of friction buffers; between them the force blends on the stroke rate,
//   w = (1 + tanh(c_dot / v_reg)) / 2, F = w F_load + (1 - w) F_unload (a regularised switch: a
//   buffer at rest carries the mean of its two curves).
// - Buffer-head friction: the heads slide across each other with the relative velocity v_t of P
//   and Q normal to e; the friction force mu F_buffer v_t / sqrt(|v_t|^2 + v_reg^2) opposes it.
// - Draw gear: tension once the gap exceeds the slack, F = k (gap - slack) (1 + f tanh(gap_dot /
//   v_reg)), f the friction ratio of its hysteresis; no force in compression (the buffers carry
//   it).
// - Coupler (instead of the draw gear): a massless link between two pivots, each `pivot` behind
//   its car body's headstock on the centre line, so its direction d follows the two car bodies'
//   relative lateral position and yaw. Its axial force N (tension > 0) follows the draw gear's
//   law in its elongation e = |P - Q| - 2 pivot and, for a coupler that carries compression
//   (central couplers), the mirror law below -slack. N acts along d on both bodies: in a curve or
//   with offset car bodies a coupler force has the lateral component N sin(angle) that a
//   compressed train exerts on its wagons. The link's angle to each car body's axis, theta =
//   atan2(d . y_body, d . x_body), is free up to angle_stop; beyond it the stop acts with
//   torque k_stop (|theta| - angle_stop) between link and body, and a massless link balances the
//   torques tau_f + tau_r of its two stops by a lateral force pair of (tau_f + tau_r) / |P - Q| at
//   its pivots, perpendicular to d (the torque balance of the link about one pivot).
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/vehicle/dynamics.hpp"
#include "workbench/vehicle/kinematics.hpp"

namespace rb::train {

// Regularising velocity of the hysteresis switches and the buffer-head friction [m/s]: far below
// the stroke rates of a run-in (0.1-1 m/s), far above the drift of a steady train.
inline constexpr double kRegularisingSpeed = 0.01;

struct BufferSpec {
  // Force [N] against the stroke [m] of one buffer, loading and unloading: strokes from 0,
  // strictly ascending; forces from 0, non-negative and non-decreasing; unloading <= loading.
  std::vector<double> load_stroke, load_force, unload_stroke, unload_force;
  double spacing = 0.0;   // [m] lateral distance between the two buffers of an end
  double height = 0.0;    // [m] above the top of rail
  double friction = 0.0;  // [-] buffer-head friction coefficient
  SourceLoc loc;
};

struct DrawGearSpec {
  double stiffness = 0.0;  // [N/m]
  double slack = 0.0;      // [m] gap at which the draw gear takes tension
  double friction = 0.0;   // [-] hysteresis ratio, 0 <= f < 1
  double height = 0.0;     // [m] above the top of rail
  SourceLoc loc;
};

// A coupler link with angling stops (see the header comment).
struct CouplerSpec {
  double stiffness = 0.0;       // [N/m] axial
  double slack = 0.0;           // [m] free play of the elongation, each way
  double friction = 0.0;        // [-] hysteresis ratio, 0 <= f < 1
  double height = 0.0;          // [m] above the top of rail
  double pivot = 0.0;           // [m] each pivot's distance behind its headstock, > 0
  bool compression = true;      // carries compression (central coupler), else tension only
  double angle_stop = 0.0;      // [rad] free angle each way between link and car body, > 0
  double stop_stiffness = 0.0;  // [N m/rad] torque of a stop per radian past it
  SourceLoc loc;
};

// One connection of train.connections, by the vehicles' names.
struct ConnectionSpec {
  std::string front, rear;            // vehicle names, front one first
  std::string front_body, rear_body;  // their car bodies ("": the vehicle's only car body)
  double front_end = 0.0;             // [m] x of the front vehicle's rear headstock (< 0)
  double rear_end = 0.0;              // [m] x of the rear vehicle's front headstock (> 0)
  std::optional<BufferSpec> buffers;
  std::optional<DrawGearSpec> draw_gear;
  std::optional<CouplerSpec> coupler;  // instead of draw_gear
  SourceLoc loc;
};

// Adds every problem of the force laws of `c` to `d` (the names are resolved by the run).
void validateConnection(const ConnectionSpec& c, Diagnostics& d);

// One buffer's force at stroke x >= 0 on a curve (linear between points, the last slope beyond
// the table).
double curveForce(const std::vector<double>& stroke, const std::vector<double>& force, double x);
// The pair's force [N] at compression c [m] and its rate c_dot [m/s].
double bufferPairForce(const BufferSpec& b, double c, double c_dot);
// The draw gear's force [N] (tension > 0) at gap [m] and its rate.
double drawGearForce(const DrawGearSpec& g, double gap, double gap_dot);
// The coupler's axial force [N] (tension > 0, compression < 0) at elongation e [m] and its rate.
double couplerForce(const CouplerSpec& c, double e, double e_dot);
// The torque [N m] a stop exerts on the link at angle theta [rad] (opposing theta; 0 inside the
// free angle).
double stopTorque(const CouplerSpec& c, double theta);

// The state of a connection at one evaluation.
struct ConnectionState {
  double gap = 0.0;            // [m] at the centre line (draw gear height)
  double buffer_left = 0.0;    // [N] compression of the left buffer pair
  double buffer_right = 0.0;   // [N]
  double draw_gear = 0.0;      // [N] draw gear or coupler: tension > 0 (a coupler: < 0 pressed)
  double angle_front = 0.0;    // [rad] coupler link against the front car body's axis (left > 0)
  double angle_rear = 0.0;     // [rad] against the rear car body's axis
  double longitudinal = 0.0;   // [N] draw gear - buffers: tension > 0
  double lateral_front = 0.0;  // [N] lateral force on the front car body, its track frame
  double lateral_rear = 0.0;   // [N] on the rear car body
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  // The point loads on the two car bodies (attachment-frame points, global forces): the two
  // buffers, the draw gear or the coupler's pivot force, and a stop's torque as a force couple.
  std::vector<vehicle::AppliedLoad> on_front, on_rear;
};

// The connection between car body kinematics kf (front vehicle, body index bf, CoM height hf)
// and kr: forces at the current positions and velocities.
void connectionForces(const ConnectionSpec& c, const vehicle::BodyKinematics& kf, int bf, double hf,
                      const vehicle::BodyKinematics& kr, int br, double hr, ConnectionState& out);

}  // namespace rb::train
