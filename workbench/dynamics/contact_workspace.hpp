#pragma once
// The data of one ContactVehicleOde evaluation, shared by its stages (contact_stages.hpp): the
// models it reads (ContactModels), the inputs of the evaluation (StageInput) and the workspace the
// stages fill (ContactWorkspace, per wheelset WheelsetWork). Internal to workbench/dynamics.
#include <Eigen/Dense>
#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "workbench/contact/elastic_search.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"
#include "workbench/contact/rail_slope.hpp"
#include "workbench/creep/creepages.hpp"
#include "workbench/creep/hertz.hpp"
#include "workbench/dynamics/contact_model.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/track/irregularities.hpp"
#include "workbench/vehicle/dynamics.hpp"
#include "workbench/vehicle/layout.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::dynamics::internal {

using Vec5 = Eigen::Matrix<double, 5, 1>;
using Vec7 = Eigen::Matrix<double, 7, 1>;

// Rhs: a right-hand side for the integrator. Output: outputs at an accepted state (they do not
// change what the integration sees). Init: the initial state (consistent normal forces even with
// the Lagged coupling). RhsOutput: the integrator's next right-hand side, evaluated early for the
// observer of the state it starts from: an Rhs evaluation in every respect (normal-force memory,
// wheel-lift refusal, derailment) that also fills the outputs (ContactVehicleOde::outputs).
enum class EvalMode { Rhs, Output, Init, RhsOutput };

// Whether an evaluation in `mode` fills the wheel outputs and body accelerations.
constexpr bool fillsOutputs(EvalMode mode) {
  return mode == EvalMode::Output || mode == EvalMode::RhsOutput;
}

// What the stages read: the models (const for the whole run).
struct ContactModels {
  const vehicle::VehicleModel& vehicle;
  const ContactModel& contact;
  const vehicle::VehicleLayout& layout;
  const track::Irregularities* irregularities;  // null on a perfect track
};

// The inputs of one evaluation.
struct StageInput {
  double t = 0.0;
  const double* y = nullptr;
  double speed = 0.0;         // [m/s] V(t)
  double acceleration = 0.0;  // [m/s^2] a = sddot of every body
  EvalMode mode = EvalMode::Rhs;
  double travel = 0.0;  // [m] distance from vehicle.start: s of body b = start + x_b + travel
};

// One contact patch of a wheel during an evaluation.
struct Patch {
  bool active = false;
  bool on_flange = false;  // wheel point in the flange window
  double q0 = 0.0;         // normal force Q = q0 + ql . lambda
  Eigen::Vector2d ql = Eigen::Vector2d::Zero();
  double s_w = 0.0, s_r = 0.0, gamma = 0.0, radius = 0.0;
  Eigen::Vector3d n = Eigen::Vector3d::UnitZ();   // rail normal into the wheel (track comps)
  Eigen::Vector3d ex = Eigen::Vector3d::UnitX();  // rolling direction (wheel x, yawed)
  Eigen::Vector3d ey = Eigen::Vector3d::UnitY();  // lateral tangent n x e_x
  Vec5 gn = Vec5::Zero();  // generalised direction of a unit normal force (y, z, phi, theta, psi)
  Vec5 gx = Vec5::Zero(), gy = Vec5::Zero(), gm = Vec5::Zero();  // creep fx, fy, spin moment
  creep::Creepages cr;
  creep::RelativeCurvatures k;
  creep::HertzShape shape;
  creep::PatchConstants pc;  // load-independent patch data, once per setupPatch (not per Q)
  // The curvatures (wheel long., wheel trans., rail trans.) k, shape and pc were computed from;
  // k, shape, pc are functions of them alone (the KEC transition-band points repeat them).
  double k_key[3] = {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0};
  double Q = 0.0, fx = 0.0, fy = 0.0, mz = 0.0, a = 0.0, b = 0.0;

  // Normal force of the patch at the normal-force multipliers lambda.
  double normalAt(const Eigen::Vector2d& lambda) const { return q0 + ql.dot(lambda); }
};

