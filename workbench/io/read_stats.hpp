#pragma once
// Reading back the /stats of a finished result file (studies collect them into a summary).
#include <map>
#include <optional>
#include <string>

namespace rb::io {

struct StatsRecord {
  std::map<std::string, std::string> text;  // status, message, method, effects
  // cpu_time_s, rhs_evals, ... (integers as doubles), and the stage shares of the datasets
  // /stats/stage_names and stage_share as "stage_share_<name>" (docs/run_stats.md).
  std::map<std::string, double> number;
};

// nullopt when the file cannot be opened or has no /stats group.
std::optional<StatsRecord> readStats(const std::string& path);

}  // namespace rb::io
