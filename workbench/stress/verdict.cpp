#include "workbench/stress/verdict.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/study/run_error.hpp"

namespace rb::stress {

namespace fs = std::filesystem;

namespace {

// A CSV file as rows of {column: value}; the header names the columns.
std::vector<std::map<std::string, std::string>> readTable(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError({path.string(), 0}, "cannot read the file");
  std::ostringstream text;
  text << in.rdbuf();
  const auto records = parseCsv(text.str());
  std::vector<std::map<std::string, std::string>> out;
  if (records.empty()) return out;
  for (std::size_t i = 1; i < records.size(); ++i) {
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < records[0].size(); ++k)
      row[records[0][k]] = k < records[i].size() ? records[i][k] : "";
    out.push_back(std::move(row));
  }
  return out;
}

double toNumber(const std::string& s) {
  if (s.empty()) return kNaN;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return end != nullptr && *end == '\0' ? v : kNaN;
}

std::string field(const std::map<std::string, std::string>& row, const char* key) {
  const auto it = row.find(key);
  return it == row.end() ? "" : it->second;
}

// A case of the study summary (summary_cases.csv) as the verdict needs it.
struct CaseRun {
  std::string status, message, file;
  std::string failure_kind, failure_reason;
  double failure_t = kNaN, failure_s = kNaN;
  double runs_ok = 0.0;
  double cpu = kNaN, rhs_evals = kNaN, rhs_evals_jac = kNaN, steps = kNaN, t_reached = kNaN;
  std::string failureText() const {
    return stress::failureText(failure_kind, failure_reason, failure_t, failure_s);
  }
};

std::map<std::string, CaseRun> readCases(const fs::path& dir) {
  std::map<std::string, CaseRun> out;
  for (const auto& r : readTable(dir / "summary_cases.csv")) {
    CaseRun c;
    c.status = field(r, "status");
    c.message = field(r, "message");
    c.file = field(r, "file");
    // A folder moved since its summary was written: its files beside the summary.
    std::error_code ec;
    if (!c.file.empty() && !fs::exists(c.file, ec) &&
        fs::exists(dir / fs::path(c.file).filename(), ec))
      c.file = (dir / fs::path(c.file).filename()).string();
    c.failure_kind = field(r, "failure_kind");
    c.failure_reason = field(r, "failure_reason");
    c.failure_t = toNumber(field(r, "failure_t"));
    c.failure_s = toNumber(field(r, "failure_s"));
    c.cpu = toNumber(field(r, "median_cpu_time_s"));
    c.runs_ok = toNumber(field(r, "runs_ok"));
    c.rhs_evals = toNumber(field(r, "rhs_evals"));
    c.rhs_evals_jac = toNumber(field(r, "rhs_evals_jac"));
    c.steps = toNumber(field(r, "steps"));
    c.t_reached = toNumber(field(r, "t_reached"));
    out[field(r, "case")] = std::move(c);
  }
  return out;
}

// A stress row of the run `meta` (a row of stress_cases.csv) and its classification.
StressRow makeRow(const std::map<std::string, std::string>& meta, const CaseRun* run,
                  const Classified& c, Outcome outcome, std::string message,
                  std::optional<double> error) {
  StressRow r;
  r.axis = field(meta, "axis");
  r.value = field(meta, "value");
  r.value_label = field(meta, "value_label");
  r.integrator = field(meta, "integrator");
  r.role = field(meta, "role");
  r.outcome = outcome;
  r.error_y_mm = error;
  r.t_reached = c.check.t_reached;
  r.t_end = toNumber(field(meta, "t_end"));
  if (run != nullptr) {
    // The median over the ok repeats; a case without one: its run up to the failure.
    r.cpu_s = run->runs_ok > 0 || !c.check.readable ? run->cpu : c.check.cpu_s;
    r.rhs_evals = run->rhs_evals;
    r.rhs_evals_jac = run->rhs_evals_jac;
    r.steps = run->steps;
    r.file = run->file;
  }
  if (c.check.readable) {
    r.max_abs_y_mm = c.check.max_abs_y_mm;
    r.min_normal_kN = c.check.min_normal_kN;
  }
  r.message = std::move(message);
  r.id = field(meta, "case");
  return r;
}

Classified classify(const CaseRun* run, const std::map<std::string, std::string>& meta,
                    const Bounds& b) {
  if (run == nullptr) {
    Classified c;
    c.problems.emplace_back("the run is missing from the study summary");
    return c;
  }
  return classifyRun(run->status, run->message, run->file, toNumber(field(meta, "t_end")), b);
}

// The failure of a run that failed cleanly in words: its failure record, or the model's
// diagnostic when it was refused before its first step.
std::string cleanFailure(const CaseRun& run, const Classified& c) {
  if (run.failure_kind.empty() && !c.notes.empty()) return join(c.notes, "; ");
  return run.failureText();
}

// The reference run of a hardened case and its own outcome, against which its runs are judged.
struct Reference {
  const CaseRun* run = nullptr;
  Outcome outcome = Outcome::FailedBadly;
};

// A finished run that passed its own checks: ok or inaccurate, its error and the reason.
std::tuple<Outcome, std::optional<double>, std::string> judge(const CaseRun& run,
                                                              const Reference& ref, double tol) {
  if (ref.run == nullptr || ref.outcome == Outcome::FailedBadly)
    return {Outcome::Inaccurate, std::nullopt,
            "no valid reference (it failed badly): accuracy not established"};
  static const study::Quantity kY = study::parseQuantities({"y"}, {}, true).front();
  const study::Error e = study::fileError(run.file, ref.run->file, kY);
  const std::optional<double> err = e.have ? std::optional<double>(e.max) : std::nullopt;
  if (ref.outcome == Outcome::FailedCleanly)
    return {Outcome::Inaccurate, err,
            "its reference stops at t = " + formatNumber(ref.run->t_reached, 4) + " s (" +
                ref.run->failureText() + "): " +
                (leavesValidity(ref.run->failure_reason)
                     ? "the model leaves its validity there, this run went on through it"
                     : "accuracy beyond it not established") +
                "; error up to there " + (err ? formatNumber(*err, 3) : std::string("?")) + " mm"};
  if (!err) return {Outcome::Inaccurate, std::nullopt, "no common output times with the reference"};
  if (*err > tol)
    return {Outcome::Inaccurate, err,
            "lateral error " + formatNumber(*err, 3) + " mm > " + formatNumber(tol, 3) + " mm"};
  return {Outcome::Ok, err, ""};
}

bool valueMatches(const std::string& pattern, const StressRow& r) {
  if (pattern == "*") return true;
  const double p = toNumber(pattern), v = toNumber(r.value);
  if (std::isfinite(p)) return std::abs(p - v) <= 1e-9 * std::max(std::abs(p), std::abs(v));
  return fnmatch(pattern.c_str(), r.value_label.c_str(), 0) == 0;
}

bool matches(const std::string& pattern, const std::string& s) {
  return fnmatch(pattern.c_str(), s.c_str(), 0) == 0;
}

std::string trim(std::string s) {
  s.erase(0, s.find_first_not_of(" \t\r"));
  s.erase(s.find_last_not_of(" \t\r") + 1);
  return s;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, sep)) out.push_back(trim(part));
  if (!s.empty() && s.back() == sep) out.emplace_back();
  return out;
}

