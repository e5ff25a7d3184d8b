#pragma once
// Linearised stability of the vehicle on wheel/rail contact (KEC or LUT, any creep law):
//   1. the steady state at a speed: the fixed point of the ODE in the track frame, rhs(y) = 0 over
//      every state except the wheelset spin angles (cyclic: the rhs does not depend on them, so
//      their rows and columns are dropped; the spin rates stay states). Newton from
//      ContactVehicleOde::initialState with a finite-difference Jacobian and a backtracking line
//      search; when Newton does not converge, the transients are let die by integrating with BDF
//      for settle_time and Newton is tried again from there (Steady::fallback).
//   2. the Jacobian there by central differences with one step per state kind (StepRule below),
//      checked by computing the eigenvalues again with the steps divided by sqrt(10)
//      (Analysis::step_check);
//   3. its eigenvalues and eigenvectors, each mode labelled from the kinetic-energy shares of the
//      body coordinates (modeLabel below);
//   4. the linear critical speed: the lowest speed at which any mode is unstable (its least damped
//      mode crosses zero damping), bracketed on a speed sweep and refined by the Illinois variant
//      of regula falsi on the speed; beside it the same for the hunting modes alone (wheelset or
//      bogie hunting), the speed the nonlinear search of `critical-speed` starts from. A car-body
//      mode of a two-axle wagon can lose its damping far below the hunting speed (the body modes
//      couple with the kinematic motion of the wheelsets when the kinematic frequency V / L_k
//      passes their natural frequency): it limits the vehicle as much as hunting does.
// The scene is the scenario's track at spec.vehicle.speed (constant: the acceleration is set to
// 0), irregularities off, the normal-force coupling forced to "consistent" (the lagged coupling
// gives the rhs a memory of the previous evaluation, so its difference quotients would not be
// the Jacobian of the model).
#include <Eigen/Dense>
#include <complex>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "workbench/scenario/scenario.hpp"

namespace rb::stability {

// The analysis could not be done (no steady state, an rhs failure at the steady state): the
// message says why. Bad input is rb::InputError from the compilation.
class Failure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Options {
  double distance = 0.0;     // [m] travelled distance of the linearisation point (a curve)
  double step_scale = 1.0;   // multiplies every finite-difference step (fdSteps)
  int max_newton = 40;       // Newton iterations per attempt
  double newton_tol = 1e-9;  // scaled residual (Steady::residual) accepted as converged
  // [s] BDF integration of the fallback: the vehicle travels V settle_time further, which must
  // stay on the same constant-radius curve (or tangent) for the settled state to be its fixed point
  double settle_time = 5.0;
  bool step_check = true;  // eigenvalues again with the steps / step_check_ratio
  double step_check_ratio = 3.1622776601683795;  // sqrt(10): see StepRule
  double step_check_limit = 1e-2;  // largest accepted relative change of a relevant eigenvalue
  std::string table_cache;         // contact-table disk cache folder ("" = memory only)
};

struct Steady {
  Eigen::VectorXd y;            // full state (spin angles as initialState gives them)
  double t = 0.0;               // [s] time of the linearisation point (distance / V)
  double residual = 0.0;        // max_i |f_i| / scale_i over the kept rows (residualScale)
  double residual_raw = 0.0;    // max_i |f_i| over the kept rows, SI units of each row
  int iterations = 0;           // Newton iterations, both attempts
  bool fallback = false;        // the BDF settle was needed
  double max_ws_lateral = 0.0;  // [m] max |y| of the wheelsets
};

// Kinetic-energy share of one body coordinate in a mode.
struct Coordinate {
  std::string name;     // "car.y", "ws1.yaw", "ws1.theta" (spin)
  int body = -1;        // body index
  int kind = 0;         // vehicle::BodyKind of the body
  int coord = 0;        // vehicle::Coord (kY .. kYaw)
  int rate_index = -1;  // state index of its rate
  double weight = 0.0;  // mass [kg] or principal inertia [kg m^2]
};

struct Mode {
  std::complex<double> eigenvalue;    // lambda = -zeta w0 + i wd [1/s]
  double frequency_hz = 0.0;          // damped frequency Im lambda / (2 pi)
  double damping_ratio = 0.0;         // -Re lambda / |lambda|
  bool oscillatory = false;           // Im lambda > 0 (one of a conjugate pair)
  std::vector<double> participation;  // per Analysis::coordinates, sums to 1
  double series_share = 0.0;          // series-damper spring energy / (it + kinetic energy)
  std::string label;                  // modeLabel
  std::string dominant;               // the coordinate with the largest share
  bool hunting = false;               // counts for the critical speed (wheelset or bogie hunting)
  double roll_centre = 0.0;           // [m] car-body sway: roll centre height above the car's CoM
  double step_change = 0.0;           // |lambda(h) - lambda(h / step_check_ratio)| / |lambda(h)|
};

// [1/s] A mode is unstable when its motion grows, exp(Re lambda t): Re lambda above this floor (a
// doubling time of 8 days, beyond any run, so that round-off on a neutral mode is not reported).
inline constexpr double kUnstableFloor = 1e-6;
inline bool unstable(const Mode& m) {
  return m.eigenvalue.real() > kUnstableFloor;
}
// One line naming a mode: "car body yaw (car.yaw), 2.065 Hz, damping ratio -0.0405".
std::string describe(const Mode& m);

struct Analysis {
  double speed = 0.0;               // [m/s]
  std::string method, creep, spin;  // contact method, creep law, wheelset spin
  Steady steady;
  std::vector<Coordinate> coordinates;
  std::vector<Mode> modes;  // every eigenvalue of the reduced Jacobian, sorted by Im then Re
  int states = 0;           // size of the reduced system
  // Largest step_change of the relevant modes: oscillatory, below 30 Hz, damping ratio < 0.9 (a
  // pair split off a nearly double real root moves as the square root of the Jacobian's error).
  double step_check = 0.0;
  bool step_check_ok = true;
  int least_hunting = -1;  // index into modes of the least damped hunting mode, -1 if none
  int least_damped = -1;   // index into modes of the least damped mode of any kind, -1 if none
  long rhs_evaluations = 0;
  double cpu_s = 0.0;
  std::vector<std::string> notes;

