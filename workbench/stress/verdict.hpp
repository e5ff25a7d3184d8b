#pragma once
// The verdict of `workbench stress` (docs/stress.md) on the runs of its folder: every run is
// classified by its own checks (result_checks.hpp) and its error against the reference of the same
// hardened case (study/run_error.hpp, wheelset lateral displacement y):
//
//   ok              finished, passes the checks, lateral error against its own reference at most
//                   the tolerance
//   inaccurate      finished and passes the checks, but the error is larger, or cannot be
//                   established (the reference stopped, or failed badly)
//   failed cleanly  exit 2 with a diagnostic naming time and distance, a partial result that is
//                   consistent and has no NaN (or a fixed step refused before the run)
//   failed badly    exit 3, a signal, no result, NaN/Inf, an inconsistent partial result or an
//                   implausible state in a finished run
//
// The command writes the rows as stress.csv, prints the map as text and checks an expectation
// file; plots/rbplot stress only draws stress_map.png from stress.csv.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "workbench/core/names.hpp"
#include "workbench/stress/result_checks.hpp"

namespace rb::stress {

enum class Outcome { Ok, Inaccurate, FailedCleanly, FailedBadly };
inline constexpr std::array<NameEntry<Outcome>, 4> kOutcomeNames = {{
    {Outcome::Ok, "ok", "finished, passes its checks, error within the tolerance"},
    {Outcome::Inaccurate, "inaccurate",
     "finished and passes its checks, error above the tolerance or not established"},
    {Outcome::FailedCleanly, "failed cleanly",
     "stopped with a diagnostic naming time and distance, consistent partial result"},
    {Outcome::FailedBadly, "failed badly",
     "crash, no result, NaN/Inf, inconsistent or implausible result"},
}};
constexpr const auto& nameTable(Outcome /*tag*/) {
  return kOutcomeNames;
}

// A run by its own checks, before its accuracy is judged: Ok (finished and passes checkResult),
// FailedCleanly (exit 2 with a consistent partial result, or refused before its first step with
// the model's diagnostic: a fixed step beyond the stability limit, wheel lift in the initial
// state) or FailedBadly. status/message: the study summary's (ok, failed, error, missing).
struct Classified {
  Outcome outcome = Outcome::FailedBadly;
  ResultCheck check;  // of the file (check.readable false: no file was read)
  std::vector<std::string> problems, notes;
};
Classified classifyRun(const std::string& status, const std::string& message,
                       const std::string& file, double t_end, const Bounds& bounds);

// One row of stress.csv: a run of the folder, the references first in each hardened case.
struct StressRow {
  std::string axis, value, value_label, integrator, role;
  Outcome outcome = Outcome::FailedBadly;
  std::optional<double> error_y_mm;  // against its own reference (a reference: 0 when ok)
  double t_reached = kNaN, t_end = kNaN;
  double cpu_s = kNaN, rhs_evals = kNaN, rhs_evals_jac = kNaN, steps = kNaN;
  double max_abs_y_mm = kNaN, min_normal_kN = kNaN;
  std::string message, id, file;
};

// Every run of the stress folder `dir` (stress_cases.csv, summary_cases.csv), classified with the
// largest lateral error `tolerance` [mm] of an ok run. Throws InputError naming the folder when it
// is not a `workbench stress` folder.
std::vector<StressRow> evaluate(const std::string& dir, double tolerance, const Bounds& bounds);

std::string stressCsv(const std::vector<StressRow>& rows);

// The stability map as text: per axis a table of value x integrator setting with the outcome and
// the lateral error, the counts per outcome and every run's message.
std::string textMap(const std::vector<StressRow>& rows, double tolerance);

// An expectation file (docs/stress.md): lines `AXIS, VALUE, INTEGRATOR, OUTCOME[|OUTCOME...]`,
// '#' starts a comment; AXIS, VALUE and INTEGRATOR are shell patterns ('*' any), VALUE also a
// number (compared with the axis value), INTEGRATOR "reference*" for the reference row.
struct Expectation {
  std::string where;  // file:line
  std::string axis, value, integrator;
  std::vector<Outcome> allowed;
};
// Throws InputError with file:line for a malformed line or an unknown outcome, and for a file
// that cannot be read.
std::vector<Expectation> readExpectations(const std::string& path);
// The mismatches, one line each (an expectation no run matches is one too).
std::vector<std::string> checkExpectations(const std::vector<StressRow>& rows,
                                           const std::vector<Expectation>& expectations);

}  // namespace rb::stress
