#pragma once
// Vehicle dynamics with wheel/rail contact (paper sections 2.3-2.5 and 3; the
// formulation is derived in docs/contact_dynamics.md).
//
// Imposed motion: every body's arc length s_i = start + x_i + V0 t + a t^2 / 2 (VehicleModel::
// bodyS; speed V(t) = V0 + a t, as the guided model; the reaction on s is the traction; the
// inertia of sddot = a enters every free equation as -M_ps a). Frames are fixed in their track
// frames. Car bodies and bogies are free in (y, z, phi, theta, psi). Wheelsets are free in y
// (lateral), theta (spin) and psi (yaw); their height z and roll phi are DEPENDENT coordinates
// given by the contact constraints at every evaluation:
//   KEC (Eq. 22): x = (z, phi, s_lk, s_rk) = solveKec(y, y_lir, y_rir, z_lir, z_rir), warm-started;
//   LUT (Eq. 17-18): z = z_clt(y - xi_a, xi_g) + xi_v, phi = phi_clt(y - xi_a, xi_g) + xi_c/(2 Lr).
// Velocities and accelerations of z and phi follow by coordinate partitioning (KEC: xdot = dx_dp
// pdot, xddot = dx_dp pddot + kecQuadraticTerm; LUT: chain rule with the table's first and second
// derivatives), so every integrator integrates an ODE in the independent coordinates only (no
// drift, no stabilisation).
//
// Per wheelset, with q = (y, z, phi, theta, psi) and s prescribed (sddot = a):
//   [ M   -N ] [qddot ]   [ Q - M_qs a + Q_t (+ Q_fla for LUT) ]
//   [ G    0 ] [lambda] = [ gamma                     ]
// G qddot = gamma are the acceleration-level constraints on z and phi. KEC: N (Eq. 25) holds the
// generalised directions of the two normal contact forces at the real contact points (in the
// regularised tread-flange band: (1 - w) at A plus w at B, Eq. 26), lambda = the normal forces of
// the left and right wheel. LUT: N = -G^T (Eq. 16, 19: Q_tre = -C_q^T lambda), lambda the
// multipliers of the z and phi constraints; the wheel normal forces follow from lambda through the
// 2x2 map of their z and roll components (docs); the flange is an applied Hertz force (Eq. 20-21).
// The planar contact picture (normals, contact frames) turns with the wheelset yaw, so normal
// forces do no work on yaw and spin (the constraints do not depend on them).
// Tangential forces (section 2.5) from the creepages at every patch, with the normal forces of the
// previous evaluation (Lagged, the paper; internal::NormalForceMemory) or solved together with
// them at every evaluation (Consistent: fixed-point iteration, Newton on the 2 normal forces when
// it contracts slowly). The evaluation's stages are listed in contact_stages.hpp.
//
// State layout: vehicle::VehicleLayout (workbench/vehicle/layout.hpp) with ws_dof = 3 wheelset
// coordinates (y, theta, psi) with a free spin, 2 (y, psi) with a prescribed spin.
// With a prescribed spin theta = travel(t) / r_c, theta_dot = V(t) / r_c (r_c =
// ContactModel::centredRadius()) are set kinematically and the spin row of the wheelset's
// equations is replaced by theta_ddot = a / r_c (its reaction, the spin torque, is not applied).
//
// rhs() is allocation-free and returns 1 (recoverable) when the KEC solver does not converge, a
// knife or the LUT entry leaves the table, the augmented system is singular or a value is not
// finite; lastError() names the wheelset, the time and the cause. Outputs are computed on demand
// (wheelOutputs, bodyCoordinates, bodyAccelerations, elementOutputs) without changing the state the
// integration depends on.
#include <Eigen/Dense>
#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "workbench/dynamics/contact_model.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/dynamics.hpp"
#include "workbench/vehicle/layout.hpp"
#include "workbench/vehicle/model.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::dynamics {

// The layout of a vehicle on wheel/rail contact (ws_dof = 3 with a free spin, 2 prescribed; the
// elastic method adds z and phi: 5 and 4; rail_masses: the track under the rail's states).
vehicle::VehicleLayout contactLayout(const vehicle::VehicleModel& model,
                                     WheelsetSpin spin = WheelsetSpin::Free,
                                     ContactMethod method = ContactMethod::Kec,
                                     bool rail_masses = false);

