#include "workbench/io/read_stats.hpp"

#include "workbench/io/result_reader.hpp"

namespace rb::io {

std::optional<StatsRecord> readStats(const std::string& path) {
  // Through the reader of every result file (result_reader.hpp): a forged file is refused there
  // (BadResult), and an attribute is read only when it holds one value.
  const ResultReader r(path);
  if (!r.ok() || !r.has("/stats")) return std::nullopt;
  StatsRecord rec;
  for (const auto& name : r.attributes("/stats")) {
    if (auto t = r.text("/stats", name))
      rec.text[name] = std::move(*t);
    else if (const auto v = r.number("/stats", name))
      rec.number[name] = *v;
  }
  // stage_names (fixed-length strings) and stage_share into rec.number["stage_share_<name>"].
  const auto names = r.strings("/stats/stage_names");
  const auto share = r.dataset("/stats/stage_share");
  if (names && share && !names->empty() && names->size() == share->size())
    for (std::size_t i = 0; i < names->size(); ++i)
      rec.number["stage_share_" + (*names)[i]] = (*share)[i];
  return rec;
}

}  // namespace rb::io
