#include "workbench/scenario/metric_lua.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
}

#include "workbench/core/error.hpp"
#include "workbench/core/files.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/scenario/lua_host.hpp"
#include "workbench/scenario/lua_sandbox.hpp"

namespace fs = std::filesystem;

namespace rb::scenario {
namespace {

constexpr int kHookEvery = 1000;
constexpr const char* kStudyKey = "rb.metric.study";
constexpr const char* kLoadedKey = "rb.metric.loaded";

// A study file or module, within the scenario host's size limit.
bool readText(const std::string& path, std::string& out) {
  std::string why;
  auto bytes = readRegularFile(path, why, kMaxScenarioBytes);
  if (!bytes) return false;
  out = std::move(*bytes);
  return true;
}

bool below(const fs::path& p, const fs::path& root) {
  const auto rel = p.lexically_relative(root);
  return !rel.empty() && *rel.begin() != "..";
}

}  // namespace

struct LuaMetrics::Impl {
  MetricBudget budget;
  lua_State* L = nullptr;
  std::size_t memory = 0;
  long long instructions = 0;
  std::chrono::steady_clock::time_point deadline;
  SandboxDeath death;  // a budget was exceeded: every further instruction raises
  std::vector<fs::path> moduleRoots;

  static Impl* from(lua_State* L) { return *static_cast<Impl**>(lua_getextraspace(L)); }

  static void* alloc(void* ud, void* ptr, std::size_t osize, std::size_t nsize) {
    auto* self = static_cast<Impl*>(ud);
    const std::size_t old = ptr ? osize : 0;
    if (nsize == 0) {
      self->memory -= old;
      std::free(ptr);
      return nullptr;
    }
    if (nsize > old && self->memory - old + nsize > self->budget.memory) return nullptr;
    void* p = std::realloc(ptr, nsize);
    if (p) self->memory = self->memory - old + nsize;
    return p;
  }

  static void hook(lua_State* L, lua_Debug*) {
    Impl* self = from(L);
    self->instructions += kHookEvery;
    if (self->death.dead || self->instructions > self->budget.instructions ||
        std::chrono::steady_clock::now() > self->deadline) {
      if (!self->death.dead) {
        self->death.dead = true;
        lua_Debug ar;
        int line = 0;
        if (lua_getstack(L, 0, &ar) && lua_getinfo(L, "l", &ar)) line = ar.currentline;
        self->death.message = (line > 0 ? "line " + std::to_string(line) + ": " : std::string()) +
                              "metric function exceeded its budget of " +
                              std::to_string(self->budget.instructions) + " Lua instructions or " +
                              formatNumber(self->budget.seconds) + " s (endless loop?)";
        // From now on the hook fires on every instruction: a pcall that caught the error gets
        // it again as soon as it returns, so no retry loop can outlast the budget.
        lua_sethook(L, &hook, LUA_MASKCOUNT, 1);
      }
      lua_pushlstring(L, self->death.message.data(), self->death.message.size());
      lua_error(L);
    }
  }

  void arm() {
    instructions = 0;
    deadline = std::chrono::steady_clock::now() +
               std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                   std::chrono::duration<double>(budget.seconds));
  }

  // kind{ ... } returns its table; study{ ... } also keeps it (upvalue 1: true for study).
  static int construct(lua_State* L) {
    luaL_checktype(L, 1, LUA_TTABLE);
    lua_settop(L, 1);
    if (lua_toboolean(L, lua_upvalueindex(1))) {
      lua_pushvalue(L, 1);
      lua_setfield(L, LUA_REGISTRYINDEX, kStudyKey);
    }
    return 1;
  }

