#pragma once
// Shared helpers for the profile tests: paths of the project's files and of the reference data.
#include <string>

namespace rb::profiles::test {

inline std::string projectFile(const std::string& rel) {
  return std::string(RB_SOURCE_DIR) + "/" + rel;
}
// Reference data copied into the repository (tests/data/, with its source and licence), so the
// tests need nothing outside the clone.
inline std::string referenceFile(const std::string& rel) {
  return std::string(RB_SOURCE_DIR) + "/tests/data/" + rel;
}
inline std::string dataFile(const std::string& name) {
  return std::string(RB_SOURCE_DIR) + "/tests/profiles/data/" + name;
}

}  // namespace rb::profiles::test