// The normal-force multipliers lambda of a wheelset remembered from one evaluation to the next:
// the Lagged coupling (paper section 2.5) evaluates the creep forces at them, the Consistent one
// starts its fixed-point iteration from them.
// Update rule: every Rhs and Init evaluation of a creep law that reaches the normal/tangential
// coupling stage remembers the lambda it solved for (even when the solution is then refused as
// non-finite or as a wheel lift); Output evaluations never change it (outputs must not change what
// the integration sees); a Consistent iteration that does not converge leaves it unchanged;
// initialState forgets it before its Newton iteration and again before its final evaluation.
// The Consistent coupling also remembers its estimate of the Jacobian d Phi / d lambda of the
// fixed-point map (same update rule, from the Consistent solves only): the creep forces change
// little between evaluations, so it makes the first step of the next solve a near-Newton step.
struct NormalForceMemory {
  Eigen::Vector2d lambda = Eigen::Vector2d::Zero();
  bool valid = false;
  Eigen::Matrix2d jacobian = Eigen::Matrix2d::Zero();  // d Phi / d lambda
  bool jacobian_valid = false;

  void remember(const Eigen::Vector2d& solved) {
    lambda = solved;
    valid = true;
  }
  void rememberJacobian(const Eigen::Matrix2d& j) {
    jacobian = j;
    jacobian_valid = true;
  }
  void forget() { valid = jacobian_valid = false; }
};

// KEC transition bands: a real contact point A or B of the last describe() and its inputs. Inside
// one transition A and B are the fixed end points of the band (the table's Hermite data of SwA ...
// SrB are constant there), so successive evaluations mostly ask for the same points again; equal
// inputs give equal outputs, so the reuse changes nothing.
struct DescribedPoint {
  double s_w = std::numeric_limits<double>::quiet_NaN(), s_r = 0.0;
  contact::ContactPoint point;
};

// Elastic contact, one wheel: the search's patches (deepest first) and the wheel's lift.
// The rail of one side at the wheelset: its displacement (irregularity, and the offsets of a
// sliced rail) and its slope along the track.
struct RailOffset {
  double y = 0.0, z = 0.0;      // [m]
  double y_s = 0.0, z_s = 0.0;  // [-] d/ds
  double blend_s = 0.0;         // [1/m] d(blend)/ds of a rail changing along the track
  double vy = 0.0, vz = 0.0;    // [m/s] velocity of the rail mass under the wheel (track support)
};

struct ElasticWheelWork {
  contact::ElasticSearchWorkspace search;  // the search's scratch, per wheel (successive poses)
  contact::ElasticWheelGeometry geometry;  // every patch of the wheel, on every rail
  // Further rails (ElasticContactModel::extra): a search workspace and result per rail, and the
  // rail of each patch of `geometry` (0 the running rail, k the k-th further rail) with that
  // rail's displacement.
  std::array<contact::ElasticSearchWorkspace, kMaxExtraRails> extra_search;
  // The second search over a rail that rises or moves sideways along the track (rail_slope.hpp),
  // per rail (0 the running rail).
  std::array<contact::SlopedSearchWorkspace, 1 + kMaxExtraRails> sloped_search;
  contact::ElasticWheelGeometry extra_geometry;
  std::array<int, contact::kMaxElasticPatches> patch_rail{};
  std::array<RailOffset, 1 + kMaxExtraRails> rail_offset{};
  std::array<Patch, contact::kMaxElasticPatches> patch;
  double lift = 0.0;  // [m] rise of the wheel's tape circle above its centred height over its rail
  // The track under the rail (ElasticContactModel::support): the rail mass's displacement and
  // rate (y, z), the force of the wheel on it and of its support, and its acceleration.
  double rail_q[2] = {0.0, 0.0}, rail_qd[2] = {0.0, 0.0};
  double wheel_force[2] = {0.0, 0.0}, support_force[2] = {0.0, 0.0}, rail_qdd[2] = {0.0, 0.0};
};

