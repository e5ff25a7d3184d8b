#pragma once
// The one registry of integrators: per method its name, description, kind (fixed step or
// adaptive), options and factory, for help and error messages, validation of a SolverSpec, and
// construction. Adding a method means adding it here only.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "workbench/integrators/integrator.hpp"
#include "workbench/integrators/spec.hpp"

namespace rb::integ {

struct OptionInfo {
  std::string key;            // SolverSpec field / scenario key: "rtol"
  std::string unit;           // "s", "-"
  std::string default_value;  // as text: "1e-06"
  std::string help;
};

struct MethodInfo {
  std::string name;  // "bdf"
  std::string description;
  // Fixed step: every output time must lie on the step grid, and a run given by distance ends on
  // the last step at or before it. Adaptive: `step` is an initial step, 0 = the solver's estimate.
  bool fixed_step = false;
  std::vector<OptionInfo> options;  // the SolverSpec keys this method uses (besides "method")
  std::unique_ptr<Integrator> (*make)(const SolverSpec&) = nullptr;  // spec already validated
};

// All methods in registry order: rk4, abm, dopri5, bdf, ida.
const std::vector<MethodInfo>& methods();
// "rk4, abm, dopri5, bdf, ida"
std::string methodNames();
// nullptr for an unknown name.
const MethodInfo* findMethod(std::string_view name);
// Whether `name` is a fixed-step method of the registry (false for an unknown name).
bool isFixedStep(std::string_view name);

// Checks the method name and the options that method uses (options it does not use are not
// checked). Throws rb::InputError at spec.loc with every problem found, e.g.
//   "solver.method: unknown integrator 'rk5' (valid: rk4, abm, dopri5, bdf, ida; did you mean
//   'rk4'?)" "solver.rtol: must be > 0 (got 0)"
void validate(const SolverSpec& spec);

// validate(), then the integrator. Throws rb::InputError as validate().
std::unique_ptr<Integrator> makeIntegrator(const SolverSpec& spec);

}  // namespace rb::integ
