#pragma once
// The run library's tests that read what a run wrote: a compiled model run into a fresh result
// file under the temporary folder, and the numeric datasets of a group.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/vehicle_run.hpp"

namespace rb::test {

// The mean of v over the samples of the last second of t (steady states of the run tests).
inline double lastSecondMean(const std::vector<double>& t, const std::vector<double>& v) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t.back() - 1.0) {
      sum += v[i];
      ++n;
    }
  return sum / n;
}

// A scenario of the source tree compiled with `sets`.
inline run::Model compiled(const std::string& scenario, std::vector<std::string> sets = {}) {
  run::CompileOptions o;
  o.scenario = scenario;
  o.root = RB_SOURCE_DIR;
  o.overrides = std::move(sets);
  return run::compile(o);
}

// The problems (InputError text, "" if none) of `scenario` with the text from its first `from` up
// to and including the next `to` after it replaced by `replacement`, written to <temp>/<file>.
inline std::string problemsWithReplaced(const std::string& scenario, const std::string& from,
                                        const std::string& to, const std::string& replacement,
                                        const std::string& file,
                                        const std::vector<std::string>& sets = {}) {
  std::ifstream in(std::string(RB_SOURCE_DIR) + "/" + scenario);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto a = text.find(from);
  const auto b = text.find(to, a) + to.size();
  text = text.substr(0, a) + replacement + "\n" + text.substr(b);
  const std::filesystem::path path = std::filesystem::temp_directory_path() / file;
  std::ofstream(path) << text;
  try {
    (void)compiled(path.string(), sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// m run into <temp>/<folder>/<name> (provenance, outputs, /stats); the path and the run's result.
struct RunFile {
  std::string path;
  run::VehicleRunResult result;
};
inline RunFile runInto(const run::Model& m, const std::string& folder, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / folder;
  std::filesystem::create_directories(dir);
  RunFile out;
  out.path = (dir / name).string();
  io::ResultFile f(out.path);
  run::writeProvenance(m, f, "now");
  out.result = run::runVehicle(m, f, run::VehicleRunOptions{});
  f.finalize();
  return out;
}

// The numeric datasets below `group`, recursively.
inline void datasets(const io::ResultReader& r, const std::string& group,
                     std::vector<std::string>& out) {
  for (const auto& m : r.members(group)) {
    const std::string p = (group == "/" ? "" : group) + "/" + m;
    if (r.dataset(p))
      out.push_back(p);
    else
      datasets(r, p, out);
  }
}

// The default scene (ABM, fixed step, KEC contact, assessment on), 0.3 s, the wagon's reference
// point at `start`, with one suspension element written (what run.output.elements gives): the
// single run a vehicle of a run of several is compared with.
inline run::Model defaultSceneWagon(double start) {
  run::Model m = compiled("scenarios/default/case3_kec_fast.lua",
                          {"run.duration=0.3", "vehicle.start=" + std::to_string(start)});
  const auto id = m.lead().vehicle.findElement("prim_y_ws1_l");
  EXPECT_TRUE(id);
  if (id) m.vehicles.front().output_elements = {*id};
  return m;
}

inline bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// Every dataset of the single run's vehicle groups is in the file of a run of several vehicles
// under `prefix` (/vehicles/<name>), bit for bit; returns how many were compared.
inline int expectSameVehicle(const std::string& single, const std::string& several,
                             const std::string& prefix) {
  const io::ResultReader s(single), t(several);
  std::vector<std::string> paths;
  for (const char* g : {"/bodies", "/elements", "/contact", "/assessment"}) datasets(s, g, paths);
  int compared = 0;
  for (const auto& p : paths) {
    const auto a = s.dataset(p), b = t.dataset(prefix + p);
    EXPECT_TRUE(b) << prefix + p << " is not written";
    if (!a || !b) continue;
    EXPECT_TRUE(sameBits(*a, *b)) << prefix + p;
    ++compared;
  }
  return compared;
}

}  // namespace rb::test
