#pragma once
// Shared helpers for the profile tests: paths of the project's and the shared reference files.
#include <string>

namespace rb::profiles::test {

inline std::string projectFile(const std::string& rel) {
  return std::string(RB_SOURCE_DIR) + "/" + rel;
}
inline std::string sharedFile(const std::string& rel) {
  return std::string(RB_SOURCE_DIR) + "/../shared/reference/" + rel;
}
inline std::string dataFile(const std::string& name) {
  return std::string(RB_SOURCE_DIR) + "/tests/profiles/data/" + name;
}

}  // namespace rb::profiles::test