  static int setmetatableGuarded(lua_State* L) {
    if (lua_istable(L, 2)) {
      lua_getfield(L, 2, "__gc");
      if (!lua_isnil(L, -1)) return luaL_error(L, "__gc metamethods are not allowed");
      lua_pop(L, 1);
    }
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, lua_gettop(L) - 1, 1);
    return 1;
  }

  static int noPrint(lua_State*) { return 0; }

  // True when the pattern call on the stack is within kPatternWorkLimit (upvalues: the library
  // function, its name, anchorable, takes a `plain` argument).
  static bool patternAffordable(lua_State* L, double& work) {
    work = 0.0;
    if (lua_toboolean(L, lua_upvalueindex(4)) && lua_toboolean(L, 4)) return true;
    if (lua_type(L, 1) != LUA_TSTRING && lua_type(L, 1) != LUA_TNUMBER) return true;
    if (lua_type(L, 2) != LUA_TSTRING) return true;  // the library reports the wrong type
    std::size_t n = 0, m = 0;
    lua_tolstring(L, 1, &n);
    const char* pat = lua_tolstring(L, 2, &m);
    const std::string_view p(pat, m);
    if (!hasPatternSpecials(p)) return true;
    work = patternWork(p, n, lua_toboolean(L, lua_upvalueindex(3)));
    return work <= kPatternWorkLimit;
  }
  static int patternGuarded(lua_State* L) {
    // The library checks these too, but from inside this wrapper its message would name no
    // function ("bad argument #2 to '?'") and no line of the study file.
    luaL_checklstring(L, 1, nullptr);
    luaL_checklstring(L, 2, nullptr);
    double work = 0.0;
    if (!patternAffordable(L, work))
      return luaL_error(L, "string.%s: pattern too costly (worst case %f steps, limit %f)",
                        lua_tostring(L, lua_upvalueindex(2)), work, kPatternWorkLimit);
    const int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, LUA_MULTRET);
    return lua_gettop(L);
  }

  // (fn, signals*): calls fn{ name = { samples... }, ... }. No C++ object lives here, since
  // Lua errors unwind by longjmp.
  static int buildAndCall(lua_State* L) {
    const auto* signals =
        static_cast<const std::vector<std::pair<std::string, std::vector<double>>>*>(
            lua_touserdata(L, 2));
    lua_settop(L, 1);
    lua_createtable(L, 0, static_cast<int>(signals->size()));
    for (const auto& sig : *signals) {
      lua_createtable(L, static_cast<int>(sig.second.size()), 0);
      lua_Integer position = 0;  // Lua arrays count from 1
      for (const double v : sig.second) {
        lua_pushnumber(L, v);
        lua_rawseti(L, -2, ++position);
      }
      lua_setfield(L, -2, sig.first.c_str());
    }
    lua_call(L, 1, 1);
    return 1;
  }

  // The file of module `name` below a module root, "" when there is none.
  std::string findModule(const std::string& name) const {
    std::string rel = name;
    for (auto& c : rel)
      if (c == '.') c = '/';
    rel += ".lua";
    for (const auto& r : moduleRoots) {
      std::error_code ec;
      const fs::path p = fs::weakly_canonical(r / rel, ec);
      if (!ec && fs::is_regular_file(p, ec) && below(p, r)) return p.string();
    }
    return {};
  }

  // require "a.b": upvalue-free; the loaded modules are kept in the registry table kLoadedKey.
  static int require(lua_State* L) {
    Impl* self = from(L);
    const char* name = luaL_checkstring(L, 1);
    lua_getfield(L, LUA_REGISTRYINDEX, kLoadedKey);
    lua_getfield(L, -1, name);
    if (!lua_isnil(L, -1)) return 1;
    lua_pop(L, 1);
    bool found = false;
    int status = LUA_ERRFILE;
    {
      const std::string n = name;
      const std::string file = isPlainName(n) ? self->findModule(n) : std::string();
      std::string text;
      found = !file.empty() && readText(file, text);
      if (found) {
        const std::string chunk = "@" + file;
        status = luaL_loadbufferx(L, text.data(), text.size(), chunk.c_str(), "t");
      }
    }
    if (!found)
      return luaL_error(L, "module '%s' not found below the study's folder or scenarios/", name);
    if (status != LUA_OK) return lua_error(L);
    lua_call(L, 0, 1);
    if (lua_isnil(L, -1)) {
      lua_pop(L, 1);
      lua_pushboolean(L, 1);
    }
    lua_pushvalue(L, -1);
    lua_setfield(L, -3, name);
    return 1;
  }

  void openSandbox() {
    scenario::openSandbox(L, {&patternGuarded, &setmetatableGuarded, &noPrint, &require}, &death,
                          {"collectgarbage"});
    lua_newtable(L);
    lua_setfield(L, LUA_REGISTRYINDEX, kLoadedKey);
    for (const auto* names : {&topLevelBlocks(), &nestedConstructors()})
      for (const auto& k : *names) {
        lua_pushboolean(L, k == "study");
        lua_pushcclosure(L, &construct, 1);
        lua_setglobal(L, k.c_str());
      }
    lua_sethook(L, &hook, LUA_MASKCOUNT, kHookEvery);
  }

  // The error message on top of the stack (popped).
  std::string popError() {
    std::string m = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "error (no message)";
    lua_pop(L, 1);
    if (m.find("not enough memory") != std::string::npos || memory > budget.memory / 2)
      m += " (memory budget " + std::to_string(budget.memory >> 20) + " MiB)";
    return m;
  }
};

