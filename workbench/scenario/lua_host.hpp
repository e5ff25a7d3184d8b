#pragma once
// The Lua 5.4 host: runs a scenario script in a sandbox and returns its blocks as a Node tree.
// This folder is the only code that includes lua.h (architecture.md).
//
// Sandbox: base, string, table, math and utf8 libraries only; no io, os, debug, load, dofile or
// loadfile. `require "a.b"` accepts plain dotted names only and reads a/b.lua below the scenario's
// folder or <root>/scenarios; the real path (symlinks resolved) must stay inside those folders.
// Data files (profiles, slices, irregularity CSVs) are read below the scenario's folder,
// <root>/scenarios and <root>/profiles only (resolveDataFile).
//
// Guard: an instruction budget, a wall-clock budget and a memory budget turn endless loops and
// runaway tables into errors instead of hangs. They are checked from a count hook that scripts
// cannot reach (no debug library). Once a budget is exceeded the state is dead: the hook raises
// the same error on every following instruction, so pcall/xpcall cannot swallow it, and the run
// fails with it even if the script caught it. Finalizers (__gc) are refused by setmetatable, since
// Lua runs them with hooks off. The pattern functions of the string library (find, match, gmatch,
// gsub) run in C where no hook fires: they refuse a call whose worst-case backtracking bound
//   starts * 2 (n+1)^q * (m + 2 + s (n+1))
// exceeds kPatternWorkLimit steps (n subject length, m pattern length, q quantifiers * + - ?,
// s back-references and %b items, starts = 1 if anchored by '^', else n+1). Plain searches and
// patterns without special characters are not limited.
//
// Conversion to the Node tree is bounded too: nesting depth, number of values, the length of one
// string and of all strings together (limits below), each a file:line error. The last bounds the
// copies: Lua keeps one copy of equal strings, the tree one per value, so a script within its
// memory budget could reference one long string from every value of the tree.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "workbench/scenario/node.hpp"

struct lua_State;

namespace rb::scenario {

struct HostOptions {
  std::string root;                                 // project root holding scenarios/ and profiles/
  long long instruction_limit = 2'000'000'000;      // Lua VM instructions for the whole script
  std::size_t memory_limit = std::size_t{1} << 30;  // bytes
  // Wall-clock budget [s] of everything run in this host (script and PSD functions); 0 takes
  // RAILBENCH_LUA_SECONDS from the environment, else kDefaultTimeLimit.
  double time_limit = 0.0;
  // A require of a module that is not found is collected (missingModules()) instead of ending
  // the script: the require returns a stand-in that absorbs every use (fields, calls,
  // arithmetic), so the rest of the script runs and its other problems are reported with it. The
  // top-level blocks built from a stand-in are left out of the tree, their kinds listed in
  // incompleteBlocks(). The caller must report missingModules() (loadScenario does).
  bool collect_missing_modules = false;
};

inline constexpr double kDefaultTimeLimit = 30.0;                     // [s]
inline constexpr int kMaxNesting = 32;                                // table levels below a block
inline constexpr std::size_t kMaxValues = 500'000;                    // values in the whole tree
inline constexpr std::size_t kMaxStringBytes = std::size_t{1} << 20;  // one string value
inline constexpr std::size_t kMaxTreeStringBytes = std::size_t{64} << 20;  // all string values
inline constexpr std::size_t kMaxScenarioBytes = std::size_t{16} << 20;  // scenario or module file
inline constexpr std::size_t kMaxModuleName = 200;  // characters of a require name
inline constexpr int kMaxRequireDepth = 32;         // nested require calls
inline constexpr double kPatternWorkLimit = 5e8;    // string pattern steps, see above

// Constructor names the host defines. Top-level blocks may appear once per scenario.
const std::vector<std::string>& topLevelBlocks();
const std::vector<std::string>& nestedConstructors();

class LuaHost {
 public:
  explicit LuaHost(HostOptions options);
  ~LuaHost();
  LuaHost(const LuaHost&) = delete;
  LuaHost& operator=(const LuaHost&) = delete;

  // Runs the script at `path` (shown in messages as given). Returns a table Node whose fields
  // are the top-level blocks by name. Throws InputError with file:line on any problem. Lua
  // function values in the tree stay callable while this host lives.
  Node runFile(const std::string& path);

  // With HostOptions::collect_missing_modules: the requires whose module was not found, and the
  // kinds of the top-level blocks made from their stand-ins (not in the tree runFile returns).
  const std::vector<Diagnostic>& missingModules() const;
  const std::vector<std::string>& incompleteBlocks() const { return incomplete_; }

  // The text of the scenario file read by runFile.
  const std::string& text() const { return text_; }

  // Every file loaded by require while running, in load order: (path as shown, full text).
  const std::vector<std::pair<std::string, std::string>>& modules() const;

  // Folders below which the scenario may read files (its own folder, scenarios/, profiles/).
  const std::vector<std::string>& readRoots() const { return roots_; }
  // Resolves a file name used inside the scenario and checks it lies below a read root. A relative
  // name is looked for beside the library whose text wrote it (`loc.file` a required file), then
  // in the scene's folder, then beside each required library (a name built in a library's plain
  // table carries the scene's location; two libraries holding different files of the name is an
  // error), then in the data directory (the root). Throws InputError at `loc`; a name not found
  // lists where it was looked for and the shipped file of that file name, if there is one.
  std::string resolveDataFile(const std::string& name, const SourceLoc& loc) const;

  // Internal, used by the C callbacks.
  struct Impl;

 private:
  Impl* impl_;
  HostOptions options_;
  std::vector<std::string> roots_;
  std::string scenarioDir_;
  std::string text_;
  std::vector<std::string> incomplete_;
};

}  // namespace rb::scenario
