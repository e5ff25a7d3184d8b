#pragma once
// The metrics of a study's cases (study.metrics, docs/studies.md "Metrics"): one function,
// caseMetrics, computes them from a case's result file for every way of running a study; the
// runner stores them in the file (/metrics) right after the run, and the summary reads them back
// when their definitions' hash matches, computing them from the file otherwise.
#include <memory>
#include <string>
#include <vector>

#include "workbench/io/metrics_output.hpp"
#include "workbench/scenario/study.hpp"

namespace rb::scenario {
class LuaMetrics;
}

namespace rb::study::detail {

// Hex hash of the metric definitions (and, with a function metric, of the study file's text,
// where the function is written).
std::string metricsHash(const scenario::StudySpec& st);

// Lazily made sandbox of the function metrics, shared by the cases of one summary.
struct MetricContext {
  const scenario::StudySpec& st;
  std::unique_ptr<scenario::LuaMetrics> lua;
  std::string luaError;  // why the sandbox could not be made
  explicit MetricContext(const scenario::StudySpec& s);
  ~MetricContext();
  MetricContext(const MetricContext&) = delete;
  MetricContext& operator=(const MetricContext&) = delete;
};

// Every metric of one case from its result file `h5`, in the study's order. Metrics against the
// reference case (kind "error") need `referenceH5` (the reference's result); with "" they are
// NaN with the reason "computed when the summary is written". Never throws: a metric that cannot
// be computed has value NaN and its reason in `why`.
std::vector<io::MetricRecord> caseMetrics(MetricContext& ctx, const scenario::StudyCase& c,
                                          const std::string& h5, const std::string& referenceH5);

// Contract for the runners: call right after a case's run finished and its result `h5` is
// complete, before it is stamped and renamed. Computes every metric but those against the
// reference (caseMetrics with no reference) and writes them with metricsHash into /metrics of
// `h5` (replacing the file atomically). A study without metrics leaves the file untouched and
// returns true. Returns false with `why` only when the file cannot be updated (a metric that
// cannot be computed is stored as NaN with its reason, not an error). Never throws.
bool storeCaseMetrics(const scenario::StudySpec& st, const scenario::StudyCase& c,
                      const std::string& h5, std::string& why);

// The metrics of a case for a summary: those of /metrics when its hash is metricsHash(st), the
// others (and all of them otherwise) computed from `h5`; the error metrics against `referenceH5`.
std::vector<io::MetricRecord> summaryMetrics(MetricContext& ctx, const scenario::StudyCase& c,
                                             const std::string& h5, const std::string& referenceH5);

}  // namespace rb::study::detail
