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
#include <string>
#include <vector>

#include "workbench/core/error.hpp"

namespace rb::scenario {

struct StudyCase {
  std::string id;  // stable file name: "case_<64-bit hash of the overrides and the own base>"
  std::vector<std::string> overrides;  // "key=value", in a fixed order
  std::string label;                   // readable name (given, or made from the overrides)
  std::string base;                    // resolved base scenario path of this case
  std::string role;                    // "", "reference", "reference_check", "baseline", ...
};

struct StudySpec {
  std::string file;  // the study file as given
  std::string base;  // resolved base scenario path
  std::vector<StudyCase> cases;
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

// A short readable label made from overrides: "KEC rk4 h=0.25ms", "LUT K=1e10 bdf tol=1e-06
// hmax=1ms", "refined", other keys as "key=value" (solver.max_steps, a work limit, is left out).
std::string caseLabel(const std::vector<std::string>& overrides);

}  // namespace rb::scenario
