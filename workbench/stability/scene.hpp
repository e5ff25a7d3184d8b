#pragma once
// The scene of a stability command (workbench modes, workbench critical-speed): a scenario as
// given, or a vehicle file (a module returning function(opts) -> vehicle table, like
// scenarios/vehicles/manchester_wagon1.lua) put on the default stability scene: a long tangent
// track without irregularities, S1002 wheels on 60E1 rails at 1:40 (B = 1360 mm, G = 1435 mm,
// r0 = 0.46 m), the chosen contact method with Polach creep at the paper's mu = 0.2364 (section
// 5.1), dopri5. The scene is written as a scenario file into the command's output folder
// (scene.lua), so every run of the command is an ordinary scenario that can be run again alone.
#include <string>
#include <vector>

#include "workbench/scenario/scenario.hpp"

namespace rb::stability {

struct StabilityScene {
  std::string file;                    // the scenario the command runs (the user's, or scene.lua)
  bool from_vehicle_file = false;      // file was generated around a vehicle file
  std::vector<std::string> overrides;  // applied to every run (the user's --set, --contact)
  scenario::ScenarioSpec spec;         // file loaded with the overrides
};

// Loads `path`: a scenario (contact = "" keeps its contact method; "kec" or "lut" sets
// contact.method) or a vehicle file, for which the scene is written to out/scene.lua with the
// contact method `contact` (default kec). Throws InputError (file:line) for a bad file or option.
StabilityScene loadStabilityScene(const std::string& path, const std::string& contact,
                                  const std::vector<std::string>& overrides,
                                  const std::string& root, const std::string& out);

}  // namespace rb::stability
