#pragma once
// The answer of `workbench precision` (docs/precision.md), computed in the engine once the runs
// are done, so that it exists and is printed whether or not the figures are drawn: the error of
// every run against its reference, the references' verification, and the cheapest setting per
// accuracy level with a plain note when a level cannot be reached or verified. The plotting step
// (plots/railbench/precision.py) reads the files written here (precision.csv,
// precision_references.csv, precision_recommendation.csv, precision.h5) and only draws.
//
// The error of a run against its reference is the one rule of study/run_error.hpp.
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "workbench/precision/plan.hpp"
#include "workbench/study/run_error.hpp"

namespace rb::precision {

using study::Error;
using study::kInf;
using study::parseQuantities;
using study::Quantity;
using study::runError;

struct ReferenceAnswer {
  std::string model;  // default-table model ("KEC")
  bool verified = false;
  std::string why;           // when not verified
  std::vector<Error> bound;  // per quantity: reference_check against reference
  std::vector<Error> table;  // per quantity: reference_same_tables against reference
  // per quantity: this model's reference against the model reference's (--model-reference;
  // empty without one, and for the model reference itself)
  std::vector<Error> model_error;
  // Its reference runs (reference, reference_check, reference_same_tables) as they ended.
  struct Run {
    std::string role, label, status;  // status: ok, failed, missing
    double cpu = 0.0;                 // [s]
    double rhs = 0.0;
  };
  std::vector<Run> runs;
};

struct CaseAnswer {
  std::string model, integrator, label, id;
  bool fixed = false;
  double value = 0.0;
  std::string status;  // ok, failed, skipped, missing
  bool ok = false;     // every repeat ended ok
  double cpu = 0.0;    // [s] median CPU time
  double rhs = 0.0;    // rhs evaluations (first repeat)
  Error integration;   // first quantity, against the same-tables reference
  Error total;         // first quantity, against the refined-table reference
  // As precision_plan.csv: contact method, tables (default, refined, none) and step or tol.
  std::string method, tables, kind;
  std::string note;                     // the plan's, or why the run failed
  double cpu_min = 0.0, cpu_max = 0.0;  // [s] over the repeats that wrote a time
  int runs_ok = 0;                      // repeats that ended ok
  std::vector<Error> integration_all;   // every quantity (the first is `integration`)
  std::vector<Error> total_all;         // every quantity (the first is `total`)
};

struct Recommendation {
  std::string model;
  double level = 0.0;
  bool reached = false;        // a setting's integration error is at most the level
  int best = -1;               // index into Answer::cases
  bool verified = false;       // the level is verified: reference verified, bound below it
  bool table_limited = false;  // the table error exceeds the level (default tables)
  std::string note;            // every reason the level is not reached or not verified
};

struct Answer {
  std::string model_reference;  // the model the model errors are measured against ("": none)
  std::vector<Quantity> quantities;
  std::vector<double> levels;
  double limit = 0.0;
  std::vector<ReferenceAnswer> references;
  std::vector<CaseAnswer> cases;
  std::vector<Recommendation> recommendations;
};

// The recommendation rule for one model and level, on the cases of that model: the ok case with
// the smallest median CPU time (ties: fewer rhs evaluations) whose integration error on the first
// quantity is at most `level`. `ref` holds the model's bound and table error (nullptr: none).
Recommendation recommend(const std::string& model, double level,
                         const std::vector<CaseAnswer>& cases, const ReferenceAnswer* ref,
                         bool refined_tables, const std::string& unit);

// Reads the runs of `plan` from <out>/reference and <out>/cases and computes the answer.
Answer computeAnswer(const Plan& plan, const std::string& out, int repeats);

// precision_recommendation.csv (one row per model and level).
std::string recommendationCsv(const Answer& answer);

// precision.csv: one row per setting of the ladders (model, method, tables, integrator, step or
// tolerance, status, CPU median / min / max, repeats ok, rhs evaluations, and per quantity the
// integration error against the same-tables reference and the total error against the
// refined-table reference, max and RMS, and a note).
std::string casesCsv(const Answer& answer);
// precision_references.csv: per default-table model its reference runs, the verification bound
// (reference_check against reference) and the table error (same-tables reference against
// reference) per quantity.
std::string referencesCsv(const Answer& answer);

// precision.h5, the engine's whole answer: /recommendation, /cases and /references (the columns
// of the three CSVs as datasets), /reference_bound/<model> attributes (verified, why, per
// quantity the bound and the table error, max and RMS), root attributes quantities, units,
// reference_limit and the dataset /levels. The plotting step only reads it.
void writeAnswerH5(const Answer& answer, const std::string& path);

// The printed answer: per model the reference state, bound and table error, then the table.
void printAnswer(const Answer& answer, std::ostream& out);

}  // namespace rb::precision