// Wheel/rail forces in the track frame (EN 14363 Y and Q): components of the force of the rail on
// the wheel in the wheelset's track frame (Eq. 1-2: x along the track, y to the left, z up, turned
// by the design cant, without the cross-level rotation of the irregularities), so y lies in the
// track plane and z is perpendicular to it.
//   X  longitudinal, positive forward;
//   Q  perpendicular to the track plane, positive upward on the wheel (the wheel load);
//   Y  in the track plane, positive toward the track centre on either wheel (EN 14363: positive
//      when it pushes the flange away from its rail), Y = -sigma y_track;
//   y_track  the same lateral component, positive to the left on both wheels (sums per wheelset:
//      the track-shifting force of a wheelset is the sum of y_track over its wheels).
struct TrackForces {
  double X = 0.0, Y = 0.0, Q = 0.0, y_track = 0.0;  // [N]
};

// One contact patch of a wheel. Creep forces act on the wheel in the patch's contact frame:
// x along the track (rolling direction), n the rail normal (into the wheel), y = n x x.
struct PatchOutput {
  bool active = false;
  bool on_flange = false;                 // the wheel point lies in the flange window
  double normal = 0.0;                    // [N] normal force (< 0: the constraint pulls, lift)
  double fx = 0.0, fy = 0.0;              // [N] creep forces on the wheel
  double mz = 0.0;                        // [N m] spin moment (kalker, fastsim; 0 with polach)
  double sx = 0.0, sy = 0.0, spin = 0.0;  // creepages [-], [-], [1/m]
  double s_w = 0.0, s_r = 0.0;            // [m] contact point on the wheel and rail profiles
  double gamma = 0.0;                     // [rad] contact angle (positive toward the centre)
  double radius = 0.0;                    // [m] rolling radius at the contact point
  double a = 0.0, b = 0.0;                // [m] Hertz semi-axes (rolling, lateral)
  // Contact angle of the normal in the track frame: gamma turned by the rails' cross-level angle
  // (Eq. 5), positive toward the centre; with it Q = N cos + sigma fy sin exactly (any yaw).
  double gamma_track = 0.0;  // [rad]
  double y = 0.0;            // [m] lateral track-frame position of the contact point (left +)
  TrackForces force;         // normal and creep forces of this patch, track frame
  // Wear number T gamma = |fx sx| + |fy sy| + |mz spin| [N] (the spin term only where the law
  // gives mz: kalker, fastsim) and the power it dissipates, T gamma V [W].
  double t_gamma = 0.0, power = 0.0;
};

// A wheel's contact with one rail of its side (elastic contact on several rails): the sums over
// the wheel's patches on that rail, and the strongest one's position and creepages.
struct RailContactOutput {
  double normal = 0.0;      // [N] normal force, sum over the rail's patches
  double normal_max = 0.0;  // [N] the strongest patch's
  double x = 0.0, y = 0.0;  // [m] its contact point: along the track from the axle, and the
                            // lateral track-frame position (left +)
  TrackForces force;        // sum of the rail's patches' forces (EN 14363 X, Y, Q, y_track)
  double sx = 0.0, sy = 0.0, spin = 0.0;  // [-], [-], [1/m] the strongest patch's creepages
  double t_gamma = 0.0;                   // [N] wear number, sum over the rail's patches
};

// Contact regime of a wheel, from the patches in contact: WheelOutput::regime holds its code.
enum class ContactRegime { Tread = 0, TwoPoint = 1, Flange = 2 };

// Why the contact vehicle refused an evaluation (ContactVehicleOde::lastFailure, the result
// file's /stats failure_reason); names in dynamics/names.hpp.
enum class ContactFailure {
  None,
  WheelLift,        // a wheel's constraint normal force below contact.min_normal_force
  Derailment,       // elastic: a wheel rose or dropped beyond contact.elastic.derailment_lift
  TableRange,       // the contact point left its table (KEC, LUT)
  ConstraintSolve,  // the KEC constraints (Eq. 22) were not solved
  Coupling,         // the normal/tangential coupling did not converge
  BodyRotation,     // a body's pitch angle reached the Euler-angle guard
  Singular,         // a mass or constraint matrix could not be factored
  NonFinite,        // the solution of a wheelset is not finite
};

// The regime's code of a wheel with patches on the tread and/or on the flange (tread when none).
constexpr int contactRegime(bool tread, bool flange) {
  return static_cast<int>(flange ? (tread ? ContactRegime::TwoPoint : ContactRegime::Flange)
                                 : ContactRegime::Tread);
}

