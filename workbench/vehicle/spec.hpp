#pragma once
// Plain input structs for a vehicle (built by workbench/scenario from the Lua vehicle{} block,
// compiled by the vehicle module). SI units. Each carries the SourceLoc of its Lua block.
#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

#include "workbench/assessment/spec.hpp"
#include "workbench/core/error.hpp"
#include "workbench/profiles/nominal.hpp"
#include "workbench/suspension/external_force.hpp"

namespace rb::vehicle {

// Frame: a massless-in-effect reference body that follows the track centreline kinematically
// (e.g. the loading frame of the single-wheelset case); its coordinates are prescribed.
enum class BodyKind { CarBody, Bogie, Wheelset, Frame };

// A rigid body. Its coordinates (s, y, z, roll, pitch, yaw) are relative to its own body track
// frame (paper Eq. 2-3, Fig. 2).
struct BodySpec {
  std::string name;  // unique, e.g. "car", "bogie1", "ws1"
  BodyKind kind = BodyKind::CarBody;
  double mass = 0.0;                                  // [kg]
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();  // [kg m^2] Ixx (roll), Iyy (pitch), Izz (yaw)
  double x = 0.0;       // [m] longitudinal position of the centre of mass relative to the
                        //     vehicle reference point, positive forward (body s = s_vehicle + x)
  double height = 0.0;  // [m] height of the centre of mass above the top of rail plane
  SourceLoc loc;
};

enum class ElementKind {
  SpringDamper,        // f = K d + D d_dot                                 (Appendix A)
  SeriesSpringDamper,  // f_dot + (K_series / D) f = K_series d_dot; f is a state (Appendix A);
                       // total force preload + K d + f with an optional parallel spring K
  ShearSpring,         // f = K_shear d
  BendingSpring,       // M = K_bend theta (relative rotation about `direction` axis)
  Bumpstop,            // f = F(d) cubic spline through a table, zero inside the clearance
};

// How the deformation d of an element is measured (Eq. 27-31): along the line between the two
// attachment points (Axial, Eq. 30 with undeformed length l0) or as one component of the relative
// displacement of the attachment points in the master track frame (X, Y, Z: bushing-like
// directional elements, as the per-direction stiffnesses of the paper's Table 4). For a
// BendingSpring the direction is the rotation axis.
enum class Direction { Axial, X, Y, Z };

struct ElementSpec {
  std::string name;
  ElementKind kind = ElementKind::SpringDamper;
  std::string body1, body2;  // body names; body1 is the master (its track frame is used)
  Eigen::Vector3d point1 = Eigen::Vector3d::Zero();  // [m] attachment point in body1's frame
  Eigen::Vector3d point2 = Eigen::Vector3d::Zero();  // [m] attachment point in body2's frame
  Direction direction = Direction::Axial;
  double stiffness = 0.0;         // [N/m] or [N m/rad] (bending)
  double damping = 0.0;           // [N s/m]
  double series_stiffness = 0.0;  // [N/m] (SeriesSpringDamper)
  double length0 = 0.0;           // [m] undeformed length, Axial only (0: the nominal distance);
                                  //     directional elements reject a non-zero value
  double preload = 0.0;           // [N] force at zero deformation (e.g. to carry static weight)
  std::vector<double> table_d;    // [m] bumpstop deformation table (|d| beyond clearance ...)
  std::vector<double> table_f;    // [N] bumpstop force table
  SourceLoc loc;
};

// The frame the direction of an external force is fixed in: the body's track frame (x along the
// track, y lateral to the left, z up from the track plane, cant included), which follows the body
// along the track but not its own motion on the suspension, or the body itself (a wheelset: its
// axle-box frame, which does not spin).
enum class ForceFrame { Track, Body };

// A force on one body from outside the vehicle model: a wind gust, the lateral push of a
// wheel-climb rig, the coupler load of a vehicle that is not simulated. Its value F(t) or F(s)
// (suspension::ForceLaw) acts along `direction` at `point`, so it also exerts its moment about
// the centre of mass. Lua: external_force{} in vehicle.elements (docs/vehicle.md).
struct ExternalForceSpec {
  std::string name;  // unique among the vehicle's elements
  std::string body;  // the body it acts on
  // [m] point of application in the body's attachment frame (a wheelset: the axle-box frame),
  // relative to its centre of mass
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  ForceFrame frame = ForceFrame::Track;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitY();  // in `frame`; any length > 0
  suspension::ForceLaw law;
  SourceLoc loc;
  SourceLoc table_loc;  // where the law's table is written (its problems are reported there)
};

// Names of the body coordinates, indexed by vehicle::Coord (kinematics.hpp: kS .. kYaw): the
// datasets /bodies/<body>/<name> of a result and the keys of vehicle.initial.<body>.
inline constexpr std::array<const char*, 6> kCoordNames = {"s", "y", "z", "roll", "pitch", "yaw"};

// An initial offset of one coordinate of one body from the state the run would start in (static
// equilibrium, wheelsets centred), in the body's track frame, and of its rate: vehicle.initial in
// a scenario (e.g. ws1 = { y = 3e-3 } for a lateral kick of the leading wheelset). A coordinate
// must be a state of the model: y, z, roll, pitch, yaw of car bodies and bogies; y, yaw (and the
// spin pitch when it is free) of wheelsets on contact, whose z and roll the contact constraints
// give; nothing of frames and guided wheelsets.
struct InitialCondition {
  std::string body;  // body name
  int coord = 1;     // vehicle::Coord (kY .. kYaw)
  bool rate = false;
  double value = 0.0;  // [m], [rad] or [m/s], [rad/s]
  SourceLoc loc;
};

struct VehicleSpec {
  std::string name;
  std::vector<BodySpec> bodies;
  std::vector<ElementSpec> elements;
  std::vector<ExternalForceSpec> external_forces;  // external_force{} of vehicle.elements
  double speed = 0.0;                              // [m/s] forward velocity V0 at t = 0
  double acceleration = 0.0;  // [m/s^2] constant longitudinal acceleration a: V(t) = V0 + a t
  double wheel_radius = profiles::kNominalWheelRadius;  // [m] nominal rolling radius r0 (wheelsets)
  double start = 0.0;  // [m] arc length of the vehicle reference point at t = 0
  // Kind of vehicle (EN 14363), for the alpha of the track shift limit of the assessment.
  assessment::VehicleCategory category = assessment::VehicleCategory::Unstated;
  std::vector<InitialCondition> initial;  // added to the initial state (vehicle.initial)
  SourceLoc loc;
};

}  // namespace rb::vehicle
