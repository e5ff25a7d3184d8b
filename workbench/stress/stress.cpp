#include "workbench/stress/stress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/scenario/study.hpp"
#include "workbench/stress/plan.hpp"
#include "workbench/stress/verdict.hpp"
#include "workbench/study/jobs.hpp"
#include "workbench/study/option_checks.hpp"
#include "workbench/study/runner.hpp"

namespace rb::stress {

namespace fs = std::filesystem;

namespace {

// Bounds of the matrix (docs/stress.md, "Limits"): every value and every setting is a run of
// its own, and each hardened case also runs its reference.
constexpr std::size_t kMaxValues = 20;    // values of one axis
constexpr std::size_t kMaxSettings = 10;  // integrator settings
constexpr std::size_t kMaxRuns = 1000;    // runs of the whole matrix

std::map<std::string, std::vector<double>> parseValues(const std::vector<std::string>& given) {
  std::map<std::string, std::vector<double>> out;
  Diagnostics d;
  for (const auto& g : given) {
    const auto eq = g.find('=');
    if (eq == std::string::npos || eq + 1 == g.size()) {
      d.add(study::kOptionLoc, "--values '" + g + "': expected AXIS=v1,v2,...");
      continue;
    }
    std::vector<double>& vs = out[g.substr(0, eq)];
    std::istringstream in(g.substr(eq + 1));
    std::string tok;
    std::size_t count = 0;
    while (std::getline(in, tok, ',')) {
      // Counted before parsing: a list of 10 000 values is refused without reading them all.
      if (++count > kMaxValues) {
        d.add(study::kOptionLoc, "--values " + g.substr(0, eq) + "=...: more than " +
                                     std::to_string(kMaxValues) +
                                     " values of one axis (each is a run "
                                     "of every setting and a reference)");
        break;
      }
      try {
        std::size_t used = 0;
        const double v = std::stod(tok, &used);
        if (used != tok.size() || !(v > 0) || !std::isfinite(v)) throw std::invalid_argument(tok);
        vs.push_back(v);
      } catch (const std::exception&) {
        d.add(study::kOptionLoc, "--values '" + g.substr(0, std::min<std::size_t>(g.size(), 80)) +
                                     "': '" + tok + "' is not a positive finite number");
      }
    }
  }
  d.throwIfAny();
  return out;
}

// The options that need no scenario, all at once with their values.
void checkStressOptions(const StressOptions& o) {
  Diagnostics d;
  if (!(std::isfinite(o.tolerance) && o.tolerance > 0.0))
    study::badOption(d, "--tolerance", o.tolerance, "must be a finite error > 0 mm");
  if (!(std::isfinite(o.run_timeout) && o.run_timeout >= 0.0))
    study::badOption(d, "--run-timeout", o.run_timeout,
                     "must be a finite time >= 0 s (0: no limit)");
  if (o.integrators.size() > kMaxSettings)
    study::badOption(d, "--integrators", std::to_string(o.integrators.size()) + " settings",
                     "at most " + std::to_string(kMaxSettings) + " settings");
  study::checkJobs(d, o.jobs, true);
  const auto& names = stress::axisNames();
  const auto known = [&](const std::string& a) {
    return std::find(names.begin(), names.end(), a) != names.end();
  };
  for (const auto& a : o.axes)
    if (!known(a))
      d.add(study::kOptionLoc,
            "--axes: unknown axis '" + a + "' (axes: " + rb::join(names, ", ") + ")");
  for (const auto& g : o.values) {
    const std::string name = g.substr(0, g.find('='));
    if (g.find('=') != std::string::npos && (!known(name) || name == "nominal"))
      d.add(study::kOptionLoc,
            "--values: unknown axis '" + name + "' (axes: " + rb::join(names, ", ") + ")");
  }
  try {
    (void)parseValues(o.values);
  } catch (const InputError& e) {
    d.add(e);
  }
  d.throwIfAny();
}

std::vector<stress::Setting> settings(const StressOptions& o, const scenario::ScenarioSpec& spec) {
  std::vector<std::string> given = o.integrators;
  if (given.empty())
    given = o.quick ? std::vector<std::string>{"rk4:1e-3", "dopri5:1e-6"}
                    : std::vector<std::string>{"rk4:1e-3", "abm:1e-3", "dopri5:1e-6", "bdf:1e-6"};
  std::vector<stress::Setting> out;
  for (const auto& g : given)
    out.push_back(stress::parseSetting(g, stress::normalForceCouplings(spec), "--integrators",
                                       spec.solver.max_step));
  return out;
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}

// The study of every hardened case x (reference + settings), and the table that tells the
// classification which case is which (stress_cases.csv).
struct Expanded {
  scenario::StudySpec study;
  std::ostringstream table;
};

void addCase(Expanded& e, const stress::Hardened& h, const stress::Setting& s,
             const std::vector<std::string>& common, const std::string& role) {
  std::vector<std::string> ov = common;
  ov.insert(ov.end(), h.overrides.begin(), h.overrides.end());
  ov.insert(ov.end(), s.overrides.begin(), s.overrides.end());
  scenario::StudyCase c;
  c.id = scenario::studyCaseId(ov, "");
  c.overrides = ov;
  c.label = h.axis + "=" + h.valueLabel + " " + s.label;
  c.base = e.study.base;
  c.role = role;
  e.table << c.id << "," << h.axis << "," << formatNumber(h.value, 12) << ","
          << csvField(h.valueLabel) << "," << csvField(s.label) << "," << role << ","
          << formatNumber(h.tEnd, 12) << "," << csvField(join(ov)) << "\n";
  e.study.cases.push_back(std::move(c));
}

// Every hardened case must be a valid scenario: a value out of a key's range is bad input.
// A refusal names the axis value the user asked for (--values, or the default of --axes), not
// only the scenario key it became; every case is checked, every problem reported.
void validate(const StressOptions& o, const std::vector<std::string>& common,
              const stress::Plan& plan, const stress::Setting& reference) {
  Diagnostics d;
  for (const auto& h : plan.cases) {
    std::vector<std::string> ov = common;
    ov.insert(ov.end(), h.overrides.begin(), h.overrides.end());
    ov.insert(ov.end(), reference.overrides.begin(), reference.overrides.end());
    try {
      loadCommandScenario(o, ov);
    } catch (const InputError& e) {
      std::string keys;
      for (const auto& k : h.overrides) keys += (keys.empty() ? "" : " ") + k;
      for (const auto& x : e.diagnostics())
        d.add(study::kOptionLoc, "axis " + h.axis + " value " + formatNumber(h.value, 12) +
                                     " (--values " + h.axis + "=...; " + keys + "): " + x.str());
    }
  }
  d.throwIfAny();
}

// Every setting's work is bounded: a fixed step's count over the run stays under the run's
// output bound (run.output.max_samples), a tolerance is a fraction in [1e-14, 1).
void checkSettings(const std::vector<std::string>& given, const std::string& option, double t_end,
                   double max_samples) {
  Diagnostics d;
  for (const auto& g : given) {
    const auto c1 = g.find(':');
    if (c1 == std::string::npos) continue;  // parseSetting names it
    const std::string m = g.substr(0, c1);
    const auto c2 = g.find(':', c1 + 1);
    double v = 0.0;
    try {
      v = std::stod(g.substr(c1 + 1, c2 == std::string::npos ? std::string::npos : c2 - c1 - 1));
    } catch (const std::exception&) {
      continue;
    }
    if (!std::isfinite(v) || !(v > 0.0)) {
      study::badOption(d, option, g, "the value must be a positive finite number");
    } else if (m == "rk4" || m == "abm") {
      if (t_end > 0.0 && t_end / v > max_samples)
        study::badOption(d, option, g,
                         formatNumber(t_end / v) + " steps over the run's " + formatNumber(t_end) +
                             " s, more than run.output.max_samples = " + formatNumber(max_samples) +
                             " (raise it with --set run.output.max_samples=N)");
    } else if (!(v >= 1e-14 && v < 1.0)) {
      study::badOption(d, option, g, "a relative tolerance must be in [1e-14, 1)");
    }
  }
  d.throwIfAny();
}

// The verdict on every run of the folder: stress.csv, the map as text, stress_map.png (drawn by
// plots/rbplot stress from stress.csv) and the expectations. The command's exit code.
int judge(const StressOptions& o, const std::string& dir,
          const std::vector<stress::Expectation>& expectations) {
  const std::vector<StressRow> rows = evaluate(dir, o.tolerance, Bounds{});
  const fs::path csv = fs::path(dir) / "stress.csv";
  study::detail::writeAtomically(csv, stressCsv(rows));
  std::cout << textMap(rows, o.tolerance) << csv.string() << "\n";
  int rc = 0;
  const char* plots = std::getenv("RAILBENCH_STUDY_PLOTS");
  if (!rows.empty() && !(plots != nullptr && std::string(plots) == "0")) {
    study::StudyOptions so;
    so.root = o.root;
    const int code =
        study::runRbplot(so, {"stress", dir, "--tolerance", formatNumber(o.tolerance, 12)});
    if (code != 0) {
      std::cerr << "stress: the figure failed"
                << (code < 0 ? " (python3 or " + o.root + "/plots/railbench not found)" : "")
                << "; the verdict above stands\n";
      rc = 4;
    }
  }
  if (!rows.empty() && std::all_of(rows.begin(), rows.end(), [](const StressRow& r) {
        return r.message.rfind("no result", 0) == 0;
      })) {
    std::cerr << "stress: no run left a result\n";
    return 2;
  }
  const auto mismatches = checkExpectations(rows, expectations);
  if (!mismatches.empty()) {
    std::cout << "\n" << mismatches.size() << " outcomes differ from " << o.expect << ":\n";
    for (const auto& m : mismatches) std::cout << "  " << m << "\n";
    return 5;
  }
  if (!expectations.empty())
    std::cout << "every outcome as expected (" << expectations.size() << " expectations, "
              << o.expect << ")\n";
  return rc;
}

}  // namespace

int runStress(const StressOptions& o) {
  checkStressOptions(o);
  // Read before anything runs: a malformed expectation file is bad input that costs no run.
  const std::vector<Expectation> expectations =
      o.expect.empty() ? std::vector<Expectation>{} : readExpectations(o.expect);
  std::vector<std::string> common = o.overrides;
  scenario::ScenarioSpec spec = loadCommandScenario(o, common);
  if (!spec.has_vehicle)
    throw InputError({o.scenario, 0}, "stress needs a vehicle scenario (no vehicle block)");
  if (o.quick) {
    const auto shorter = stress::shortenRun(spec, o.quickSeconds);
    common.insert(common.end(), shorter.begin(), shorter.end());
    if (!shorter.empty()) spec = loadCommandScenario(o, common);
  }
  stress::PlanRequest req{o.axes, parseValues(o.values), o.quick};
  const stress::Plan plan = stress::planAxes(spec, req);
  for (const auto& n : plan.notes) std::cout << "stress: " << n << "\n";
  if (plan.cases.empty()) throw InputError({"--axes", 0}, "no axis applies to " + o.scenario);
  const auto runs = settings(o, spec);
  stress::Setting reference = stress::parseSetting(o.reference, stress::normalForceCouplings(spec),
                                                   "--reference", spec.solver.max_step);
  // The reference has to reach the end of every hardened case: at its tight tolerance the
  // solver's default work limit (500 internal steps per output interval) stops BDF in flange
  // contact ("too much work") where nothing is wrong with the case. The same limit as precision's.
  if (reference.adaptive) reference.overrides.emplace_back("solver.max_steps=100000");
  // The run's length as the cases run it; every setting brings its own integrator, so the check
  // runs an adaptive one (the scenario's own fixed step must not refuse it).
  std::vector<std::string> adaptive = common;
  adaptive.emplace_back("solver.method=dopri5");
  const double t_end = checkOptionOverrides(o, adaptive, {});
  checkSettings(o.integrators, "--integrators", t_end, spec.run.max_output_samples);
  checkSettings({o.reference}, "--reference", t_end, spec.run.max_output_samples);
  const std::size_t total = plan.cases.size() * (runs.size() + 1);
  if (total > kMaxRuns)
    throw InputError(study::kOptionLoc,
                     "--axes/--values/--integrators: " + std::to_string(plan.cases.size()) +
                         " hardened cases x (" + std::to_string(runs.size()) +
                         " settings + reference) = " + std::to_string(total) + " runs, more than " +
                         std::to_string(kMaxRuns));
  validate(o, common, plan, reference);

  Expanded e;
  e.study.file = fs::path(o.scenario).filename().string() + " (stress)";
  e.study.base = o.scenario;
  e.table << "case,axis,value,value_label,integrator,role,t_end,overrides\n";
  for (const auto& h : plan.cases) {
    addCase(e, h, reference, common, "reference");
    for (const auto& s : runs) addCase(e, h, s, common, "");
  }

  study::StudyOptions so = commandStudyOptions(o, "stress");
  so.file = e.study.file;
  so.run_timeout_s = o.run_timeout;
  std::error_code ec;
  fs::create_directories(so.out, ec);
  {
    std::ofstream t(fs::path(so.out) / "stress_cases.csv");
    t << e.table.str();
    if (!t) throw InputError({"--out", 0}, "cannot write " + so.out + "/stress_cases.csv");
  }
  std::cout << "stress " << o.scenario << ": " << plan.cases.size() << " hardened cases x ("
            << runs.size() << " settings + reference " << reference.label << ") into " << so.out
            << "\n";
  // A failed run is a result here: runStudySpec's "no run ok" (2) does not end the command.
  const int rc = study::runStudySpec(e.study, so, {});
  if (rc == 1) return 1;
  return judge(o, so.out, expectations);
}

}  // namespace rb::stress
