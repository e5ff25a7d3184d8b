#pragma once
// The cases of `workbench precision` (precision.hpp): which contact models a scenario has, the
// references of each model and the integrator ladders, ordered from cheap to expensive.
#include <string>
#include <vector>

#include "workbench/precision/precision.hpp"
#include "workbench/scenario/study.hpp"

namespace rb::precision {

// The roles of the cases in precision_plan.csv (read by plots/railbench/precision.py).
inline constexpr const char* kRoleReference = "reference";               // refined tables, method A
inline constexpr const char* kRoleCheck = "reference_check";             // refined tables, method B
inline constexpr const char* kRoleSameTables = "reference_same_tables";  // own tables, method A
inline constexpr const char* kRoleCase = "case";

// A contact model of the scenario: a contact method ("" for a guided vehicle) on the default or
// the refined tables. Its overrides select it on top of the scenario and the user's --set.
struct Model {
  std::string name;  // "KEC", "LUT refined", "guided"
  std::string method;
  bool refined = false;
  std::vector<std::string> overrides;
};

// One rung of a ladder: a fixed step [s] or a tolerance, and its study case.
struct Rung {
  double value = 0.0;
  scenario::StudyCase c;
  std::string status = "planned";  // planned, run, skipped
  std::string note;
  double cpu = 0.0;  // median CPU time over the repeats [s] once run (0: none ok)
};

// The settings of one integrator on one model, cheap to expensive.
struct Ladder {
  std::string model;
  std::string integrator;
  bool fixed = false;
  std::vector<Rung> rungs;
  std::size_t next = 0;  // the first rung not yet run or skipped
};

// A reference run of a model.
struct Reference {
  std::string model;
  std::string role;
  std::string integrator;
  double value = 0.0;  // its rtol
  scenario::StudyCase c;
};

// A setting of the options that was left out, and why (printed and written to the plan).
struct Note {
  std::string model, integrator, text;
};

struct Plan {
  std::string scenario;             // resolved path
  std::vector<std::string> base;    // the user's --set and the run shortening
  bool contact = false;             // the scenario has wheel/rail contact
  std::vector<std::string> bodies;  // the vehicle's body names (BODY.y quantities)
  std::vector<Model> models;
  std::string model_reference;  // --model-reference: the name of its model ("" none)
  std::vector<Reference> references;
  std::vector<Ladder> ladders;
  std::vector<Note> notes;
  // What the plan changed so that every setting can run (e.g. a step that does not divide the
  // output interval), printed and written to the plan.
  std::vector<std::string> adaptations;
  std::vector<std::string> quantities;
  std::vector<double> levels;
  double limit = 0.0;  // verification limit of the reference, display units
};

// Parses a comma-separated list; throws InputError naming `option` for an empty entry.
std::vector<std::string> splitList(const std::string& text, const std::string& option);

// Parses a comma-separated list of positive numbers (InputError naming `option`).
std::vector<double> splitNumbers(const std::string& text, const std::string& option);

// The plan of the command for `o`: loads the scenario (InputError when it or an option is bad),
// decides the models and the ladders, and leaves out (with a note) what the scenario refuses.
Plan makePlan(const PrecisionOptions& o);

// The tables a case of `model` (contact method `method`) runs on, as precision_plan.csv and
// precision.csv write it: "none" (a method without tables), "refined" or "default".
std::string tablesOf(const std::string& method, const std::string& model);

// precision_plan.csv: one row per case (references and rungs, also those skipped) with its
// folder, id, role, model, integrator, setting, status and note.
std::string planCsv(const Plan& plan);

}  // namespace rb::precision
