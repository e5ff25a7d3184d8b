#pragma once
// Lua function metrics of a study (study.metrics entries with fn = function(s) ... end): the
// study file is run again in a sandbox of its own that lives as long as this object, so one
// sandbox serves every case of a summary, and the function is called with a table of signals.
//
// Sandbox (as the scenario host's, scenario/lua_host.hpp): base, string, table, math and utf8
// only; no io, os, debug, load, dofile, loadfile or collectgarbage; setmetatable refuses __gc;
// the pattern functions of the string library (find, match, gmatch, gsub), which run in C where
// the instruction budget cannot stop them, refuse a call beyond the host's worst-case bound
// (kPatternWorkLimit); `require "a.b"` reads a/b.lua below
// the study's folder or <root>/scenarios (real path checked) as the scenario host does. Each call
// has an instruction, wall-clock and memory budget.
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rb::scenario {

inline constexpr long long kMetricInstructionLimit = 1'000'000'000;      // per call
inline constexpr double kMetricTimeLimit = 30.0;                         // [s] per call
inline constexpr std::size_t kMetricMemoryLimit = std::size_t{1} << 30;  // bytes

// The budgets of the metric functions' sandbox: per call (and for the run of the study file),
// the Lua instructions and the wall-clock time; the memory of the whole Lua state. The program
// uses the defaults; tests and the fuzz harness (tests/fuzz) lower them so that the guard answers
// quickly.
struct MetricBudget {
  long long instructions = kMetricInstructionLimit;
  double seconds = kMetricTimeLimit;
  std::size_t memory = kMetricMemoryLimit;
};

class LuaMetrics {
 public:
  // Runs the study file `path`; throws InputError (file:line) when it does not run.
  LuaMetrics(const std::string& path, const std::string& root, const MetricBudget& budget = {});
  ~LuaMetrics();
  LuaMetrics(const LuaMetrics&) = delete;
  LuaMetrics& operator=(const LuaMetrics&) = delete;

  // Calls the `fn` of study.metrics[index] (1-based) with s = { <name> = { samples... }, ... }.
  // False with `why` when the function raises, exceeds a budget or returns no finite number.
  bool call(int index, const std::vector<std::pair<std::string, std::vector<double>>>& signals,
            double& out, std::string& why);

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace rb::scenario
