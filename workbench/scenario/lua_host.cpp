#include "workbench/scenario/lua_host.hpp"

#include <lua.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#include "workbench/core/files.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/scenario/lua_sandbox.hpp"
#include "workbench/scenario/source_positions.hpp"
#include "workbench/track/names.hpp"
#include "workbench/vehicle/names.hpp"

namespace fs = std::filesystem;

namespace rb::scenario {

const std::vector<std::string>& topLevelBlocks() {
  static const std::vector<std::string> names = {"track",   "profiles", "vehicle", "train",
                                                 "contact", "solver",   "run",     "study"};
  return names;
}

const std::vector<std::string>& nestedConstructors() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = namesOf<track::SegmentKind>();
    for (const char* other : {"psd", "measured", "body"}) n.emplace_back(other);
    for (auto& e : namesOf<vehicle::ElementKind>()) n.push_back(std::move(e));
    n.emplace_back(vehicle::kExternalForceKind);
    return n;
  }();
  return names;
}

namespace {

const char* const kMetaKey = "railbench.meta";        // registry: table -> {kind, file, line}
const char* const kBlocksKey = "railbench.blocks";    // registry: array of top-level tables
const char* const kLoadedKey = "railbench.loaded";    // registry: module name -> value
const char* const kStandinKey = "railbench.standin";  // registry: metatable of the stand-ins

// Memory the host itself may use beyond the script's budget once the script has ended (converting
// the tree, references to PSD functions): an allocation refused outside a protected call would
// abort the process, so the host never runs out where the script stopped.
constexpr std::size_t kHostReserve = std::size_t{64} << 20;

std::string displayPath(const fs::path& p) {
  std::error_code ec;
  fs::path rel = fs::proximate(p, fs::current_path(ec), ec);
  if (!ec && !rel.empty() && rel.native().rfind("..", 0) != 0) return rel.string();
  return p.string();
}

// True if `file` lies below `root`; both must already be canonical (symlinks resolved).
bool isBelowCanonical(const fs::path& file, const fs::path& root) {
  auto [rootEnd, fileIt] = std::mismatch(root.begin(), root.end(), file.begin(), file.end());
  (void)fileIt;
  return rootEnd == root.end();
}

bool isBelow(const fs::path& file, const fs::path& root) {
  std::error_code ec;
  fs::path f = fs::weakly_canonical(file, ec);
  if (ec) return false;
  fs::path r = fs::weakly_canonical(root, ec);
  if (ec) return false;
  return isBelowCanonical(f, r);
}

// "file:line: message" -> Diagnostic; anything else keeps an empty location.
Diagnostic parseLuaMessage(const std::string& msg, const std::string& fallbackFile) {
  // Lua prefixes positions as "<chunkname>:<line>: "; the chunk name may itself contain ':'.
  for (std::size_t colon = msg.find(':'); colon != std::string::npos;
       colon = msg.find(':', colon + 1)) {
    std::size_t digits = colon + 1;
    while (digits < msg.size() && digits - colon <= 9 &&
           std::isdigit(static_cast<unsigned char>(msg[digits])))
      ++digits;
    if (digits > colon + 1 && digits - colon <= 9 && msg.compare(digits, 2, ": ") == 0 &&
        msg.find('\n') > colon) {
      return Diagnostic{
          {msg.substr(0, colon), std::stoi(msg.substr(colon + 1, digits - colon - 1))},
          msg.substr(digits + 2)};
    }
  }
  return Diagnostic{{fallbackFile, 0}, msg};
}

bool hasLocation(const std::string& msg) {
  return parseLuaMessage(msg, "").loc.line > 0;
}

}  // namespace

struct LuaHost::Impl {
  lua_State* L = nullptr;
  LuaHost* host = nullptr;
  std::size_t memory = 0;
  std::size_t memoryLimit = 0;  // the script's budget
  bool hostPhase = false;       // the script has ended: allow kHostReserve beyond the budget
  bool memoryRefused = false;   // an allocation was refused: the state is dead
  long long instructions = 0;
  long long instructionLimit = 0;
  double timeLimit = kDefaultTimeLimit;
  std::chrono::steady_clock::time_point deadline;
  // A budget was exceeded: every further Lua instruction raises death.message ("file:line: ..."
  // of the first budget error); xpcall's message handlers are skipped (lua_sandbox.hpp).
  SandboxDeath death;
  SourceLoc memoryLoc;                   // last place seen by the hook while memory was high
  std::string chunkFile;                 // the scenario file as shown
  std::vector<std::string> moduleRoots;  // canonical: scenario dir, scenarios/
  std::vector<std::pair<std::string, std::string>> modules;  // required files: path, text
  std::vector<std::string> loading;                          // require calls in progress
  bool collectMissing = false;                               // HostOptions::collect_missing_modules
  bool moduleMissing = false;              // set by findModule: the error is "not found"
  std::vector<Diagnostic> missingModules;  // collected requires of modules not found
  // The canonical folder of each required file, by its path as shown (the file of a SourceLoc):
  // where the data files a library names are looked for first (LuaHost::resolveDataFile).
  std::vector<std::pair<std::string, std::string>> moduleFolders;

  static Impl* from(lua_State* L) { return *static_cast<Impl**>(lua_getextraspace(L)); }

  static void* alloc(void* ud, void* ptr, std::size_t osize, std::size_t nsize) {
    auto* self = static_cast<Impl*>(ud);
    std::size_t old = ptr ? osize : 0;
    if (nsize == 0) {
      self->memory -= old;
      std::free(ptr);
      return nullptr;
    }
    // After a refusal the reserve is open too: the script is dead from the next hook on, and the
    // error handling between (messages, constructors) must not fail again at the limit.
    const bool reserve = self->hostPhase || self->memoryRefused;
    const std::size_t limit = self->memoryLimit + (reserve ? kHostReserve : 0);
    if (nsize > old && self->memory - old + nsize > limit) {
      // Lua raises "not enough memory"; the refusal itself ends the scenario (below), so a
      // script that catches the error cannot carry on at the limit.
      self->memoryRefused = true;
      return nullptr;
    }
    void* p = std::realloc(ptr, nsize);
    if (p) self->memory = self->memory - old + nsize;
    return p;
  }

