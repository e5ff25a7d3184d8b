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
#include "workbench/train/train_ode.hpp"
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

// One vehicle of a run: its bodies, elements and wheelsets (vehicle.start places it along the
// track), its wheel/rail contact (none: guided wheelsets), the offsets its run starts from, and
// the name that keeps its outputs apart from the other vehicles'.
struct RunVehicle {
  // Empty for the only vehicle of a run: its outputs are the file's /bodies, /contact, ...
  // groups. In a run of several every vehicle is named and its groups are under prefix().
  std::string name;
  vehicle::VehicleModel vehicle;
  std::optional<dynamics::ContactModel> contact;
  std::vector<vehicle::InitialCondition> initial;   // vehicle.initial
  std::vector<vehicle::ElementId> output_elements;  // run.output.elements

  // "" or "/vehicles/<name>": what the paths of this vehicle's outputs begin with.
  std::string prefix() const { return name.empty() ? std::string() : "/vehicles/" + name; }
  // Body position x of the foremost and the rearmost body relative to the vehicle's reference
  // point.
  double leadingX() const;
  double trailingX() const;
};

struct Model {
  scenario::ScenarioSpec spec;
  std::optional<track::TrackModel> track;
  // The vehicles of the run, front to rear: the first leads (a run's distance and a failure's
  // distance are measured at its foremost body). Empty: a track-only scenario. A scenario gives
  // one vehicle; a run of several is built by adding vehicles (addVehicle) to a compiled one.
  std::vector<RunVehicle> vehicles;
  // Buffers and draw gear between neighbouring vehicles (train.connections), and the vehicles'
  // longitudinal motion when it is a state (train.longitudinal).
  std::vector<train::Connection> connections;
  train::Longitudinal longitudinal;
  integ::SolverSpec solver;           // the scenario's, or the paper's default (ABM, 1 ms)
  double track_build_s = 0.0;         // [s] wall time of the track build
  double t_end = 0.0;                 // [s] simulated time of a vehicle run
  std::vector<std::string> warnings;  // "file:line: warning: ...", printed by the app
  // Fixed-step runs: the stability limit at the initial state (step_limit.hpp), and the warnings
  // about it that the run records in /stats/warnings (a step close to the limit, or beyond it
  // with solver.accept_unstable_step).
  StepLimit step_limit;
  std::vector<std::string> run_warnings;

  bool hasVehicle() const { return !vehicles.empty(); }
  // The leading vehicle (the only one of a run a scenario gives): what the analyses of one
  // vehicle (modes, critical speed, static wheel loads) work on.
  const RunVehicle& lead() const { return vehicles.front(); }
  bool hasContact() const { return hasVehicle() && lead().contact.has_value(); }
  // leadingX() of the leading vehicle: a run's distance and a failure's distance are measured at
  // its foremost body (the first wheelset of the wagon).
  double leadingX() const { return lead().leadingX(); }
  // The stretch of track [s_from, s_to] a vehicle run covers: from the rearmost body of its last
  // vehicle at the start to the foremost body of its first at t_end.
  struct Stretch {
    double s_from = 0.0, s_to = 0.0;  // [m]
  };
  // With a longitudinal motion (computed, not prescribed) s_to is an upper bound.
  Stretch coveredStretch() const;
};

// Throws InputError with every problem found.
Model compile(const CompileOptions& options);

// The track, the vehicles of a loaded `spec` (its vehicle{}, or every vehicle of train{}) with
// their contact models, and the train's connections and longitudinal motion: the model alone,
// without the checks of a run (its length on the track, its outputs, its step, its start), for
// analyses that evaluate it at states of their own (the linearised stability of a train).
// options.table_cache is used; scenario and overrides are not (the spec is loaded). Throws
// InputError.
Model compileModel(scenario::ScenarioSpec spec, const CompileOptions& options);

// The vehicle ODE of vehicle k of a compiled model: on wheel/rail contact when it has a contact
// model, guided otherwise. compile() and runVehicle() both build theirs here.
std::unique_ptr<vehicle::VehicleOde> makeVehicleOde(const Model& model, std::size_t k = 0);
// The ODE of a whole run: every vehicle's, one after the other (train::TrainOde).
std::unique_ptr<train::TrainOde> makeRunOde(const Model& model);

// Adds v behind the model's vehicles (v.vehicle.start places it; it runs at the model's speed
// over the model's t_end on its track). Every vehicle of a run of several must be named, with a
// name of its own: InputError otherwise, or when v's bodies are not on the track at the start.
void addVehicle(Model& model, RunVehicle v);

// Upper bound of output samples per run unless run.output.max_samples says otherwise.
inline constexpr double kDefaultMaxOutputSamples = 1e7;

}  // namespace rb::run
