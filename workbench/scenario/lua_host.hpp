#pragma once
// The Lua 5.4 host: runs a scenario script in a sandbox and returns its blocks as a Node tree.
// This folder is the only code that includes lua.h (architecture.md).
//
// Sandbox: base, string, table, math and utf8 libraries only; no io, os, debug, load, dofile or
// loadfile. `require "a.b"` reads a/b.lua below the scenario's folder or <root>/scenarios, and
// nothing else. An instruction budget and a memory limit turn endless loops and runaway tables
// into errors instead of hangs.
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
};

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

  // Every file loaded by require while running, in load order: (path as shown, full text).
  const std::vector<std::pair<std::string, std::string>>& modules() const;

  // Folders below which the scenario may read files (its own folder, scenarios/, profiles/).
  const std::vector<std::string>& readRoots() const { return roots_; }
  // Resolves a file name used inside the scenario (relative to the scenario's folder, then to the
  // project root) and checks it lies below a read root. Throws InputError at `loc`.
  std::string resolveDataFile(const std::string& name, const SourceLoc& loc) const;

  // Internal, used by the C callbacks.
  struct Impl;

 private:
  Impl* impl_;
  HostOptions options_;
  std::vector<std::string> roots_;
  std::string scenarioDir_;
};

}  // namespace rb::scenario