std::string shortName(Outcome o) {
  switch (o) {
    case Outcome::Ok:
      return "ok";
    case Outcome::Inaccurate:
      return "inacc";
    case Outcome::FailedCleanly:
      return "clean-fail";
    case Outcome::FailedBadly:
      return "BAD";
  }
  return "?";
}

std::string cellText(const StressRow* r) {
  if (r == nullptr) return "-";
  std::string t = shortName(r->outcome);
  if (r->error_y_mm && (r->outcome == Outcome::Ok || r->outcome == Outcome::Inaccurate) &&
      r->integrator.rfind("reference", 0) != 0)
    t += " " + formatNumber(*r->error_y_mm, 2);
  return t;
}

// One axis of the map: value x integrator setting, columns padded to their widest cell.
std::string axisTable(const std::vector<StressRow>& rows, const std::string& axis) {
  std::vector<std::string> values, integrators;
  std::map<std::pair<std::string, std::string>, const StressRow*> cells;
  for (const auto& r : rows) {
    if (r.axis != axis) continue;
    if (std::find(values.begin(), values.end(), r.value_label) == values.end())
      values.push_back(r.value_label);
    if (std::find(integrators.begin(), integrators.end(), r.integrator) == integrators.end())
      integrators.push_back(r.integrator);
    cells[{r.value_label, r.integrator}] = &r;
  }
  std::vector<std::vector<std::string>> table{{axis}};
  table[0].insert(table[0].end(), integrators.begin(), integrators.end());
  for (const auto& v : values) {
    std::vector<std::string> line{v};
    for (const auto& i : integrators) {
      const auto it = cells.find({v, i});
      line.push_back(cellText(it == cells.end() ? nullptr : it->second));
    }
    table.push_back(std::move(line));
  }
  std::vector<std::size_t> width(table[0].size(), 0);
  for (const auto& line : table)
    for (std::size_t k = 0; k < line.size(); ++k) width[k] = std::max(width[k], line[k].size());
  std::string out;
  for (const auto& line : table) {
    for (std::size_t k = 0; k < line.size(); ++k)
      out += (k ? "  " : "") + line[k] + std::string(width[k] - line[k].size(), ' ');
    out += "\n";
  }
  return out;
}

