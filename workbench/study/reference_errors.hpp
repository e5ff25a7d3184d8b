#pragma once
// summary_errors.csv of a study folder: the error of every case against the case it is measured
// against, by the one rule of run_error.hpp, so that the study's figures (work-precision diagrams,
// plots/railbench/study_precision.py) and `workbench effects` (the change each effect makes) only
// read them. The pairs, by role:
//   against "reference" and "reference_same_tables": every case without a reference role against
//     the first case of that role with the same physical model (physicalKey);
//   against "reference" also the reference's own checks: the "reference_check" and
//     "reference_same_tables" cases of its model against it (the reference's own error and the
//     error of the default contact tables);
//   against "baseline": every case against the first case of role "baseline" (the full scene of
//     `workbench effects`), whatever its model.
// Quantities: the wheelsets' lateral displacement y [mm] and yaw [mrad] (a guided vehicle: every
// other body's), every wheel's normal force Q and lateral creep force Fy [kN].
#include <string>
#include <vector>

#include "workbench/scenario/study.hpp"

namespace rb::study {

// The model of a case without its numerical settings: its base scenario and its overrides other
// than solver.*, run.output.*, profiles.refined_tables and contact.normal_forces, sorted.
std::string physicalKey(const scenario::StudyCase& c);

// A case and the result file it is measured by ("" when it left none).
struct CaseResult {
  const scenario::StudyCase* c = nullptr;
  std::string file;
};

// The table: case, against (role), reference (case id), quantity, unit, max, rms; one row per
// pair and quantity (max and rms "inf" for a diverged run, empty where the two files do not share
// the quantity or its times, or one cannot be read).
std::string referenceErrorsCsv(const std::vector<CaseResult>& cases);

}  // namespace rb::study
