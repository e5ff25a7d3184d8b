#pragma once
// Rules the scenario host (lua_host) and the metric sandbox (metric_lua) both enforce: the bound
// on the work of Lua's string pattern functions (find, match, gmatch, gsub; lua_host.hpp explains
// it: a pattern whose worst case on its subject exceeds the budget is refused before it runs) and
// the names `require` accepts.
#include <cstddef>
#include <string>
#include <string_view>

struct lua_State;

namespace rb::scenario {

// A sandbox whose budget was exceeded is dead: its hook raises `message` on every further Lua
// instruction, so a pcall that catches the budget error cannot go on (the error is raised again
// as soon as the pcall returns).
struct SandboxDeath {
  bool dead = false;
  std::string message;
};

// Replaces xpcall by one whose message handler is skipped once `death` is dead: Lua calls the
// handler of an error raised by a hook with hooks off, so a handler that loops could not be
// stopped; the budget error is kept instead. `death` must outlive the state.
void guardMessageHandlers(lua_State* L, const SandboxDeath* death);

// Worst-case work of one call of a Lua pattern function on a subject of `subjectLen` bytes.
double patternWork(std::string_view pat, std::size_t subjectLen, bool anchorable);

// Whether `pat` has any magic character (a plain pattern is a plain search).
bool hasPatternSpecials(std::string_view pat);

// A module name `require` accepts: dot-separated identifiers (no path, no "..", at most
// kMaxModuleName characters), so a name can never leave the module folders.
bool isPlainName(const std::string& name);

}  // namespace rb::scenario
