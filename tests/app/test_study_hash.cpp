// The input hash of a study case: it changes with everything that determines the result (scenario
// text, required modules, overrides, the bytes of the data files read, the build) and with
// nothing else, so a study resumes exactly the cases whose inputs are unchanged.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "workbench/scenario/scenario.hpp"
#include "workbench/study/runner.hpp"

namespace fs = std::filesystem;

namespace {

class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = fs::temp_directory_path() / ("railbench_study_hash_" + std::to_string(rd()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name, std::ios::binary | std::ios::trunc) << text;
    return (path_ / name).string();
  }

 private:
  fs::path path_;
};

const char* kBase = R"(local m = require "mod"
track { segments = { tangent { length = m.length } },
        irregularities = measured { file = "irr.csv" } }
profiles { wheel = "wheel.txt" }
run { distance = 10 }
)";

std::string hashOf(const std::string& base, const std::vector<std::string>& overrides = {},
                   const std::string& build = "build:a") {
  rb::scenario::LoadOptions o;
  o.root = RB_SOURCE_DIR;
  o.overrides = overrides;
  return rb::study::caseInputHash(rb::scenario::loadScenario(base, o), build);
}

}  // namespace

TEST(StudyHash, ChangesWithEveryInputAndOnlyWithThem) {
  TempDir d;
  d.write("mod.lua", "return { length = 100 }\n");
  d.write("irr.csv", "s,alignment,vertical,gauge,cross_level\n0,0,0,0,0\n100,0,0,0,0\n");
  d.write("wheel.txt", "0 0\n1 1\n");
  const std::string base = d.write("base.lua", kBase);
  const std::string h0 = hashOf(base);
  ASSERT_EQ(h0.size(), 16u);
  EXPECT_EQ(hashOf(base), h0);  // nothing changed: the same case

  d.write("base.lua", std::string(kBase) + "-- a comment is text too\n");
  EXPECT_NE(hashOf(base), h0);
  d.write("base.lua", kBase);
  EXPECT_EQ(hashOf(base), h0);

  d.write("mod.lua", "return { length = 101 }\n");  // a required module
  EXPECT_NE(hashOf(base), h0);
  d.write("mod.lua", "return { length = 100 }\n");

  d.write("irr.csv", "s,alignment,vertical,gauge,cross_level\n0,0,0,0,0\n100,1e-3,0,0,0\n");
  EXPECT_NE(hashOf(base), h0);  // the bytes of an irregularity CSV
  d.write("irr.csv", "s,alignment,vertical,gauge,cross_level\n0,0,0,0,0\n100,0,0,0,0\n");

  d.write("wheel.txt", "0 0\n1 2\n");  // the bytes of a profile file
  EXPECT_NE(hashOf(base), h0);
  d.write("wheel.txt", "0 0\n1 1\n");
  EXPECT_EQ(hashOf(base), h0);

  EXPECT_NE(hashOf(base, {"run.distance=11"}), h0);  // overrides
  EXPECT_NE(hashOf(base, {}, "build:b"), h0);        // another build of the workbench
}

namespace {

// The base scenario with its profiles{} replaced by `profiles`, which names the data file `file`:
// editing that file's bytes is a new case, restoring them the same case again.
void expectHashFollowsFile(const std::string& profiles, const std::string& file) {
  TempDir d;
  d.write("mod.lua", "return { length = 100 }\n");
  d.write("irr.csv", "s,alignment,vertical,gauge,cross_level\n0,0,0,0,0\n100,0,0,0,0\n");
  d.write("wheel.txt", "0 0\n1 1\n");
  d.write(file, "0 0\n1 1\n");
  std::string text = kBase;
  const std::string from = "profiles { wheel = \"wheel.txt\" }";
  text.replace(text.find(from), from.size(), profiles);
  const std::string base = d.write("base.lua", text);
  const std::string h0 = hashOf(base);
  d.write(file, "0 0\n1 2\n");
  EXPECT_NE(hashOf(base), h0) << file;
  d.write(file, "0 0\n1 1\n");
  EXPECT_EQ(hashOf(base), h0) << file;
}

}  // namespace

TEST(StudyHash, ChangesWithEachWheelSidesOwnProfile) {
  // profiles.wheel_right names a file of its own: its bytes are an input of the case (a worn
  // wheel edited between two runs of a study is a new case, never a resumed stale result).
  expectHashFollowsFile("profiles { wheel = \"wheel.txt\", wheel_right = \"right.txt\" }",
                        "right.txt");
}

TEST(StudyHash, ChangesWithEachRailSlicesProfile) {
  // profiles.rail_slices and extra_rails name files of their own: each one's bytes are an input.
  expectHashFollowsFile(
      "profiles { wheel = \"wheel.txt\", rail_slices = { right = { { s = 1, rail = \"60e1\" }, "
      "{ s = 5, rail = \"blade.txt\" } } } }",
      "blade.txt");
  expectHashFollowsFile(
      "profiles { wheel = \"wheel.txt\", extra_rails = { left = { { name = \"nose\", slices = "
      "{ { s = 1, rail = \"nose.txt\" } } } } } }",
      "nose.txt");
}

TEST(StudyHash, BuildIdIsTheProgramContent) {
  TempDir d;
  const std::string a = d.write("a", "program one"), b = d.write("b", "program two");
  EXPECT_EQ(rb::study::buildId(a), rb::study::buildId(a));
  EXPECT_NE(rb::study::buildId(a), rb::study::buildId(b));
  EXPECT_EQ(rb::study::buildId(a).substr(0, 6), "build:");
  EXPECT_EQ(rb::study::buildId(a + ".missing"), "build:unknown");
}
