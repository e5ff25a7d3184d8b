#pragma once
// Solver choice as read from a scenario's solver{} block. Strings stay at this boundary: the
// registry turns `method` into an integrator and lists valid names/options for errors and help.
#include <array>
#include <string>
#include <string_view>

#include "workbench/core/error.hpp"
#include "workbench/core/names.hpp"
#include "workbench/core/range.hpp"

namespace rb::integ {

// Registry names of the integrators (registry.cpp pairs each with its factory, its kind and its
// options; the integrators' name() returns them).
inline constexpr std::string_view kRk4 = "rk4";
inline constexpr std::string_view kAbm = "abm";
inline constexpr std::string_view kDopri5 = "dopri5";
inline constexpr std::string_view kBdf = "bdf";
inline constexpr std::string_view kIda = "ida";

// Admissible ranges of the tolerances and the BDF order (the scenario schema shows and checks
// them, validate() of the registry guards SolverSpecs made without a scenario).
inline constexpr Range kRtolRange{0.0, 1.0, true, true};                                // [-]
inline constexpr Range kAtolRange{0.0, std::numeric_limits<double>::infinity(), true};  // [-]
inline constexpr Range kMaxOrderRange{1.0, 5.0};                                        // [-]

// Where the Newton iterations of bdf and ida take their Jacobian from (SolverSpec::jacobian).
enum class JacobianMode { Auto, Fd };
inline constexpr std::array<NameEntry<JacobianMode>, 2> kJacobianModeNames = {{
    {JacobianMode::Auto, "auto",
     "the model's analytic Jacobian if it has one, else finite differences"},
    {JacobianMode::Fd, "fd", "always finite differences"},
}};
constexpr const auto& nameTable(JacobianMode /*tag*/) {
  return kJacobianModeNames;
}

// How the fixed-step methods integrate the components the model declares stiff
// (OdeSystem::stiffComponents: free wheelset spin rates, series-damper forces): classically, or
// exponentially on their diagonal Jacobian entry (exponential.hpp).
enum class StiffTreatment { Explicit, Exponential };
inline constexpr std::array<NameEntry<StiffTreatment>, 2> kStiffTreatmentNames = {{
    {StiffTreatment::Explicit, "explicit",
     "the method's own formula for every component (the paper's RK4 and ABM)"},
    {StiffTreatment::Exponential, "exponential",
     "stiff components (free wheelset spin rates, series-damper forces) integrated exponentially "
     "on their diagonal Jacobian entry (ETDRK4, exponential Adams); the rest as explicit"},
}};
constexpr const auto& nameTable(StiffTreatment /*tag*/) {
  return kStiffTreatmentNames;
}

struct SolverSpec {
  std::string method{kAbm};  // registry name: rk4, abm, dopri5, bdf, ida
  double step = 1e-3;        // [s] fixed step (rk4, abm); initial step hint for adaptive (0 = auto)
  double rtol = 1e-6;        // [-] relative tolerance (adaptive methods)
  double atol = 1e-6;        // [-] absolute tolerance, in state units (adaptive methods)
  double max_step = 0.0;     // [s] maximum step, 0 = unlimited (adaptive methods)
  int max_order = 5;         // [-] BDF maximum order 1..5
  long max_steps = 0;        // [-] cap on internal steps per output interval, 0 = solver default
  // A JacobianMode name: "auto" (model's if it has one, else finite differences), "fd".
  std::string jacobian{nameOf(JacobianMode::Auto)};
  StiffTreatment stiff = StiffTreatment::Exponential;  // rk4, abm
  // Run a fixed step beyond the stability limit of the model's stiffest mode anyway (studies of
  // the paper's settings); otherwise compile() refuses it.
  bool accept_unstable_step = false;
  SourceLoc loc;
};

}  // namespace rb::integ