// Contact of one wheel at an output time.
struct WheelOutput {
  // KEC: outside a regularised band the single contact point; inside it A (the field-side end,
  // weight 1 - w) and B (the flange-side end, weight w), Eq. (26). LUT: the tread contact (patch
  // 0) and the Hertz flange contact when delta > 0 (patch 1).
  PatchOutput patch[2];
  double normal = 0.0;              // [N] sum over the patches
  double normal_tread = 0.0;        // [N] patches on the tread
  double normal_flange = 0.0;       // [N] patches on the flange
  int regime = 0;                   // 0 tread only, 1 two-point (tread and flange), 2 flange only
  double weight = 0.0;              // KEC: weight w of B in a regularised band (Eq. 26), else 0
  double flange_indentation = 0.0;  // [m] LUT flange delta (Eq. 21), > 0 penetration (KEC: 0)
  double flange_force = 0.0;        // [N] LUT Hertz flange force (Eq. 20)
  double force_y = 0.0, force_z = 0.0;  // [N] resultant contact force on the wheel (normal +
                                        // tangential, all patches), track-frame Y and Z
  TrackForces force;      // the resultant in EN 14363 terms: the sum of the patches' forces
  double y_over_q = 0.0;  // derailment quotient Y/Q (EN 14363) of `force`
  bool lift = false;      // a constraint normal force is negative (wheel lift, not modelled)
  // Active patches (elastic: every patch of the wheel, patch[0] its strongest tread patch,
  // patch[1] its strongest flange patch, the totals sum all of them), the rise of its tape circle
  // above the centred height over its rail (every method), and whether that passed the elastic
  // method's derailment lift.
  int patch_count = 0;
  double wheel_lift = 0.0;  // [m]
  bool derailed = false;
  double creep_x = 0.0, creep_y = 0.0;  // [N] creep forces summed over the patches
  // Elastic contact on several rails (profiles.extra_rails): per rail (0 the running rail, k the
  // k-th further rail), RailContactOutput (all 0 where the wheel does not touch the rail).
  std::array<RailContactOutput, 1 + kMaxExtraRails> rail{};
  // The track under the rail (contact.elastic.rail_support): the rail mass's displacement under
  // the wheel (lateral, vertical; track frame) and the force of its support on it.
  double rail_mass_y = 0.0, rail_mass_z = 0.0;          // [m]
  double support_force_y = 0.0, support_force_z = 0.0;  // [N]
};

// Work counters (since construction or resetStats()).
struct ContactStats {
  long evaluations = 0;            // model evaluations (rhs and outputs)
  long shared_evaluations = 0;     // rhs calls served by the observer's evaluation (outputs())
  long kec_iterations = 0;         // Newton iterations of solveKec, summed
  long consistent_solves = 0;      // wheelset solves with NormalForceCoupling::Consistent
  long consistent_iterations = 0;  // fixed-point iterations, summed over those solves
  int consistent_max_iterations = 0;
  long lift_evaluations = 0;       // evaluations in which some wheel had a negative normal force
  double max_lagged_change = 0.0;  // [N] largest |lambda - lambda_previous| seen (Lagged)
  long elastic_searches = 0;       // elastic contact: wheel searches
  long elastic_patches = 0;        // elastic contact: patches found, summed over the searches
  int elastic_max_patches = 0;     // elastic contact: most patches on one wheel
};

namespace internal {
struct ContactWorkspace;
enum class EvalMode;
}  // namespace internal

class ContactVehicleOde final : public vehicle::VehicleOde {
 public:
  // Keeps references: all three must outlive this object.
  ContactVehicleOde(const vehicle::VehicleModel& vehicle, const ContactModel& contact,
                    const track::TrackModel& track);

  int rhs(double t, const double* y, double* ydot) override;
  std::string lastError() const override;
  integ::ModelFailure lastFailure() const override;

  const ContactModel& contact() const { return *contact_; }

