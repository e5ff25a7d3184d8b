#pragma once
// The Manchester wagon's stability scene for the tests of workbench/stability.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "workbench/scenario/scenario.hpp"
#include "workbench/stability/scene.hpp"
#include "workbench/stability/stability.hpp"

namespace rb::modes_test {

namespace fs = std::filesystem;

inline const std::string kRoot = RB_SOURCE_DIR;
inline const std::string kWagon = kRoot + "/scenarios/vehicles/manchester_wagon1.lua";

inline std::string outDir(const std::string& name) {
  const fs::path p = fs::path(RB_BINARY_DIR) / "modes_tests" / name;
  fs::create_directories(p);
  return p.string();
}

inline scenario::ScenarioSpec wagon(const std::string& contact) {
  return stability::loadStabilityScene(kWagon, contact, {}, kRoot, outDir("scene_" + contact)).spec;
}

// The wagon scene with the primary longitudinal stiffness Kpx [N/m] (the wagon module's option).
inline scenario::ScenarioSpec wagonWithKpx(const std::string& contact, double kpx) {
  const std::string dir = outDir("kpx_" + contact + "_" + std::to_string(static_cast<long>(kpx)));
  const stability::StabilityScene s =
      stability::loadStabilityScene(kWagon, contact, {}, kRoot, dir);
  std::ifstream in(s.file);
  std::stringstream text;
  text << in.rdbuf();
  std::string t = text.str();
  const std::string from = "make { speed = 20 }";
  const auto at = t.find(from);
  EXPECT_NE(at, std::string::npos);
  t.replace(at, from.size(),
            "make { speed = 20, primary_longitudinal_stiffness = " + std::to_string(kpx) + " }");
  const std::string file = (fs::path(dir) / "scene_kpx.lua").string();
  std::ofstream(file) << t;
  scenario::LoadOptions lo;
  lo.root = kRoot;
  return scenario::loadScenario(file, lo);
}

}  // namespace rb::modes_test
