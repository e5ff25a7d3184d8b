#include "workbench/study/summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "workbench/core/strings.hpp"
#include "workbench/io/read_stats.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/scenario/override_check.hpp"
#include "workbench/study/metrics.hpp"
#include "workbench/study/reference_errors.hpp"
#include "workbench/vehicle/stage_clock.hpp"

namespace fs = std::filesystem;

namespace rb::study::detail {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The solver part of a case's label (caseLabel of its solver.* overrides: "rk4 h=0.25ms",
// "bdf tol=1e-6 hmax=1ms"), "" when the case keeps the base scenario's solver. The figures
// group cases by it, so they read it from summary_cases.csv instead of deriving it again.
std::string solverLabel(const std::vector<std::string>& overrides) {
  std::vector<std::string> solver;
  for (const auto& o : overrides)
    if (o.rfind("solver.", 0) == 0) solver.push_back(o);
  const std::string label = scenario::caseLabel(solver);
  return solver.empty() || label == "base" ? std::string() : label;
}

// The environment of the figures' python: this one with <root>/plots first on PYTHONPATH, so

// timed), the integrator's and the observer's.
std::vector<std::string> summaryNumbers() {
  std::vector<std::string> k = {"cpu_time_s",        "wall_time_s",     "rhs_evals",
                                "rhs_evals_jac",     "steps",           "rejected_steps",
                                "jacobian_evals",    "nonlinear_iters", "t_reached",
                                "model_evaluations", "stage_samples"};
  for (const auto& e : vehicle::kStageNames) k.push_back("stage_share_" + std::string(e.name));
  k.emplace_back("stage_share_integrator");
  k.emplace_back("stage_share_observer");
  return k;
}
const std::vector<std::string> kSummaryNumbers = summaryNumbers();

// Per case: the CPU times of its ok repeats, and the status, reason and counts of its first
// problem (or of its first run when every repeat is ok).
struct CaseSum {
  std::vector<double> cpu;
  int runs = 0;
  std::string status, message, file;
  std::string failure;                    // the failure record's fields of the same run (CSV)
  std::map<std::string, double> first;    // counts of the first run (exact, equal over repeats)
  std::vector<io::MetricRecord> metrics;  // of the first run with a result (deterministic)
};

// What the summaries hold: summary.csv's text, the per-case sums, the columns of summary.h5.
struct Summary {
  std::ostringstream csv;
  std::map<std::string, CaseSum> cases;
  std::vector<double> ok;
  std::map<std::string, std::vector<double>> cols;
  std::vector<std::vector<double>> metricCols;  // per metric, per run
  std::size_t runsOk = 0, runsKnown = 0, runsElsewhere = 0;
};

// The status of a run in the summary, and its reason.
struct RunState {
  std::string status, message;
};

// The failure record of a run's /stats (run/simulate.hpp) as the CSV fields failure_kind,
// failure_reason, failure_body, failure_t, failure_s (empty where the file has none), so that a
// reader branches on them instead of parsing the message.
constexpr const char* kFailureColumns =
    "failure_kind,failure_reason,failure_body,failure_t,failure_s";
std::string failureFields(const std::optional<io::StatsRecord>& rec) {
  if (!rec) return ",,,,";
  auto text = [&](const char* k) {
    const auto it = rec->text.find(k);
    return it == rec->text.end() ? std::string() : csvField(it->second);
  };
  auto number = [&](const char* k) {
    const auto it = rec->number.find(k);
    return it == rec->number.end() || !std::isfinite(it->second) ? std::string()
                                                                 : formatNumberExact(it->second);
  };
  return text("failure_kind") + "," + text("failure_reason") + "," + text("failure_body") + "," +
         number("failure_t") + "," + number("failure_s");
}

// The state of a run that left no valid result.
RunState noResult(const Job& j, Summary& sm) {
  if (j.outcome == Outcome::Skipped) {
    ++sm.runsElsewhere;
    return {"skipped", "being run by another runner when this summary was written"};
  }
  if (j.outcome == Outcome::Pending)  // no runner ran it with these inputs (outcomesFromDisk)
    return {"missing", "no result of the current inputs on disk: not run yet (or not finished)"};
  if (!j.note.empty()) return {"error", j.note};
  // The run stopped on bad input or crashed; its log says why.
  std::ifstream log(j.log);
  std::string line, last;
  while (std::getline(log, line))
    if (!line.empty()) last += (last.empty() ? "" : " | ") + line;
  return {"error", last.empty() ? "no result" : last.substr(0, 500)};
}

// A metric value to the last bit (round trip), "inf" for the error of a diverged run, "" when it
// could not be computed.
std::string exactField(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (!std::isfinite(v)) return {};
  return formatNumber(v, 17);
}

// `message` with the reasons of the metrics that could not be computed and the notes of those
// that were, "metric NAME: reason", joined by "; ".
std::string withMetricReasons(std::string message, const std::vector<io::MetricRecord>& ms) {
  for (const auto& m : ms) {
    const std::string& r = m.why.empty() ? m.note : m.why;
    if (r.empty()) continue;
    message += (message.empty() ? "" : "; ") + ("metric " + m.name + ": " + r);
  }
  return message;
}

// Per case id, its matrix combination (its matrix overrides joined), "" without a matrix.
std::map<std::string, std::string> combinations(const scenario::StudySpec& st) {
  std::map<std::string, std::string> out;
  for (std::size_t i = 0; i < st.cases.size(); ++i)
    out[st.cases[i].id] = i < st.matrix_parts.size() ? join(st.matrix_parts[i], " ") : "";
  return out;
}

// Per matrix combination, the result of the first valid run of a case with role "reference".
std::map<std::string, std::string> referenceFiles(const std::map<std::string, std::string>& combo,
                                                  const std::vector<Job>& all) {
  std::map<std::string, std::string> out;
  // Only a reference that ran to its end: a failed one would give the error over the part it
  // covered as if it were the whole run.
  for (const auto& j : all) {
    if (j.c->role != "reference" || !isDone(j.h5, *j.hash)) continue;
    const auto rec = io::readStats(j.h5);
    if (rec && rec->text.count("status") && rec->text.at("status") == "ok")
      out.emplace(combo.at(j.c->id), j.h5);
  }
  return out;
}

// The metrics of one run: computed (or read back) from a valid file, else NaN with no reason of
// their own (the run's message says why there is no result). Error metrics compare with the
// reference case of the same matrix combination.
std::vector<io::MetricRecord> runMetrics(MetricContext& ctx, const Job& j, bool valid,
                                         const std::string& ref) {
  std::vector<io::MetricRecord> out;
  if (!valid) {
    for (const auto& m : ctx.st.metrics) out.push_back({m.name, std::nan(""), "", ""});
    return out;
  }
  out = summaryMetrics(ctx, *j.c, j.h5, ref);
  for (std::size_t k = 0; k < out.size() && ref.empty(); ++k)
    if (ctx.st.metrics[k].kind == "error")
      out[k].why = "the reference case has no result that ran to its end (status ok)";
  return out;
}

// The metric fields of a row of summary.csv and their summary.h5 columns.
void addMetricFields(const std::vector<io::MetricRecord>& metrics, Summary& sm) {
  for (std::size_t k = 0; k < metrics.size(); ++k) {
    sm.csv << "," << exactField(metrics[k].value);
    sm.metricCols[k].push_back(metrics[k].value);
  }
}

// One row of summary.csv per run, and the per-case sums.
void summariseRuns(const scenario::StudySpec& st, const std::vector<Job>& all, Summary& sm) {
  MetricContext ctx(st);
  const std::map<std::string, std::string> combo = combinations(st);
  const std::map<std::string, std::string> refs = referenceFiles(combo, all);
  sm.metricCols.assign(st.metrics.size(), {});
  sm.csv.precision(12);  // counts above 1e6 exactly, CPU times to the nanosecond
  sm.csv << "case,repeat,label,role,base,overrides,status";
  for (const auto& k : kSummaryNumbers) sm.csv << "," << k;
  for (const auto& m : st.metrics) sm.csv << ",metric_" << m.name;
  sm.csv << "," << kFailureColumns << ",message,file\n";
  for (const auto& j : all) {
    const bool valid = isDone(j.h5, *j.hash);
    auto rec = valid ? io::readStats(j.h5) : std::nullopt;
    const RunState run =
        rec ? RunState{rec->text["status"], rec->text["message"]} : noResult(j, sm);
    const std::string& status = run.status;
    const auto ref = refs.find(combo.at(j.c->id));
    const auto metrics = runMetrics(ctx, j, valid, ref == refs.end() ? "" : ref->second);
    const std::string message = withMetricReasons(run.message, metrics);
    if (status != "skipped") ++sm.runsKnown;
    if (status == "ok") ++sm.runsOk;
    sm.csv << j.c->id << "," << j.repeat << "," << csvField(j.c->label) << "," << j.c->role << ","
           << csvField(j.c->base) << "," << csvField(join(j.c->overrides, " ")) << "," << status;
    std::map<std::string, double> numbers;
    for (const auto& k : kSummaryNumbers) {
      numbers[k] = rec && rec->number.count(k) ? rec->number[k] : 0.0;
      sm.csv << "," << numbers[k];
      sm.cols[k].push_back(numbers[k]);
    }
    addMetricFields(metrics, sm);
    const std::string failure = failureFields(rec);
    sm.csv << "," << failure << "," << csvField(message) << "," << csvField(valid ? j.h5 : "")
           << "\n";
    sm.ok.push_back(status == "ok" ? 1.0 : 0.0);
    CaseSum& cs = sm.cases[j.c->id];
    ++cs.runs;
    if (cs.metrics.empty() && valid) cs.metrics = metrics;
    if (status == "ok" && rec) cs.cpu.push_back(numbers["cpu_time_s"]);
    // The case's status: ok only when every repeat is ok; else the first problem and its reason.
    if (cs.status.empty() || (cs.status == "ok" && status != "ok")) {
      cs.status = status;
      cs.message = run.message;
      cs.failure = failure;
      cs.file = valid ? j.h5 : "";
      cs.first = numbers;
    }
  }
}

// summary_cases.csv: one row per case, the median CPU time over its repeats.
std::string casesCsv(const scenario::StudySpec& st, std::map<std::string, CaseSum>& sum) {
  std::ostringstream cases;
  cases.precision(12);
  cases << "case,label,role,base,overrides,solver,runs,runs_ok,status,median_cpu_time_s,"
           "min_cpu_time_s,max_cpu_time_s";
  for (const auto& k : kSummaryNumbers)
    if (k != "cpu_time_s" && k != "wall_time_s") cases << "," << k;
  for (const auto& m : st.metrics) cases << ",metric_" << m.name;
  cases << "," << kFailureColumns << ",message,file\n";
  for (const auto& c : st.cases) {
    CaseSum& cs = sum[c.id];
    auto [lo, hi] =
        cs.cpu.empty() ? std::pair<double, double>{0.0, 0.0}
                       : std::pair<double, double>{*std::min_element(cs.cpu.begin(), cs.cpu.end()),
                                                   *std::max_element(cs.cpu.begin(), cs.cpu.end())};
    cases << c.id << "," << csvField(c.label) << "," << c.role << "," << csvField(c.base) << ","
          << csvField(join(c.overrides, " ")) << "," << csvField(solverLabel(c.overrides)) << ","
          << cs.runs << "," << cs.cpu.size() << "," << cs.status << "," << median(cs.cpu) << ","
          << lo << "," << hi;
    for (const auto& k : kSummaryNumbers)
      if (k != "cpu_time_s" && k != "wall_time_s") cases << "," << cs.first[k];
    for (std::size_t k = 0; k < st.metrics.size(); ++k)
      cases << "," << (k < cs.metrics.size() ? exactField(cs.metrics[k].value) : std::string());
    cases << "," << (cs.failure.empty() ? std::string(",,,,") : cs.failure) << ","
          << csvField(withMetricReasons(cs.message, cs.metrics)) << "," << csvField(cs.file)
          << "\n";
  }
  return cases.str();
}

// summary.h5: the per-run numbers as datasets under /runs.
void writeSummaryH5(const fs::path& path, const scenario::StudySpec& st,
                    const std::vector<Job>& all, Summary& sm) {
  io::ResultFile h5(path.string());
  h5.attr("/", "study_file", st.file);
  h5.attr("/", "base", st.base);
  std::string caseIds, overrides, labels;
  for (const auto& j : all) {
    caseIds += (caseIds.empty() ? "" : "\n") + j.name;
    overrides += (overrides.empty() ? "" : "\n") + join(j.c->overrides, " ");
    labels += (labels.empty() ? "" : "\n") + j.c->label;
  }
  h5.attr("/runs", "labels", labels);
  h5.attr("/runs", "ids", caseIds);
  h5.attr("/runs", "overrides", overrides);
  h5.dataset("/runs/ok", sm.ok, "-");
  for (const auto& k : kSummaryNumbers)
    h5.dataset("/runs/" + k, sm.cols[k],
               k == "cpu_time_s" || k == "wall_time_s" || k == "t_reached" ? "s" : "-");
  // NaN where a metric could not be computed (summary.csv's message says why).
  for (std::size_t k = 0; k < st.metrics.size(); ++k)
    h5.dataset("/runs/metric_" + st.metrics[k].name, sm.metricCols[k], "-");
  h5.finalize();
}

struct MetricLabel {
  std::string label, unit, limit, limit_source;
};

// What a metric is, in which unit, and the standard's limit it is judged against where there is
// one: an assessment quantity carries its unit and limit in each result (/assessment/summary
// <key>_unit, <key>_limit: the limit is drawn when it is the same for every case), a signal its
// dataset's units; the maximum of a Y/Q signal is judged against EN 14363's flange-climbing limit
// (Y/Q)lim = 0.8, the default of run.assessment.yq_limit.
MetricLabel metricLabel(const scenario::MetricSpec& m, const std::vector<Job>& all) {
  MetricLabel out;
  out.label = m.name;
  auto firstWith = [&](const std::string& object, const std::string& attr) {
    for (const auto& j : all) {
      if (std::error_code ec; !fs::exists(j.h5, ec)) continue;
      const io::ResultReader r(j.h5);
      if (auto t = r.text(object, attr)) return *t;
    }
    return std::string();
  };
  if (m.kind == "linear_critical_speed") {
    out.label = m.name + " (linear critical speed)";
    out.unit = "m/s";
  } else if (m.kind == "assessment" && !m.quantity.empty() && m.quantity[0] != '/') {
    out.label = m.name + " (" + m.quantity + ")";
    out.unit = firstWith("/assessment/summary", m.quantity + "_unit");
    std::vector<double> limits;
    for (const auto& j : all) {
      if (std::error_code ec; !fs::exists(j.h5, ec)) continue;
      const io::ResultReader r(j.h5);
      if (auto v = r.number("/assessment/summary", m.quantity + "_limit")) limits.push_back(*v);
    }
    if (!limits.empty() &&
        std::all_of(limits.begin(), limits.end(), [&](double v) { return v == limits[0]; })) {
      out.limit = formatNumberExact(limits[0]);
      out.limit_source = "EN 14363 limit of " + m.quantity + " (run.assessment)";
    } else if (!limits.empty()) {
      out.limit_source = "the limit of " + m.quantity + " differs between the cases";
    }
  } else if (m.kind == "signal" || m.kind == "steady" || m.kind == "error") {
    const std::string units = firstWith(m.signal, "units");
    out.unit = units;
    out.label = m.name + " (" +
                (m.kind == "error"    ? "max |difference| of "
                 : m.kind == "steady" ? "steady "
                                      : "") +
                (m.kind == "signal" ? m.stat + " of " : "") + m.signal + ")";
    const bool yq = m.signal.size() >= 8 && m.signal.ends_with("y_over_q");
    if (yq && m.kind == "signal" && m.stat.find("max") != std::string::npos) {
      out.limit = "0.8";
      out.limit_source = "EN 14363 flange-climbing limit (Y/Q)lim";
    }
  }
  return out;
}

// study_labels.csv: the swept parameters and the metrics as a figure's axes read them (label,
// SI unit) and the limit line of a metric that has a standard limit.
std::string labelsCsv(const scenario::StudySpec& st, const std::vector<Job>& all) {
  std::ostringstream s;
  s << "kind,name,label,unit,limit,limit_source\n";
  for (const auto& p : scenario::studyParameterLabels(st))
    s << "parameter," << csvField(p.key) << "," << csvField(p.label) << "," << csvField(p.unit)
      << ",,\n";
  for (const auto& m : st.metrics) {
    const MetricLabel l = metricLabel(m, all);
    s << "metric," << csvField(m.name) << "," << csvField(l.label) << "," << csvField(l.unit) << ","
      << l.limit << "," << csvField(l.limit_source) << "\n";
  }
  return s.str();
}

}  // namespace

SummaryCounts writeSummaries(const scenario::StudySpec& st, const std::vector<Job>& all,
                             const fs::path& dir) {
  Summary sm;
  summariseRuns(st, all, sm);
  writeAtomically(dir / "summary.csv", sm.csv.str());
  writeAtomically(dir / "summary_cases.csv", casesCsv(st, sm.cases));
  writeSummaryH5(dir / "summary.h5", st, all, sm);
  std::vector<CaseResult> results;
  for (const auto& c : st.cases) results.push_back({&c, sm.cases[c.id].file});
  writeAtomically(dir / "summary_errors.csv", referenceErrorsCsv(results));
  // Labels are for the figures: a base scenario that cannot be read again leaves them raw.
  try {
    writeAtomically(dir / "study_labels.csv", labelsCsv(st, all));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "study: study_labels.csv not written: %s\n", e.what());
  }
  return {sm.runsOk, sm.runsKnown, sm.runsElsewhere};
}

}  // namespace rb::study::detail
