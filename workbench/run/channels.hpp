#pragma once
// The output channels of a vehicle run, each quantity declared once as a row {name, unit,
// meaning, getter}: the writer's channel set-up (dataset path and units), the sampled value (the
// getter applied to the model's output struct) and the result file's /schema (architecture.md,
// "Output layout") all iterate over the same rows, so a name can never be paired with another
// quantity's value.
//
// A code-valued channel (a number that stands for a name) names its enum; the enum's codes are
// written from its name table (core/names.hpp) into /schema/enums.
#include <algorithm>
#include <array>
#include <numbers>
#include <string_view>

#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/io/schema.hpp"
#include "workbench/train/train_ode.hpp"

namespace rb::run {

// The /schema/enums attribute of the regime's codes (io::codesOf<dynamics::ContactRegime>()).
inline constexpr std::string_view kRegimeEnum = "contact_regime";

// One quantity of an output struct In: dataset name, SI unit ("-" dimensionless), what it is,
// and how its value is read. `codes` names the enum of a code-valued channel (/schema/enums).
template <class In>
struct ChannelRow {
  std::string_view name, unit, meaning;
  double (*get)(const In&);
  std::string_view codes = {};
};

// Peak pressure p0 = 3 N / (2 pi a b) of a Hertz patch (Johnson, Contact Mechanics (1985),
// section 3.5: 1.5 times the mean pressure N / (pi a b) over the ellipse); 0
// for a patch out of contact or pulled (N <= 0).
inline double peakPressure(const dynamics::PatchOutput& p) {
  const double area = std::numbers::pi * p.a * p.b;
  return p.active && p.normal > 0.0 && area > 0.0 ? 1.5 * p.normal / area : 0.0;
}

// A wheel at an output time with its dominant patch (the larger normal force of an active
// patch), which gives the wheel's creepages and contact position.
struct WheelSample {
  const dynamics::WheelOutput& w;
  const dynamics::PatchOutput& p;
};

// Per wheel, /contact/<wheelset>/<left|right>/<name>: the quantities a user expects of a contact
// run.
inline constexpr ChannelRow<WheelSample> kWheelChannels[] = {
    {"normal_force", "N", "normal force, sum over the wheel's patches",
     [](const WheelSample& s) { return s.w.normal; }},
    {"normal_tread", "N", "normal force of the patches on the tread",
     [](const WheelSample& s) { return s.w.normal_tread; }},
    {"normal_flange", "N", "normal force of the patches on the flange",
     [](const WheelSample& s) { return s.w.normal_flange; }},
    {"creep_force_x", "N", "longitudinal creep force, sum over the patches",
     [](const WheelSample& s) { return s.w.creep_x; }},
    {"creep_force_y", "N", "lateral creep force, sum over the patches",
     [](const WheelSample& s) { return s.w.creep_y; }},
    {"creepage_x", "-", "longitudinal creepage of the dominant patch",
     [](const WheelSample& s) { return s.p.sx; }},
    {"creepage_y", "-", "lateral creepage of the dominant patch",
     [](const WheelSample& s) { return s.p.sy; }},
    {"spin", "1/m", "spin creepage of the dominant patch",
     [](const WheelSample& s) { return s.p.spin; }},
    {"wheel_s", "m", "contact point on the wheel profile (dominant patch)",
     [](const WheelSample& s) { return s.p.s_w; }},
    {"rail_s", "m", "contact point on the rail profile (dominant patch)",
     [](const WheelSample& s) { return s.p.s_r; }},
    {"contact_angle", "rad", "contact angle of the dominant patch, positive toward the centre",
     [](const WheelSample& s) { return s.p.gamma; }},
    {"flange_indentation", "m", "LUT flange indentation delta (Eq. 21), > 0 penetration",
     [](const WheelSample& s) { return s.w.flange_indentation; }},
    {"flange_force", "N", "LUT Hertz flange force (Eq. 20)",
     [](const WheelSample& s) { return s.w.flange_force; }},
    {"regime", "-", "contact regime (codes in /schema/enums)",
     [](const WheelSample& s) { return static_cast<double>(s.w.regime); }, kRegimeEnum},
    {"y_over_q", "-", "derailment quotient Y/Q (EN 14363)",
     [](const WheelSample& s) { return s.w.y_over_q; }},
    {"X", "N", "longitudinal force of the rail on the wheel, track frame (EN 14363)",
     [](const WheelSample& s) { return s.w.force.X; }},
    {"Y", "N", "lateral force of the rail on the wheel, positive toward the track centre",
     [](const WheelSample& s) { return s.w.force.Y; }},
    {"Q", "N", "wheel load, perpendicular to the track plane, positive upward",
     [](const WheelSample& s) { return s.w.force.Q; }},
    {"y_track", "N", "lateral force of the rail on the wheel, positive to the left",
     [](const WheelSample& s) { return s.w.force.y_track; }},
    {"contact_count", "-", "number of active patches",
     [](const WheelSample& s) { return static_cast<double>(s.w.patch_count); }},
    {"wheel_lift", "m", "rise of the tape circle above its centred height over the rail",
     [](const WheelSample& s) { return s.w.wheel_lift; }},
    {"max_pressure", "Pa",
     "largest peak Hertz pressure p0 = 3 N / (2 pi a b) of the wheel's patches (elastic: of its "
     "strongest tread and flange patch)",
     [](const WheelSample& s) {
       return std::max(peakPressure(s.w.patch[0]), peakPressure(s.w.patch[1]));
     }},
};

// Per contact patch, /contact/<wheelset>/<side>/patch0|patch1/<name>: what an EN 14363 assessment
// and a wear (T gamma) analysis read. An inactive patch writes zeros (active = 0).
inline constexpr ChannelRow<dynamics::PatchOutput> kPatchChannels[] = {
    {"active", "-", "1 when the patch is in contact, else 0 (and every value of it 0)",
     [](const dynamics::PatchOutput& p) { return p.active ? 1.0 : 0.0; }},
    {"on_flange", "-", "1 when the wheel point lies in the flange window, else 0",
     [](const dynamics::PatchOutput& p) { return p.on_flange ? 1.0 : 0.0; }},
    {"normal_force", "N", "normal force", [](const dynamics::PatchOutput& p) { return p.normal; }},
    {"creep_force_x", "N", "creep force along the patch's x (rolling direction)",
     [](const dynamics::PatchOutput& p) { return p.fx; }},
    {"creep_force_y", "N", "creep force along the patch's y = n x x",
     [](const dynamics::PatchOutput& p) { return p.fy; }},
    {"spin_moment", "N m", "spin moment (0 with a law that gives none: polach)",
     [](const dynamics::PatchOutput& p) { return p.mz; }},
    {"creepage_x", "-", "longitudinal creepage",
     [](const dynamics::PatchOutput& p) { return p.sx; }},
    {"creepage_y", "-", "lateral creepage", [](const dynamics::PatchOutput& p) { return p.sy; }},
    {"spin", "1/m", "spin creepage", [](const dynamics::PatchOutput& p) { return p.spin; }},
    {"wheel_s", "m", "contact point on the wheel profile",
     [](const dynamics::PatchOutput& p) { return p.s_w; }},
    {"rail_s", "m", "contact point on the rail profile",
     [](const dynamics::PatchOutput& p) { return p.s_r; }},
    {"y", "m", "lateral track-frame position of the contact point, positive to the left",
     [](const dynamics::PatchOutput& p) { return p.y; }},
    {"contact_angle", "rad", "contact angle from the contact table, positive toward the centre",
     [](const dynamics::PatchOutput& p) { return p.gamma; }},
    {"contact_angle_track", "rad", "contact angle including the rails' cross-level angle (Eq. 5)",
     [](const dynamics::PatchOutput& p) { return p.gamma_track; }},
    {"rolling_radius", "m", "rolling radius at the contact point",
     [](const dynamics::PatchOutput& p) { return p.radius; }},
    {"semi_axis_a", "m", "Hertz semi-axis along the rolling direction",
     [](const dynamics::PatchOutput& p) { return p.a; }},
    {"semi_axis_b", "m", "Hertz semi-axis across the rolling direction",
     [](const dynamics::PatchOutput& p) { return p.b; }},
    {"X", "N", "longitudinal force of the patch on the wheel, track frame",
     [](const dynamics::PatchOutput& p) { return p.force.X; }},
    {"Y", "N", "lateral force of the patch on the wheel, positive toward the track centre",
     [](const dynamics::PatchOutput& p) { return p.force.Y; }},
    {"Q", "N", "force of the patch perpendicular to the track plane, positive upward",
     [](const dynamics::PatchOutput& p) { return p.force.Q; }},
    {"y_track", "N", "lateral force of the patch on the wheel, positive to the left",
     [](const dynamics::PatchOutput& p) { return p.force.y_track; }},
    {"t_gamma", "N", "wear number T gamma = |fx sx| + |fy sy| + |mz spin|",
     [](const dynamics::PatchOutput& p) { return p.t_gamma; }},
    {"power", "W", "power dissipated in the patch, T gamma V",
     [](const dynamics::PatchOutput& p) { return p.power; }},
};

// Per rail of a side with further rails (profiles.extra_rails), /contact/<wheelset>/<side>/rails/
// <rail>/<name>: the wheel's contact with that rail (zeros where it does not touch it), for the
// load transfer between rails (stock rail to blade, wing rail to nose) and Y/Q on a blade.
inline constexpr ChannelRow<dynamics::RailContactOutput> kRailChannels[] = {
    {"normal_force", "N", "normal force of the wheel's patches on this rail (0: no contact)",
     [](const dynamics::RailContactOutput& r) { return r.normal; }},
    {"y", "m",
     "lateral track-frame position of the strongest patch on this rail, positive to the left (0: "
     "no contact)",
     [](const dynamics::RailContactOutput& r) { return r.y; }},
    {"x", "m",
     "longitudinal position of the strongest patch on this rail from the axle, positive forward "
     "(ahead of the axle on a rail that rises)",
     [](const dynamics::RailContactOutput& r) { return r.x; }},
    {"X", "N", "longitudinal force of this rail on the wheel, track frame",
     [](const dynamics::RailContactOutput& r) { return r.force.X; }},
    {"Y", "N", "lateral force of this rail on the wheel, positive toward the track centre",
     [](const dynamics::RailContactOutput& r) { return r.force.Y; }},
    {"Q", "N", "force of this rail on the wheel perpendicular to the track plane, upward",
     [](const dynamics::RailContactOutput& r) { return r.force.Q; }},
    {"y_over_q", "-", "Y/Q of this rail's forces alone (0 where Q = 0)",
     [](const dynamics::RailContactOutput& r) {
       return std::abs(r.force.Q) > 0.0 ? r.force.Y / r.force.Q : 0.0;
     }},
    {"creepage_x", "-", "longitudinal creepage of the strongest patch on this rail",
     [](const dynamics::RailContactOutput& r) { return r.sx; }},
    {"creepage_y", "-", "lateral creepage of the strongest patch on this rail",
     [](const dynamics::RailContactOutput& r) { return r.sy; }},
    {"spin", "1/m", "spin creepage of the strongest patch on this rail",
     [](const dynamics::RailContactOutput& r) { return r.spin; }},
    {"t_gamma", "N", "wear number T gamma, sum over the patches on this rail",
     [](const dynamics::RailContactOutput& r) { return r.t_gamma; }},
};

// Per wheel on the track under the rail (contact.elastic.rail_support),
// /contact/<wheelset>/<side>/track/<name>.
inline constexpr ChannelRow<dynamics::WheelOutput> kTrackChannels[] = {
    {"rail_y", "m", "lateral displacement of the rail mass under the wheel (left +)",
     [](const dynamics::WheelOutput& w) { return w.rail_mass_y; }},
    {"rail_z", "m", "vertical displacement of the rail mass under the wheel (up +)",
     [](const dynamics::WheelOutput& w) { return w.rail_mass_z; }},
    {"support_force_y", "N", "lateral force of the support on the rail mass (left +)",
     [](const dynamics::WheelOutput& w) { return w.support_force_y; }},
    {"support_force_z", "N", "vertical force of the support on the rail mass (up +)",
     [](const dynamics::WheelOutput& w) { return w.support_force_z; }},
};

inline constexpr std::size_t kWheelChannelCount = std::size(kWheelChannels);
inline constexpr std::size_t kTrackChannelCount = std::size(kTrackChannels);
inline constexpr std::size_t kRailChannelCount = std::size(kRailChannels);
inline constexpr std::size_t kPatchChannelCount = std::size(kPatchChannels);

// One body's coordinates and absolute centre-of-mass acceleration at an output time.
struct BodySample {
  const vehicle::Vector6d& q;
  const Eigen::Vector3d& a;
};

// Per body, /bodies/<body>/<name>: the coordinates of the body's track frame (vehicle::kCoordNames
// order, paper Eq. 1-2) and, with run.output.body_accelerations, its acceleration.
inline constexpr ChannelRow<BodySample> kBodyCoordChannels[] = {
    {vehicle::kCoordNames[0], "m", "arc length of the body's track frame along the track",
     [](const BodySample& b) { return b.q[0]; }},
    {vehicle::kCoordNames[1], "m", "lateral displacement in the track frame, positive to the left",
     [](const BodySample& b) { return b.q[1]; }},
    {vehicle::kCoordNames[2], "m", "vertical displacement in the track frame",
     [](const BodySample& b) { return b.q[2]; }},
    {vehicle::kCoordNames[3], "rad", "roll angle relative to the track frame",
     [](const BodySample& b) { return b.q[3]; }},
    {vehicle::kCoordNames[4], "rad", "pitch angle relative to the track frame",
     [](const BodySample& b) { return b.q[4]; }},
    {vehicle::kCoordNames[5], "rad", "yaw angle relative to the track frame",
     [](const BodySample& b) { return b.q[5]; }},
};
inline constexpr ChannelRow<BodySample> kBodyAccelerationChannels[] = {
    {"ax", "m/s^2", "absolute centre-of-mass acceleration, body track-frame x",
     [](const BodySample& b) { return b.a[0]; }},
    {"ay", "m/s^2", "absolute centre-of-mass acceleration, body track-frame y",
     [](const BodySample& b) { return b.a[1]; }},
    {"az", "m/s^2", "absolute centre-of-mass acceleration, body track-frame z",
     [](const BodySample& b) { return b.a[2]; }},
};

// Per connection of a train, /train/connections/<front>-<rear>/<name>.
inline constexpr ChannelRow<train::ConnectionState> kConnectionChannels[] = {
    {"gap", "m", "gap between the buffer faces on the centre line (< 0: buffers pressed)",
     [](const train::ConnectionState& c) { return c.gap; }},
    {"force", "N", "longitudinal force of the connection: draw gear - buffers (tension > 0)",
     [](const train::ConnectionState& c) { return c.longitudinal; }},
    {"buffer_left", "N", "compressive force of the left buffer pair",
     [](const train::ConnectionState& c) { return c.buffer_left; }},
    {"buffer_right", "N", "compressive force of the right buffer pair",
     [](const train::ConnectionState& c) { return c.buffer_right; }},
    {"draw_gear", "N",
     "axial force of the draw gear or coupler (tension > 0, a coupler pressed < 0)",
     [](const train::ConnectionState& c) { return c.draw_gear; }},
    {"coupler_angle_front", "rad",
     "angle of the coupler link to the front car body's axis (left > 0; 0 without a coupler)",
     [](const train::ConnectionState& c) { return c.angle_front; }},
    {"coupler_angle_rear", "rad", "angle of the coupler link to the rear car body's axis",
     [](const train::ConnectionState& c) { return c.angle_rear; }},
    {"lateral_front", "N",
     "lateral force of the connection on the front car body, its track frame (left > 0)",
     [](const train::ConnectionState& c) { return c.lateral_front; }},
    {"lateral_rear", "N", "lateral force of the connection on the rear car body, its track frame",
     [](const train::ConnectionState& c) { return c.lateral_rear; }},
};

// Per vehicle of a train whose motion is a state, /vehicles/<name>/motion/<name>.
inline constexpr ChannelRow<train::VehicleMotion> kMotionChannels[] = {
    {"travel", "m", "distance travelled from vehicle.start",
     [](const train::VehicleMotion& m) { return m.travel; }},
    {"speed", "m/s", "speed along the track",
     [](const train::VehicleMotion& m) { return m.speed; }},
    {"acceleration", "m/s^2", "acceleration along the track",
     [](const train::VehicleMotion& m) { return m.acceleration; }},
    {"traction", "N", "traction (> 0) or braking (< 0) force",
     [](const train::VehicleMotion& m) { return m.traction; }},
    {"resistance", "N", "running resistance (Davis)",
     [](const train::VehicleMotion& m) { return m.resistance; }},
    {"grade_force", "N", "the weight's component along the track (uphill > 0)",
     [](const train::VehicleMotion& m) { return m.grade; }},
    {"connection_force", "N", "the connections' force along the track on the vehicle",
     [](const train::VehicleMotion& m) { return m.connections; }},
    {"rail_force", "N",
     "the wheel/rail contact forces along the track (with traction_at = \"wheelsets\"; else 0)",
     [](const train::VehicleMotion& m) { return m.rail; }},
};

}  // namespace rb::run
