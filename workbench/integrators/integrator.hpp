#pragma once
// Integrator interface and the driver integrate() (paper section 4). One Integrator per
// method (made by makeIntegrator() in registry.hpp from a SolverSpec); integrate() runs it over a
// list of output times and turns every failure into a RunResult instead of a crash.
//
// Failure policy (docs/integrators.md):
//  - fatal rhs (< 0), SUNDIALS errors, too many steps, NaN/Inf: RunResult{ok = false} with a
//    message naming the method, the last time with a valid solution, the reason (SUNDIALS flag name
//    and SUNDIALS' own message text, SUNDIALS never prints to stderr), and the offending state
//    components (non-finite ones, or the largest weighted local errors).
//  - the observer has been called for every output time up to the failure (partial output).
//  - exceptions thrown by the model (rhs, jacobian, residual) propagate out of integrate(), also
//    through SUNDIALS (caught in the callback, rethrown after the solver returned).
#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "workbench/core/names.hpp"
#include "workbench/integrators/ode.hpp"
#include "workbench/integrators/spec.hpp"

namespace rb::integ {

// Work counters of one run. A plain struct: printed and stored by the app.
struct Stats {
  // Time inside integrate(), observer and progress callbacks included (like tic/toc around a
  // Matlab ode call). In Progress reports cpu_time_s is refreshed at most every 0.2 s.
  double cpu_time_s = 0.0;            // process CPU time
  double wall_time_s = 0.0;           // wall-clock time
  double callback_wall_time_s = 0.0;  // wall time spent in the observer/progress (included above)
  long rhs_evals = 0;      // rhs (ida: residual) evaluations, excluding finite-difference Jacobians
  long rhs_evals_jac = 0;  // rhs/residual evaluations spent on finite-difference Jacobians
  long steps = 0;          // accepted steps (fixed-step methods: substeps of split steps count)
  long rejected_steps = 0;   // error-test failures + nonlinear-solver failures + steps discarded
                             // after a recoverable rhs failure
  long jacobian_evals = 0;   // Jacobian evaluations (analytic or finite differences; bdf, ida)
  long nonlinear_iters = 0;  // Newton iterations (bdf, ida)
  long nonlinear_conv_fails = 0;      // Newton convergence failures (bdf, ida)
  long recoverable_rhs_failures = 0;  // rhs returned > 0, or (adaptive methods) NaN/Inf in y/ydot
};

// What ended a failed run, as the integrator saw it; the model's own reason (wheel lift, a contact
// point leaving its table) is RunResult::cause when the kind is Model.
enum class FailureKind : std::uint8_t {
  None,       // the run did not fail
  Model,      // the model refused its evaluation (fatal, or recoverable down to the smallest step)
  NonFinite,  // NaN/Inf in the state, a derivative or an output
  StepSize,   // the error test kept failing down to the smallest step
  TooMuchWork,  // the step limit (solver.max_steps) was reached
  Convergence,  // the Newton iteration of an implicit method kept failing
  Solver,       // another error of the solver
  Setup,        // the solver could not be set up
  Validity,     // an output left the model's validity (the run's checks)
};
inline constexpr std::array<NameEntry<FailureKind>, 9> kFailureKindNames = {{
    {FailureKind::None, "none", "the run did not fail"},
    {FailureKind::Model, "model", "the model refused its evaluation (failure_reason says why)"},
    {FailureKind::NonFinite, "non_finite", "NaN/Inf in the state, a derivative or an output"},
    {FailureKind::StepSize, "step_size", "the error test kept failing down to the smallest step"},
    {FailureKind::TooMuchWork, "too_much_work", "the step limit solver.max_steps was reached"},
    {FailureKind::Convergence, "convergence", "the Newton iteration kept failing"},
    {FailureKind::Solver, "solver", "another error of the solver"},
    {FailureKind::Setup, "setup", "the solver could not be set up"},
    {FailureKind::Validity, "validity", "an output left the model's validity"},
}};
constexpr const auto& nameTable(FailureKind /*tag*/) {
  return kFailureKindNames;
}

struct RunResult {
  bool ok = false;
  bool stopped_by_observer = false;  // ok, but the observer returned false at t_reached
  std::string message;               // empty on a complete successful run
  double t_reached = 0.0;            // last time with a valid solution (final time when complete)
  double t_fail = std::numeric_limits<double>::quiet_NaN();  // == t_reached when !ok, else NaN
  std::vector<int> offending_components;                     // state indices blamed for a failure
  FailureKind failure = FailureKind::None;                   // what ended a failed run
  ModelFailure cause;  // the model's reason and body (failure == Model)
  Stats stats;
};

// Called at t0 and at each output time with the state there; return false to stop early.
using Observer = std::function<bool(double t, const Eigen::VectorXd& y)>;
// Optional: called after each observed output time with the statistics so far.
using Progress = std::function<void(double t, const Stats& stats)>;

class Integrator;

// Integrates the ODE from (t0, y0), observing at t0 and at each of output_times (strictly
// increasing, all > t0). Fixed-step methods (rk4, abm) need every output time on the step grid
// t0 + k * step: throws rb::InputError at spec().loc otherwise. Variable-step methods interpolate
// (dense output) at the output times; outputs never force extra steps.
RunResult integrate(OdeSystem& sys, Integrator& integrator, double t0, const Eigen::VectorXd& y0,
                    const std::vector<double>& output_times, const Observer& observer,
                    const Progress& progress = {});

// Index-reduced DAE F(t, y, y') = 0 (only methods with supportsDae(), i.e. ida; others throw
// rb::InputError at spec().loc). y0/yp0 are guesses: IDACalcIC makes the algebraic components of
// y0 and the derivatives of the differential components consistent before the first step; the
// observer sees the consistent y at t0.
RunResult integrate(DaeSystem& sys, Integrator& integrator, double t0, const Eigen::VectorXd& y0,
                    const Eigen::VectorXd& yp0, const std::vector<double>& output_times,
                    const Observer& observer, const Progress& progress = {});

class Integrator {
 public:
  explicit Integrator(SolverSpec spec) : spec_(std::move(spec)) {}
  virtual ~Integrator() = default;
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;

  const SolverSpec& spec() const { return spec_; }
  virtual std::string_view name() const = 0;  // registry name: "rk4", "abm", ...
  virtual bool isFixedStep() const = 0;
  virtual bool supportsDae() const { return false; }

 protected:
  // Implementations; integrate() validates the arguments, wraps the callbacks (timing) and fills
  // the time fields of Stats. An Integrator can run several times, one run at a time.
  virtual RunResult runOde(OdeSystem& sys, double t0, const Eigen::VectorXd& y0,
                           const std::vector<double>& output_times, const Observer& observer,
                           const Progress& progress) = 0;
  virtual RunResult runDae(DaeSystem& sys, double t0, const Eigen::VectorXd& y0,
                           const Eigen::VectorXd& yp0, const std::vector<double>& output_times,
                           const Observer& observer, const Progress& progress);

  friend RunResult integrate(OdeSystem&, Integrator&, double, const Eigen::VectorXd&,
                             const std::vector<double>&, const Observer&, const Progress&);
  friend RunResult integrate(DaeSystem&, Integrator&, double, const Eigen::VectorXd&,
                             const Eigen::VectorXd&, const std::vector<double>&, const Observer&,
                             const Progress&);

 private:
  SolverSpec spec_;
};

}  // namespace rb::integ
