#include "workbench/integrators/registry.hpp"

#include <cmath>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/integrators/fixed_step.hpp"
#include "workbench/integrators/sundials_integrators.hpp"

namespace rb::integ {
namespace {

template <FixedStepIntegrator::Method M>
std::unique_ptr<Integrator> makeFixed(const SolverSpec& spec) {
  return std::make_unique<FixedStepIntegrator>(M, spec);
}

template <class I>
std::unique_ptr<Integrator> make(const SolverSpec& spec) {
  return std::make_unique<I>(spec);
}

std::vector<MethodInfo> build() {
  const SolverSpec d;
  const OptionInfo fixed_step{"step", "s", formatNumber(d.step),
                              "fixed step; output times must be multiples of it"};
  const OptionInfo init_step{"step", "s", formatNumber(d.step),
                             "initial step, 0 = solver's estimate"};
  const OptionInfo rtol{"rtol", "-", formatNumber(d.rtol), "relative tolerance, in (0, 1)"};
  const OptionInfo atol{"atol", "-", formatNumber(d.atol),
                        "absolute tolerance in state units, > 0"};
  const OptionInfo max_step{"max_step", "s", formatNumber(d.max_step),
                            "largest step, 0 = unlimited"};
  const OptionInfo max_order{"max_order", "-", std::to_string(d.max_order),
                             "maximum BDF order, 1..5"};
  const OptionInfo max_steps{"max_steps", "-", std::to_string(d.max_steps),
                             "internal steps per output interval, 0 = SUNDIALS default (500)"};
  std::string jacobianHelp;
  for (const auto& e : kJacobianModeNames) {
    if (!jacobianHelp.empty()) jacobianHelp += "; ";
    jacobianHelp.append(e.name).append(" = ").append(e.help);
  }
  const OptionInfo jacobian{"jacobian", "-", d.jacobian, jacobianHelp};
  std::string stiffHelp;
  for (const auto& e : kStiffTreatmentNames) {
    if (!stiffHelp.empty()) stiffHelp += "; ";
    stiffHelp.append(e.name).append(" = ").append(e.help);
  }
  const OptionInfo stiff{"stiff", "-", std::string(nameOf(d.stiff)), stiffHelp};
  const OptionInfo accept{"accept_unstable_step", "-", "false",
                          "run a step beyond the stability limit of the model's stiffest mode "
                          "(otherwise check and run refuse it)"};
  return {
      {std::string(kRk4),
       "classical 4th-order Runge-Kutta, fixed step, 4 rhs evaluations per step",
       true,
       {fixed_step, stiff, accept},
       makeFixed<FixedStepIntegrator::Method::Rk4>},
      {std::string(kAbm),
       "4th-order Adams-Bashforth-Moulton predictor-corrector (PECE, paper Eq. 32), fixed step, "
       "started with RK4, 2 rhs evaluations per step",
       true,
       {fixed_step, stiff, accept},
       makeFixed<FixedStepIntegrator::Method::Abm>},
      {std::string(kDopri5),
       "Dormand-Prince 5(4), variable step (ARKODE ERKStep; the method of Matlab's ode45)",
       false,
       {init_step, rtol, atol, max_step, max_steps},
       make<Dopri5Integrator>},
      {std::string(kBdf),
       "variable-order (1..5) variable-step BDF with Newton and dense LU (CVODE) for stiff "
       "problems; stands in for Matlab's ode15s (which uses NDFs)",
       false,
       {init_step, rtol, atol, max_step, max_order, max_steps, jacobian},
       make<BdfIntegrator>},
      {std::string(kIda),
       "variable-order BDF for index-reduced DAEs F(t, y, y') = 0 with consistent initial values "
       "(IDA); also runs ODEs",
       false,
       {init_step, rtol, atol, max_step, max_order, max_steps, jacobian},
       make<IdaIntegrator>},
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

bool isFixedStep(std::string_view name) {
  const MethodInfo* m = findMethod(name);
  return m != nullptr && m->fixed_step;
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
  const bool fixed = m->fixed_step;
  if (uses("step")) {
    if (fixed && !(s.step > 0 && std::isfinite(s.step)))
      d.add(s.loc, "solver.step: must be > 0 (got " + formatNumber(s.step) + ")");
    if (!fixed && !(s.step >= 0 && std::isfinite(s.step)))
      d.add(s.loc, "solver.step: must be >= 0, 0 = automatic initial step (got " +
                       formatNumber(s.step) + ")");
  }
  if (uses("rtol") && !kRtolRange.contains(s.rtol))
    d.add(s.loc, "solver.rtol: must be > 0 and < 1 (got " + formatNumber(s.rtol) + ")");
  if (uses("atol") && !kAtolRange.contains(s.atol))
    d.add(s.loc, "solver.atol: must be > 0 (got " + formatNumber(s.atol) + ")");
  if (uses("max_step")) {
    if (!(s.max_step >= 0 && std::isfinite(s.max_step)))
      d.add(s.loc,
            "solver.max_step: must be >= 0, 0 = unlimited (got " + formatNumber(s.max_step) + ")");
    else if (s.max_step > 0 && s.step > s.max_step)
      d.add(s.loc, "solver.step: the initial step " + formatNumber(s.step) +
                       " s is larger than solver.max_step " + formatNumber(s.max_step) + " s");
  }
  if (uses("max_order") && !kMaxOrderRange.contains(s.max_order))
    d.add(s.loc, "solver.max_order: must be in 1..5 (got " + std::to_string(s.max_order) + ")");
  if (uses("max_steps") && s.max_steps < 0)
    d.add(s.loc, "solver.max_steps: must be >= 0, 0 = solver default (got " +
                     std::to_string(s.max_steps) + ")");
  if (uses("jacobian") && !parse<JacobianMode>(s.jacobian)) {
    const std::vector<std::string> modes = namesOf<JacobianMode>();
    std::string msg =
        "solver.jacobian: unknown value '" + s.jacobian + "' (valid: " + join(modes, ", ");
    const std::string hint = closestMatch(s.jacobian, modes);
    if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
    d.add(s.loc, msg + ")");
  }
  d.throwIfAny();
}

std::unique_ptr<Integrator> makeIntegrator(const SolverSpec& spec) {
  validate(spec);
  const MethodInfo* m = findMethod(spec.method);
  RB_CHECK(m != nullptr && m->make != nullptr,
           "method '" + spec.method + "' is in the registry but not constructible");
  return m->make(spec);
}

}  // namespace rb::integ