LuaMetrics::LuaMetrics(const std::string& path, const std::string& root, const MetricBudget& budget)
    : impl_(std::make_unique<Impl>()) {
  Impl& im = *impl_;
  im.budget = budget;
  im.L = lua_newstate(&Impl::alloc, &im);
  if (!im.L) throw InputError({path, 0}, "cannot create the Lua state of the metric functions");
  *static_cast<Impl**>(lua_getextraspace(im.L)) = &im;
  std::error_code ec;
  im.moduleRoots.push_back(fs::weakly_canonical(fs::absolute(path, ec).parent_path(), ec));
  if (!root.empty())
    im.moduleRoots.push_back(fs::weakly_canonical(fs::path(root) / "scenarios", ec));
  im.openSandbox();
  std::string text;
  if (!readText(path, text)) throw InputError({path, 0}, "cannot read the study file");
  im.arm();
  const std::string chunk = "@" + path;
  int status = luaL_loadbufferx(im.L, text.data(), text.size(), chunk.c_str(), "t");
  if (status == LUA_OK) status = lua_pcall(im.L, 0, 0, 0);
  if (status != LUA_OK) {
    const std::string m = im.popError();
    throw InputError({path, 0}, "running the study file for its metric functions: " + m);
  }
}

LuaMetrics::~LuaMetrics() {
  if (impl_ && impl_->L) lua_close(impl_->L);
}

bool LuaMetrics::call(int index,
                      const std::vector<std::pair<std::string, std::vector<double>>>& signals,
                      double& out, std::string& why) {
  Impl& im = *impl_;
  lua_State* L = im.L;
  if (im.death.dead) {
    why = "the metric functions' Lua state exceeded a budget in an earlier call";
    return false;
  }
  lua_settop(L, 0);
  lua_getfield(L, LUA_REGISTRYINDEX, kStudyKey);
  if (lua_istable(L, -1)) lua_getfield(L, -1, "metrics");
  if (lua_istable(L, -1)) lua_rawgeti(L, -1, index);
  if (lua_istable(L, -1)) lua_getfield(L, -1, "fn");
  if (!lua_isfunction(L, -1)) {
    lua_settop(L, 0);
    why = "study.metrics[" + std::to_string(index) + "].fn is not a function in the study file";
    return false;
  }
  // Where the function is written, so a failure names it (not only the line that raised).
  lua_Debug ar;
  lua_pushvalue(L, -1);
  std::string fnName = "the function";
  if (lua_getinfo(L, ">S", &ar) != 0 && ar.source != nullptr && ar.source[0] == '@' &&
      ar.linedefined > 0)
    fnName += " (" + std::string(ar.source + 1) + ":" + std::to_string(ar.linedefined) + ")";
  // The table is built inside the protected call, so a refused allocation is an error of the
  // call, not a panic. Stack: handler-less pcall of (builder, fn, signals*).
  lua_pushcfunction(L, &Impl::buildAndCall);
  lua_insert(L, -2);
  lua_pushlightuserdata(L, const_cast<void*>(static_cast<const void*>(&signals)));
  im.arm();
  if (lua_pcall(L, 2, 1, 0) != LUA_OK) {
    why = fnName + " raised: " + im.popError();
    lua_settop(L, 0);
    return false;
  }
  if (im.death.dead) {  // the function caught its budget error and returned: still a failure
    why = fnName + " raised: " + im.death.message;
    lua_settop(L, 0);
    return false;
  }
  const bool number = lua_type(L, -1) == LUA_TNUMBER;
  out = number ? lua_tonumber(L, -1) : std::nan("");
  if (!number)
    why = fnName + " returned a " + luaL_typename(L, -1) + ", not a number";
  else if (!std::isfinite(out))
    why = fnName + " returned " + formatNumber(out);
  lua_settop(L, 0);
  return why.empty();
}

}  // namespace rb::scenario