  std::string memoryMessage() const {
    return "scenario exceeded its memory budget of " + std::to_string(memoryLimit >> 20) +
           " MiB (not enough memory)";
  }

  // Lua reports errors by longjmp, which skips C++ destructors. So every C function below does
  // its C++ work in a *Body function that returns false with the message pushed on the Lua stack;
  // the thin wrapper calls lua_error only after all C++ objects are gone (architecture.md: never
  // throw across a Lua longjmp). Bodies also catch C++ exceptions, which must not cross Lua frames.

  static constexpr int kHookEvery = 1000;

  // Location of the innermost Lua function on the stack at or above `level`.
  static SourceLoc luaLoc(lua_State* L, int level) {
    lua_Debug ar;
    for (int lv = level; lua_getstack(L, lv, &ar); ++lv) {
      if (!lua_getinfo(L, "Sl", &ar) || ar.currentline <= 0) continue;
      std::string src = ar.source ? ar.source : "?";
      if (!src.empty() && src[0] == '@') src.erase(0, 1);
      return {src, ar.currentline};
    }
    return {"?", 0};
  }

  // Marks the state dead with `msg` at the current Lua line and pushes the message.
  void die(lua_State* state, const std::string& msg) {
    if (!death.dead) {
      death.dead = true;
      SourceLoc loc = luaLoc(state, 0);
      if (loc.line == 0) loc.file = chunkFile;
      death.message = loc.str() + ": " + msg;
      // From now on the hook fires on every instruction, so the error is raised again as soon as
      // a pcall that caught it returns.
      lua_sethook(state, &Impl::countHook, LUA_MASKCOUNT, 1);
    }
    lua_pushlstring(state, death.message.data(), death.message.size());
  }

  // Checks the budgets that do not count instructions; false with the error pushed if exceeded.
  bool checkBudgets(lua_State* state) {
    if (death.dead) {
      lua_pushlstring(state, death.message.data(), death.message.size());
      return false;
    }
    if (memoryRefused || memory > memoryLimit + (hostPhase ? kHostReserve : 0)) {
      die(state, memoryMessage());
      return false;
    }
    if (std::chrono::steady_clock::now() > deadline) {
      std::ostringstream os;
      os << "scenario exceeded its time budget of " << formatNumber(timeLimit)
         << " s (endless loop?)";
      die(state, os.str());
      return false;
    }
    return true;
  }

  static bool countHookBody(lua_State* L) {
    Impl* self = from(L);
    if (self->death.dead) return self->checkBudgets(L);
    self->instructions += kHookEvery;
    if (self->memory > self->memoryLimit / 2) self->memoryLoc = luaLoc(L, 0);
    if (self->instructions > self->instructionLimit) {
      self->die(L, "scenario exceeded its budget of " + std::to_string(self->instructionLimit) +
                       " Lua instructions (endless loop?)");
      return false;
    }
    return self->checkBudgets(L);
  }
  static void countHook(lua_State* L, lua_Debug*) {
    if (!countHookBody(L)) lua_error(L);
  }

  // Message handler of every protected call the host makes: gives every error a location (the
  // Lua line that raised it) and a string message, whatever value was raised.
  static void messageBody(lua_State* L) {
    Impl* self = from(L);
    if (self->death.dead) {
      lua_pushlstring(L, self->death.message.data(), self->death.message.size());
      return;
    }
    std::string msg;
    const int t = lua_type(L, 1);
    if (t == LUA_TSTRING) {
      std::size_t len = 0;
      const char* s = lua_tolstring(L, 1, &len);
      msg.assign(s, std::min(len, std::size_t{4096}));
      if (hasLocation(msg)) {
        lua_pushlstring(L, msg.data(), msg.size());
        return;
      }
      if (msg.empty()) msg = "error called with an empty message";
    } else if (t == LUA_TNUMBER) {
      lua_pushvalue(L, 1);
      msg = std::string("error ") + lua_tostring(L, -1);
      lua_pop(L, 1);
    } else if (t == LUA_TNIL || t == LUA_TNONE) {
      msg = "error called with nil (no message)";
    } else {
      msg = std::string("error called with a ") + lua_typename(L, t) + " value (no message)";
    }
    // Level 0 is this handler; the first Lua function above it is where the error was raised.
    SourceLoc loc = luaLoc(L, 1);
    if (loc.line == 0) loc.file = self->chunkFile;
    push(L, loc, msg);
  }
  static int messageHandler(lua_State* L) {
    messageBody(L);
    return 1;
  }

  // Location of the Lua code that called the current C function.
  static SourceLoc callerLoc(lua_State* L) { return luaLoc(L, 1); }

  // Pushes "file:line: msg" as the pending error value.
  static void push(lua_State* L, const SourceLoc& loc, const std::string& msg) {
    std::string full = loc.str() + ": " + msg;
    lua_pushlstring(L, full.data(), full.size());
  }

  // Constructor: kind{ ... }. Upvalue 1: kind name, upvalue 2: true if top-level block.
  static bool constructBody(lua_State* L) {
    const char* kind = lua_tostring(L, lua_upvalueindex(1));
    bool top = lua_toboolean(L, lua_upvalueindex(2));
    if (lua_gettop(L) != 1 || !lua_istable(L, 1)) {
      std::string got = lua_gettop(L) == 0 ? "nothing" : luaL_typename(L, 1);
      push(L, callerLoc(L),
           std::string(kind) + " expects one table of named values, e.g. " + kind +
               " { ... }, got " + got);
      return false;
    }
    if (!lua_checkstack(L, 8)) {
      push(L, callerLoc(L), "Lua stack exhausted");
      return false;
    }
    SourceLoc loc = callerLoc(L);
    lua_getfield(L, LUA_REGISTRYINDEX, kMetaKey);
    lua_pushvalue(L, 1);
    lua_createtable(L, 0, 3);
    lua_pushstring(L, kind);
    lua_setfield(L, -2, "kind");
    lua_pushstring(L, loc.file.c_str());
    lua_setfield(L, -2, "file");
    lua_pushinteger(L, loc.line);
    lua_setfield(L, -2, "line");
    lua_settable(L, -3);
    lua_pop(L, 1);
    if (top) {
      lua_getfield(L, LUA_REGISTRYINDEX, kBlocksKey);
      lua_pushvalue(L, 1);
      lua_rawseti(L, -2, static_cast<lua_Integer>(lua_rawlen(L, -2) + 1));
      lua_pop(L, 1);
    }
    lua_pushvalue(L, 1);
    return true;
  }
  static int construct(lua_State* L) { return constructBody(L) ? 1 : lua_error(L); }

