#include "workbench/precision/plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <unistd.h>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/precision/answer.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/study/option_checks.hpp"

namespace fs = std::filesystem;

namespace rb::precision {
namespace {

const SourceLoc kCommandLine{"<command line>", 0};
const std::vector<std::string> kIntegrators = {"rk4", "abm", "dopri5", "bdf", "ida"};
// The contact methods of the registry (dynamics/contact_methods.hpp), by name.
const std::vector<std::string> kMethods = [] {
  std::vector<std::string> out;
  for (const dynamics::ContactMethodInfo& i : dynamics::kContactMethodInfos)
    out.emplace_back(i.name);
  return out;
}();

// The ladders (cheap to expensive). Fixed steps: 2 ms is beyond the explicit stability limit of
// the free wheelset spin's creep mode at 20 m/s (docs/contact_dynamics.md, "Time integration"),
// 0.125 ms well inside it; tolerances over the range where dopri5 and BDF are still cheaper than
// the reference.
const std::vector<double> kSteps = {2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4};
const std::vector<double> kTolerances = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
const std::vector<double> kQuickSteps = {1e-3, 5e-4};
const std::vector<double> kQuickTolerances = {1e-3, 1e-5};
const std::vector<double> kLevels = {1.0, 0.1, 0.01};  // [mm] of the first quantity
// The finest relative tolerance of a ladder or the references: about 50 ulp of a double.
constexpr double kFinestTolerance = 1e-14;

// An executable named `name` in a folder of $PATH.
bool onPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::stringstream ss(path);
  for (std::string d; std::getline(ss, d, ':');) {
    std::error_code ec;
    const fs::path p = fs::path(d.empty() ? "." : d) / name;
    if (fs::is_regular_file(p, ec) && access(p.c_str(), X_OK) == 0) return true;
  }
  return false;
}

bool isFixed(const std::string& integrator) {
  return integrator == "rk4" || integrator == "abm";
}

bool isImplicit(const std::string& integrator) {
  return integrator == "bdf" || integrator == "ida";
}

// The solver overrides of one rung or reference. The references and BDF and IDA solve the normal
// forces together with the creep forces (contact.normal_forces = "consistent"): the coupling that
// converges under step refinement, and with the lagged normal forces a Newton iteration sees a
// right-hand side that changes between its iterations (docs/contact_dynamics.md section 4.1).
// solver.max_steps is a work limit: at tight tolerances the solver default (500 internal steps per
// output interval) stops BDF in flange contact.
std::vector<std::string> solverOverrides(const std::string& integrator, double value, double atol,
                                         bool contact, bool reference = false) {
  std::vector<std::string> s = {"solver.method=" + integrator};
  if (isFixed(integrator)) {
    // Steps beyond the stability limit run anyway, so that they show as failed or inaccurate
    // settings in the figure instead of being refused by `check`.
    s.push_back("solver.step=" + formatNumberExact(value));
    s.push_back("solver.accept_unstable_step=true");
    return s;
  }
  s.push_back("solver.rtol=" + formatNumberExact(value));
  s.push_back("solver.atol=" + formatNumberExact(atol));
  s.push_back("solver.max_steps=100000");
  if (contact && (reference || isImplicit(integrator)))
    s.push_back("contact.normal_forces=consistent");
  return s;
}

// The registry row of a model's contact method (dynamics/contact_methods.hpp).
// A guided model (no method) reads as the first row (it has "tables" in the plan, as before).
const dynamics::ContactMethodInfo& methodNamed(std::string_view name) {
  const dynamics::ContactMethodInfo* i = dynamics::methodInfoNamed(name);
  return i ? *i : dynamics::kContactMethodInfos.front();
}
const dynamics::ContactMethodInfo& methodOf(const Model& m) {
  return methodNamed(m.method);
}

// Whether the model has a normal-force coupling to set (the constraint methods; the elastic
// method's normal forces follow from the approach).
bool couplingApplies(const Plan& p, const Model& m) {
  return p.contact && (m.method.empty() || methodOf(m).coupling);
}

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Why the scenario refuses these overrides ("" when it loads).
std::string refusal(const Plan& p, const PrecisionOptions& o, const std::vector<std::string>& ov) {
  try {
    scenario::LoadOptions lo;
    lo.root = o.root;
    lo.overrides = concat(p.base, ov);
    scenario::loadScenario(p.scenario, lo);
    return "";
  } catch (const InputError& e) {
    return e.diagnostics().empty() ? std::string("refused") : e.diagnostics().front().str();
  }
}

scenario::StudyCase makeCase(const Plan& p, const std::vector<std::string>& own,
                             const std::string& role) {
  scenario::StudyCase c;
  c.overrides = concat(p.base, own);
  c.id = scenario::studyCaseId(c.overrides, "");
  c.label = scenario::caseLabel(own);
  c.base = p.scenario;
  c.role = role;
  return c;
}

std::vector<std::string> chosen(const std::string& text, const std::string& option,
                                const std::vector<std::string>& valid,
                                const std::vector<std::string>& fallback) {
  if (text.empty()) return fallback;
  std::vector<std::string> out;
  for (const auto& v : splitList(text, option)) {
    if (std::find(valid.begin(), valid.end(), v) == valid.end())
      throw InputError(kCommandLine, option + ": unknown '" + v + "' (one of " + join(valid) + ")");
    if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
  }
  return out;
}

// The models: the scenario's own contact method first, then the others asked for, each on the
// default tables (and the refined ones with --refine); a guided vehicle has one model.
void addModels(Plan& p, const PrecisionOptions& o, const scenario::ScenarioSpec& spec) {
  if (!p.contact) {
    if (!o.methods.empty() || !o.model_reference.empty())
      throw InputError(kCommandLine,
                       std::string(o.methods.empty() ? "--model-reference" : "--methods") +
                           ": the scenario has no wheel/rail contact (guided vehicle)");
    p.models.push_back({"guided", "", false, {}});
    return;
  }
  const std::string own(nameOf(spec.contact.method));
  if (!o.model_reference.empty() &&
      std::find(kMethods.begin(), kMethods.end(), o.model_reference) == kMethods.end())
    throw InputError(kCommandLine, "--model-reference: unknown '" + o.model_reference +
                                       "' (one of " + join(kMethods) + ")");
  // The constraint methods compare with each other by default; an elastic scenario with itself.
  std::vector<std::string> fallback = {own};
  if (!o.quick && own != "elastic") fallback.push_back(own == "kec" ? "lut" : "kec");
  std::vector<std::string> methods = chosen(o.methods, "--methods", kMethods, fallback);
  // The model reference is a model of the matrix (its references are verified like any other).
  if (!o.model_reference.empty() &&
      std::find(methods.begin(), methods.end(), o.model_reference) == methods.end())
    methods.push_back(o.model_reference);
  for (const auto& m : methods) {
    std::string upper = m == "kec" ? "KEC" : (m == "lut" ? "LUT" : "elastic");
    std::vector<std::string> ov = {"contact.method=" + m};
    if (const std::string why = refusal(p, o, ov); !why.empty()) {
      // A method the command line names is an option the scene cannot use: refused before
      // anything runs. A default comparison method is left out with a note.
      const bool asked = m == o.model_reference || !o.methods.empty();
      if (asked)
        throw InputError(kCommandLine,
                         std::string(m == o.model_reference ? "--model-reference " : "--methods ") +
                             m + ": the scenario refuses contact.method=" + m + ": " + why);
      p.notes.push_back(
          {upper, "", "left out: the scenario refuses contact.method=" + m + ": " + why});
      continue;
    }
    p.models.push_back({upper, m, false, ov});
    if (m == o.model_reference) p.model_reference = upper;
    if (o.refine && methodNamed(m).table)
      p.models.push_back(
          {upper + " refined", m, true, concat(ov, {"profiles.refined_tables=true"})});
    else if (o.refine)
      p.notes.push_back({upper, "", "--refine: the " + m + " method has no contact tables"});
  }
  if (p.models.empty())
    throw InputError(kCommandLine, "--methods: the scenario accepts none of the contact methods");
}

// The references of model `m` (its default-table model carries them; a refined model uses them
// as they are). False when the scenario refuses a reference setting (the model is dropped).
bool addReferences(Plan& p, const PrecisionOptions& o, const Model& m,
                   const std::vector<std::string>& refMethods) {
  std::vector<std::string> tables = m.overrides;
  tables.erase(std::remove(tables.begin(), tables.end(), "profiles.refined_tables=true"),
               tables.end());
  // A guided vehicle has no contact tables to refine (and no profiles{} block to set), nor has
  // the elastic method (its reference is its own model; no table error).
  const bool has_tables = p.contact && methodOf(m).table;
  const bool coupling = couplingApplies(p, m);
  const std::vector<std::string> refined =
      has_tables ? concat(tables, {"profiles.refined_tables=true"}) : tables;
  const double tol = o.reference_tol;
  std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
      {kRoleReference,
       concat(refined, solverOverrides(refMethods[0], tol, tol / 10, coupling, true))},
      {kRoleCheck, concat(refined, solverOverrides(refMethods[1], tol, tol / 10, coupling, true))}};
  if (has_tables || !p.contact)
    runs.push_back({kRoleSameTables,
                    concat(tables, solverOverrides(refMethods[0], tol, tol / 10, coupling, true))});
  for (const auto& [role, ov] : runs) {
    if (const std::string why = refusal(p, o, ov); !why.empty()) {
      p.notes.push_back(
          {m.name, "",
           std::string("left out: its ") + role + " is refused by the scenario: " + why});
      return false;
    }
  }
  for (const auto& [role, ov] : runs)
    p.references.push_back(
        {m.name, role, refMethods[role == kRoleCheck ? 1 : 0], tol, makeCase(p, ov, role)});
  return true;
}

