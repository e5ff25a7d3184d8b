#include "workbench/app/scenario_command.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>

#include "workbench/effects/effects.hpp"
#include "workbench/precision/precision.hpp"
#include "workbench/stress/stress.hpp"

namespace rb::app {

CLI::App* addScenarioCommand(CLI::App& app, const std::string& name, const std::string& description,
                             ScenarioCommandOptions& o) {
  auto* c = app.add_subcommand(name, description);
  c->add_option("scenario", o.scenario, "scenario file (.lua)")->required();
  c->add_option("--set", o.overrides, "override a scenario value in every case: block.key=value")
      ->allow_extra_args(false);
  c->add_option("--out", o.out, "output folder (default out/<scenario>_" + name + ")");
  c->add_option("--jobs", o.jobs,
                "runs at once, 0..4 x cores (default 0: cores; 1 for quiet CPU timings)");
  return c;
}

// The command lines of the commands on a scenario, here together: CLI11 is header-only and costs
// about 8 s of compile time in every translation unit that declares options with it.

CLI::App* addEffectsCommand(CLI::App& app, effects::EffectsOptions& o) {
  auto* c = addScenarioCommand(
      app, "effects",
      "each optional effect of the scene switched off in turn: what it costs (instructions per "
      "evaluation) and what it changes in the answer",
      o);
  c->add_option("--repeats", o.repeats,
                "runs per case (1..100), CPU time per evaluation is their median")
      ->capture_default_str();
  c->add_option("--duration", o.duration,
                "simulated time of every case [s] > 0, on the track (default: the scene's)");
  c->add_option("--distance", o.distance,
                "distance of every case [m] > 0, on the track (default: the scene's)");
  c->add_option("--cost-duration", o.cost_duration,
                "simulated time of each case's callgrind run [s], on the track")
      ->capture_default_str();
  for (const char* name : {"--repeats", "--duration", "--distance", "--cost-duration"})
    c->get_option(name)->each([&o, name](const std::string&) { o.given.insert(name); });
  c->add_flag("--no-callgrind", o.no_callgrind, "skip the instruction counts (valgrind)");
  c->add_flag("--quick", o.quick, "a smoke test: 0.2 s, one repeat, no callgrind");
  c->add_option("--quantities", o.quantities,
                "change in answer over every wheelset: y, yaw, Q, Fy (comma separated)")
      ->capture_default_str();
  return c;
}

CLI::App* addCriticalSpeedCommand(CLI::App& app, critical_speed::CriticalSpeedOptions& o) {
  auto* c = addScenarioCommand(app, "critical-speed",
                               "nonlinear critical speed: ramp-down or bisection, bifurcation "
                               "diagram",
                               o);
  c->add_option("--method", o.method, "ramp, bisection or both")
      ->check(CLI::IsMember({"ramp", "bisection", "both"}));
  c->add_option("--criterion", o.criterion, "amplitude or en14363")
      ->check(CLI::IsMember({"amplitude", "en14363"}));
  c->add_option("--contact", o.contact,
                "contact method kec, lut or elastic (default: the scenario's)");
  c->add_flag("--no-plots", o.no_plots, "no figures");
  c->add_option("--from", o.from,
                "start speed [m/s], (0, 200] (default: the scene's speed, then x1.2 until "
                "hunting)")
      ->each([&o](const std::string&) { o.from_given = true; });
  c->add_option("--to", o.to,
                "end speed of the ramp and low end of the bracket [m/s], (0, 200] "
                "(default: half the start speed)")
      ->each([&o](const std::string&) { o.to_given = true; });
  c->add_option("--max-speed", o.max_speed, "highest probe without --from [m/s], (0, 200] (150)");
  c->add_option("--kick", o.kick,
                "lateral offset of the first wheelset at t = 0 [m], 0 < |kick| <= 0.02 (0.005)");
  c->add_option("--deceleration", o.deceleration,
                "deceleration of the ramp [m/s^2], [0.05, 20] (0.5)");
  c->add_option("--duration", o.duration, "duration of a constant-speed run [s], <= 600 (10)");
  c->add_option("--window", o.window, "amplitude window [s], >= 0.05 (1)");
  c->add_option("--transient", o.transient, "time after the kick left out [s] (1)");
  c->add_option("--threshold", o.threshold,
                "limit-cycle amplitude threshold [m], [1e-7, 0.02] (1e-4; 1e-3 with "
                "irregularities)");
  c->add_option("--decay", o.decay, "decay factor last/middle window of a stable run (0.8)");
  c->add_option("--tolerance", o.tolerance,
                "bracket width of the bisection [m/s], at least 1e-4 x the highest speed "
                "(--from, else --max-speed) (0.5)");
  c->add_flag("--irregular", o.irregular, "keep the scenario's track irregularities");
  return c;
}

CLI::App* addModesCommand(CLI::App& app, modes::ModesOptions& o) {
  auto* c = addScenarioCommand(
      app, "modes", "linearised stability: modes, damping versus speed, linear critical speed", o);
  c->add_option("--speeds", o.speeds,
                "speeds a:b:n [m/s]: 0 < a <= b <= 200, n <= 200 (default: the scenario's speed)");
  c->add_option("--contact", o.contact,
                "contact method kec, lut or elastic (default: the scenario's)");
  c->add_flag("--no-plots", o.no_plots, "no figures");
  c->add_option("--distance", o.distance,
                "travelled distance [m] of the linearisation point, on the track (default 0: the "
                "start; in a constant-radius curve the steady state is the curving equilibrium)");
  c->add_option("--fd-scale", o.fd_scale,
                "factor on the finite-difference steps of the Jacobian (default 1: 1e-8 m/rad, "
                "1e-7 m/s, 0.01 N)");
  return c;
}

namespace {

// Records that `option` was typed (PrecisionOptions::given).
std::function<void(const std::string&)> markGiven(precision::PrecisionOptions& o,
                                                  const std::string& option) {
  return [&o, option](const std::string&) { o.given.insert(option); };
}

}  // namespace

CLI::App* addPrecisionCommand(CLI::App& app, precision::PrecisionOptions& o) {
  auto* c = addScenarioCommand(
      app, "precision",
      "what accuracy costs in time: a verified reference, contact methods x integrators x "
      "steps / tolerances, errors, Pareto fronts and the cheapest setting per accuracy level",
      o);
  c->add_option("--methods", o.methods,
                "contact methods, e.g. kec,lut,elastic (default: the scenario's and the other "
                "constraint method; an elastic scenario: elastic)");
  c->add_option("--model-reference", o.model_reference,
                "a contact method whose verified reference the other models' references are "
                "compared with: their model error beside the integration and table errors "
                "(e.g. elastic; added to --methods)");
  c->add_option("--integrators", o.integrators,
                "integrators of the matrix: rk4,abm,dopri5,bdf,ida (default rk4,abm,dopri5,bdf)");
  c->add_option("--steps", o.steps,
                "fixed-step ladder [s], each dividing the output interval and at most "
                "run.output.max_samples steps per run (default 2e-3,1e-3,5e-4,2.5e-4,1.25e-4)");
  c->add_option("--tolerances", o.tolerances,
                "tolerance ladder, rtol = atol, each in [1e-14, 1) (default 1e-3,1e-4,...,1e-8)");
  c->add_option("--quantities", o.quantities,
                "error quantities: y, yaw (every wheelset; guided: every body), Q, Fy, Y, YQ "
                "(every wheel; Y/Q of EN 14363), BODY.y|z|roll|pitch|yaw (default y,yaw)");
  c->add_option("--levels", o.levels,
                "accuracy levels of the recommendation, in the first quantity's display unit "
                "(default 1,0.1,0.01 mm)");
  c->add_option("--repeats", o.repeats,
                "runs per setting (1..100); the cost is their median CPU time")
      ->capture_default_str();
  c->add_option("--distance", o.distance,
                "run distance [m] > 0, on the track (shortens the scenario's run)");
  c->add_option("--duration", o.duration,
                "run duration [s] > 0, on the track (shortens the scenario's run)");
  c->add_option("--budget", o.budget,
                "wall-time target [s]: later rungs of a ladder whose estimated cost does not fit "
                "are skipped (docs/precision.md)");
  c->add_option("--reference-methods", o.reference_methods,
                "the two integrators of the verified reference (default bdf,dopri5)");
  c->add_option("--reference-tol", o.reference_tol, "the references' rtol (atol = rtol / 10)")
      ->capture_default_str();
  c->add_option("--reference-limit", o.reference_limit,
                "largest difference of the two references that verifies them, display units "
                "(default: the smallest level / 10)");
  c->add_flag("--quick", o.quick,
              "a tiny matrix (the scenario's method; abm and dopri5, two settings each; 1 "
              "repeat) for tests");
  c->add_flag("--refine", o.refine, "also run the matrix on the refined contact tables");
  c->add_flag("--callgrind", o.callgrind,
              "count the instructions of the recommended settings under valgrind's callgrind");
  for (const char* name :
       {"--methods", "--model-reference", "--integrators", "--steps", "--tolerances",
        "--quantities", "--levels", "--repeats", "--distance", "--duration", "--budget",
        "--reference-methods", "--reference-tol", "--reference-limit", "--jobs"})
    c->get_option(name)->each(markGiven(o, name));
  return c;
}

CLI::App* addStressCommand(CLI::App& app, stress::StressOptions& o) {
  auto* c = addScenarioCommand(
      app, "stress",
      "hardened variants of a scenario against their own reference: the stability map", o);
  c->add_option("--axes", o.axes,
                "axes to harden along (default all that apply): nominal, flange_stiffness, "
                "transition, speed, irregularity, friction, curve_radius")
      ->delimiter(',');
  c->add_option("--values", o.values,
                "values of one axis: AXIS=v1,v2,... (flange_stiffness [N/m^1.5], transition "
                "[m], friction [-]; speed, irregularity, curve_radius: factors on the nominal); at "
                "most 20 values per axis, 1000 runs in all")
      ->allow_extra_args(false);
  c->add_option(
       "--integrators", o.integrators,
       "at most 10 settings METHOD:VALUE[:paper] (step [s] of rk4/abm, tolerance in [1e-14, 1) of "
       "dopri5/bdf/ida; "
       "default rk4:1e-3,abm:1e-3,dopri5:1e-6,bdf:1e-6)")
      ->delimiter(',');
  c->add_option("--reference", o.reference, "the reference setting of every hardened case")
      ->capture_default_str();
  c->add_option("--tolerance", o.tolerance,
                "largest wheelset lateral error [mm] against the reference of an ok run")
      ->capture_default_str();
  c->add_option("--run-timeout", o.run_timeout,
                "wall time [s] after which a run is killed and classified as failed badly (a "
                "hang); 0: no limit")
      ->capture_default_str();
  c->add_flag("--quick", o.quick,
              "the hardest value of each axis, rk4:1e-3 and dopri5:1e-6, runs of at most 2 s");
  c->add_option("--expect", o.expect,
                "expectation file: AXIS, VALUE, INTEGRATOR, OUTCOME[|OUTCOME] per line; exit 5 "
                "and the mismatches when an outcome differs")
      ->check(CLI::ExistingFile);
  return c;
}

}  // namespace rb::app