  // The modules beside where `name` was looked for (same folder, every module root), as dotted
  // names: the candidates of a did-you-mean. At most 1000 entries per folder are looked at.
  std::vector<std::string> siblingModules(const std::string& name) const {
    const auto dot = name.rfind('.');
    const std::string prefix = dot == std::string::npos ? "" : name.substr(0, dot + 1);
    std::string folder = prefix;
    for (char& c : folder)
      if (c == '.') c = '/';
    std::vector<std::string> out;
    for (const auto& root : moduleRoots) {
      std::error_code ec;
      fs::directory_iterator it(fs::path(root) / folder, ec), end;
      for (int n = 0; !ec && it != end && n < 1000; it.increment(ec), ++n) {
        const fs::path& f = it->path();
        if (f.extension() == ".lua") out.push_back(prefix + f.stem().string());
      }
    }
    return out;
  }

  // Finds and reads the module file; false with the error pushed.
  bool findModule(lua_State* state, const std::string& name, const SourceLoc& loc,
                  std::string& shown, std::string& text, std::string& folder) {
    std::string rel = name;
    for (char& c : rel)
      if (c == '.') c = '/';
    rel += ".lua";
    std::string tried;
    for (const auto& root : moduleRoots) {
      const fs::path cand = fs::path(root) / rel;
      tried += "\n\t" + displayPath(cand);
      std::error_code ec;
      if (!fs::exists(cand, ec)) continue;
      const fs::path real = fs::canonical(cand, ec);
      if (ec || !isBelowCanonical(real, fs::path(root))) {
        push(state, loc,
             "require \"" + name + "\": " + displayPath(cand) +
                 " leads outside the folders modules may come from (the scenario's folder, "
                 "scenarios/)");
        return false;
      }
      shown = displayPath(cand);
      std::string why;
      std::optional<std::string> content = readRegularFile(real.string(), why, kMaxScenarioBytes);
      if (!content) {
        push(state, loc, "require \"" + name + "\": cannot read " + shown + ": " + why);
        return false;
      }
      text = std::move(*content);
      folder = real.parent_path().string();
      return true;
    }
    const std::string hint = closestMatch(name, siblingModules(name));
    push(state, loc,
         "require \"" + name + "\": module not found" +
             (hint.empty() ? "" : " (did you mean \"" + hint + "\"?)") + "; tried:" + tried);
    moduleMissing = true;
    return false;
  }

  // Checks the name and loads the chunk; on success the chunk is pushed and `name` set.
  static bool requireLoadBody(lua_State* L, std::string& name) {
    Impl* self = from(L);
    SourceLoc loc = callerLoc(L);
    if (lua_type(L, 1) != LUA_TSTRING) {
      push(L, loc, "require expects a module name string, e.g. require \"vehicles.wagon\"");
      return false;
    }
    std::size_t len = 0;
    const char* raw = lua_tolstring(L, 1, &len);
    name.assign(raw, std::min(len, kMaxModuleName + 1));
    // Shown in messages: control characters (a NUL would cut the message short) become '?'.
    for (char& c : name)
      if (std::iscntrl(static_cast<unsigned char>(c))) c = '?';
    if (len > kMaxModuleName) {
      push(L, loc,
           "require: module name longer than " + std::to_string(kMaxModuleName) + " characters");
      return false;
    }
    if (!isPlainName(name)) {
      push(L, loc,
           "require \"" + name +
               "\": module names are names separated by dots (letters, digits and '_', not "
               "starting with a digit), e.g. \"vehicles.wagon\"");
      return false;
    }
    for (std::size_t i = 0; i < self->loading.size(); ++i) {
      if (self->loading[i] != name) continue;
      std::string chain;
      for (std::size_t j = i; j < self->loading.size(); ++j) chain += self->loading[j] + " -> ";
      push(L, loc, "require \"" + name + "\": require cycle: " + chain + name);
      return false;
    }
    if (static_cast<int>(self->loading.size()) >= kMaxRequireDepth) {
      push(L, loc,
           "require \"" + name + "\": more than " + std::to_string(kMaxRequireDepth) +
               " nested require calls");
      return false;
    }
    std::string shown, text, folder;
    if (!self->findModule(L, name, loc, shown, text, folder)) return false;
    std::string chunk = "@" + shown;
    if (luaL_loadbufferx(L, text.data(), text.size(), chunk.c_str(), "t") != LUA_OK) return false;
    self->modules.push_back({shown, std::move(text)});  // provenance: every file the run read
    self->moduleFolders.emplace_back(shown, std::move(folder));
    return true;
  }
  static bool requireLoad(lua_State* L, std::string& name) {
    try {
      return requireLoadBody(L, name);
    } catch (const std::exception& e) {
      push(L, callerLoc(L), std::string("require: ") + e.what());
      return false;
    }
  }

