#pragma once
// The compiled, immutable vehicle model (Spec -> Model): validated bodies, suspension elements
// grouped by kind into separate vectors (a vehicle without bumpstops or series dampers has empty
// vectors and pays nothing for them; no per-evaluation branch on element kind), and a copy of the
// track geometry the bodies' track frames run on.
//
// Validation (compileVehicle/validateVehicle): every problem is reported with the SourceLoc of its
// Lua block, all collected and thrown together as one rb::InputError:
// - vehicle: at least one body; speed >= 0; wheel_radius > 0; finite start.
// - bodies: non-empty unique names; mass > 0 and inertias > 0 (not checked for frames, whose mass
//   plays no role); finite x and height.
// - elements: non-empty unique names (unique across all kinds); from/to name existing bodies and
//   differ; finite attachment points; stiffness, damping, preload finite and stiffness, damping
//   >= 0; per kind:
//   spring_damper: axial elements need distinct attachment points in the nominal configuration;
//     length0 >= 0 (axial only; 0 = the nominal distance); directional elements take no length0;
//   series_damper: damping > 0 and series_stiffness > 0 (the Maxwell ODE divides by D);
//   shear_spring, bending_spring: direction x, y or z (a shear spring acts across its axis, a
//     bending spring about an axis);
//   bumpstop: a valid table (suspension::BumpstopLaw::check), direction x, y, z or axial.
// - external forces: a name unique among all elements; an existing body that is not a frame (a
//   frame's motion is prescribed: a force on it would do nothing); a point within 100 m of the
//   body's centre of mass; a direction of length > 0; a valid law (suspension::checkForceLaw).
#include <Eigen/Dense>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/profiles/nominal.hpp"
#include "workbench/suspension/bumpstop.hpp"
#include "workbench/track/geometry.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/kinematics.hpp"
#include "workbench/vehicle/spec.hpp"