  double huntingDamping() const;  // damping ratio of modes[least_hunting] (NaN if none)
  double leastDamping() const;    // damping ratio of modes[least_damped] (NaN if none)
  std::vector<std::size_t> unstableModes() const;  // indices of the unstable modes
};

// The finite-difference step of every state (length = the ODE's size), before step_scale:
//   positions: 1e-8 m or rad;
//   rates:     1e-7 m/s or rad/s, times max(1, |y|) (the spin rates V / r0 ~ 40 rad/s);
//   series-damper forces: 0.01 N times max(1, |f| / 1e4 N) (0.01 N is 1e-8 m of a series spring
//   of 1e6 N/m, the size of the position step).
// Why so small: the contact geometry of S1002 on 60E1 is not linear in the lateral displacement
// even over micrometres around the centred position, so a step of 1e-6 m gives a secant, not the
// tangent: on the Manchester wagon at 70 m/s (KEC) the bogie hunting mode's real part moves from
// -0.6 (1e-6 m) to -0.01 (1e-7 m) to +0.16 1/s (1e-8 m); below about 3e-9 m the KEC solver's
// convergence tolerance shows as noise in the difference quotients (1e-9 m: +0.15, 3e-10 m: -0.7).
// 1e-8 m is the smallest step clear of that noise. The step check compares with the steps divided
// by sqrt(10) (Options::step_check_ratio), which stays clear of it too.
struct StepRule {
  double position = 1e-8, rate = 1e-7, series = 1e-2, series_ref = 1e4;
};

// The label of a mode from its shares (the rule, in a rail-vehicle engineer's words):
//   series-spring energy > half of (it + kinetic energy)     "series-damper relaxation"
//   otherwise the group with the largest kinetic-energy share:
//   wheelset spin         "wheelset spin (creep)"
//   wheelset y + yaw or bogie y + yaw (W and B their shares), oscillatory:
//                         B < 0.25 (W + B): "wheelset hunting" (the wheelsets against a quiet
//                           frame);
//                         W < 0.2 (W + B): "bogie yaw/lateral" (the frame on its primary
//                           suspension against nearly still wheelsets);
//                         else: "bogie hunting" (frame and wheelsets together: the kinematic
//                           hunting of the bogie);
//                         not oscillatory: "wheelset lateral/yaw (creep)" or "bogie yaw (creep)"
//                         by the larger of W and B
//   bogie z / pitch / roll  "bogie bounce" / "bogie pitch" / "bogie roll" (largest of the three)
//   car y + roll          roll centre below the CoM: "car body lower sway", above: "upper sway"
//   car yaw               "car body yaw";   car z "car body bounce";   car pitch "car body pitch"
//   (a non-oscillatory body mode gets " (aperiodic)" appended).
// hunting = the label is "wheelset hunting", "bogie hunting" or "bogie yaw/lateral" (the modes
// whose damping decides the linear critical speed).
// car_y, car_roll: the first car body's lateral and roll amplitudes in the mode (rates or
// positions: only their ratio is used).
void labelMode(Mode& mode, const std::vector<Coordinate>& coordinates, std::complex<double> car_y,
               std::complex<double> car_roll);

// One speed: steady state, Jacobian, modes. Throws Failure when the steady state cannot be found
// or the model cannot be evaluated there, rb::InputError for a scene that does not compile.
class Analyser {
 public:
  Analyser(scenario::ScenarioSpec spec, Options options);
  ~Analyser();
  Analyser(const Analyser&) = delete;
  Analyser& operator=(const Analyser&) = delete;

