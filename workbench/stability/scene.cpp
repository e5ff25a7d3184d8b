#include "workbench/stability/scene.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/spec.hpp"
#include "workbench/profiles/nominal.hpp"

namespace fs = std::filesystem;

namespace rb::stability {

namespace {

// A file that runs as a scenario without defining any block other than reporting the missing
// track: a vehicle file (it only returns its constructor).
bool looksLikeVehicleFile(const InputError& e) {
  const auto& d = e.diagnostics();
  return d.size() == 1 && d[0].message.find("scenario has no track") != std::string::npos;
}

// The file alone (no overrides) loads as a scenario without blocks.
bool isVehicleFile(const std::string& path, const std::string& root) {
  scenario::LoadOptions plain;
  plain.root = root;
  try {
    (void)scenario::loadScenario(path, plain);
  } catch (const InputError& e) {
    return looksLikeVehicleFile(e);
  }
  return false;
}

// The module name under which scene.lua requires the vehicle file: its path below
// <root>/scenarios with dots, or (a file elsewhere) the copy placed beside scene.lua.
std::string vehicleModule(const std::string& path, const std::string& root, const fs::path& dir) {
  std::error_code ec;
  const fs::path file = fs::canonical(path, ec);
  const fs::path scen = fs::canonical(fs::path(root) / "scenarios", ec);
  if (!ec) {
    fs::path rel = file.lexically_relative(scen);
    if (!rel.empty() && *rel.begin() != "..") {
      std::string name = rel.replace_extension().generic_string();
      bool plain = name.find('.') == std::string::npos;
      for (char& c : name)
        if (c == '/') c = '.';
      if (plain) return name;
    }
  }
  const std::string stem = fs::path(path).stem().string();
  if (stem.empty() || stem.find('.') != std::string::npos)
    throw InputError({path, 0},
                     "a vehicle file's name may not contain dots (it is required as a "
                     "module)");
  fs::copy_file(path, dir / "vehicle_file.lua", fs::copy_options::overwrite_existing, ec);
  if (ec)
    throw InputError({path, 0}, "cannot copy the vehicle file beside the scene: " + ec.message());
  return "vehicle_file";
}

// A Lua string literal of any text (paths may hold quotes, backslashes, newlines).
std::string luaString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string sceneText(const std::string& path, const std::string& module,
                      const std::string& contact) {
  std::ostringstream s;
  std::string shown = path;
  for (char& c : shown)
    if (c == '\n') c = ' ';
  s << "-- Stability scene written by workbench for the vehicle file " << shown << "\n"
    << "-- (workbench/stability/scene.hpp): long tangent track without irregularities,\n"
    << "-- S1002 on 60E1 at 1:40 (B = 1360 mm, G = " << formatNumber(track::kStandardGauge * 1e3)
    << " mm, r0 = " << formatNumber(profiles::kNominalWheelRadius) << " m), " << contact
    << " contact with\n"
    << "-- Polach creep at the paper's mu = " << formatNumber(creep::kDefaultMu)
    << " (section 5.1), dopri5. The commands set\n"
    << "-- vehicle.speed and run.duration per run.\n"
    << "local make = require \"" << module << "\"\n"
    << "if type(make) ~= \"function\" then\n"
    << "  error(" << luaString(path) << " .. \""
    << " is neither a scenario (it has no track{} block) nor a vehicle file (a module \"\n"
    << "        .. \"returning function(opts) -> vehicle table)\")\n"
    << "end\n"
    << "track { segments = { tangent { length = 20000 } }, step = 0.5 }\n"
    << "profiles { wheel = \"s1002\", rail = \"60e1\", back_to_back = 1.360, gauge = "
    << formatNumber(track::kStandardGauge)
    << ", r0 = " << formatNumber(profiles::kNominalWheelRadius) << ",\n"
    << "           inclination = 0.025 }\n"
    << "contact { method = \"" << contact
    << "\", creep = \"polach\", mu = " << formatNumber(creep::kDefaultMu) << " }\n"
    << "vehicle (make { speed = 20 })\n"
    << "solver { method = \"dopri5\" }\n"
    << "run { duration = 10, output = { every = 0.01 } }\n";
  return s.str();
}

// A scenario that loads with `overrides` but not with --contact's method refuses the option
// (e.g. KEC or LUT on rails that change along the track): the option is named, as precision
// names its --methods, rather than the scenario line the override became.
void refuseContactOption(const InputError& e, const std::string& path, const std::string& contact,
                         const std::vector<std::string>& overrides, const std::string& root) {
  if (contact.empty()) return;
  scenario::LoadOptions lo;
  lo.root = root;
  lo.overrides = overrides;
  try {
    (void)scenario::loadScenario(path, lo);
  } catch (const InputError&) {
    return;  // the scenario's own problem, reported as it is
  }
  throw InputError(
      {"<command line>", 0},
      "--contact " + contact + ": the scenario refuses contact.method=" + contact + ": " +
          (e.diagnostics().empty() ? std::string(e.what()) : e.diagnostics().front().str()));
}

}  // namespace

StabilityScene loadStabilityScene(const std::string& path, const std::string& contact,
                                  const std::vector<std::string>& overrides,
                                  const std::string& root, const std::string& out) {
  // The methods of the help text: the elastic method linearises as the table methods do.
  if (!contact.empty() && contact != "kec" && contact != "lut" && contact != "elastic")
    throw InputError({"--contact", 0},
                     "--contact must be kec, lut or elastic, got '" + contact + "'");
  StabilityScene scene;
  scene.file = path;
  scene.overrides = overrides;
  if (!contact.empty())
    scene.overrides.insert(scene.overrides.begin(), "contact.method=" + contact);
  scenario::LoadOptions lo;
  lo.root = root;
  lo.overrides = scene.overrides;
  bool loaded = false;
  try {
    scene.spec = scenario::loadScenario(path, lo);
    loaded = true;
  } catch (const InputError& e) {
    // Overrides (--set solver.method=bdf) add complaints of their own about a file without
    // blocks: whether the file is a vehicle file is decided on the file alone.
    if (!looksLikeVehicleFile(e) && !(scene.overrides.size() > 0 && isVehicleFile(path, root))) {
      refuseContactOption(e, path, contact, overrides, root);
      throw;
    }
  }
  if (loaded) return scene;
  // A vehicle file: write the scene around it.
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw InputError({out, 0}, "cannot create the output folder: " + ec.message());
  const std::string module = vehicleModule(path, root, fs::path(out));
  const fs::path scene_file = fs::path(out) / "scene.lua";
  {
    std::ofstream f(scene_file);
    f << sceneText(path, module, contact.empty() ? "kec" : contact);
    if (!f) throw InputError({scene_file.string(), 0}, "cannot write the scene file");
  }
  scene.file = scene_file.string();
  scene.from_vehicle_file = true;
  scene.overrides = overrides;  // the method is in the scene
  lo.overrides = scene.overrides;
  scene.spec = scenario::loadScenario(scene.file, lo);
  return scene;
}

}  // namespace rb::stability