namespace rb::vehicle {

struct Body {
  std::string name;
  BodyKind kind = BodyKind::CarBody;
  double mass = 0.0;                                  // [kg]
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();  // [kg m^2] principal, body axes
  double x = 0.0;                                     // [m] longitudinal offset of its track frame
  double height = 0.0;                                // [m] nominal CoM height above top of rail
  RotationSequence rotation = RotationSequence::YawPitchRoll;
  SourceLoc loc;
};

// Geometry shared by all two-point elements. body1 is the master (Eq. 28).
struct ElementGeometry {
  std::string name;
  SourceLoc loc;
  int body1 = 0, body2 = 0;
  Eigen::Vector3d u1 = Eigen::Vector3d::Zero();  // attachment point, body1 attachment frame
  Eigen::Vector3d u2 = Eigen::Vector3d::Zero();  // attachment point, body2 attachment frame
  Direction direction = Direction::Axial;
  int axis = -1;  // 0, 1, 2 for X, Y, Z; -1 for Axial
  // Relative position r_Q - r_P in the nominal configuration (all body coordinates zero, straight
  // level track): the zero of directional deformations.
  Eigen::Vector3d delta_nominal = Eigen::Vector3d::Zero();
  double length0 = 0.0;  // [m] axial undeformed length (the nominal distance if spec gives 0)
  int pair = -1;         // index into VehicleModel::body_pairs of (body1, body2)
  // Index into VehicleModel::point_pairs of (body1, u1, body2, u2); -1 for bending springs, which
  // act through the attachment frames alone.
  int point_pair = -1;
};

// A distinct pair of attachment points of the point-based elements (all kinds but bending
// springs). The elements of one suspension location (the primary x, y and z elements of an axle
// box, the secondary springs and dampers of one side) share the relative motion of their points
// (delta, delta_dot of Eq. 28), evaluated once per point pair and evaluation.
struct PointPair {
  int body1 = 0, body2 = 0;
  int pair = -1;  // index into VehicleModel::body_pairs
  Eigen::Vector3d u1 = Eigen::Vector3d::Zero(), u2 = Eigen::Vector3d::Zero();
};

struct SpringDamperElement {
  ElementGeometry g;
  double stiffness = 0.0, damping = 0.0, preload = 0.0;
};
struct SeriesDamperElement {
  ElementGeometry g;
  double stiffness = 0.0;  // [N/m] optional spring in parallel with the Maxwell branch
  double damping = 0.0, series_stiffness = 0.0, preload = 0.0;
};
struct ShearSpringElement {
  ElementGeometry g;
  double stiffness = 0.0, preload = 0.0;
};
struct BendingSpringElement {
  ElementGeometry g;
  double stiffness = 0.0, preload = 0.0;  // [N m/rad], [N m]
};
struct BumpstopElement {
  ElementGeometry g;
  suspension::BumpstopLaw law;
};

// A force on one body from outside the vehicle (ExternalForceSpec): F(t, s) along `direction`
// at the point u.
struct ExternalForce {
  std::string name;
  SourceLoc loc;
  int body = 0;
  Eigen::Vector3d u = Eigen::Vector3d::Zero();  // [m] attachment frame, relative to the CoM
  ForceFrame frame = ForceFrame::Track;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitY();  // unit vector in `frame`
  suspension::ForceLaw law;
};

// Handle of one element: its kind and its index in that kind's vector.
struct ElementId {
  ElementKind kind = ElementKind::SpringDamper;
  int index = 0;
  bool operator==(const ElementId&) const = default;
};

// Lua name of an element kind: "spring_damper", "series_damper", "shear_spring", "bending_spring",
// "bumpstop".
std::string_view elementKindName(ElementKind kind);

struct VehicleModel {
  std::string name;
  double speed = 0.0;         // [m/s] V0, the forward speed at t = 0
  double acceleration = 0.0;  // [m/s^2] a, constant: V(t) = V0 + a t (a speed ramp)
  double wheel_radius = profiles::kNominalWheelRadius;  // [m] r0
  double start = 0.0;     // [m] s of the vehicle reference point at t = 0
  double gravity = 9.81;  // [m/s^2]
  std::vector<Body> bodies;
  std::vector<SpringDamperElement> spring_dampers;
  std::vector<SeriesDamperElement> series_dampers;
  std::vector<ShearSpringElement> shear_springs;
  std::vector<BendingSpringElement> bending_springs;
  std::vector<BumpstopElement> bumpstops;
  // Forces from outside the vehicle (external_force{}): not suspension elements (no ElementId),
  // applied by evaluate() after them.
  std::vector<ExternalForce> external_forces;
  // Lua names of the kinds present, in enum order, then "external_force" when there is one.
  std::vector<std::string> element_kinds;
  // The distinct (master, other) body pairs of the elements: the relative placement of their
  // track frames (A_ij, R_ij of Eq. 28) is computed once per pair and evaluation (the wagon's 48
  // elements join 6 pairs).
  std::vector<std::array<int, 2>> body_pairs;
  // The distinct attachment-point pairs of the point-based elements (the wagon's 44 point-based
  // elements join 16 pairs).
  std::vector<PointPair> point_pairs;
  track::TrackGeometry geometry;
  SourceLoc loc;

  int findBody(std::string_view name) const;  // -1 if unknown
  std::optional<ElementId> findElement(std::string_view name) const;
  int findExternalForce(std::string_view name) const;  // index into external_forces, -1 if none
  const ElementGeometry& element(ElementId id) const;
  std::string elementName(ElementId id) const { return element(id).name; }
  int elementCount() const;
  std::vector<ElementId> elements() const;  // all, by kind then index
  // The imposed forward motion (rheonomic, docs/vehicle.md section 1): speed V(t) = V0 + a t,
  // distance travelled V0 t + a t^2 / 2 and the arc length s = start + x + travel(t) of body b's
  // track frame. With a = 0 these are bit-identical to the constant-speed expressions (the a terms
  // add +0.0). The run checks that V(t) >= 0 over its duration (a negative speed is an input
  // error, not clamped).
  double speedAt(double t) const { return speed + acceleration * t; }
  double travel(double t) const { return speed * t + 0.5 * acceleration * t * t; }
  double bodyS(int b, double t) const { return bodySAt(b, travel(t)); }
  // The same after a given distance travelled (a train's longitudinal state).
  double bodySAt(std::size_t b, double travelled) const { return start + bodies[b].x + travelled; }
};

// Adds every problem of `spec` to `diags`. Does not throw.
void validateVehicle(const VehicleSpec& spec, Diagnostics& diags);

// Validates (throws one rb::InputError listing all problems) and builds the model. The track
// geometry is copied: the model does not refer to `track` afterwards.
VehicleModel compileVehicle(const VehicleSpec& spec, const track::TrackModel& track);

}  // namespace rb::vehicle
