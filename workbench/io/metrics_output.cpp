#include "workbench/io/metrics_output.hpp"

#include <sstream>

#include "workbench/io/result_file.hpp"
#include "workbench/io/result_reader.hpp"

namespace rb::io {

void writeMetrics(const std::string& h5, const MetricsBlock& block) {
  ResultFile f(h5, ResultFile::UpdateExisting{});
  f.remove("/metrics");
  std::string names;
  for (const auto& m : block.values) {
    names += (names.empty() ? "" : "\n") + m.name;
    f.attr("/metrics", m.name, m.value);
    if (!m.why.empty()) f.attr("/metrics", m.name + "_why", m.why);
    if (!m.note.empty()) f.attr("/metrics", m.name + "_note", m.note);
  }
  f.attr("/metrics", "names", names);
  f.attr("/metrics", "definitions_hash", block.hash);
  f.finalize();
}

std::optional<MetricsBlock> readMetrics(const std::string& h5) {
  ResultReader r(h5);
  if (!r.ok() || !r.has("/metrics")) return std::nullopt;
  const auto hash = r.text("/metrics", "definitions_hash");
  const auto names = r.text("/metrics", "names");
  if (!hash || !names) return std::nullopt;
  MetricsBlock b;
  b.hash = *hash;
  std::istringstream in(*names);
  std::string name;
  while (std::getline(in, name)) {
    if (name.empty()) continue;
    const auto v = r.number("/metrics", name);
    if (!v) return std::nullopt;
    MetricRecord m{name, *v, r.text("/metrics", name + "_why").value_or(""),
                   r.text("/metrics", name + "_note").value_or("")};
    b.values.push_back(std::move(m));
  }
  return b;
}

}  // namespace rb::io
