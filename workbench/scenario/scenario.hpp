#pragma once
// Loading a scenario: run the Lua file, apply --set overrides, validate against the schema and
// build the typed Specs the engine compiles (Spec -> Model -> State -> Workspace).
#include <string>
#include <vector>

#include "workbench/assessment/spec.hpp"
#include "workbench/dynamics/spec.hpp"
#include "workbench/integrators/spec.hpp"
#include "workbench/scenario/effect_names.hpp"
#include "workbench/track/spec.hpp"
#include "workbench/train/connection.hpp"
#include "workbench/train/longitudinal.hpp"
#include "workbench/vehicle/spec.hpp"

namespace rb::scenario {

struct RunSpec {
  double distance = 0.0;                     // [m] 0 = to the end of the track
  double duration = 0.0;                     // [s] 0 = distance / speed
  double output_every = 0.01;                // [s]
  SourceLoc output_every_loc;                // where every was given (a --set: the command line)
  std::vector<std::string> output_elements;  // element names (checked against the vehicle)
  bool body_accelerations = false;
  double max_output_samples = 1e7;        // refuse runs with more output times (memory, disk)
  bool output_patches = true;             // /contact/<ws>/<side>/patch0, patch1
  assessment::AssessmentSpec assessment;  // nothing asked: nothing sampled, nothing computed
  // run.effects: which optional effects the scene has and which of them the compiled model keeps
  // (loadScenario removes every switched-off effect from the Specs; effect_names.hpp).
  EffectSwitches effects;
  SourceLoc loc;
};

// One vehicle of train{}: its name (its outputs' group /vehicles/<name>), its vehicle (placed
// by its own vehicle.start) and the profiles and contact model it runs on: the entry's own, else
// the scenario's profiles{} and contact{}.
struct TrainVehicleSpec {
  std::string name;
  vehicle::VehicleSpec vehicle;
  bool has_profiles = false;
  dynamics::ProfilesSpec profiles;
  bool has_contact = false;  // a contact model; false for guided wheelsets (or none)
  bool guided = false;
  bool own_contact = false;  // its own contact{} block (else the scenario's)
  dynamics::ContactSpec contact;
  SourceLoc loc;
  train::TractionSpec traction;  // train.longitudinal only
  train::ResistanceSpec resistance;
};

struct ScenarioSpec {
  std::string file;  // as given by the user
  std::string text;  // full text of the scenario file (provenance)
  std::vector<std::pair<std::string, std::string>> modules;  // required files: path, full text
  std::vector<std::string> overrides;                        // --set key=value, in order
  track::TrackSpec track;
  bool track_rails_given = false;  // track.rail_lr or track.rail_inclination set explicitly
  bool has_profiles = false;
  dynamics::ProfilesSpec profiles;
  bool has_contact = false;  // a contact model (kec or lut); false for guided wheelsets
  dynamics::ContactSpec contact;
  // contact { method = "guided" }: the wheelsets follow the track kinematically, asked for by
  // name (a vehicle with wheelsets and no contact{} block is an error, never a silent default).
  bool guided = false;
  bool has_vehicle = false;
  vehicle::VehicleSpec vehicle;
  // train{}: the vehicles of the run, front to rear (empty without a train{} block). The first
  // is also vehicle, profiles and contact above (with has_*), the leading vehicle that the
  // analyses of one vehicle work on.
  std::vector<TrainVehicleSpec> train;
  std::vector<train::ConnectionSpec> train_connections;
  train::LongitudinalSpec train_longitudinal;
  bool has_solver = false;
  integ::SolverSpec solver;
  RunSpec run;
};

struct LoadOptions {
  std::string root;                    // project root (scenarios/, profiles/)
  std::vector<std::string> overrides;  // "a.b[2].c=value"
  // Where each override is written, when it comes from a file (a study's matrix value or case
  // entry): its problems are reported there. Empty (or shorter): the command line.
  std::vector<SourceLoc> override_locs;
  long long instruction_limit = 2'000'000'000;  // Lua VM instructions before "endless loop?"
};

// Throws InputError listing every problem found, each as file:line: message.
ScenarioSpec loadScenario(const std::string& path, const LoadOptions& options);

// An analysis of one vehicle (critical-speed, whose runs ramp one vehicle's speed) on a scenario
// with train{}: InputError at the train's first entry naming `command`, instead of an answer for
// the first vehicle alone.
void refuseTrain(const ScenarioSpec& spec, const std::string& command);

}  // namespace rb::scenario
