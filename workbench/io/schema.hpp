#pragma once
// /schema of a result file (architecture.md, "Output layout"): the layout the file follows,
// stated in the file. Each writer of a part of the file declares its datasets in a table
// /schema/<part>/{path, unit, meaning, codes} (parallel 1-D string datasets, one row per
// dataset); /schema/enums holds, per code-valued quantity, the names of its codes as an
// attribute "0=tangent,1=transition,2=curve" taken from the enum's name table.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "workbench/core/names.hpp"
#include "workbench/io/result_file.hpp"

namespace rb::io {

// One dataset of the file: its path, SI unit ("-" dimensionless), what it is and, for a
// code-valued dataset, the name of its /schema/enums attribute (else empty).
struct SchemaEntry {
  std::string path, units, meaning, codes;
};

// "0=tread,1=two_point,2=flange": the codes of an enum as its datasets store them (the value as a
// number), in the order of its name table (core/names.hpp).
template <class E>
std::string codesOf() {
  std::string out;
  for (const auto& e : nameTable(E{})) {
    if (!out.empty()) out += ',';
    out += std::to_string(static_cast<int>(e.value)) + "=" + std::string(e.name);
  }
  return out;
}

// The layout version a reader can check (/schema attribute `version`); raised when a dataset's
// meaning or unit changes.
inline constexpr std::int64_t kSchemaVersion = 1;

// Writes the table /schema/<part> of `entries` and the attributes `enums` (name, codes) of
// /schema/enums. Throws WriteError (ResultFile).
void writeSchema(ResultFile& f, const std::string& part, const std::vector<SchemaEntry>& entries,
                 const std::vector<std::pair<std::string, std::string>>& enums);

}  // namespace rb::io