  // require: stack [name]; the loaded value is cached in the registry by name.
  static int require(lua_State* L) {
    if (!lua_checkstack(L, 8)) return luaL_error(L, "Lua stack exhausted");
    lua_settop(L, 1);
    if (lua_type(L, 1) == LUA_TSTRING) {
      lua_getfield(L, LUA_REGISTRYINDEX, kLoadedKey);
      lua_pushvalue(L, 1);
      lua_rawget(L, -2);
      if (!lua_isnil(L, -1)) return 1;
      lua_settop(L, 1);
    }
    bool ok = false;
    Impl* self = from(L);
    self->moduleMissing = false;
    {
      std::string name;
      ok = requireLoad(L, name);
      if (ok) self->loading.push_back(name);
    }
    if (!ok && self->moduleMissing && self->collectMissing) {
      // Collected: the rest of the script runs on a stand-in (see HostOptions).
      self->moduleMissing = false;
      std::size_t len = 0;
      const char* msg = lua_tolstring(L, -1, &len);
      self->missingModules.push_back(parseLuaMessage(std::string(msg, len), self->chunkFile));
      lua_pop(L, 1);
      pushStandin(L);
      return 1;
    }
    if (!ok) return lua_error(L);
    // Stack: [name, chunk]. Run it under the message handler so errors keep their own line.
    lua_pushcfunction(L, &Impl::messageHandler);
    lua_insert(L, 2);
    lua_pushvalue(L, 1);
    const int status = lua_pcall(L, 1, 1, 2);
    from(L)->loading.pop_back();
    if (status != LUA_OK) return lua_error(L);
    if (lua_isnil(L, -1)) {
      lua_pop(L, 1);
      lua_pushboolean(L, 1);
    }
    lua_getfield(L, LUA_REGISTRYINDEX, kLoadedKey);
    lua_pushvalue(L, 1);
    lua_pushvalue(L, -3);
    lua_rawset(L, -3);
    lua_pop(L, 1);
    return 1;
  }

  // A stand-in for a module that was not found: an empty table whose metatable answers every
  // field name, call and arithmetic with a new stand-in (list positions with nil, so ipairs and
  // # see an empty list), compares false and converts to text.
  static void pushStandin(lua_State* L) {
    lua_newtable(L);
    lua_getfield(L, LUA_REGISTRYINDEX, kStandinKey);
    lua_setmetatable(L, -2);
  }
  static int standinNew(lua_State* L) {
    pushStandin(L);
    return 1;
  }
  static int standinIndex(lua_State* L) {
    if (lua_type(L, 2) == LUA_TSTRING)
      pushStandin(L);
    else
      lua_pushnil(L);
    return 1;
  }
  static int standinFalse(lua_State* L) {
    lua_pushboolean(L, 0);
    return 1;
  }
  static int standinLen(lua_State* L) {
    lua_pushinteger(L, 0);
    return 1;
  }
  static int standinText(lua_State* L) {
    lua_pushliteral(L, "<module not found>");
    return 1;
  }
  static void defineStandin(lua_State* L) {
    lua_newtable(L);
    lua_pushcfunction(L, &standinIndex);
    lua_setfield(L, -2, "__index");
    for (const char* op :
         {"__call", "__add", "__sub", "__mul", "__div", "__mod", "__pow", "__unm", "__idiv",
          "__concat", "__band", "__bor", "__bxor", "__shl", "__shr", "__bnot"}) {
      lua_pushcfunction(L, &standinNew);
      lua_setfield(L, -2, op);
    }
    lua_pushcfunction(L, &standinFalse);
    lua_setfield(L, -2, "__lt");
    lua_pushcfunction(L, &standinFalse);
    lua_setfield(L, -2, "__le");
    lua_pushcfunction(L, &standinLen);
    lua_setfield(L, -2, "__len");
    lua_pushcfunction(L, &standinText);
    lua_setfield(L, -2, "__tostring");
    lua_pushliteral(L, "locked");
    lua_setfield(L, -2, "__metatable");
    lua_setfield(L, LUA_REGISTRYINDEX, kStandinKey);
  }
  // True when the value at idx is a stand-in.
  static bool isStandin(lua_State* L, int idx) {
    if (!lua_getmetatable(L, idx)) return false;
    lua_getfield(L, LUA_REGISTRYINDEX, kStandinKey);
    const bool same = lua_rawequal(L, -1, -2) != 0;
    lua_pop(L, 2);
    return same;
  }

  static int print(lua_State* L) {
    int n = lua_gettop(L);
    for (int i = 1; i <= n; ++i) {
      if (i > 1) std::fputc('\t', stderr);
      std::fputs(luaL_tolstring(L, i, nullptr), stderr);
      lua_pop(L, 1);
    }
    std::fputc('\n', stderr);
    return 0;
  }

