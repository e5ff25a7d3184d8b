// Registry: names, options, validation messages, "did you mean".
#include <gtest/gtest.h>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/integrators/registry.hpp"

namespace rb::integ {
namespace {

SolverSpec spec(const std::string& method) {
  SolverSpec s;
  s.method = method;
  s.loc = {"scen.lua", 12};
  return s;
}

std::vector<std::string> messages(const SolverSpec& s) {
  try {
    validate(s);
  } catch (const InputError& e) {
    std::vector<std::string> out;
    for (const auto& d : e.diagnostics()) out.push_back(d.str());
    return out;
  }
  return {};
}

TEST(Registry, NamesInOrder) {
  EXPECT_EQ(methodNames(), "rk4, abm, dopri5, bdf, ida");
  ASSERT_EQ(methods().size(), 5u);
  for (const auto& m : methods()) {
    EXPECT_FALSE(m.description.empty());
    EXPECT_EQ(findMethod(m.name), &m);
    auto integ = makeIntegrator(spec(m.name));
    EXPECT_EQ(integ->name(), m.name);
  }
  EXPECT_EQ(findMethod("ode45"), nullptr);
}

TEST(Registry, OptionsPerMethod) {
  const auto keys = [](const std::string& name) {
    std::vector<std::string> k;
    for (const auto& o : findMethod(name)->options) k.push_back(o.key);
    return join(k);
  };
  EXPECT_EQ(keys("rk4"), "step, stiff, accept_unstable_step");
  EXPECT_EQ(keys("abm"), "step, stiff, accept_unstable_step");
  EXPECT_EQ(keys("dopri5"), "step, rtol, atol, max_step, max_steps");
  EXPECT_EQ(keys("bdf"), "step, rtol, atol, max_step, max_order, max_steps, jacobian");
  EXPECT_EQ(keys("ida"), "step, rtol, atol, max_step, max_order, max_steps, jacobian");
  for (const auto& m : methods())
    for (const auto& o : m.options) {
      EXPECT_FALSE(o.unit.empty()) << m.name << "." << o.key;
      EXPECT_FALSE(o.default_value.empty()) << m.name << "." << o.key;
      EXPECT_FALSE(o.help.empty()) << m.name << "." << o.key;
    }
  EXPECT_EQ(findMethod("bdf")->options[1].default_value, "1e-06");
  EXPECT_EQ(findMethod("bdf")->options[6].default_value, "auto");
}

TEST(Registry, UnknownMethodSuggestsClosest) {
  try {
    (void)makeIntegrator(spec("rk5"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "scen.lua:12: solver.method: unknown integrator 'rk5' (valid: rk4, abm, dopri5, "
                 "bdf, ida; did you mean 'rk4'?)");
  }
  EXPECT_EQ(
      messages(spec("dopri")),
      std::vector<std::string>{"scen.lua:12: solver.method: unknown integrator 'dopri' "
                               "(valid: rk4, abm, dopri5, bdf, ida; did you mean 'dopri5'?)"});
  EXPECT_EQ(messages(spec("ode15s")),
            std::vector<std::string>{"scen.lua:12: solver.method: unknown integrator 'ode15s' "
                                     "(valid: rk4, abm, dopri5, bdf, ida)"});
}

TEST(Registry, AllOptionProblemsReportedTogether) {
  SolverSpec s = spec("bdf");
  s.rtol = 0.0;
  s.atol = -1.0;
  s.max_order = 7;
  s.max_steps = -3;
  s.max_step = -1.0;
  s.jacobian = "analytc";
  EXPECT_EQ(messages(s), (std::vector<std::string>{
                             "scen.lua:12: solver.rtol: must be > 0 and < 1 (got 0)",
                             "scen.lua:12: solver.atol: must be > 0 (got -1)",
                             "scen.lua:12: solver.max_step: must be >= 0, 0 = unlimited (got -1)",
                             "scen.lua:12: solver.max_order: must be in 1..5 (got 7)",
                             "scen.lua:12: solver.max_steps: must be >= 0, 0 = solver default "
                             "(got -3)",
                             "scen.lua:12: solver.jacobian: unknown value 'analytc' (valid: auto, "
                             "fd)"}));
  s = spec("bdf");
  s.jacobian = "FD";
  EXPECT_EQ(messages(s), std::vector<std::string>{"scen.lua:12: solver.jacobian: unknown value "
                                                  "'FD' (valid: auto, fd; did you mean 'fd'?)"});
}

TEST(Registry, StepRules) {
  SolverSpec s = spec("rk4");
  s.step = 0.0;
  EXPECT_EQ(messages(s), std::vector<std::string>{"scen.lua:12: solver.step: must be > 0 (got 0)"});
  s.step = std::nan("");
  EXPECT_EQ(messages(s).size(), 1u);
  s = spec("dopri5");
  s.step = 0.0;  // automatic initial step
  EXPECT_TRUE(messages(s).empty());
  s.step = -1e-3;
  EXPECT_EQ(messages(s), std::vector<std::string>{"scen.lua:12: solver.step: must be >= 0, 0 = "
                                                  "automatic initial step (got -0.001)"});
  s.step = 0.1;
  s.max_step = 0.01;
  EXPECT_EQ(messages(s), std::vector<std::string>{"scen.lua:12: solver.step: the initial step "
                                                  "0.1 s is larger than solver.max_step 0.01 s"});
}

TEST(Registry, OptionsAMethodDoesNotUseAreNotChecked) {
  SolverSpec s = spec("rk4");
  s.rtol = -1.0;
  s.max_order = 9;
  s.jacobian = "nonsense";
  EXPECT_TRUE(messages(s).empty());
  s = spec("dopri5");
  s.max_order = 9;
  EXPECT_TRUE(messages(s).empty());
}

TEST(Strings, EditDistanceAndClosestMatch) {
  EXPECT_EQ(editDistance("rk5", "rk4"), 1);
  EXPECT_EQ(editDistance("bfd", "bdf"), 1);  // transposition
  EXPECT_EQ(editDistance("", "abc"), 3);
  EXPECT_EQ(editDistance("ABM", "abm"), 0);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3);
  const std::vector<std::string> names = {"rk4", "abm", "dopri5", "bdf", "ida"};
  EXPECT_EQ(closestMatch("rk5", names), "rk4");
  EXPECT_EQ(closestMatch("BDF", names), "bdf");
  EXPECT_EQ(closestMatch("dorpi5", names), "dopri5");
  EXPECT_EQ(closestMatch("xyz", names), "");
  EXPECT_EQ(closestMatch("", names), "");
  EXPECT_EQ(join({"a", "b", "c"}), "a, b, c");
  EXPECT_EQ(join({}, "; "), "");
}

}  // namespace
}  // namespace rb::integ