  Analysis analyse(double speed);
  const Options& options() const { return options_; }

 private:
  struct Impl;
  scenario::ScenarioSpec spec_;
  Options options_;
  std::unique_ptr<Impl> impl_;
};

Analysis analyse(const scenario::ScenarioSpec& spec, double speed, const Options& options = {});

struct CriticalSpeed {
  bool found = false;
  double speed = 0.0;                         // [m/s] linear critical speed (when found)
  double bracket_lo = 0.0, bracket_hi = 0.0;  // [m/s] last bracket of the refinement
  // The mode that loses its damping at `speed` (describe()), or, with below_range, the least
  // damped of the modes already unstable at the sweep's lowest speed.
  std::string mode;
  bool mode_is_hunting = false;
  // A mode is unstable at the sweep's lowest speed: the linear critical speed is below the range
  // (found = false, why says so and names the modes).
  bool below_range = false;
  std::vector<Analysis> sweep;       // the sweep, in speed order
  std::vector<Analysis> refinement;  // the refinement steps (of both crossings)
  std::string why;                   // when not found: "none in range" and the damping seen
  // The same crossing for the hunting modes alone (wheelset or bogie hunting): where the nonlinear
  // search of `critical-speed` starts. Equal to `speed` when a hunting mode is the first to lose
  // its damping.
  bool hunting_found = false;
  double hunting_speed = 0.0;  // [m/s]
  std::string hunting_why;     // when not found, or a note on its refinement
  // [m/s] How far the finite-difference step can move the critical speed: the step check's
  // relative eigenvalue change of the least damped hunting mode at the analysis nearest the
  // critical speed (an upper bound of the change of its damping ratio) divided by the slope of
  // the damping against speed over the sweep's bracket. NaN when not found.
  double step_uncertainty = 0.0;
  long rhs_evaluations = 0;
  double cpu_s = 0.0;
};

// n >= 2 speeds from v_lo to v_hi, then refinement to tol [m/s]. The critical speed is the lowest
// speed at which the least damped mode's damping ratio (any mode) changes sign from positive to
// negative; hunting_speed the same for the least damped hunting mode.
CriticalSpeed linearCriticalSpeed(const scenario::ScenarioSpec& spec, double v_lo, double v_hi,
                                  int n, const Options& options = {}, double tol = 0.05);
// The same on speeds already analysed by `analyser` (the sweep is moved into the result).
CriticalSpeed linearCriticalSpeed(Analyser& analyser, std::vector<Analysis> sweep,
                                  double tol = 0.05);

}  // namespace rb::stability
