#pragma once
// The one vehicle-run path: a compiled Model with its vehicles (wheelsets guided along the track,
// or on wheel/rail contact by a contact method) is integrated into a result file with one set of
// outputs, so every run.output key means the same in every vehicle run (the groups below are
// the only vehicle's; in a run of several each vehicle's are under /vehicles/<name>):
//   /vehicle/speed; /bodies/<b>/{s, y, z, roll, pitch, yaw} (track frame of the body);
//   with run.output.body_accelerations /bodies/<b>/{ax, ay, az}: the absolute acceleration of the
//     centre of mass in the body's track-frame components [m/s^2];
//   with run.output.elements /elements/<name>/{deflection, force};
//   with contact /contact/<ws>/<left|right>/... per wheel.
// Validity checks stop the run as a failure (exit 2, partial results kept): wheel lift (the rhs
// refuses the state, see ContactVehicleOde), non-finite outputs, a contact point leaving its
// table. Questionable but valid results are recorded as warnings in /stats/warnings.
#include <string>
#include <vector>

#include "workbench/assessment/spec.hpp"
#include "workbench/integrators/integrator.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/run_stats.hpp"
#include "workbench/run/vehicle_assessment.hpp"
#include "workbench/vehicle/stage_clock.hpp"

namespace rb::run {

struct VehicleRunOptions {
  bool progress = false;  // progress line on stderr
  // Rhs stage timing: 1 evaluation in stage_period is timed (0: off; run_stats.hpp).
  unsigned stage_period = vehicle::StageClock::kDefaultPeriod;
};

struct VehicleRunResult {
  integ::RunResult result;
  std::vector<std::string> warnings;  // also written to /stats/warnings
  // The printed assessment summary (empty when none was asked) and why groups were left out.
  std::vector<std::string> assessment_summary;
  std::vector<std::string> assessment_notes;
  // Where each wheel on several rails moved onto a further rail and the largest force on each
  // (VehicleOutputs::writeRailAnswers); empty without further rails.
  std::vector<std::string> rails_summary;
  std::vector<EffectUse> effects;  // /stats/effects
  StageCosts costs;                // /stats/stage_*
};

// Integrates m (which must have a vehicle) and writes outputs, /stats and warnings into f (not
// finalized), vehicle by vehicle: their outputs (vehicle_outputs.hpp) and assessments
// (vehicle_assessment.hpp). Throws InputError only for problems compile() could not know.
VehicleRunResult runVehicle(const Model& m, io::ResultFile& f, const VehicleRunOptions& options);

// Root provenance attributes (version, scenario text and modules, overrides, effects, seeds) and
// the /track group of a compiled model. With a track_store folder the track is written once per
// distinct track into that folder (io/track_store.hpp) and /track only references it; the
// returned message says which store file (empty without a store).
std::string writeProvenance(const Model& m, io::ResultFile& f, const std::string& created,
                            const std::string& track_store = {});

// Why `path` is not a dataset a vehicle run of `spec` writes, "" when it is one or when it lies
// outside the groups known before the run (/vehicle, /bodies, /elements, /contact; /assessment,
// /track and the rest are resolved against the result file). A study checks its metrics' signals
// with it before any run starts.
std::string signalProblem(const scenario::ScenarioSpec& spec, const std::string& path);

// Creepage above which the creep laws leave the range they are calibrated for (assumption, see
// docs/contact_dynamics.md): a run that exceeds it is recorded with a warning.
inline constexpr double kCreepageWarning = 0.1;

}  // namespace rb::run