  // State at t0: wheelsets centred (y = 0, psi = 0, theta = 0; z, phi from the constraints), spin
  // rate V / r_c (r_c: mean rolling radius of the centred wheelset), car bodies and bogies in
  // static (on a curve: quasi-static) equilibrium on their suspension (vehicle::
  // solveStaticEquilibrium, as GuidedVehicleOde::initialState), series forces 0. Initialises the
  // normal forces (consistent solve) used by the Lagged coupling at the first step, so the normal
  // forces at t0 are the static wheel loads. Throws rb::InputError when no equilibrium is found.
  Eigen::VectorXd initialState(double t0) override;
  // The static equilibrium again from y (after initialState at the same t0), with the positions
  // `held` (state indices: offsets of vehicle.initial) kept where y has them: every other
  // coordinate initialState solves settles around them (on elastic contact a wheelset pushed
  // sideways rises or sinks on its profiles instead of starting in the rail or above it). Throws
  // rb::InputError as initialState.
  void settle(double t0, Eigen::VectorXd& y, std::span<const int> held);

  // Outputs at (t, y), evaluated on demand; they do not change what the integration sees (the
  // Lagged normal-force memory is kept). Return 0, or the rhs error code.
  // Full coordinates (s, y, z, roll, pitch, yaw) of every body, q.size() == bodies.
  int bodyCoordinates(double t, const double* y, std::span<vehicle::Vector6d> q) override;
  // Two entries per wheelset, in wheelset order: [2w] left, [2w + 1] right.
  int wheelOutputs(double t, const double* y, std::span<WheelOutput> out);
  // Accelerations (sddot = a, y, z, roll, pitch, yaw) of every body, qdd.size() == bodies; for
  // wheelsets z and roll are the constraint accelerations (G qddot = gamma).
  int bodyAccelerations(double t, const double* y, std::span<vehicle::Vector6d> qdd) override;
  // wheelOutputs and bodyAccelerations from one evaluation (the same values as the two calls).
  // With shareOutputEvaluations on, that evaluation is also the integrator's next right-hand side
  // at (t, y) (see there).
  int outputs(double t, const double* y, std::span<WheelOutput> wheels,
              std::span<vehicle::Vector6d> qdd);
  // For a fixed-step integrator observed at its step ends: its next rhs call is at the observed
  // state (RK4's and ABM's first evaluation of a step), so outputs() evaluates that rhs there and
  // then, for the observer, and rhs() returns it (the same bits: the same memory, the same
  // warm-started solves) instead of evaluating the state a second time. A state the integrator
  // does not evaluate next must not be observed this way: its rhs would move the normal-force
  // memory where the integration never was. Off by default.
  void shareOutputEvaluations(bool on);
  // Element values of a full evaluation at (t, y); NaN force and deflection when it fails.
  int elementOutputs(double t, const double* y, std::span<const vehicle::ElementId> ids,
                     std::span<vehicle::ElementValue> out) override;
  // Vehicle workspace of the last evaluation (element values, forces).
  const vehicle::Workspace& workspace() const override;
  double railForce() const override;

  const ContactStats& stats() const;
  void resetStats();

  ~ContactVehicleOde() override;
  ContactVehicleOde(ContactVehicleOde&&) noexcept;

 protected:
  vehicle::Workspace& bodyWorkspace() override;
  // The right-hand side kept by outputs() was made with the old train inputs.
  void inputsChanged() override;

 private:
  int evaluate(double t, const double* y, double* ydot, internal::EvalMode mode);
  int setCoordinates(double t, const double* y);
  // The evaluation, compiled for each contact method and creep law (chosen once, in the
  // constructor: no per-patch branch on the law; creep "none" compiles the creep code out).
  template <ContactMethod kMethod, class Law>
  int evaluateT(double t, const double* y, double* ydot, internal::EvalMode mode);
  using EvalFn = int (ContactVehicleOde::*)(double, const double*, double*, internal::EvalMode);
  // The elastic method's evaluation for a creep law (contact_ode_elastic.cpp).
  static EvalFn elasticEvaluation(CreepModel creep);
  // The static equilibrium of the coordinates `unknowns` (state indices) at t0 from y, then the
  // consistent normal forces there and the check that no wheel lifts.
  void solveEquilibrium(double t0, Eigen::VectorXd& y, const std::vector<int>& unknowns);

  const ContactModel* contact_;
  const track::Irregularities* irr_ = nullptr;
  std::unique_ptr<internal::ContactWorkspace> work_;
  EvalFn eval_ = nullptr;
  bool share_outputs_ = false;
  std::vector<int> equilibrium_unknowns_;  // what initialState solved (settle solves them again)
};

}  // namespace rb::dynamics
