#include "workbench/core/strings.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/scenario/build.hpp"
#include "workbench/scenario/reader.hpp"

namespace rb::scenario {
namespace {

// Options that the chosen method does not use are conflicts, not silently ignored.
void checkUnusedOptions(const Node& n, const integ::MethodInfo& m, Reader& r) {
  std::vector<std::string> valid;
  for (const auto& o : m.options) valid.push_back(o.key);
  for (const auto& [k, v] : n.fields) {
    if (k == "method" || !block("solver").key(k)) continue;
    bool used = false;
    for (const auto& o : valid) used = used || o == k;
    if (!used)
      r.error(v, k + " has no effect with method '" + m.name +
                     "' (its options: " + join(valid, ", ") + ")");
  }
}

}  // namespace

void buildSolver(const Node& n, integ::SolverSpec& s, Diagnostics& d) {
  Reader r(n, block("solver"), "solver", d);
  s.loc = n.loc;
  s.method = r.choice("method");
  s.step = r.number("step");
  // Adaptive methods estimate their own initial step unless the scenario gives one.
  if (!r.has("step") && !integ::isFixedStep(s.method)) s.step = 0.0;
  s.rtol = r.number("rtol");
  s.atol = r.number("atol");
  s.max_step = r.number("max_step");
  s.max_order = toInteger<int>(r.number("max_order"));
  s.max_steps = toInteger<long>(r.number("max_steps"));
  s.jacobian = r.choice("jacobian");
  s.stiff = r.choiceOf<integ::StiffTreatment>("stiff");
  s.accept_unstable_step = r.boolean("accept_unstable_step");
  if (const integ::MethodInfo* m = integ::findMethod(s.method)) checkUnusedOptions(n, *m, r);
}

}  // namespace rb::scenario