// Per wheelset: the constraints, patches and normal forces of the evaluation.
struct WheelsetWork {
  std::size_t body = 0;
  // The contact model of this wheelset's wheels (ContactModel::forWheelset): its profiles'
  // tables, centred pose and radii, and elastic searches. Set once, with the workspace.
  const ContactModel* contact = nullptr;
  double height = 0.0;  // nominal centre height h (body z = contact z - h)
  // Contact constraints at this evaluation.
  contact::KecSolution kec;
  bool kec_warm = false;
  contact::LutSample lut;
  double delta_irr = 0.0;               // cross-level angle of the irregular rails [rad]
  double cos_irr = 1.0, sin_irr = 0.0;  // its cosine and sine
  // Irregularities at s = irr_key (the stages of a step at one time share them).
  track::IrregularityPoint irr;
  double irr_key = std::numeric_limits<double>::quiet_NaN();
  // LUT: rates of the table entry (y - xi_a, xi_g) (Eq. 18) and of the table's z and phi.
  double ybar_dot = 0.0, xig_dot = 0.0, zbar_dot = 0.0, phibar_dot = 0.0;
  double lut_ybar = 0.0, lut_xig = 0.0;  // the LUT entry of `lut`
  // LUT, per wheel: its tread contact point on both sides of a contact-point jump in the table
  // cell of the entry (LutTable::treadBranches), and whether the wheel's constraint normal force
  // is split between them (tread patches in slots 0 and 1; lutNormalMap).
  contact::LutTreadBranches lut_branches[2];
  bool lut_split[2] = {false, false};
  DescribedPoint described[2][2];  // [side][0 A, 1 B]
  // Acceleration-level constraints G qddot = gamma on z and phi.
  Eigen::Matrix<double, 2, 5> G = Eigen::Matrix<double, 2, 5>::Zero();
  Eigen::Vector2d gamma = Eigen::Vector2d::Zero();
  // Patches [side][0 tread / A, 1 flange / B] and per-wheel data.
  Patch patch[2][2];
  int regime[2] = {0, 0};
  double weight[2] = {0.0, 0.0};
  double fl_delta[2] = {0.0, 0.0}, fl_force[2] = {0.0, 0.0};
  Vec5 q_flange = Vec5::Zero();  // LUT: generalised Hertz flange forces (Eq. 20)
  // Generalised directions of the normal-force multipliers (Eq. 25; LUT: -G^T, Eq. 16).
  Eigen::Matrix<double, 5, 2> N = Eigen::Matrix<double, 5, 2>::Zero();
  Eigen::Vector2d lambda = Eigen::Vector2d::Zero();  // the normal-force multipliers solved for
  NormalForceMemory memory;
  ElasticWheelWork elastic[2];  // elastic contact method: [side]
};

// Everything an evaluation writes.
struct ContactWorkspace {
  vehicle::Workspace bodies;            // full coordinates, mass matrices, forces
  std::vector<WheelsetWork> wheelsets;  // in wheelset order
  std::vector<WheelOutput> wheels;      // [2w + side], filled by Output evaluations
  std::vector<vehicle::Vector6d> qdd;   // body accelerations of the last Output evaluation
  std::vector<double> scratch;          // ydot of output and initial-state evaluations
  // Sum over the wheelsets of the contact forces' component along the track [N] (track-frame x:
  // creep and normal forces), for the longitudinal equation of a train; evaluated only when a
  // train sets the forward motion (bodies.motion).
  double rail_force = 0.0;
  // The right-hand side of a RhsOutput evaluation at (next_t, next_y), kept for the integrator's
  // next call (ContactVehicleOde::rhs) when it is at the same state, bit for bit.
  bool next_valid = false;
  double next_t = 0.0;
  std::vector<double> next_y, next_ydot;
  ContactStats stats;
  // Initial-state evaluations do not refuse a negative constraint normal force (the equilibrium
  // iteration's trial states may unload a wheel that the equilibrium loads): they record the
  // wheels [2w + side] that had one, and their forces [N], for the check of the equilibrium.
  std::vector<std::pair<int, double>> init_lifts;
  std::string error;                              // why the last evaluation failed
  ContactFailure failure = ContactFailure::None;  // the same as a code
  std::string failure_body;                       // the body it concerns

  // The failure of this evaluation: its code, its body and its message.
  void fail(ContactFailure why, const std::string& body, std::string message) {
    failure = why;
    failure_body = body;
    error = std::move(message);
  }

  WheelsetWork& wheelset(int w) { return wheelsets[static_cast<std::size_t>(w)]; }
};

}  // namespace rb::dynamics::internal
