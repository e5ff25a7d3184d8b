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
// previous evaluation (Lagged, the paper) or solved together with them at every evaluation
// (Consistent: fixed-point iteration, Newton on the 2 normal forces when it contracts slowly).
//
// State layout (nf free bodies in body order, nw wheelsets in body order, ns series dampers, d = 3
// wheelset coordinates with a free spin, 2 with a prescribed spin; size 10 nf + 2 d nw + ns):
//   [5k + c]                  position c (0..4: y, z, phi, theta, psi) of free body k  "car.y"
//   [5 nf + d w + j]          wheelset w: j = 0 y, 1 theta (spin, free only), 2 (or 1) psi
//                                                                         "ws1.y", "ws1.theta"
//   [5 nf + d nw + 5k + c]    rate of free body coordinate                              "car.y_dot"
//   [10 nf + d nw + d w + j]  wheelset rate                                        "ws1.theta_dot"
//   [10 nf + 2 d nw + e]      Maxwell force of series damper e                      "series[3].f"
// ContactLayout::wsPosition(w, c) / wsRate(w, c) take c = 0 y, 1 theta, 2 psi in both cases.
// With a prescribed spin theta = travel(t) / r_c, theta_dot = V(t) / r_c (r_c =
// ContactModel::centredRadius()) are set kinematically and the spin row of the wheelset's
// equations is replaced by theta_ddot = a / r_c (its reaction, the spin torque, is not applied).
//
// rhs() is allocation-free and returns 1 (recoverable) when the KEC solver does not converge, a
// knife or the LUT entry leaves the table, the augmented system is singular or a value is not
// finite; lastError() names the wheelset, the time and the cause. Outputs are computed on demand
// (wheelOutputs, bodyCoordinates) without changing the state the integration depends on.
#include <Eigen/Dense>
#include <span>
#include <string>
#include <vector>

#include "workbench/dynamics/contact_model.hpp"
#include "workbench/integrators/ode.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/dynamics.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::dynamics {

struct ContactLayout {
  std::vector<int> free_bodies;  // car bodies and bogies, body order
  std::vector<int> wheelsets;    // wheelsets, body order
  std::vector<int> slot;         // per body: free-body number, wheelset number, or -1 (frame)
  int n_free = 0, n_ws = 0, n_series = 0, size = 0;
  // Independent coordinates per wheelset: 3 (y, theta, psi) with a free spin, 2 (y, psi) with a
  // prescribed one (WheelsetSpin::Prescribed: theta is not a state).
  int ws_dof = 3;
  bool spinFree() const { return ws_dof == 3; }
  // Slot of wheelset coordinate c (0 y, 1 theta, 2 psi) among the wheelset's states; -1 for the
  // spin when it is prescribed.
  int wsSlot(int c) const { return ws_dof == 3 ? c : (c == 0 ? 0 : (c == 2 ? 1 : -1)); }
  int position(int k, int c) const { return 5 * k + c; }  // c = 0..4: y, z, phi, theta, psi
  // c: 0 y, 1 theta, 2 psi; -1 if c is the prescribed spin.
  int wsPosition(int w, int c) const {
    const int j = wsSlot(c);
    return j < 0 ? -1 : 5 * n_free + ws_dof * w + j;
  }
  int rate(int k, int c) const { return 5 * n_free + ws_dof * n_ws + 5 * k + c; }
  int wsRate(int w, int c) const {
    const int j = wsSlot(c);
    return j < 0 ? -1 : 10 * n_free + ws_dof * n_ws + ws_dof * w + j;
  }
  int series(int e) const { return 10 * n_free + 2 * ws_dof * n_ws + e; }
};
ContactLayout contactLayout(const vehicle::VehicleModel& model,
                            WheelsetSpin spin = WheelsetSpin::Free);

// One contact patch of a wheel. Creep forces act on the wheel in the patch's contact frame:
// x along the track (rolling direction), n the rail normal (into the wheel), y = n x x.
struct PatchOutput {
  bool active = false;
  bool on_flange = false;                 // the wheel point lies in the flange window
  double normal = 0.0;                    // [N] normal force (< 0: the constraint pulls, lift)
  double fx = 0.0, fy = 0.0;              // [N] creep forces on the wheel
  double mz = 0.0;                        // [N m] spin moment (Kalker linear only)
  double sx = 0.0, sy = 0.0, spin = 0.0;  // creepages [-], [-], [1/m]
  double s_w = 0.0, s_r = 0.0;            // [m] contact point on the wheel and rail profiles
  double gamma = 0.0;                     // [rad] contact angle (positive toward the centre)
  double radius = 0.0;                    // [m] rolling radius at the contact point
  double a = 0.0, b = 0.0;                // [m] Hertz semi-axes (rolling, lateral)
};

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
  double y_over_q = 0.0;  // derailment quotient Y/Q: Y = lateral force of the rail on the wheel
                          // toward the track centre (-sigma force_y), Q = force_z
  bool lift = false;      // a constraint normal force is negative (wheel lift, not modelled)
};