bool isMultiple(double t, double h) {
  const double r = t / h;
  return std::abs(r - std::round(r)) <= 1e-6;
}

// The largest step not above h that a fixed-step run can use with this output interval and
// duration: every output time k * every (and the end, `duration` when given) must lie on the step
// grid (run/compile.cpp refuses the run otherwise), so the step is every / n for the smallest
// integer n that also divides the duration. 0 when none is found.
double onGridStep(double h, double every, double duration) {
  const int n0 = std::max(1, static_cast<int>(std::ceil(every / h - 1e-9)));
  for (int n = n0; n <= n0 + 100000; ++n) {
    const double c = every / n;
    if (duration <= 0.0 || isMultiple(duration, c)) return c;
  }
  return 0.0;
}

// The fixed-step ladder. The defaults are moved onto the scenario's output grid (each to the
// largest step below it that divides the output interval), and the plan says so; a step the user
// gives that does not divide it is refused before anything runs (a skipped setting must never be
// silent).
std::vector<double> fixedSteps(Plan& p, const PrecisionOptions& o, const scenario::RunSpec& run) {
  const double every = run.output_every;
  const double duration = run.duration;
  if (!o.steps.empty()) {
    std::vector<double> steps = splitNumbers(o.steps, "--steps");
    for (double h : steps) {
      if (isMultiple(every, h) && (duration <= 0.0 || isMultiple(duration, h))) continue;
      const double fit = onGridStep(h, every, duration);
      throw InputError(
          kCommandLine,
          "--steps: " + formatNumberExact(h) +
              " s does not divide the output interval run.output.every = " +
              formatNumberExact(every) + " s" +
              (duration > 0.0 ? " and the duration " + formatNumberExact(duration) + " s" : "") +
              " (a fixed-step run must reach every output time on its step grid)" +
              (fit > 0.0 ? "; the largest step below it that does is " + formatNumber(fit) + " s"
                         : "") +
              ", or change the output interval with --set run.output.every=...");
    }
    return steps;
  }
  std::vector<double> steps;
  for (double h : o.quick ? kQuickSteps : kSteps) {
    const double fit = onGridStep(h, every, duration);
    if (fit <= 0.0) {
      p.adaptations.push_back(
          "fixed steps: no step near " + formatNumberExact(h) + " s divides the output interval " +
          formatNumberExact(every) + " s" +
          (duration > 0.0 ? " and the duration " + formatNumberExact(duration) + " s" : "") +
          ": left out");
      continue;
    }
    if (!isMultiple(fit, h) || !isMultiple(h, fit))
      p.adaptations.push_back(
          "fixed steps: " + formatNumberExact(h) +
          " s does not divide the output interval run.output.every = " + formatNumberExact(every) +
          " s" + (duration > 0.0 ? " and the duration " + formatNumberExact(duration) + " s" : "") +
          ": the ladder uses " + formatNumber(fit) + " s instead");
    if (std::find(steps.begin(), steps.end(), fit) == steps.end()) steps.push_back(fit);
  }
  return steps;
}

