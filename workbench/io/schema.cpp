#include "workbench/io/schema.hpp"

namespace rb::io {

void writeSchema(ResultFile& f, const std::string& part, const std::vector<SchemaEntry>& entries,
                 const std::vector<std::pair<std::string, std::string>>& enums) {
  f.attr("/schema", "version", kSchemaVersion);
  f.attr("/schema", "layout",
         std::string("/schema/<part>/{path, unit, meaning, codes}: one row per dataset of the "
                     "file (codes: its attribute in /schema/enums when its values are codes); "
                     "/schema/enums: code=name,... of every code-valued quantity"));
  const std::string base = "/schema/" + part + "/";
  std::vector<std::string> path, unit, meaning, codes;
  for (const auto& e : entries) {
    path.push_back(e.path);
    unit.push_back(e.units);
    meaning.push_back(e.meaning);
    codes.push_back(e.codes);
  }
  f.stringDataset(base + "path", path);
  f.stringDataset(base + "unit", unit);
  f.stringDataset(base + "meaning", meaning);
  f.stringDataset(base + "codes", codes);
  for (const auto& [name, value] : enums) f.attr("/schema/enums", name, value);
}

}  // namespace rb::io
