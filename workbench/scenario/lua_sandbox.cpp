#include "workbench/scenario/lua_sandbox.hpp"

#include "workbench/scenario/lua_host.hpp"

#include <cctype>
#include <cmath>

#include <lua.hpp>

namespace rb::scenario {
namespace {

constexpr const char* kDeathKey = "rb.sandbox.death";

const SandboxDeath* deathOf(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, kDeathKey);
  const auto* d = static_cast<const SandboxDeath*>(lua_touserdata(L, -1));
  lua_pop(L, 1);
  return d;
}

// Upvalue 1: the script's message handler.
int handlerGuard(lua_State* L) {
  const SandboxDeath* d = deathOf(L);
  if (d != nullptr && d->dead) {
    lua_pushlstring(L, d->message.data(), d->message.size());
    return 1;
  }
  const int n = lua_gettop(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, n, 1);
  return 1;
}

// Upvalue 1: the library's xpcall.
int xpcallGuarded(lua_State* L) {
  if (lua_type(L, 2) == LUA_TFUNCTION) {
    lua_pushvalue(L, 2);
    lua_pushcclosure(L, &handlerGuard, 1);
    lua_replace(L, 2);
  }
  const int n = lua_gettop(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, n, LUA_MULTRET);
  return lua_gettop(L);
}

}  // namespace

void openSandbox(lua_State* L, const SandboxFunctions& f, const SandboxDeath* death,
                 std::initializer_list<const char*> banned) {
  const luaL_Reg libs[] = {{LUA_GNAME, luaopen_base},
                           {LUA_STRLIBNAME, luaopen_string},
                           {LUA_TABLIBNAME, luaopen_table},
                           {LUA_MATHLIBNAME, luaopen_math},
                           {LUA_UTF8LIBNAME, luaopen_utf8}};
  for (const auto& l : libs) {
    luaL_requiref(L, l.name, l.func, 1);
    lua_pop(L, 1);
  }
  for (const auto& names :
       {std::initializer_list<const char*>{"dofile", "loadfile", "load"}, banned})
    for (const char* g : names) {
      lua_pushnil(L);
      lua_setglobal(L, g);
    }
  lua_getglobal(L, "setmetatable");
  lua_pushcclosure(L, f.setmetatable_guard, 1);
  lua_setglobal(L, "setmetatable");
  lua_getglobal(L, "string");
  struct PatternFn {
    const char* name;
    bool anchorable;  // a leading '^' anchors the pattern
    bool plainArg;    // argument 4 asks for a plain search (find)
  };
  for (const PatternFn& p : {PatternFn{"find", true, true}, PatternFn{"match", true, false},
                             PatternFn{"gmatch", false, false}, PatternFn{"gsub", true, false}}) {
    lua_getfield(L, -1, p.name);
    lua_pushstring(L, p.name);
    lua_pushboolean(L, p.anchorable);
    lua_pushboolean(L, p.plainArg);
    lua_pushcclosure(L, f.pattern_guard, 4);
    lua_setfield(L, -2, p.name);
  }
  lua_pop(L, 1);
  lua_pushcfunction(L, f.print);
  lua_setglobal(L, "print");
  lua_pushcfunction(L, f.require);
  lua_setglobal(L, "require");
  guardMessageHandlers(L, death);
}

void guardMessageHandlers(lua_State* L, const SandboxDeath* death) {
  lua_pushlightuserdata(L, const_cast<SandboxDeath*>(death));
  lua_setfield(L, LUA_REGISTRYINDEX, kDeathKey);
  lua_getglobal(L, "xpcall");
  lua_pushcclosure(L, &xpcallGuarded, 1);
  lua_setglobal(L, "xpcall");
}

double patternWork(std::string_view pat, std::size_t subjectLen, bool anchorable) {
  const double n1 = static_cast<double>(subjectLen) + 1.0;
  double q = 0, s = 0;
  std::size_t i = 0;
  const bool anchored = anchorable && !pat.empty() && pat[0] == '^';
  if (anchored) i = 1;
  while (i < pat.size()) {
    const char c = pat[i];
    bool single = true;  // a single-character class that a quantifier may follow
    if (c == '(' || c == ')') {
      ++i;
      single = false;
    } else if (c == '%' && i + 1 < pat.size()) {
      const char d = pat[i + 1];
      if (d == 'b') {
        s += 1;
        i += 4;
        single = false;
      } else if (d == 'f') {
        i += 2;
        single = false;  // the set that follows is skipped as a class below
      } else {
        if (std::isdigit(static_cast<unsigned char>(d))) s += 1;
        i += 2;
      }
    } else if (c == '[') {
      ++i;
      if (i < pat.size() && pat[i] == '^') ++i;
      if (i < pat.size()) ++i;  // a ']' first in the set is literal
      while (i < pat.size() && pat[i] != ']') i += pat[i] == '%' ? 2 : 1;
      ++i;
    } else {
      ++i;
    }
    if (single && i < pat.size() &&
        (pat[i] == '*' || pat[i] == '+' || pat[i] == '-' || pat[i] == '?')) {
      q += 1;
      ++i;
    }
  }
  const double starts = anchored ? 1.0 : n1;
  return starts * 2.0 * std::pow(n1, q) * (static_cast<double>(pat.size()) + 2.0 + s * n1);
}

bool hasPatternSpecials(std::string_view pat) {
  return pat.find_first_of("^$*+?.([%-") != std::string_view::npos;
}

bool isPlainName(const std::string& name) {
  if (name.empty() || name.size() > kMaxModuleName) return false;
  bool segmentStart = true;
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '.') {
      if (segmentStart) return false;
      segmentStart = true;
    } else if (std::isalpha(u) || c == '_' || (!segmentStart && std::isdigit(u))) {
      segmentStart = false;
    } else {
      return false;
    }
  }
  return !segmentStart;
}

}  // namespace rb::scenario
