#pragma once
// The engineering assessment of a vehicle run (run.assessment), vehicle by vehicle: what applies
// to a vehicle, its signals sampled at the assessment's own interval while the run goes, and the
// assessment of them written after the run (assessment_run.hpp computes the quantities).
#include <cstddef>
#include <string>
#include <vector>

#include "workbench/assessment/spec.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/run/assessment_run.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/state_outputs.hpp"

namespace rb::run {

// Refuses (InputError at run.assessment's file:line) assessment groups a vehicle cannot give when
// the scenario names them: safety and wear need wheel/rail contact, stability a bogie, comfort a
// car body. run.assessment = true drops them instead. check and run call it after compile().
void checkAssessment(const Model& m);
// The assessment groups that apply to the leading vehicle of m (those it cannot give dropped).
assessment::AssessmentSpec applicableAssessment(const Model& m);

// The static wheel load Q0 of every wheel of vehicle k (per wheelset of its contact model: left,
// right) [N]: the vehicle's static equilibrium on perfect level tangent track with the run's
// profiles, gauge and rail inclination (EN 14363's Q0 is the static wheel force, the same for
// every run of the vehicle, not the load of a run's first state on its curve or irregular track),
// and a sentence saying so. The vehicle must be on wheel/rail contact.
struct StaticWheelLoads {
  std::vector<double> load;  // [N]
  std::string source;
};
StaticWheelLoads staticWheelLoads(const Model& m, std::size_t k = 0);

// The track sections a run's safety assessment evaluates on their own: run.assessment.sections,
// else one per track segment (tangentN, transitionN, curveN with N the segment's number), with
// test zone, radius and cant.
std::vector<assessment::TrackSection> assessmentSections(const Model& m);

// A point fixed on a body at x offset r_x from its centre of mass (at its height).
struct BodyPoint {
  int body = 0;
  double r_x = 0.0;  // [m]
};

// The assessment of one vehicle during a run: what applies to it, its signals and the body points
// they are sampled at.
struct AssessmentSetup {
  assessment::AssessmentSpec spec;  // what applies
  AssessmentSignals signals;
  std::vector<BodyPoint> bogie_points, floor_points;
};

// The set-up of vehicle k of m (contact: its contact ODE, null when guided); the groups it cannot
// give are dropped with a note in notes.
AssessmentSetup setupAssessment(const Model& m, std::size_t k,
                                const dynamics::ContactVehicleOde* contact,
                                std::vector<std::string>& notes);
// One sample of every signal at the state `state` observes, s the arc length of the vehicle's
// foremost body.
void sampleAssessment(AssessmentSetup& as, StateOutputs& state, bool contact, double t, double s);
// After a run that did not fail and sampled finite signals: the assessment into the group `root`
// (/assessment, or /vehicles/<name>/assessment), its summary lines and a warning per limit
// exceeded (a result, not a failure). Returns false, with a warning, when a signal is not finite.
struct AssessmentOutcome {
  std::vector<std::string> summary, warnings;
  std::vector<io::SchemaEntry> schema;  // its datasets' rows of /schema/assessment
  double cpu_s = 0.0;                   // [s] of computing and writing it
};
AssessmentOutcome finishAssessment(const Model& m, const AssessmentSetup& as, io::ResultFile& f,
                                   const std::string& root);

}  // namespace rb::run