void addLadders(Plan& p, const PrecisionOptions& o, const Model& m,
                const std::vector<std::string>& integrators, const std::vector<double>& steps) {
  const std::vector<double> tols = !o.tolerances.empty()
                                       ? splitNumbers(o.tolerances, "--tolerances")
                                   : o.quick ? kQuickTolerances
                                             : kTolerances;
  for (const auto& integ : integrators) {
    Ladder l{m.name, integ, isFixed(integ), {}, 0};
    std::vector<double> values = l.fixed ? steps : tols;
    // Cheap to expensive: large steps and loose tolerances first.
    std::sort(values.begin(), values.end(), std::greater<>());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    const auto first = concat(
        m.overrides, solverOverrides(integ, values.front(), values.front(), couplingApplies(p, m)));
    if (const std::string why = refusal(p, o, first); !why.empty()) {
      p.notes.push_back({m.name, integ, "left out: the scenario refuses it: " + why});
      continue;
    }
    for (double v : values) {
      Rung r;
      r.value = v;
      r.c = makeCase(p, concat(m.overrides, solverOverrides(integ, v, v, couplingApplies(p, m))),
                     kRoleCase);
      l.rungs.push_back(r);
    }
    p.ladders.push_back(std::move(l));
  }
}

}  // namespace

std::vector<std::string> splitList(const std::string& text, const std::string& option) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (item.empty()) throw InputError(kCommandLine, option + ": empty entry in '" + text + "'");
    out.push_back(item);
  }
  if (out.empty()) throw InputError(kCommandLine, option + ": no entry");
  return out;
}

