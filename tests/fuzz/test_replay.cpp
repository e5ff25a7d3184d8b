// Replays every kept fuzz input (tests/fuzz/<harness>/*) through the entry point its harness
// fuzzes: none may crash or let anything but rb::InputError escape. The crashes/ folders hold
// reproducers of findings not fixed yet and are skipped (README.md, "Found crashes").
#include <gtest/gtest.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "entry_points.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> keptInputs(const std::string& harness) {
  std::vector<fs::path> files;
  const fs::path dir = fs::path(RB_SOURCE_DIR) / "tests" / "fuzz" / harness;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.is_regular_file() && e.path().filename().string().rfind("README", 0) != 0) {
      files.push_back(e.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class Replay : public testing::TestWithParam<std::string> {};

TEST_P(Replay, KeptInputsNeitherCrashNorThrow) {
  const rb::fuzz::EntryPoint run = rb::fuzz::entryPoint(GetParam());
  ASSERT_NE(run, nullptr);
  const std::vector<fs::path> files = keptInputs(GetParam());
  EXPECT_FALSE(files.empty());
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    try {
      run(readBytes(f));
    } catch (const std::exception& e) {
      ADD_FAILURE() << f.string() << ": escaped: " << e.what();
    }
  }
}

// The table seeds are in the current cache format (regenerate them with fuzz_make_table_seeds
// after a format change), so that fuzzing starts from tables that load.
TEST(TableSeeds, Load) {
  for (const char* name : {"lut_file", "kec_file", "lut_payload", "kec_payload"}) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(
        rb::fuzz::loadTable(readBytes(fs::path(RB_SOURCE_DIR) / "tests/fuzz/tables" / name)));
  }
}

INSTANTIATE_TEST_SUITE_P(Fuzz, Replay,
                         testing::Values("scenario", "profile", "csv", "tables", "study", "metric",
                                         "result"),
                         [](const testing::TestParamInfo<std::string>& p) { return p.param; });

}  // namespace