  // setmetatable without finalizers: Lua runs __gc with hooks off, so the guard could not stop
  // an endless loop inside one. Upvalue 1: the library's setmetatable.
  static int setmetatableGuarded(lua_State* L) {
    if (lua_type(L, 2) == LUA_TTABLE) {
      lua_pushstring(L, "__gc");
      lua_rawget(L, 2);
      const bool gc = !lua_isnil(L, -1);
      lua_pop(L, 1);
      if (gc) {
        unknownHelper(L, "setmetatable: finalizers (__gc) are not allowed in a scenario");
        return lua_error(L);
      }
    }
    const int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, 1);
    return 1;
  }
  static void unknownHelper(lua_State* L, const char* msg) { push(L, callerLoc(L), msg); }

  // string.find/match/gmatch/gsub: refuses calls whose worst-case work is beyond the limit, then
  // runs the library function (upvalue 1). Upvalue 2: function name; upvalue 3: true if a leading
  // '^' anchors the pattern; upvalue 4: true for find (argument 4 asks for a plain search).
  static bool patternCheckBody(lua_State* L) {
    Impl* self = from(L);
    if (!self->checkBudgets(L)) return false;
    if (lua_toboolean(L, lua_upvalueindex(4)) && lua_toboolean(L, 4)) return true;
    if (lua_type(L, 1) != LUA_TSTRING && lua_type(L, 1) != LUA_TNUMBER) return true;
    if (lua_type(L, 2) != LUA_TSTRING) return true;  // the library reports the wrong type
    std::size_t n = 0, m = 0;
    lua_tolstring(L, 1, &n);  // numbers are converted in place, as the library would
    const char* pat = lua_tolstring(L, 2, &m);
    std::string_view p(pat, m);
    if (!hasPatternSpecials(p)) return true;
    const double work = patternWork(p, n, lua_toboolean(L, lua_upvalueindex(3)));
    if (work <= kPatternWorkLimit) return true;
    std::ostringstream os;
    os << "string." << lua_tostring(L, lua_upvalueindex(2)) << ": pattern too costly for a " << n
       << "-character subject (worst case " << formatNumber(work, 3) << " steps, limit "
       << formatNumber(kPatternWorkLimit, 3)
       << "); use fewer repetition items (* + - ?) or shorter strings";
    push(L, callerLoc(L), os.str());
    return false;
  }
  static int patternGuarded(lua_State* L) {
    // The library checks these too, but from inside this wrapper its message would name no
    // function ("bad argument #2 to '?'") and no line of the script.
    luaL_checklstring(L, 1, nullptr);
    luaL_checklstring(L, 2, nullptr);
    if (!patternCheckBody(L)) return lua_error(L);
    const int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, LUA_MULTRET);
    return lua_gettop(L);
  }

  // __index on the globals: an unknown name is an error with a hint, not a silent nil.
  static void unknownGlobalBody(lua_State* L) {
    std::string name = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : "?";
    if (name.size() > 100) name = name.substr(0, 100) + "...";
    std::vector<std::string> known;
    lua_pushnil(L);
    while (lua_next(L, 1)) {
      if (lua_type(L, -2) == LUA_TSTRING && known.size() < 1000)
        known.emplace_back(lua_tostring(L, -2));
      lua_pop(L, 1);
    }
    std::string msg = "unknown name '" + name + "'";
    std::string hint = closestMatch(name, known);
    if (!hint.empty()) msg += " (did you mean '" + hint + "'?)";
    push(L, callerLoc(L), msg);
  }
  static int unknownGlobal(lua_State* L) {
    unknownGlobalBody(L);
    return lua_error(L);
  }

  // A Lua error outside any protected call: nothing can be recovered, but say what happened
  // instead of aborting silently. The host keeps a memory reserve so this is never expected.
  static int panic(lua_State* L) {
    const char* m = lua_tostring(L, -1);
    std::fprintf(stderr, "internal error: unprotected Lua error: %s\n", m ? m : "?");
    std::fflush(stderr);
    std::_Exit(3);
  }

  // The error of a failed protected call, as an InputError.
  InputError errorOf(int status) {
    if (death.dead) return InputError({parseLuaMessage(death.message, chunkFile)});
    if (status == LUA_ERRMEM || memoryRefused) {
      SourceLoc loc = memoryLoc.line > 0 ? memoryLoc : SourceLoc{chunkFile, 0};
      return InputError(loc, memoryMessage());
    }
    std::string msg = "unknown Lua error";
    if (lua_type(L, -1) == LUA_TSTRING) {
      std::size_t len = 0;
      const char* s = lua_tolstring(L, -1, &len);
      msg.assign(s, len);
    }
    if (status == LUA_ERRERR) msg = "error while handling an error (" + msg + ")";
    return InputError({parseLuaMessage(msg, chunkFile)});
  }
};

LuaHost::LuaHost(HostOptions options) : impl_(new Impl), options_(std::move(options)) {
  impl_->host = this;
  impl_->memoryLimit = options_.memory_limit;
  impl_->instructionLimit = options_.instruction_limit;
  impl_->timeLimit = options_.time_limit;
  if (!(impl_->timeLimit > 0)) {
    impl_->timeLimit = kDefaultTimeLimit;
    if (const char* env = std::getenv("RAILBENCH_LUA_SECONDS")) {
      char* end = nullptr;
      const double v = std::strtod(env, &end);
      if (end != env && *end == '\0' && v > 0 && v < 1e6) impl_->timeLimit = v;
    }
  }
  impl_->deadline = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(impl_->timeLimit));
  // Opening the libraries is the host's own work, not the script's.
  impl_->hostPhase = true;
  lua_State* L = lua_newstate(&Impl::alloc, impl_);
  if (!L) {
    delete impl_;
    throw std::runtime_error("cannot create Lua state");
  }
  impl_->L = L;
  *static_cast<Impl**>(lua_getextraspace(L)) = impl_;
  lua_atpanic(L, &Impl::panic);

  // collectgarbage stays: the allocator's budget bounds the memory whatever the collector does.
  openSandbox(L, {&Impl::patternGuarded, &Impl::setmetatableGuarded, &Impl::print, &Impl::require},
              &impl_->death, {});
  lua_newtable(L);
  lua_setfield(L, LUA_REGISTRYINDEX, kMetaKey);
  lua_newtable(L);
  lua_setfield(L, LUA_REGISTRYINDEX, kBlocksKey);
  lua_newtable(L);
  lua_setfield(L, LUA_REGISTRYINDEX, kLoadedKey);
  Impl::defineStandin(L);
  impl_->collectMissing = options_.collect_missing_modules;
  auto defineConstructors = [&](const std::vector<std::string>& names, bool top) {
    for (const auto& n : names) {
      lua_pushstring(L, n.c_str());
      lua_pushboolean(L, top);
      lua_pushcclosure(L, &Impl::construct, 2);
      lua_setglobal(L, n.c_str());
    }
  };
  defineConstructors(topLevelBlocks(), true);
  defineConstructors(nestedConstructors(), false);
  lua_pushglobaltable(L);
  lua_newtable(L);
  lua_pushcfunction(L, &Impl::unknownGlobal);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, -2);
  lua_pop(L, 1);
  lua_sethook(L, &Impl::countHook, LUA_MASKCOUNT, Impl::kHookEvery);
  impl_->hostPhase = false;
}

const std::vector<Diagnostic>& LuaHost::missingModules() const {
  return impl_->missingModules;
}

const std::vector<std::pair<std::string, std::string>>& LuaHost::modules() const {
  return impl_->modules;
}

LuaHost::~LuaHost() {
  lua_close(impl_->L);
  delete impl_;
}

