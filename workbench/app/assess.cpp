#include "workbench/app/assess.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/io/schema.hpp"
#include "workbench/run/assessment_run.hpp"
#include "workbench/scenario/schema.hpp"

namespace rb::app {
namespace {

const SourceLoc kCli{"<command line>", 0};
constexpr const char* kPrefix = "run.assessment.";

// Whether the run wrote the per-patch contact datasets the wear assessment reads (a compact run
// or run.output.patches = false leaves them out).
bool hasPatchOutputs(const io::ResultReader& f) {
  for (const auto& ws : f.members("/contact"))
    if (f.has("/contact/" + ws + "/left/patch0")) return true;
  return false;
}

// One parameter the file's assessment applied (an attribute of /assessment), into `value` when
// present: finite (finiteNumber throws BadResult otherwise) and in the range of its scenario key,
// as --set requires of the same key; a value out of range is a problem in `errors`.
void fileParameter(const io::ResultReader& f, const std::string& key, double& value,
                   std::vector<Diagnostic>& errors) {
  const auto v = f.finiteNumber("/assessment", key);
  if (!v) return;
  const scenario::KeySpec* k = scenario::block("run.assessment").key(key);
  if (const auto problem = k ? scenario::rangeProblem(*k, *v) : std::nullopt) {
    errors.push_back(
        {SourceLoc{f.path(), 0}, "assess: /assessment@" + key + " must be " + *problem});
    return;
  }
  value = *v;
}

// The parameters the file's assessment applied, and its groups (safety and wear from the outputs
// when it has none).
assessment::AssessmentSpec specOfFile(const io::ResultReader& f, std::vector<Diagnostic>& errors) {
  assessment::AssessmentSpec s;
  const std::string A = "/assessment";
  fileParameter(f, "alpha", s.alpha, errors);
  fileParameter(f, "flange_angle", s.flange_angle, errors);
  fileParameter(f, "mu", s.mu, errors);
  fileParameter(f, "yq_limit", s.yq_limit, errors);
  s.instability_frequency = 0.0;
  fileParameter(f, "instability_frequency", s.instability_frequency, errors);
  fileParameter(f, "comfort_limit", s.comfort_limit, errors);
  fileParameter(f, "sample_every", s.sample_every, errors);
  if (f.has(A + "/time")) {
    s.safety = f.has(A + "/safety");
    s.stability = f.has(A + "/stability");
    s.comfort = f.has(A + "/comfort");
    s.wear = f.has(A + "/wear");
  } else {
    s.safety = f.has("/contact");
    s.wear = hasPatchOutputs(f);
  }
  return s;
}

// Why a file gives assess nothing to do: what the file holds and what assess needs from it, so a
// modes.h5, a study summary or a run written without contact outputs is told apart from a bug.
std::string nothingToAssess(const io::ResultReader& f, const std::string& file) {
  const auto top = f.members("/");
  std::string held;
  for (const auto& m : top) held += (held.empty() ? "/" : ", /") + m;
  return "nothing to assess in '" + file + "': it holds " +
         (held.empty() ? std::string("no groups") : held) +
         " but no /contact (the wheel-rail outputs of a vehicle run) and no /assessment; assess "
         "reads the result of `workbench run` on a vehicle scenario, not a track-only run, a "
         "modes or a study summary file";
}

std::optional<double> parseNumber(const std::string& v) {
  try {
    std::size_t used = 0;
    const double x = std::stod(v, &used);
    if (used == v.size()) return x;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

bool parseBool(const std::string& v, bool& out) {
  if (v == "true" || v == "1")
    out = true;
  else if (v == "false" || v == "0")
    out = false;
  else
    return false;
  return true;
}

// One --set run.assessment.KEY=VALUE; problems into `errors`.
void applyOverride(const std::string& o, assessment::AssessmentSpec& s,
                   std::vector<Diagnostic>& errors) {
  const auto eq = o.find('=');
  if (o.rfind(kPrefix, 0) != 0 || eq == std::string::npos) {
    errors.push_back({kCli, "--set " + o + ": assess takes run.assessment.KEY=VALUE"});
    return;
  }
  const std::string key = o.substr(std::string(kPrefix).size(), eq - std::string(kPrefix).size());
  const std::string value = o.substr(eq + 1);
  const scenario::KeySpec* k = scenario::block("run.assessment").key(key);
  bool* flag = key == "safety"      ? &s.safety
               : key == "stability" ? &s.stability
               : key == "comfort"   ? &s.comfort
               : key == "wear"      ? &s.wear
                                    : nullptr;
  if (flag != nullptr) {
    if (!parseBool(value, *flag))
      errors.push_back({kCli, "--set " + o + ": " + key + " must be true or false"});
    return;
  }
  double* num = key == "alpha"                   ? &s.alpha
                : key == "flange_angle"          ? &s.flange_angle
                : key == "mu"                    ? &s.mu
                : key == "yq_limit"              ? &s.yq_limit
                : key == "instability_frequency" ? &s.instability_frequency
                : key == "comfort_limit"         ? &s.comfort_limit
                                                 : nullptr;
  if (k == nullptr || num == nullptr) {
    errors.push_back({kCli, "--set " + o + ": assess cannot change run.assessment." + key +
                                " (the sampled signals are fixed by the run)"});
    return;
  }
  const auto x = parseNumber(value);
  const auto problem = x ? scenario::rangeProblem(*k, *x) : std::optional<std::string>("a number");
  if (problem) {
    errors.push_back({kCli, "--set " + o + ": " + key + " must be " + *problem});
    return;
  }
  *num = *x;
}

}  // namespace

int assessFile(const AssessOptions& o) {
  if (!std::filesystem::is_regular_file(o.file))
    throw InputError(kCli, "assess: '" + o.file + "' is not a result file");
  assessment::AssessmentSpec spec;
  run::AssessmentSignals signals;
  std::vector<std::string> missing;
  double contact_mu = 0.0;
  {
    const io::ResultReader f(o.file);
    if (!f.ok()) throw InputError(kCli, "assess: '" + o.file + "' is not an HDF5 result file");
    std::vector<Diagnostic> errors;
    spec = specOfFile(f, errors);
    for (const auto& s : o.overrides) applyOverride(s, spec, errors);
    if (!errors.empty()) throw InputError(std::move(errors));
    if (!spec.any()) throw InputError(kCli, "assess: " + nothingToAssess(f, o.file));
    contact_mu = f.finiteNumber("/contact", "mu").value_or(spec.mu);
    if (const scenario::KeySpec* k = scenario::block("contact").key("mu"); k && f.has("/contact"))
      if (const auto problem =
              f.number("/contact", "mu") ? scenario::rangeProblem(*k, contact_mu) : std::nullopt)
        throw InputError(SourceLoc{o.file, 0}, "assess: /contact@mu must be " + *problem);
    signals = run::signalsFromFile(f, spec, missing);
    const bool patch = std::any_of(missing.begin(), missing.end(), [](const std::string& m) {
      return m.find("/patch") != std::string::npos;
    });
    if (const auto compact = f.text("/", "compact"); patch && compact)
      missing.push_back("the run was compact and left out: " + *compact);
  }
  if (!missing.empty()) {
    std::vector<Diagnostic> errors;
    for (const auto& m : missing) errors.push_back({SourceLoc{o.file, 0}, "assess: " + m});
    throw InputError(std::move(errors));
  }
  const run::AssessmentResult r = run::assess(signals, spec, contact_mu);
  try {
    io::ResultFile f(o.file, io::ResultFile::UpdateExisting{});
    f.remove("/assessment");
    f.remove("/schema/assessment");
    io::writeSchema(f, "assessment", run::writeAssessment(f, signals, r), {});
    f.finalize();
  } catch (const io::WriteError& e) {
    // Nothing was run and the file is as it was (the copy is deleted): an environment problem
    // (read-only folder, disk full) before anything changed, exit 1 as for bad input.
    throw InputError(SourceLoc{o.file, 0},
                     std::string("assess: cannot write the new /assessment: ") + e.what() +
                         "; the file is unchanged");
  }
  if (!o.quiet)
    for (const auto& line : run::summaryLines(r)) std::cout << line << "\n";
  for (const auto& w : run::exceededWarnings(r)) std::cout << "warning: " << w << "\n";
  std::cout << "replaced /assessment of " << o.file << "\n";
  return 0;
}

}  // namespace rb::app