std::vector<double> splitNumbers(const std::string& text, const std::string& option) {
  std::vector<double> out;
  for (const auto& item : splitList(text, option)) {
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !(v > 0.0) || v > 1e300)
      throw InputError(kCommandLine, option + ": '" + item + "' is not a positive number");
    out.push_back(v);
  }
  return out;
}

namespace {

// One list option's entries: numbers where numbers are asked for (tolerances in range), names
// among the known ones.
void checkListItems(const std::string& option, const std::string& text, Diagnostics& d) {
  try {
    if (option == "--tolerances") {
      // A relative tolerance is a fraction: 1 or more accepts any answer; below 1e-14 it is
      // under the resolution of a double and only costs work.
      for (double t : splitNumbers(text, option))
        if (!(t >= kFinestTolerance && t < 1.0))
          study::badOption(
              d, option, formatNumber(t),
              "a relative tolerance must be in [" + formatNumber(kFinestTolerance) + ", 1)");
      return;
    }
    if (option == "--steps" || option == "--levels") {
      (void)splitNumbers(text, option);
      return;
    }
    const std::vector<std::string>* valid =
        option == "--methods"                                          ? &kMethods
        : option == "--integrators" || option == "--reference-methods" ? &kIntegrators
                                                                       : nullptr;
    for (const auto& v : splitList(text, option))
      if (valid != nullptr && std::find(valid->begin(), valid->end(), v) == valid->end())
        d.add(kCommandLine, option + ": unknown '" + v + "' (one of " + join(*valid) + ")");
  } catch (const InputError& e) {
    d.add(e);
  }
}

// A list typed empty ('') is refused, not read as the default list.
void checkLists(const PrecisionOptions& o, Diagnostics& d) {
  const std::vector<std::pair<const char*, const std::string*>> lists = {
      {"--methods", &o.methods},
      {"--integrators", &o.integrators},
      {"--steps", &o.steps},
      {"--tolerances", &o.tolerances},
      {"--quantities", &o.quantities},
      {"--levels", &o.levels},
      {"--reference-methods", &o.reference_methods}};
  for (const auto& [option, text] : lists)
    if (o.given.contains(option) || !text->empty()) checkListItems(option, *text, d);
}

// The options that need no scenario: every problem at once, each with its value.
void checkNumbers(const PrecisionOptions& o) {
  Diagnostics d;
  auto typed = [&](const char* option) { return o.given.contains(option); };
  // A length typed as 0 is no default: it would run the scenario's whole length unasked.
  if (typed("--distance") || o.distance != 0.0)
    if (const auto why = study::notPositive(o.distance, 1e12); !why.empty())
      study::badOption(d, "--distance", o.distance, why + " m");
  if (typed("--duration") || o.duration != 0.0)
    if (const auto why = study::notPositive(o.duration, 1e9); !why.empty())
      study::badOption(d, "--duration", o.duration, why + " s");
  if (o.distance > 0.0 && o.duration > 0.0)
    d.add(kCommandLine, "--distance and --duration: give one of them");
  if (!(std::isfinite(o.budget) && o.budget >= 0.0))
    study::badOption(d, "--budget", o.budget, "must be a finite time >= 0 s (0: none)");
  if (!(std::isfinite(o.reference_limit) && o.reference_limit >= 0.0))
    study::badOption(d, "--reference-limit", o.reference_limit,
                     "must be a finite number >= 0 (0: the smallest level / 10)");
  if (!(o.reference_tol >= kFinestTolerance && o.reference_tol < 1e-2))
    study::badOption(d, "--reference-tol", o.reference_tol,
                     "must be in [" + formatNumber(kFinestTolerance) + ", 1e-2)");
  if (o.repeats < 1 || o.repeats > 100)
    study::badOption(d, "--repeats", std::to_string(o.repeats), "must be in 1..100");
  study::checkJobs(d, o.jobs, true);
  checkLists(o, d);
  d.throwIfAny();
}

// Every fixed step must keep a run's work bounded: its number of steps over the run stays under
// the run's output bound (run.output.max_samples), as the output times do.
void checkStepCount(const PrecisionOptions& o, double t_end, double max_samples) {
  if (o.steps.empty() || !(t_end > 0.0)) return;
  Diagnostics d;
  for (double h : splitNumbers(o.steps, "--steps")) {
    const double n = t_end / h;
    if (n > max_samples)
      study::badOption(d, "--steps", formatNumber(h),
                       formatNumber(n) + " steps over the run's " + formatNumber(t_end) +
                           " s, more than run.output.max_samples = " + formatNumber(max_samples) +
                           " (the bound of a run's work; raise it with --set "
                           "run.output.max_samples=N, or shorten the run with --duration)");
  }
  d.throwIfAny();
}

}  // namespace