// Work counters (since construction or resetStats()).
struct ContactStats {
  long evaluations = 0;            // model evaluations (rhs and outputs)
  long kec_iterations = 0;         // Newton iterations of solveKec, summed
  long consistent_solves = 0;      // wheelset solves with NormalForceCoupling::Consistent
  long consistent_iterations = 0;  // fixed-point iterations, summed over those solves
  int consistent_max_iterations = 0;
  long lift_evaluations = 0;       // evaluations in which some wheel had a negative normal force
  double max_lagged_change = 0.0;  // [N] largest |lambda - lambda_previous| seen (Lagged)
};

class ContactVehicleOde : public integ::OdeSystem {
 public:
  // Keeps references: all three must outlive this object.
  ContactVehicleOde(const vehicle::VehicleModel& vehicle, const ContactModel& contact,
                    const track::TrackModel& track);

  int size() const override { return layout_.size; }
  int rhs(double t, const double* y, double* ydot) override;
  std::string componentName(int i) const override;
  std::string lastError() const override { return last_error_; }
  // The free spin rates (creep damping, about -2 f11 r0^2 / (V I_yy): the stiffest mode) and
  // the series-damper forces (relaxation -K_series / D, Appendix A).
  std::vector<int> stiffComponents() const override;

  const ContactLayout& layout() const { return layout_; }
  const vehicle::VehicleModel& vehicle() const { return *vehicle_; }
  const ContactModel& contact() const { return *contact_; }
  // State index of coordinate c of body b (or of its rate); -1 if not a state (prescribed or
  // dependent: s of every body, z and phi of wheelsets, all of a frame).
  int index(int body, vehicle::Coord c, bool rate = false) const;
  int indexOf(const std::string& component) const;  // by componentName(); -1 if none

  // State at t0: wheelsets centred (y = 0, psi = 0, theta = 0; z, phi from the constraints), spin
  // rate V / r_c (r_c: mean rolling radius of the centred wheelset), car bodies and bogies in
  // static (on a curve: quasi-static) equilibrium on their suspension (Newton on their
  // accelerations, as GuidedVehicleOde::staticState), series forces 0. Initialises the normal
  // forces (consistent solve) used by the Lagged coupling at the first step, so the normal forces
  // at t0 are the static wheel loads. Throws rb::InputError when no equilibrium is found.
  Eigen::VectorXd initialState(double t0);

  // Outputs at (t, y), evaluated on demand; they do not change what the integration sees (the
  // Lagged normal-force memory is restored). Return 0, or the rhs error code.
  // Full coordinates (s, y, z, roll, pitch, yaw) of every body, q.size() == bodies.
  int bodyCoordinates(double t, const double* y, std::span<vehicle::Vector6d> q);
  // Two entries per wheelset, in wheelset order: [2w] left, [2w + 1] right.
  int wheelOutputs(double t, const double* y, std::span<WheelOutput> out);
  // Accelerations (sddot = a, y, z, roll, pitch, yaw) of every body, qdd.size() == bodies; for
  // wheelsets z and roll are the constraint accelerations (G qddot = gamma).
  int bodyAccelerations(double t, const double* y, std::span<vehicle::Vector6d> qdd);
  // Vehicle workspace of the last evaluation (element values, forces).
  const vehicle::Workspace& workspace() const { return ws_; }

  const ContactStats& stats() const { return stats_; }
  void resetStats() { stats_ = {}; }

  ~ContactVehicleOde() override;
  ContactVehicleOde(ContactVehicleOde&&) noexcept;

 private:
  enum class Mode { Rhs, Output, Init };
  struct WheelsetWork;
  int evaluate(double t, const double* y, double* ydot, Mode mode);
  int setCoordinates(double t, const double* y);
  // The evaluation, compiled for each contact method and creep law (chosen once, in the
  // constructor: no per-patch branch on the law; creep "none" compiles the creep code out).
  template <ContactMethod kMethod, class Law>
  int evaluateT(double t, const double* y, double* ydot, Mode mode);
  using EvalFn = int (ContactVehicleOde::*)(double, const double*, double*, Mode);

  const vehicle::VehicleModel* vehicle_;
  const ContactModel* contact_;
  const track::Irregularities* irr_ = nullptr;
  ContactLayout layout_;
  vehicle::Workspace ws_;
  std::vector<double> scratch_;
  std::string last_error_;
  ContactStats stats_;
  std::vector<WheelsetWork> work_;
  std::vector<WheelOutput> out_;
  std::vector<vehicle::Vector6d> qdd_;  // body accelerations of the last Output evaluation
  EvalFn eval_ = nullptr;
};

}  // namespace rb::dynamics