std::string number(double v) {
  return std::isfinite(v) ? formatNumber(v, 12) : std::string();
}

}  // namespace

Classified classifyRun(const std::string& status, const std::string& message,
                       const std::string& file, double t_end, const Bounds& bounds) {
  Classified c;
  // Refused before the first step with the model's diagnostic (a fixed step beyond the stability
  // limit, wheel lift already in the initial state): the model says where it stops being valid.
  // Every hardened case passed the scenario checks before the command ran anything, so this is
  // not bad input.
  if (status == "error" && (message.find("stability limit") != std::string::npos ||
                            message.find("nothing was run") != std::string::npos)) {
    c.outcome = Outcome::FailedCleanly;
    c.notes.push_back("refused before the run: " + message.substr(0, 200));
    return c;
  }
  std::error_code ec;
  if ((status != "ok" && status != "failed") || file.empty() || !fs::exists(file, ec)) {
    c.problems.push_back("no result: " + (message.empty() ? (status.empty() ? "?" : status)
                                                          : message.substr(0, 300)));
    return c;
  }
  const int rc = status == "ok" ? 0 : 2;
  c.check = checkResult(file, rc, bounds, std::isfinite(t_end) ? t_end : 0.0);
  c.problems = c.check.problems;
  c.notes = c.check.notes;
  c.outcome = !c.problems.empty() ? Outcome::FailedBadly
              : rc == 0           ? Outcome::Ok
                                  : Outcome::FailedCleanly;
  return c;
}

std::vector<StressRow> evaluate(const std::string& dirName, double tol, const Bounds& bounds) {
  const fs::path dir(dirName);
  std::error_code ec;
  if (!fs::exists(dir / "stress_cases.csv", ec))
    throw InputError({dirName, 0}, "no stress_cases.csv (not a `workbench stress` folder)");
  const auto metas = readTable(dir / "stress_cases.csv");
  const auto runs = readCases(dir);
  const auto runOf = [&](const std::map<std::string, std::string>& m) -> const CaseRun* {
    const auto it = runs.find(field(m, "case"));
    return it == runs.end() ? nullptr : &it->second;
  };
  // The hardened cases in their order, each with its runs.
  std::vector<std::pair<std::string, std::vector<const std::map<std::string, std::string>*>>>
      groups;
  for (const auto& m : metas) {
    const std::string key = field(m, "axis") + "\n" + field(m, "value");
    auto it =
        std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == key; });
    if (it == groups.end()) it = groups.insert(groups.end(), {key, {}});
    it->second.push_back(&m);
  }
  std::vector<StressRow> rows;
  for (const auto& [key, ms] : groups) {
    const auto refMeta = std::find_if(
        ms.begin(), ms.end(), [](const auto* m) { return field(*m, "role") == "reference"; });
    Reference ref;
    if (refMeta != ms.end()) {
      ref.run = runOf(**refMeta);
      const Classified c = classify(ref.run, **refMeta, bounds);
      ref.outcome = c.outcome;
      std::string msg = join(c.problems, "; ");
      if (c.problems.empty() && c.outcome == Outcome::FailedCleanly)
        msg = cleanFailure(*ref.run, c) + "; " +
              (leavesValidity(ref.run->failure_reason)
                   ? "the model leaves its validity there"
                   : "the reference itself could not be computed past it");
      auto meta = **refMeta;
      meta["integrator"] = "reference " + meta["integrator"];
      rows.push_back(makeRow(meta, ref.run, c, c.outcome, msg,
                             c.outcome == Outcome::Ok ? std::optional<double>(0.0) : std::nullopt));
    }
    for (const auto* m : ms) {
      if (refMeta != ms.end() && m == *refMeta) continue;
      const CaseRun* run = runOf(*m);
      const Classified c = classify(run, *m, bounds);
      Outcome outcome = c.outcome;
      std::optional<double> err;
      std::string msg = join(c.problems, "; ");
      if (outcome == Outcome::Ok) {
        std::tie(outcome, err, msg) = judge(*run, ref, tol);
      } else if (outcome == Outcome::FailedCleanly) {
        msg = cleanFailure(*run, c);
        if (ref.outcome == Outcome::FailedCleanly) msg += "; the reference fails too";
      }
      rows.push_back(makeRow(*m, run, c, outcome, msg, err));
    }
  }
  return rows;
}

