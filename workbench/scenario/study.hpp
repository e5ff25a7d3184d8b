#pragma once
// A study file: study { base = "...", matrix = {...}, cases = {...}, repeats, jobs, max_cases }.
// Loading expands it into the list of cases, each a list of --set overrides on a base scenario.
//
// An entry of `cases` holds --set paths ("block.key") and, optionally, three study keys (no dot):
//   label = "LUT K=1e10"    readable name of the case in summaries and figures (default: made
//                           from the overrides, e.g. "LUT K=1e10 bdf tol=1e-6", leaving out
//                           the overrides every case of the study has; with a matrix, the
//                           matrix part is put before a given label)
//   base  = "other.lua"     another base scenario for this case (relative to the study file),
//                           e.g. the same model without irregularities
//   role  = "reference"     what the post-processing (plots/plot_study.py) does with the case:
//                           "reference" (work-precision reference), "reference_check" (the
//                           reference at a tighter tolerance, for its convergence),
//                           "reference_same_tables" (the reference's settings on the cases' own
//                           contact tables: integration error only), "baseline" (the full
//                           model of an effects study)
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "workbench/core/error.hpp"

namespace rb::scenario {

struct StudyCase {
  std::string id;  // stable file name: "case_<64-bit hash of the overrides and the own base>"
  std::vector<std::string> overrides;  // "key=value", in a fixed order
  std::string label;                   // readable name (given, or made from the overrides)
  std::string base;                    // resolved base scenario path of this case
  std::string role;                    // "", "reference", "reference_check", "baseline", ...
  // Where each override is written in the study file (its matrix value or its key in the entry
  // of `cases`), parallel to `overrides`; loc: the entry of `cases` (else the matrix, else the
  // study block).
  std::vector<SourceLoc> override_locs;
  SourceLoc loc;
};

// One entry of study.metrics (docs/studies.md, "Metrics"): a number extracted from each case's
// result file. Kinds:
//   "signal"    stat (max, min, max_abs, mean, rms, std, half_peak_to_peak, final) of the 1-D
//               dataset `signal` over the window [from, to]
//   "steady"    the steady-state value of `signal`: the mean over the last `length` of the window
//               (default the last 20 %), checked for drift and oscillation against `tolerance`
//   "assessment" a number of /assessment: `quantity` a summary name ("y_over_q", "sum_y", ...)
//               or a path "/assessment/...@attribute"
//   "error"     max |signal - signal of the reference case| on the reference's samples in the
//               window (computed when the summary is written)
//   "linear_critical_speed"  the stability library's linear critical speed of the case's
//               scenario over speeds = { lo, hi, n }
//   "lua"       fn(s) over `signals` (name -> path) in the Lua sandbox (scenario/metric_lua)
// The window is along the track coordinate s [m] of the signal's body (along = "distance") or
// time [s] (along = "time").
struct MetricSpec {
  std::string name;
  std::string kind;    // "signal", "steady", "assessment", "error", "linear_critical_speed", "lua"
  std::string signal;  // dataset path (signal, steady, error)
  std::string stat;    // signal kind: the statistic's name
  std::string along = "distance";  // "distance" or "time"
  double from = -std::numeric_limits<double>::infinity();
  double to = std::numeric_limits<double>::infinity();
  double length = 0.0;      // steady: length of the last part [m or s]; 0 = 20 % of the window
  double tolerance = -1.0;  // steady: absolute tolerance; < 0 = 1 % of the part's largest |value|
  std::string quantity;     // assessment: summary name or "/assessment/...@attr" or a dataset
  double v_lo = 0.0, v_hi = 0.0;  // linear_critical_speed: speeds [m/s]
  int speeds = 0;                 // linear_critical_speed: number of speeds of the sweep
  std::vector<std::pair<std::string, std::string>> signals;  // lua: name -> dataset path
  int index = 0;  // position in study.metrics (1-based), how metric_lua finds the function
  SourceLoc loc;
  // The definition as text (every key that changes the value), hashed into /metrics.
  std::string definition() const;
};

struct StudySpec {
  std::string file;  // the study file as given
  std::string base;  // resolved base scenario path
  std::vector<StudyCase> cases;
  std::vector<MetricSpec> metrics;
  // Per case (by index into cases): the matrix part of its overrides. An error metric compares a
  // case with the reference case of the same matrix combination. Empty for a study made without
  // a matrix (or by a command).
  std::vector<std::vector<std::string>> matrix_parts;
  std::string text;  // the study file's text (a Lua metric's function is part of it)
  // The modules the study file requires ("-- file: <path>" and its text each): a Lua metric's
  // function may come from one, so they are part of the metrics' definitions.
  std::string modules_text;
  std::string root;  // project root the study was loaded with (Lua metrics re-run the file)
  // What every case writes: "full" (as `workbench run`), or "compact" (study files' default: the
  // signals without the per-patch series, compressed, and the track once per distinct track in
  // <out>/tracks/, referenced from /track).
  std::string output = "full";
  int repeats = 1;
  int jobs = 0;
  // Largest number of cases (matrix combinations x entries of `cases`) loadStudy expands: a
  // study beyond it is refused at its study{} block before anything is expanded or run (key
  // study.max_cases).
  long long max_cases = kDefaultMaxCases;
  SourceLoc loc;
  static constexpr long long kDefaultMaxCases = 10000;
};

// The stable file name of a case: "case_<64-bit hash of its overrides and its own base>" (ownBase
// as written in the study, "" for the study's base), so adding cases to a study or relabelling them
// keeps earlier results resumable.
std::string studyCaseId(const std::vector<std::string>& overrides, const std::string& ownBase);

// Throws InputError (file:line) for a bad study file.
StudySpec loadStudy(const std::string& path, const std::string& root);

// True when the file's script builds a study{} block and no other top-level block (what
// `workbench check` checks as a study); false for a scenario, or a file that does not run.
bool isStudyFile(const std::string& path, const std::string& root);

// A short readable label made from overrides: "KEC rk4 h=0.25ms", "LUT K=1e10 bdf tol=1e-06
// hmax=1ms", "refined", other keys as "key=value" (solver.max_steps, a work limit, is left out).
std::string caseLabel(const std::vector<std::string>& overrides);

}  // namespace rb::scenario