Plan makePlan(const PrecisionOptions& o) {
  Plan p;
  p.scenario = fs::absolute(o.scenario).lexically_normal().string();
  p.base = o.overrides;
  checkNumbers(o);
  // --callgrind runs valgrind after the whole matrix: its absence must show before the matrix.
  if (o.callgrind && !onPath("valgrind"))
    throw InputError(kCommandLine, "--callgrind: valgrind is not on the PATH");
  std::vector<study::OptionOverride> lengths;
  if (o.distance > 0.0)
    lengths.push_back({"--distance", formatNumberExact(o.distance),
                       "run.distance=" + formatNumberExact(o.distance)});
  if (o.duration > 0.0)
    lengths.push_back({"--duration", formatNumberExact(o.duration),
                       "run.duration=" + formatNumberExact(o.duration)});
  for (const auto& l : lengths) p.base.push_back(l.key_value);

  scenario::LoadOptions lo;
  lo.root = o.root;
  lo.overrides = o.overrides;
  (void)scenario::loadScenario(p.scenario, lo);  // the user's own --set: bad: exit 1
  // The run as every case runs it (the track's end, the output bound): a refusal names the
  // option that shortened it, not the scenario key it became.
  // Every case sets its own integrator: the check runs an adaptive one, so that the scenario's
  // own fixed step does not refuse a length the ladders' steps fit.
  std::vector<std::string> adaptive = o.overrides;
  adaptive.emplace_back("solver.method=dopri5");
  const double t_end = checkOptionOverrides(o, adaptive, lengths);
  lo.overrides = p.base;
  const scenario::ScenarioSpec spec = scenario::loadScenario(p.scenario, lo);
  // A train's contact models are compared through contact.method, the scenario's contact{}:
  // a vehicle with its own would keep its method in every model of the matrix.
  for (const auto& v : spec.train)
    if (v.own_contact)
      throw InputError(v.loc,
                       "train: `workbench precision` compares contact methods through the "
                       "scenario's contact{} block; vehicle '" +
                           v.name +
                           "' gives its own, which no model of the matrix would change "
                           "(give the train one contact{} block)");
  if (!spec.has_vehicle)
    throw InputError({o.scenario, 0},
                     "precision needs a vehicle{} block: nothing is integrated without one");
  checkStepCount(o, t_end, spec.run.max_output_samples);
  p.contact = spec.has_contact;

  p.quantities = o.quantities.empty() ? std::vector<std::string>{"y", "yaw"}
                                      : splitList(o.quantities, "--quantities");
  for (const auto& b : spec.vehicle.bodies) p.bodies.push_back(b.name);
  // A train's body quantities cover every vehicle that has the body.
  for (const auto& v : spec.train)
    for (const auto& b : v.vehicle.bodies)
      if (std::find(p.bodies.begin(), p.bodies.end(), b.name) == p.bodies.end())
        p.bodies.push_back(b.name);
  // Every quantity is checked now, before any run: a mistyped one must not cost the matrix.
  (void)parseQuantities(p.quantities, p.bodies, p.contact);
  p.levels = o.levels.empty() ? kLevels : splitNumbers(o.levels, "--levels");
  std::sort(p.levels.begin(), p.levels.end(), std::greater<>());
  p.limit = o.reference_limit > 0.0 ? o.reference_limit : p.levels.back() / 10.0;

  const auto refMethods =
      chosen(o.reference_methods, "--reference-methods", kIntegrators, {"bdf", "dopri5"});
  if (refMethods.size() != 2)
    throw InputError(kCommandLine, "--reference-methods: give two different integrators");
  const auto integrators =
      chosen(o.integrators, "--integrators", kIntegrators,
             o.quick ? std::vector<std::string>{"abm", "dopri5"}
                     : std::vector<std::string>{"rk4", "abm", "dopri5", "bdf"});

  addModels(p, o, spec);
  std::vector<Model> kept;
  for (const auto& m : p.models) {
    if (!m.refined && !addReferences(p, o, m, refMethods)) continue;
    kept.push_back(m);
  }
  // A refined model whose default-table model was dropped has no reference either.
  std::erase_if(kept, [&](const Model& m) {
    return std::none_of(p.references.begin(), p.references.end(), [&](const Reference& r) {
      return r.model == (m.refined ? m.name.substr(0, m.name.find(' ')) : m.name);
    });
  });
  p.models = kept;
  if (p.models.empty())
    throw InputError({o.scenario, 0},
                     "no contact model of the scenario accepts the reference "
                     "settings (see the notes above)");
  const bool anyFixed = std::any_of(integrators.begin(), integrators.end(), isFixed);
  const std::vector<double> steps = anyFixed ? fixedSteps(p, o, spec.run) : std::vector<double>{};
  for (const auto& m : p.models) addLadders(p, o, m, integrators, steps);
  return p;
}