namespace {

// The text of a file the script ran (the scenario or a module), for the lines of table entries.
struct SourceText {
  std::string_view text;
  std::vector<std::size_t> starts;  // lineStarts(text)
};

// Where a value is written: a file's text and the offset where the value starts.
struct SourcePos {
  const SourceText* source = nullptr;
  std::size_t offset = 0;
};

// Tables deeper than this below their constructor keep the enclosing line: each level rescans
// its part of the text, so the work stays linear in the text for any nesting.
constexpr int kMaxScannedLevels = 8;

struct Converter {
  lua_State* L;
  LuaHost::Impl* impl;
  Diagnostics& diags;
  std::map<std::string, SourceText> sources;  // by the file name of SourceLoc
  std::set<const void*> active;
  std::size_t values = 0;
  std::size_t stringBytes = 0;  // of the string values converted so far
  bool stopped = false;         // a limit that ends the conversion was hit
  bool standin = false;         // a stand-in of a missing module was met (HostOptions)

  void addSource(const std::string& file, std::string_view text) {
    sources[file] = SourceText{text, lineStarts(text)};
  }

  void fail(const SourceLoc& loc, const std::string& msg) {
    if (diags.size() >= 50) {
      stopped = true;
      return;
    }
    diags.add(loc, msg);
  }

  Node convert(int idx, const SourceLoc& parentLoc, const std::string& path, int depth,
               SourcePos pos = {}, int scanned = 0) {
    idx = lua_absindex(L, idx);
    Node n;
    n.loc = parentLoc;
    if (pos.source != nullptr) n.loc.line = lineOf(pos.source->starts, pos.offset);
    if (stopped) return n;
    if (++values > kMaxValues) {
      fail(parentLoc, path + ": the scenario holds more than " + std::to_string(kMaxValues) +
                          " values (tables and their entries)");
      stopped = true;
      return n;
    }
    switch (lua_type(L, idx)) {
      case LUA_TNIL:
        n.type = Node::Type::Nil;
        break;
      case LUA_TBOOLEAN:
        n.type = Node::Type::Bool;
        n.boolean = lua_toboolean(L, idx);
        break;
      case LUA_TNUMBER:
        n.type = Node::Type::Number;
        n.number = lua_tonumber(L, idx);
        break;
      case LUA_TSTRING: {
        n.type = Node::Type::String;
        std::size_t len = 0;
        const char* s = lua_tolstring(L, idx, &len);
        if (len > kMaxStringBytes) {
          fail(parentLoc, path + ": string of " + std::to_string(len) + " bytes, longer than " +
                              std::to_string(kMaxStringBytes) + " bytes");
          break;
        }
        stringBytes += len;
        if (stringBytes > kMaxTreeStringBytes) {
          fail(parentLoc, path + ": the scenario's strings hold more than " +
                              std::to_string(kMaxTreeStringBytes) +
                              " bytes together (one long string used for many values?)");
          stopped = true;
          break;
        }
        n.string.assign(s, len);
        break;
      }
      case LUA_TFUNCTION:
        convertFunction(idx, n, parentLoc, path);
        break;
      case LUA_TTABLE:
        convertTable(idx, n, path, depth, pos, scanned);
        break;
      default:
        n.type = Node::Type::Nil;
        fail(parentLoc, path + ": values of type " + std::string(luaL_typename(L, idx)) +
                            " are not allowed in a scenario");
    }
    return n;
  }

  void convertFunction(int idx, Node& n, const SourceLoc& parentLoc, const std::string& path) {
    n.type = Node::Type::Function;
    lua_pushvalue(L, idx);
    int ref = luaL_ref(L, LUA_REGISTRYINDEX);
    lua_State* state = L;
    LuaHost::Impl* host = impl;
    n.function = std::make_shared<std::function<double(double)>>(
        [state, host, ref, loc = parentLoc, where = path](double x) {
          if (!lua_checkstack(state, 4)) throw InputError(loc, where + ": Lua stack exhausted");
          lua_pushcfunction(state, &LuaHost::Impl::messageHandler);
          lua_rawgeti(state, LUA_REGISTRYINDEX, ref);
          lua_pushnumber(state, x);
          const int status = lua_pcall(state, 1, 1, -3);
          if (status != LUA_OK) {
            InputError e = host->errorOf(status);
            lua_pop(state, 2);
            throw e;
          }
          if (host->death.dead) {  // the function caught a budget error and returned
            lua_pop(state, 2);
            throw host->errorOf(LUA_ERRRUN);
          }
          if (!lua_isnumber(state, -1)) {
            std::string t = luaL_typename(state, -1);
            lua_pop(state, 2);
            throw InputError(loc, where + ": function must return a number, got " + t);
          }
          double v = lua_tonumber(state, -1);
          lua_pop(state, 2);
          return v;
        });
  }

  // The entries of the table as written: its constructor call's line (a constructor) or its
  // own position (a table written as a value); nullopt when the text does not show it.
  std::optional<TableEntries> writtenEntries(const Node& n, SourcePos& pos, bool constructed,
                                             int scanned) {
    if (scanned >= kMaxScannedLevels) return std::nullopt;
    if (constructed) {
      const auto it = sources.find(n.loc.file);
      if (it == sources.end()) return std::nullopt;
      const auto brace = constructorBrace(it->second.text, n.loc.line, n.kind);
      if (!brace) return std::nullopt;
      pos = {&it->second, *brace};
    }
    if (pos.source == nullptr) return std::nullopt;
    return scanTable(pos.source->text, pos.offset);
  }

