#pragma once
// Runs a scenario of the source tree into a fresh result file under the temporary folder, for
// the app tests that read what a run wrote (h5read.hpp).
#include <hdf5.h>

#include <filesystem>
#include <string>
#include <vector>

#include "workbench/app/run.hpp"

namespace h5test {

// <temp>/<folder>/<name>, with any earlier file of that name removed.
inline std::string freshResult(const std::string& folder, const std::string& name) {
  const std::filesystem::path d = std::filesystem::temp_directory_path() / folder;
  std::filesystem::create_directories(d);
  const std::string out = (d / name).string();
  std::filesystem::remove(out);
  return out;
}

// Quiet run options of scenario (relative to the source tree) writing to out.
inline rb::app::RunOptions quietRun(const std::string& scenario, const std::string& out,
                                    const std::vector<std::string>& overrides) {
  rb::app::RunOptions o;
  o.scenario = scenario;
  o.root = RB_SOURCE_DIR;
  o.out = out;
  o.overrides = overrides;
  o.quiet = true;
  return o;
}

// Runs it; the open result file, or -1 when the run did not end ok.
inline hid_t runAndOpen(const rb::app::RunOptions& o) {
  if (rb::app::runScenario(o) != 0) return -1;
  return H5Fopen(o.out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
}

}  // namespace h5test
