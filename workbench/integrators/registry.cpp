#include "workbench/integrators/registry.hpp"

#include <cmath>
#include <cstdio>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/integrators/fixed_step.hpp"
#include "workbench/integrators/sundials_integrators.hpp"

namespace rb::integ {
namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::vector<MethodInfo> build() {
  const SolverSpec d;
  const OptionInfo fixed_step{"step", "s", fmt(d.step),
                              "fixed step; output times must be multiples of it"};
  const OptionInfo init_step{"step", "s", fmt(d.step), "initial step, 0 = solver's estimate"};
  const OptionInfo rtol{"rtol", "-", fmt(d.rtol), "relative tolerance, in (0, 1)"};
  const OptionInfo atol{"atol", "-", fmt(d.atol), "absolute tolerance in state units, > 0"};
  const OptionInfo max_step{"max_step", "s", fmt(d.max_step), "largest step, 0 = unlimited"};
  const OptionInfo max_order{"max_order", "-", std::to_string(d.max_order),
                             "maximum BDF order, 1..5"};
  const OptionInfo max_steps{"max_steps", "-", std::to_string(d.max_steps),
                             "internal steps per output interval, 0 = SUNDIALS default (500)"};
  const OptionInfo jacobian{"jacobian", "-", d.jacobian,
                            "auto = the model's analytic Jacobian if it has one, else finite "
                            "differences; fd = always finite differences"};
  return {
      {"rk4",
       "classical 4th-order Runge-Kutta, fixed step, 4 rhs evaluations per step",
       {fixed_step}},
      {"abm",
       "4th-order Adams-Bashforth-Moulton predictor-corrector (PECE, paper Eq. 32), fixed step, "
       "started with RK4, 2 rhs evaluations per step",
       {fixed_step}},
      {"dopri5",
       "Dormand-Prince 5(4), variable step (ARKODE ERKStep; the method of Matlab's ode45)",
       {init_step, rtol, atol, max_step, max_steps}},
      {"bdf",
       "variable-order (1..5) variable-step BDF with Newton and dense LU (CVODE) for stiff "
       "problems; stands in for Matlab's ode15s (which uses NDFs)",
       {init_step, rtol, atol, max_step, max_order, max_steps, jacobian}},
      {"ida",
       "variable-order BDF for index-reduced DAEs F(t, y, y') = 0 with consistent initial values "
       "(IDA); also runs ODEs",
       {init_step, rtol, atol, max_step, max_order, max_steps, jacobian}},
  };
}

std::vector<std::string> names() {
  std::vector<std::string> out;
  for (const auto& m : methods()) out.push_back(m.name);
  return out;
}

}  // namespace

const std::vector<MethodInfo>& methods() {
  static const std::vector<MethodInfo> m = build();
  return m;
}

std::string methodNames() {
  return join(names(), ", ");
}

const MethodInfo* findMethod(std::string_view name) {
  for (const auto& m : methods())
    if (m.name == name) return &m;
  return nullptr;
}

void validate(const SolverSpec& s) {
  Diagnostics d;
  const MethodInfo* m = findMethod(s.method);
  if (!m) {
    std::string msg =
        "solver.method: unknown integrator '" + s.method + "' (valid: " + methodNames();
    const std::string hint = closestMatch(s.method, names());
    if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
    d.add(s.loc, msg + ")");
    d.throwIfAny();
  }
  const auto uses = [m](std::string_view key) {
    for (const auto& o : m->options)
      if (o.key == key) return true;
    return false;
  };
  const bool fixed = s.method == "rk4" || s.method == "abm";
  if (uses("step")) {
    if (fixed && !(s.step > 0 && std::isfinite(s.step)))
      d.add(s.loc, "solver.step: must be > 0 (got " + fmt(s.step) + ")");
    if (!fixed && !(s.step >= 0 && std::isfinite(s.step)))
      d.add(s.loc,
            "solver.step: must be >= 0, 0 = automatic initial step (got " + fmt(s.step) + ")");
  }
  if (uses("rtol") && !(s.rtol > 0 && s.rtol < 1))
    d.add(s.loc, "solver.rtol: must be > 0 and < 1 (got " + fmt(s.rtol) + ")");
  if (uses("atol") && !(s.atol > 0 && std::isfinite(s.atol)))
    d.add(s.loc, "solver.atol: must be > 0 (got " + fmt(s.atol) + ")");
  if (uses("max_step")) {
    if (!(s.max_step >= 0 && std::isfinite(s.max_step)))
      d.add(s.loc, "solver.max_step: must be >= 0, 0 = unlimited (got " + fmt(s.max_step) + ")");
    else if (s.max_step > 0 && s.step > s.max_step)
      d.add(s.loc, "solver.step: the initial step " + fmt(s.step) +
                       " s is larger than solver.max_step " + fmt(s.max_step) + " s");
  }
  if (uses("max_order") && !(s.max_order >= 1 && s.max_order <= 5))
    d.add(s.loc, "solver.max_order: must be in 1..5 (got " + std::to_string(s.max_order) + ")");
  if (uses("max_steps") && s.max_steps < 0)
    d.add(s.loc, "solver.max_steps: must be >= 0, 0 = solver default (got " +
                     std::to_string(s.max_steps) + ")");
  if (uses("jacobian") && s.jacobian != "auto" && s.jacobian != "fd") {
    std::string msg = "solver.jacobian: unknown value '" + s.jacobian + "' (valid: auto, fd";
    const std::string hint = closestMatch(s.jacobian, {"auto", "fd"});
    if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
    d.add(s.loc, msg + ")");
  }
  d.throwIfAny();
}

std::unique_ptr<Integrator> makeIntegrator(const SolverSpec& spec) {
  validate(spec);
  if (spec.method == "rk4")
    return std::make_unique<FixedStepIntegrator>(FixedStepIntegrator::Method::Rk4, spec);
  if (spec.method == "abm")
    return std::make_unique<FixedStepIntegrator>(FixedStepIntegrator::Method::Abm, spec);
  if (spec.method == "dopri5") return std::make_unique<Dopri5Integrator>(spec);
  if (spec.method == "bdf") return std::make_unique<BdfIntegrator>(spec);
  if (spec.method == "ida") return std::make_unique<IdaIntegrator>(spec);
  RB_CHECK(false, "method '" + spec.method + "' is in the registry but not constructible");
}

}  // namespace rb::integ
