#pragma once
// The engineering assessment of a vehicle run (run.assessment, docs/assessment.md): the signals a
// run samples at the assessment's own interval, the pure computation of every asked quantity
// with rb_assessment (EN 14363 running safety, track loading and stability, EN 12299 comfort,
// Sperling's Wz, T gamma wear) and its result group /assessment (the layout the figures read).
#include <limits>
#include <string>
#include <vector>

#include "workbench/assessment/en12299.hpp"
#include "workbench/assessment/en14363.hpp"
#include "workbench/assessment/sections.hpp"
#include "workbench/assessment/spec.hpp"
#include "workbench/assessment/wear.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/io/schema.hpp"

namespace rb::run {

// One wheel's track-frame forces (EN 14363 Y, Q, y_track [N]) and per patch T gamma [N] and
// frictional power [W] at the sample times, with its static wheel load Q0 [N] (the vehicle's
// static equilibrium on perfect tangent track, staticWheelLoads()).
struct WheelSignals {
  std::string wheelset, side;  // as in /contact
  double q0 = 0.0;             // [N]
  // [m] this wheel's arc length minus AssessmentSignals::distance (<= 0 behind the leading
  // wheelset): every position of this wheel's quantities is its own distance along the track.
  double s_offset = 0.0;
  std::vector<double> Y, Q, y_track;
  std::vector<double> t_gamma[2], power[2];
};

// Lateral acceleration [m/s^2] of a bogie frame at the point above one of its wheelsets.
struct BogiePointSignals {
  std::string bogie, wheelset;
  double bogie_mass = 0.0;  // [kg]
  double s_offset = 0.0;    // [m] the wheelset's arc length minus AssessmentSignals::distance
  std::vector<double> ay;
};

// Absolute acceleration [m/s^2] of a car-body floor point, body track-frame components.
struct FloorPointSignals {
  std::string name;       // front, centre, rear (or x_<offset>)
  double x_offset = 0.0;  // [m] from the car body's centre of mass
  std::vector<double> ax, ay, az;
};

struct AssessmentSignals {
  double dt = 0.0;                     // sample interval [s]
  std::vector<double> time, distance;  // [s], [m] (leading wheelset)
  // The sections assessed on their own (the track's segments or run.assessment.sections); empty:
  // the whole run is one section.
  std::vector<assessment::TrackSection> sections;
  std::string q0_source;                  // where the static wheel loads Q0 come from (a sentence)
  std::vector<WheelSignals> wheels;       // per wheelset: left, right
  std::vector<BogiePointSignals> bogies;  // per bogie: its wheelsets, leading first
  std::vector<FloorPointSignals> floor;
};

// One assessed quantity, as its /assessment group's attributes.
struct Assessed {
  assessment::Check check;
  std::string unit, clause, where;
  double at_s = std::numeric_limits<double>::quiet_NaN();  // [m], NaN: not located
};

struct WheelSafety {
  std::vector<double> s;                       // the wheel's own arc length per sample [m]
  std::vector<double> y_filtered, q_filtered;  // the 20 Hz low-passed Y and Q [N]
  assessment::en14363::SlidingAssessment y_over_q;
  Assessed yq;               // (Y/Q)_2m against yq_limit
  double nadal_limit = 0.0;  // [-] Nadal's flange-climbing limit
  double nadal_mu = 0.0;     // [-] the friction coefficient it used
  Assessed dq;               // dQ/Q0
  std::vector<double> dq_series;
  Assessed y_qst, q_qst, q_max;
};
struct WheelsetSafety {
  std::string wheelset;
  assessment::en14363::SlidingAssessment sum_y;
  Assessed sy;
  double q0 = 0.0;  // mean static wheel load of the wheelset [N]
};
struct StabilityResult {
  std::string bogie, wheelset;
  double f0 = 0.0, bogie_mass = 0.0;
  assessment::en14363::StabilityAssessment st;
  Assessed a;
};
struct ComfortResult {
  std::string name;
  double x_offset = 0.0;
  assessment::en12299::MeanComfort n_mv;
  Assessed n;
  std::vector<double> nc[3];
  double wz_lateral = 0.0, wz_vertical = 0.0;
};
struct WearResult {
  std::vector<double> t_gamma, power;  // per wheel, sum over patches
  assessment::wear::WearSummary wheel, patch[2];
};

// One line of /assessment/summary and of the printed summary.
struct SummaryItem {
  std::string key;  // y_over_q, sum_y, ...
  std::string unit;
  Assessed a;
};

// The EN 14363 quantities of one track section, each wheel on its own stretch of the section
// (its own arc length), and the worst of them.
struct SectionWheel {
  bool assessed = false;  // the wheel's samples cover the section
  Assessed yq, dq, q_max, y_qst, q_qst;
  bool quasi_static = false;  // y_qst and q_qst assessed (curve and given sections)
};
struct SectionResult {
  assessment::TrackSection section;
  double covered = 0.0;              // [m] length of the section the leading wheel sampled
  std::vector<SectionWheel> wheels;  // order of signals.wheels
  std::vector<Assessed> sum_y;       // per wheelset (NaN value: not assessed)
  std::vector<SummaryItem> summary;  // the worst wheel or wheelset per quantity
  std::vector<std::string> notes;
};

struct AssessmentResult {
  assessment::AssessmentSpec spec;  // as applied (groups that do not apply dropped)
  double sample_every = 0.0;
  double mu = 0.0;  // friction coefficient of Nadal's limit as applied [-]
  std::vector<std::string> assumptions, notes;  // notes: why a quantity was left out
  std::vector<WheelSafety> wheel_safety;        // per wheel, order of signals.wheels
  std::vector<WheelsetSafety> wheelset_safety;
  std::vector<StabilityResult> stability;
  std::vector<ComfortResult> comfort;
  std::vector<WearResult> wear;  // per wheel
  std::vector<SectionResult> sections;
  std::vector<SummaryItem> summary;
  std::vector<std::string> quantities;
};

// Computes every asked quantity from the signals (pure). mu is the friction coefficient of
// Nadal's limit when spec.mu < 0. The safety quantities are evaluated per section
// (signals.sections, or the whole run as one section); the summary gives the worst section.
AssessmentResult assess(const AssessmentSignals& signals, const assessment::AssessmentSpec& spec,
                        double contact_mu);

// Writes the group `root` (/assessment, or a vehicle's /vehicles/<name>/assessment in a run of
// several; ASSESSMENT_LAYOUT: one group per quantity with unit, value, limit, margin, ok, clause,
// at_s) and its series. Returns the /schema rows of the datasets written (the caller writes the
// table /schema/assessment once for all of a file's assessments).
std::vector<io::SchemaEntry> writeAssessment(io::ResultFile& f, const AssessmentSignals& signals,
                                             const AssessmentResult& r,
                                             const std::string& root = "/assessment");

// The one-screen summary printed after a run: one line per summary quantity, "ok" or
// "EXCEEDED".
std::vector<std::string> summaryLines(const AssessmentResult& r);
// The per-section table of the summary (no lines when the whole run is one section).
std::vector<std::string> sectionLines(const AssessmentResult& r);
// The warnings of a result whose quantities exceed their limits (one line each).
std::vector<std::string> exceededWarnings(const AssessmentResult& r);

// The signals of an assessment read back from a result file (`workbench assess`): from the
// series a run's assessment wrote under /assessment when it has them, otherwise (safety and wear
// only) from the run's outputs /time, /bodies/<leading>/s and /contact (whose interval must be
// at most kMaxFileSampleInterval). The groups of spec whose signals the file lacks are named in
// `missing` (one sentence each).
inline constexpr double kMaxFileSampleInterval = 5e-3;  // [s]: 10 x the 20 Hz force low-pass
AssessmentSignals signalsFromFile(const io::ResultReader& file,
                                  const assessment::AssessmentSpec& spec,
                                  std::vector<std::string>& missing);

// Largest of |X(f)|^2 of a series (mean removed) on f in [f_low, f_high] by steps of df [Hz]:
// the instability frequency f0 of the stability criterion when the scenario gives none.
double spectrumPeak(const std::vector<double>& x, double dt, double f_low, double f_high,
                    double df);
// spectrumPeak of each of several series of one sampling interval, in one pass over the
// frequencies: the same values as one call per series.
std::vector<double> spectrumPeaks(const std::vector<const std::vector<double>*>& xs, double dt,
                                  double f_low, double f_high, double df);

}  // namespace rb::run
