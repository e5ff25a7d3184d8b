#pragma once
// The /metrics group of a study case's result file (docs/studies.md, "Metrics"): the values of
// the study's metrics for this case, and the hash of their definitions, so that a summary uses
// them only when the study still defines the same metrics.
//
// Layout: /metrics attributes `definitions_hash` (string), `names` (newline-separated, in the
// study's order) and per metric <name> (float64, NaN when it could not be computed),
// <name>_why (why not) and <name>_note (a remark on a computed value, e.g. "not steady").
#include <optional>
#include <string>
#include <vector>

namespace rb::io {

struct MetricRecord {
  std::string name;
  double value = 0.0;
  std::string why, note;
};

struct MetricsBlock {
  std::string hash;
  std::vector<MetricRecord> values;
};

// Replaces /metrics of the existing result `h5` (through a copy renamed over it, so a failure
// leaves the file as it was). Throws WriteError.
void writeMetrics(const std::string& h5, const MetricsBlock& block);

// nullopt when the file cannot be read or has no complete /metrics group.
std::optional<MetricsBlock> readMetrics(const std::string& h5);

}  // namespace rb::io