std::string stressCsv(const std::vector<StressRow>& rows) {
  std::ostringstream s;
  s << "axis,value,value_label,integrator,role,outcome,error_y_mm,t_reached,t_end,cpu_s,"
       "rhs_evals,rhs_evals_jac,steps,max_abs_y_mm,min_normal_kN,message,case,file\n";
  for (const auto& r : rows) {
    s << csvField(r.axis) << "," << csvField(r.value) << "," << csvField(r.value_label) << ","
      << csvField(r.integrator) << "," << csvField(r.role) << "," << nameOf(r.outcome) << ","
      << (r.error_y_mm ? formatNumber(*r.error_y_mm, 6) : "") << "," << number(r.t_reached) << ","
      << number(r.t_end) << "," << (std::isfinite(r.cpu_s) ? formatNumber(r.cpu_s) : "") << ","
      << number(r.rhs_evals) << "," << number(r.rhs_evals_jac) << "," << number(r.steps) << ","
      << number(r.max_abs_y_mm) << "," << number(r.min_normal_kN) << "," << csvField(r.message)
      << "," << csvField(r.id) << "," << csvField(r.file) << "\n";
  }
  return s.str();
}

std::string textMap(const std::vector<StressRow>& rows, double tol) {
  std::ostringstream out;
  out << "stability map (error = max wheelset lateral error [mm] vs the case's own reference; ok "
         "<= "
      << formatNumber(tol) << " mm)\n";
  std::vector<std::string> axes;
  for (const auto& r : rows)
    if (std::find(axes.begin(), axes.end(), r.axis) == axes.end()) axes.push_back(r.axis);
  for (const auto& axis : axes) out << "\n" << axisTable(rows, axis);
  std::vector<std::string> counts;
  for (const auto& e : kOutcomeNames)
    counts.push_back(
        std::to_string(std::count_if(rows.begin(), rows.end(),
                                     [&](const StressRow& r) { return r.outcome == e.value; })) +
        " " + std::string(e.name));
  out << "\nruns: " << join(counts) << "\n";
  bool first = true;
  for (const auto& r : rows) {
    if (r.message.empty()) continue;
    if (first) out << "\n";
    first = false;
    out << "- " << r.axis << "=" << r.value_label << " " << r.integrator << ": "
        << nameOf(r.outcome) << ": " << r.message.substr(0, 300) << "\n";
  }
  return out.str();
}

std::vector<Expectation> readExpectations(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError({"--expect", 0}, "cannot read the expectation file " + path);
  std::vector<Expectation> out;
  Diagnostics d;
  std::string line;
  for (int no = 1; std::getline(in, line); ++no) {
    line = trim(line.substr(0, line.find('#')));
    if (line.empty()) continue;
    const SourceLoc at{path, no};
    const auto parts = split(line, ',');
    if (parts.size() != 4) {
      d.add(at, "expected AXIS, VALUE, INTEGRATOR, OUTCOME");
      continue;
    }
    Expectation e{at.str(), parts[0], parts[1], parts[2], {}};
    for (const auto& o : split(parts[3], '|')) {
      if (const auto v = parse<Outcome>(o)) {
        e.allowed.push_back(*v);
      } else {
        d.add(at, "unknown outcome '" + o + "' (one of " + join(namesOf<Outcome>()) + ")");
      }
    }
    out.push_back(std::move(e));
  }
  d.throwIfAny();
  return out;
}

std::vector<std::string> checkExpectations(const std::vector<StressRow>& rows,
                                           const std::vector<Expectation>& expectations) {
  std::vector<std::string> out;
  for (const auto& e : expectations) {
    bool hit = false;
    for (const auto& r : rows) {
      if (!matches(e.axis, r.axis) || !valueMatches(e.value, r) ||
          !matches(e.integrator, r.integrator))
        continue;
      hit = true;
      if (std::find(e.allowed.begin(), e.allowed.end(), r.outcome) != e.allowed.end()) continue;
      std::vector<std::string> allowed;
      for (const Outcome o : e.allowed) allowed.emplace_back(nameOf(o));
      out.push_back(e.where + ": " + r.axis + "=" + r.value_label + " " + r.integrator + ": " +
                    std::string(nameOf(r.outcome)) + ", expected " + join(allowed, " or ") + " (" +
                    r.message.substr(0, 200) + ")");
    }
    if (!hit)
      out.push_back(e.where + ": no run matches " + e.axis + ", " + e.value + ", " + e.integrator);
  }
  return out;
}

}  // namespace rb::stress