std::string tablesOf(const std::string& method, const std::string& model) {
  if (!methodNamed(method).table) return "none";
  return model.find("refined") != std::string::npos ? "refined" : "default";
}

std::string planCsv(const Plan& plan) {
  std::ostringstream s;
  s.precision(12);
  s << "folder,case,role,model,method,tables,integrator,kind,value,label,status,note\n";
  for (const auto& r : plan.references) {
    const bool refined = r.role != std::string(kRoleSameTables);
    std::string method;
    for (const auto& m : plan.models)
      if (m.name == r.model) method = m.method;
    s << "reference," << r.c.id << "," << r.role << "," << csvField(r.model) << "," << method << ","
      << (!methodNamed(method).table ? "none" : (refined ? "refined" : "default")) << ","
      << r.integrator << ",tol," << r.value << "," << csvField(r.c.label) << ",planned,\n";
  }
  for (const auto& l : plan.ladders) {
    std::string method;
    for (const auto& m : plan.models)
      if (m.name == l.model) method = m.method;
    for (const auto& r : l.rungs)
      s << "cases," << r.c.id << "," << kRoleCase << "," << csvField(l.model) << "," << method
        << "," << tablesOf(method, l.model) << "," << l.integrator << ","
        << (l.fixed ? "step" : "tol") << "," << r.value << "," << csvField(r.c.label) << ","
        << r.status << "," << csvField(r.note) << "\n";
  }
  for (const auto& n : plan.notes)
    s << ",,note," << csvField(n.model) << ",,," << n.integrator << ",,,,left out,"
      << csvField(n.text) << "\n";
  for (const auto& a : plan.adaptations) s << ",,note,,,,,,,,adapted," << csvField(a) << "\n";
  return s.str();
}

}  // namespace rb::precision