  void convertTable(int idx, Node& n, const std::string& blockPath, int depth, SourcePos pos,
                    int scanned) {
    n.type = Node::Type::Table;
    const SourceLoc parentLoc = n.loc;
    // Top-level blocks are converted with an empty path and named by their kind below.
    std::string path = blockPath;
    const void* ptr = lua_topointer(L, idx);
    if (active.count(ptr)) {
      fail(parentLoc, path + ": table refers to itself (cycle)");
      return;
    }
    if (depth >= kMaxNesting) {
      fail(parentLoc,
           path + ": tables nested more than " + std::to_string(kMaxNesting) + " levels deep");
      stopped = true;
      return;
    }
    // Each level keeps a key, a value and the registry lookups on the Lua stack.
    if (!lua_checkstack(L, 8)) {
      fail(parentLoc, path + ": tables nested too deeply (Lua stack exhausted)");
      stopped = true;
      return;
    }
    if (LuaHost::Impl::isStandin(L, idx)) {
      standin = true;  // its kind and place, if a constructor made it, are still read below
      n.type = Node::Type::Nil;
    }
    active.insert(ptr);
    lua_getfield(L, LUA_REGISTRYINDEX, kMetaKey);
    lua_pushvalue(L, idx);
    lua_rawget(L, -2);
    if (lua_istable(L, -1)) {
      lua_getfield(L, -1, "kind");
      n.kind = lua_tostring(L, -1);
      lua_getfield(L, -2, "file");
      n.loc.file = lua_tostring(L, -1);
      lua_getfield(L, -3, "line");
      n.loc.line = static_cast<int>(lua_tointeger(L, -1));
      lua_pop(L, 3);
      if (path.empty()) path = n.kind;
    }
    const bool constructed = lua_istable(L, -1);
    lua_pop(L, 2);
    if (constructed) scanned = 0;
    const std::optional<TableEntries> written = writtenEntries(n, pos, constructed, scanned);
    auto at = [&](std::size_t offset) { return SourcePos{pos.source, offset}; };
    lua_Integer len = static_cast<lua_Integer>(lua_rawlen(L, idx));
    // Positional values are matched by position only when the text lists as many as the table
    // holds (a list filled in code is not what the constructor shows).
    const bool itemsWritten =
        written && written->items.size() == static_cast<std::size_t>(std::max<lua_Integer>(len, 0));
    for (lua_Integer i = 1; i <= len && !stopped; ++i) {
      lua_rawgeti(L, idx, i);
      const SourcePos ip =
          itemsWritten ? at(written->items[static_cast<std::size_t>(i - 1)]) : SourcePos{};
      n.items.push_back(
          convert(-1, n.loc, path + "[" + std::to_string(i) + "]", depth + 1, ip, scanned + 1));
      lua_pop(L, 1);
    }
    lua_pushnil(L);
    while (!stopped && lua_next(L, idx)) {
      if (lua_type(L, -2) == LUA_TSTRING) {
        std::size_t klen = 0;
        const char* k = lua_tolstring(L, -2, &klen);
        std::string key(k, std::min(klen, std::size_t{200}));
        SourcePos kp;
        if (written)  // the last one written wins, as in Lua
          for (const auto& [name, offset] : written->fields)
            if (name == key) kp = at(offset);
        n.fields.emplace_back(key,
                              convert(-1, n.loc, path + "." + key, depth + 1, kp, scanned + 1));
      } else if (!(lua_isinteger(L, -2) && lua_tointeger(L, -2) >= 1 &&
                   lua_tointeger(L, -2) <= len)) {
        fail(n.loc, path + ": keys must be names or list positions 1.." + std::to_string(len) +
                        ", got a " + luaL_typename(L, -2) + " key");
      }
      lua_pop(L, 1);
    }
    if (stopped) lua_settop(L, idx);  // lua_next left a key on the stack
    // Sorted once here rather than by inserting in order (quadratic in the number of keys).
    std::sort(n.fields.begin(), n.fields.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    active.erase(ptr);
  }
};

}  // namespace

Node LuaHost::runFile(const std::string& path) {
  lua_State* L = impl_->L;
  fs::path file(path);
  std::string why;
  std::optional<std::string> content = readRegularFile(path, why, kMaxScenarioBytes);
  if (!content) throw InputError({path, 0}, "cannot open scenario file: " + why);
  text_ = std::move(*content);
  impl_->chunkFile = path;
  std::error_code ec;
  scenarioDir_ = fs::weakly_canonical(fs::absolute(file, ec).parent_path(), ec).string();
  roots_ = {scenarioDir_};
  impl_->moduleRoots = {scenarioDir_};
  if (!options_.root.empty()) {
    roots_.push_back((fs::path(options_.root) / "scenarios").string());
    roots_.push_back((fs::path(options_.root) / "profiles").string());
    const fs::path scen = fs::canonical(fs::path(options_.root) / "scenarios", ec);
    if (!ec) impl_->moduleRoots.push_back(scen.string());
  }
  std::string chunk = "@" + path;
  lua_pushcfunction(L, &Impl::messageHandler);
  int status = luaL_loadbufferx(L, text_.data(), text_.size(), chunk.c_str(), "t");
  if (status != LUA_OK && status != LUA_ERRMEM && lua_type(L, -1) == LUA_TSTRING &&
      !hasLocation(lua_tostring(L, -1))) {
    // The parser reports its nesting limit without a line. (The script will not run: the host's
    // reserve covers the new message.)
    impl_->hostPhase = true;
    std::string msg = std::string("cannot parse the scenario: ") + lua_tostring(L, -1);
    if (msg.find("C stack overflow") != std::string::npos)
      msg += " (expressions or blocks nested too deeply)";
    lua_pop(L, 1);
    lua_pushlstring(L, msg.data(), msg.size());
  }
  if (status == LUA_OK) status = lua_pcall(L, 0, 0, -2);
  // From here on the host converts the result: give it the reserve beyond the script's budget.
  impl_->hostPhase = true;
  if (status != LUA_OK || impl_->death.dead || impl_->memoryRefused) {
    InputError e = impl_->errorOf(status);
    lua_settop(L, 0);
    if (impl_->missingModules.empty()) throw e;
    // The missing modules first: the error may well follow from a stand-in.
    Diagnostics all;
    for (const auto& m : impl_->missingModules) all.add(m.loc, m.message);
    all.add(e);
    all.throwIfAny();
  }
  lua_settop(L, 0);

  Diagnostics diags;
  Converter conv{L, impl_, diags, {}, {}};
  conv.addSource(path, text_);
  for (const auto& [shown, text] : impl_->modules) conv.addSource(shown, text);
  Node root;
  root.type = Node::Type::Table;
  root.loc = {path, 0};
  lua_getfield(L, LUA_REGISTRYINDEX, kBlocksKey);
  lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, -1));
  for (lua_Integer i = 1; i <= n && !conv.stopped; ++i) {
    lua_rawgeti(L, -1, i);
    conv.standin = false;
    Node block = conv.convert(-1, {path, 0}, "", 0);
    lua_pop(L, 1);
    block.loc.file = block.loc.file.empty() ? path : block.loc.file;
    std::string kind = block.kind;
    if (conv.standin) {
      // Made (in part) from a missing module: not validated, its kind kept for the caller.
      incomplete_.push_back(kind);
      continue;
    }
    if (const Node* prev = root.field(kind)) {
      diags.add(block.loc, kind + " block given twice (first at " + prev->loc.str() + ")");
      continue;
    }
    // Paths inside the tree are named from the block down, e.g. "track.segments[2]".
    root.setField(kind, std::move(block));
  }
  lua_settop(L, 0);
  diags.throwIfAny();
  return root;
}

