#pragma once
// Spec -> Model for a whole run (architecture.md): compile() loads a scenario, validates every
// block and builds the immutable Model of the run (track, vehicle, contact tables, solver,
// outputs) with every problem collected and reported at once as one InputError. Everything that
// can be known before integrating is checked here, so `workbench check` accepts exactly what
// `workbench run` can start: the initial state (static equilibrium on the contact constraints),
// the output grid of fixed-step methods, the travelled range against the track's length and the
// size of the output. The app, the benchmarks and the tests all build their runs from it.
#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "workbench/dynamics/contact_model.hpp"
#include "workbench/integrators/spec.hpp"
#include "workbench/run/step_limit.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/model.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::run {

struct CompileOptions {
  std::string scenario;                // scenario file
  std::vector<std::string> overrides;  // --set key=value, in order
  std::string root;                    // project root holding scenarios/ and profiles/
  // Folder of the contact-table disk cache; empty: tables are built in memory only.
  std::string table_cache;
};

struct Model {
  scenario::ScenarioSpec spec;
  std::optional<track::TrackModel> track;
  std::optional<vehicle::VehicleModel> vehicle;
  std::optional<dynamics::ContactModel> contact;
  integ::SolverSpec solver;  // the scenario's, or the paper's default (ABM, 1 ms)
  std::vector<vehicle::ElementId> output_elements;
  double track_build_s = 0.0;         // [s] wall time of the track build
  double t_end = 0.0;                 // [s] simulated time of a vehicle run
  std::vector<std::string> warnings;  // "file:line: warning: ...", printed by the app
  // Fixed-step runs: the stability limit at the initial state (step_limit.hpp), and the warnings
  // about it that the run records in /stats/warnings (a step close to the limit, or beyond it
  // with solver.accept_unstable_step).
  StepLimit step_limit;
  std::vector<std::string> run_warnings;

  bool hasVehicle() const { return vehicle.has_value(); }
  bool hasContact() const { return contact.has_value(); }
  // Body position x of the leading body (largest x: the first wheelset of the wagon) relative to
  // the vehicle's reference point. A run's distance and a failure's distance are measured there.
  double leadingX() const;
  double trailingX() const;
  // The stretch of track [s_from, s_to] a vehicle run covers: from its rearmost body at the start
  // to its leading body at t_end.
  struct Stretch {
    double s_from = 0.0, s_to = 0.0;  // [m]
  };
  Stretch coveredStretch() const;
};

// Throws InputError with every problem found.
Model compile(const CompileOptions& options);

// The vehicle ODE of a compiled model with a vehicle: on wheel/rail contact when the model has a
// contact block, guided otherwise. compile() and runVehicle() both build theirs here.
std::unique_ptr<vehicle::VehicleOde> makeVehicleOde(const Model& model);

// Upper bound of output samples per run unless run.output.max_samples says otherwise.
inline constexpr double kDefaultMaxOutputSamples = 1e7;

}  // namespace rb::run
