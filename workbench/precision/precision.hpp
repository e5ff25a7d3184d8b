#pragma once
// `workbench precision SCENARIO.lua`: what accuracy costs in time on the user's own scenario
// (docs/precision.md).
//
// A verified reference per contact model (two different integrators at tight tolerances on the
// refined contact tables, whose difference is the reference's bound), a same-tables reference
// (the reference's settings on the cases' own tables: splits every case's error into table and
// integration error), and the matrix contact method x integrator x step / tolerance ladder run as
// an expanded study (study.hpp: resumable, one process per run). `plots/rbplot precision` then
// computes the errors, the Pareto fronts, the figures and the recommendation table.
#include <set>
#include <string>
#include <vector>

#include "workbench/study/command.hpp"

namespace rb::precision {

struct PrecisionOptions : study::ScenarioCommandOptions {
  // The options typed on the command line: a typed empty list or 0 is refused, never read as
  // "the default".
  std::set<std::string> given;
  std::string methods;            // contact methods "kec,lut" ("" = default)
  std::string model_reference;    // contact method of the model error's reference ("": none)
  std::string integrators;        // "rk4,abm,dopri5,bdf" ("" = default)
  std::string quantities;         // error quantities "y,yaw" ("" = default)
  std::string levels;             // recommendation levels in the first quantity's unit
  std::string steps;              // fixed-step ladder [s] ("" = default)
  std::string tolerances;         // tolerance ladder ("" = default)
  std::string reference_methods;  // the two reference integrators ("bdf,ida")
  double reference_tol = 1e-9;    // reference rtol (atol = rtol / 10)
  double reference_limit = 0.0;   // verification limit, display units (0: levels / 10)
  int repeats = 3;                // runs per case (median CPU time)
  double distance = 0.0;          // [m] shortens the run (0: the scenario's)
  double duration = 0.0;          // [s] shortens the run (0: the scenario's)
  double budget = 0.0;            // [s] wall-time target (0: none)
  bool quick = false;             // tiny matrix (tests)
  bool refine = false;            // also the matrix on the refined tables
  bool callgrind = false;         // instructions of the recommended settings
};

// Runs the command; returns the process exit code (0 ok, 1 bad input, 2 no case ran, 4 figures
// failed). Throws InputError for a bad scenario or option.
int runPrecision(const PrecisionOptions& options);

}  // namespace rb::precision