namespace {

// Where a data file is looked for, in order (LuaHost::resolveDataFile).
struct DataPlace {
  fs::path dir;
  std::string what;      // for messages: "the folder of scenarios/turnout/lib.lua"
  bool library = false;  // one of the required libraries' folders (the third kind of place)
  // Shown in full in messages (the data directory: relative to the working folder, often the
  // checkout, its candidates would read as the scene's).
  bool full = false;
};

// Files of the data directory named `filename`, relative to it (at most 3, sorted): the shipped
// file a user most likely meant by a name that was not found. Only profiles/ and scenarios/ are
// walked, at most kMaxWalk entries, symlinked folders not followed.
std::vector<std::string> shippedFilesNamed(const std::string& root, const fs::path& filename) {
  constexpr int kMaxWalk = 20000;
  std::vector<std::string> out;
  if (root.empty() || filename.empty() || filename == "." || filename == "..") return out;
  int seen = 0;
  for (const char* sub : {"profiles", "scenarios"}) {
    std::error_code ec;
    fs::recursive_directory_iterator it(fs::path(root) / sub, ec), end;
    for (; !ec && it != end && seen < kMaxWalk; it.increment(ec), ++seen) {
      if (it->path().filename() != filename) continue;
      std::error_code fe;
      if (!it->is_regular_file(fe)) continue;
      out.push_back(it->path().lexically_relative(root).generic_string());
    }
  }
  std::sort(out.begin(), out.end());
  if (out.size() > 3) out.resize(3);
  return out;
}

}  // namespace

std::string LuaHost::resolveDataFile(const std::string& name, const SourceLoc& loc) const {
  // A file named inside a library resolves beside that library first, so a library carries its
  // own data wherever the scene that requires it lives; then the scene's folder; then, for a name
  // that reached the tree in a plain table (whose text shows no constructor, so its location is
  // the scene's and not the library's), beside each library the scene required; then the data
  // directory. Every candidate must lie below a read root, whichever place found it.
  std::vector<DataPlace> places;
  const fs::path p(name);
  if (p.is_absolute()) {
    places.push_back({fs::path(), "as given"});
  } else {
    const auto& mods = impl_->moduleFolders;
    const auto own =
        std::find_if(mods.begin(), mods.end(), [&](const auto& m) { return m.first == loc.file; });
    if (own != mods.end()) places.push_back({own->second, "the folder of " + own->first});
    places.push_back({scenarioDir_, "the scene's folder"});
    for (const auto& [shown, folder] : mods)
      places.push_back({folder, "the folder of " + shown, true});
    if (!options_.root.empty())
      places.push_back({options_.root, "the data directory", false, true});
  }
  std::string found;       // the real path of the first candidate that exists
  std::string foundWhere;  // beside which library, when found in the library group
  std::vector<std::string> looked;
  std::set<std::string> dirs;
  // Error-code forms throughout: a name the file system refuses (too long, bad characters) is
  // the user's input problem, not an exception.
  for (const auto& place : places) {
    if (!found.empty() && !place.library) break;  // the libraries' folders came before this
    const fs::path c = place.dir.empty() ? p : place.dir / p;
    if (!place.dir.empty() && !dirs.insert(place.dir.lexically_normal().string()).second) continue;
    looked.push_back((place.full ? c.string() : displayPath(c)) + " (" + place.what + ")");
    std::error_code ec;
    if (!fs::exists(c, ec)) continue;
    bool allowed = false;
    for (const auto& r : roots_) allowed = allowed || isBelow(c, r);
    if (!allowed)
      throw InputError(loc, "file '" + name + "' is outside the folders a scenario may read (" +
                                "its own folder, scenarios/, profiles/)");
    const fs::path real = fs::weakly_canonical(c, ec);
    if (ec) continue;
    if (found.empty()) {
      if (!place.library) return real.string();
      found = real.string();
      foundWhere = place.what;
    } else if (place.library && real.string() != found) {
      // Two libraries hold different files of this name and the text does not show whose name it
      // is: refusing beats reading the wrong one.
      throw InputError(loc, "file '" + name + "' is in " + foundWhere + " and in " + place.what +
                                ", and the scene does not show which library named it; give its "
                                "path from the scene's folder or the data directory");
    }
  }
  if (!found.empty()) return found;
  std::string msg = "file '" + name + "' not found (looked in " + join(looked, ", ") + ")";
  const std::vector<std::string> shipped = shippedFilesNamed(options_.root, p.filename());
  if (!shipped.empty()) {
    msg += "; did you mean '" + shipped.front() + "' (shipped in the data directory";
    if (shipped.size() > 1)
      msg += "; also '" + join({shipped.begin() + 1, shipped.end()}, "', '") + "'";
    msg += ")?";
  }
  throw InputError(loc, msg);
}

}  // namespace rb::scenario
