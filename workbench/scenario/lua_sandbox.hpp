#pragma once
// Rules the scenario host (lua_host) and the metric sandbox (metric_lua) both enforce: the bound
// on the work of Lua's string pattern functions (find, match, gmatch, gsub; lua_host.hpp explains
// it: a pattern whose worst case on its subject exceeds the budget is refused before it runs) and
// the names `require` accepts.
#include <cstddef>
#include <initializer_list>
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

// The functions by which the two sandboxes differ: each guard accounts to its own state's budget
// and names its own caller in its messages. All are C functions of the Lua API (lua_CFunction).
struct SandboxFunctions {
  int (*pattern_guard)(lua_State*);       // upvalues: library function, name, anchorable, plain
  int (*setmetatable_guard)(lua_State*);  // upvalue: the library's setmetatable
  int (*print)(lua_State*);
  int (*require)(lua_State*);
};

// The one set-up of a sandboxed state: the safe libraries only (base, string, table, math,
// utf8); dofile, loadfile, load and each name of `banned` removed; setmetatable without
// finalizers and string.find/match/gmatch/gsub behind the pattern budget (also as the methods of
// every string, since the string table is their __index); print and require replaced; xpcall's
// message handlers guarded by `death` (guardMessageHandlers). `death` must outlive the state.
void openSandbox(lua_State* L, const SandboxFunctions& f, const SandboxDeath* death,
                 std::initializer_list<const char*> banned);

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
