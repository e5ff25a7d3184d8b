#include "workbench/scenario/lua_host.hpp"

#include <lua.hpp>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "workbench/core/strings.hpp"

namespace fs = std::filesystem;

namespace rb::scenario {

const std::vector<std::string>& topLevelBlocks() {
  static const std::vector<std::string> names = {"track",  "profiles", "vehicle", "contact",
                                                 "solver", "run",      "study"};
  return names;
}

const std::vector<std::string>& nestedConstructors() {
  static const std::vector<std::string> names = {
      "tangent",      "transition",     "curve",         "psd",
      "measured",     "body",           "spring_damper", "series_damper",
      "shear_spring", "bending_spring", "bumpstop"};
  return names;
}

namespace {

const char* const kMetaKey = "railbench.meta";      // registry: table -> {kind, file, line}
const char* const kBlocksKey = "railbench.blocks";  // registry: array of top-level tables
const char* const kLoadedKey = "railbench.loaded";  // registry: module name -> value

std::string displayPath(const fs::path& p) {
  std::error_code ec;
  fs::path rel = fs::proximate(p, fs::current_path(ec), ec);
  if (!ec && !rel.empty() && rel.native().rfind("..", 0) != 0) return rel.string();
  return p.string();
}

bool isBelow(const fs::path& file, const fs::path& root) {
  std::error_code ec;
  fs::path f = fs::weakly_canonical(file, ec);
  fs::path r = fs::weakly_canonical(root, ec);
  auto [rootEnd, fileIt] = std::mismatch(r.begin(), r.end(), f.begin(), f.end());
  return rootEnd == r.end();
}

bool readText(const fs::path& p, std::string& out) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return true;
}

// "file:line: message" -> Diagnostic; anything else keeps an empty location.
Diagnostic parseLuaMessage(const std::string& msg, const std::string& fallbackFile) {
  // Lua prefixes positions as "<chunkname>:<line>: "; the chunk name may itself contain ':'.
  for (std::size_t colon = msg.find(':'); colon != std::string::npos;
       colon = msg.find(':', colon + 1)) {
    std::size_t digits = colon + 1;
    while (digits < msg.size() && std::isdigit(static_cast<unsigned char>(msg[digits]))) ++digits;
    if (digits > colon + 1 && msg.compare(digits, 2, ": ") == 0 && msg.find('\n') > colon) {
      return Diagnostic{
          {msg.substr(0, colon), std::stoi(msg.substr(colon + 1, digits - colon - 1))},
          msg.substr(digits + 2)};
    }
  }
  return Diagnostic{{fallbackFile, 0}, msg};
}

}  // namespace

struct LuaHost::Impl {
  lua_State* L = nullptr;
  LuaHost* host = nullptr;
  std::size_t memory = 0;
  std::size_t memoryLimit = 0;
  long long instructions = 0;
  long long instructionLimit = 0;
  std::vector<std::string> moduleRoots;                      // scenario dir, <root>/scenarios
  std::vector<std::pair<std::string, std::string>> modules;  // required files: path, text

  static Impl* from(lua_State* L) { return *static_cast<Impl**>(lua_getextraspace(L)); }

  static void* alloc(void* ud, void* ptr, std::size_t osize, std::size_t nsize) {
    auto* self = static_cast<Impl*>(ud);
    std::size_t old = ptr ? osize : 0;
    if (nsize == 0) {
      self->memory -= old;
      std::free(ptr);
      return nullptr;
    }
    if (self->memory - old + nsize > self->memoryLimit)
      return nullptr;  // Lua raises "not enough memory"
    void* p = std::realloc(ptr, nsize);
    if (p) self->memory = self->memory - old + nsize;
    return p;
  }

  // Lua reports errors by longjmp, which skips C++ destructors. So every C function below does
  // its C++ work in a *Body function that returns false with the message pushed on the Lua stack;
  // the thin wrapper calls lua_error only after all C++ objects are gone (architecture.md: never
  // throw across a Lua longjmp).

  static constexpr int kHookEvery = 10000;
  static bool countHookBody(lua_State* L) {
    Impl* self = from(L);
    self->instructions += kHookEvery;
    if (self->instructions <= self->instructionLimit) return true;
    // Level 0 is the Lua function that was running when the hook fired.
    lua_Debug ar;
    SourceLoc loc{"?", 0};
    if (lua_getstack(L, 0, &ar) && lua_getinfo(L, "Sl", &ar)) {
      loc.file = ar.source && ar.source[0] == '@' ? ar.source + 1 : "?";
      loc.line = ar.currentline;
    }
    push(L, loc,
         "scenario exceeded its budget of " + std::to_string(self->instructionLimit) +
             " Lua instructions (endless loop?)");
    return false;
  }
  static void countHook(lua_State* L, lua_Debug*) {
    if (!countHookBody(L)) lua_error(L);
  }

  // Location of the Lua code that called the current C function.
  static SourceLoc callerLoc(lua_State* L) {
    lua_Debug ar;
    if (lua_getstack(L, 1, &ar) && lua_getinfo(L, "Sl", &ar)) {
      std::string src = ar.source ? ar.source : "?";
      if (!src.empty() && src[0] == '@') src.erase(0, 1);
      return {src, ar.currentline};
    }
    return {"?", 0};
  }

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

  static bool requireBody(lua_State* L) {
    Impl* self = from(L);
    SourceLoc loc = callerLoc(L);
    if (lua_type(L, 1) != LUA_TSTRING) {
      push(L, loc, "require expects a module name string, e.g. require \"vehicles.wagon\"");
      return false;
    }
    std::string name = lua_tostring(L, 1);
    for (char c : name) {
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.')) {
        push(
            L, loc,
            "require \"" + name + "\": module names may contain only letters, digits, '_' and '.'");
        return false;
      }
    }
    lua_getfield(L, LUA_REGISTRYINDEX, kLoadedKey);
    lua_getfield(L, -1, name.c_str());
    if (!lua_isnil(L, -1)) return true;
    lua_pop(L, 1);
    std::string rel = name;
    for (char& c : rel)
      if (c == '.') c = '/';
    rel += ".lua";
    fs::path found;
    std::string tried;
    for (const auto& root : self->moduleRoots) {
      fs::path cand = fs::path(root) / rel;
      tried += "\n\t" + displayPath(cand);
      if (fs::is_regular_file(cand)) {
        found = cand;
        break;
      }
    }
    if (found.empty()) {
      push(L, loc, "require \"" + name + "\": module not found; tried:" + tried);
      return false;
    }
    std::string text;
    if (!readText(found, text)) {
      push(L, loc, "require \"" + name + "\": cannot read " + displayPath(found));
      return false;
    }
    std::string chunk = "@" + displayPath(found);
    self->modules.push_back({displayPath(found), text});  // provenance: every file the run read
    if (luaL_loadbufferx(L, text.data(), text.size(), chunk.c_str(), "t") != LUA_OK) return false;
    lua_pushstring(L, name.c_str());
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) return false;
    if (lua_isnil(L, -1)) {
      lua_pop(L, 1);
      lua_pushboolean(L, 1);
    }
    lua_pushvalue(L, -1);
    lua_setfield(L, -3, name.c_str());
    return true;
  }
  static int require(lua_State* L) { return requireBody(L) ? 1 : lua_error(L); }

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

  // __index on the globals: an unknown name is an error with a hint, not a silent nil.
  static void unknownGlobalBody(lua_State* L) {
    std::string name = lua_isstring(L, 2) ? lua_tostring(L, 2) : "?";
    std::vector<std::string> known;
    lua_pushnil(L);
    while (lua_next(L, 1)) {
      if (lua_type(L, -2) == LUA_TSTRING) known.emplace_back(lua_tostring(L, -2));
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
};

LuaHost::LuaHost(HostOptions options) : impl_(new Impl), options_(std::move(options)) {
  impl_->host = this;
  impl_->memoryLimit = options_.memory_limit;
  impl_->instructionLimit = options_.instruction_limit;
  lua_State* L = lua_newstate(&Impl::alloc, impl_);
  if (!L) {
    delete impl_;
    throw std::runtime_error("cannot create Lua state");
  }
  impl_->L = L;
  *static_cast<Impl**>(lua_getextraspace(L)) = impl_;

  // Only safe libraries: base, string, table, math, utf8.
  luaL_requiref(L, LUA_GNAME, luaopen_base, 1);
  luaL_requiref(L, LUA_STRLIBNAME, luaopen_string, 1);
  luaL_requiref(L, LUA_TABLIBNAME, luaopen_table, 1);
  luaL_requiref(L, LUA_MATHLIBNAME, luaopen_math, 1);
  luaL_requiref(L, LUA_UTF8LIBNAME, luaopen_utf8, 1);
  lua_pop(L, 5);
  for (const char* banned : {"dofile", "loadfile", "load"}) {
    lua_pushnil(L);
    lua_setglobal(L, banned);
  }
  lua_pushcfunction(L, &Impl::print);
  lua_setglobal(L, "print");
  lua_pushcfunction(L, &Impl::require);
  lua_setglobal(L, "require");
  lua_newtable(L);
  lua_setfield(L, LUA_REGISTRYINDEX, kMetaKey);
  lua_newtable(L);
  lua_setfield(L, LUA_REGISTRYINDEX, kBlocksKey);
  lua_newtable(L);
  lua_setfield(L, LUA_REGISTRYINDEX, kLoadedKey);
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
}

const std::vector<std::pair<std::string, std::string>>& LuaHost::modules() const {
  return impl_->modules;
}

LuaHost::~LuaHost() {
  lua_close(impl_->L);
  delete impl_;
}

namespace {

struct Converter {
  lua_State* L;
  Diagnostics& diags;
  std::set<const void*> active;

  Node convert(int idx, const SourceLoc& parentLoc, const std::string& path, int depth) {
    idx = lua_absindex(L, idx);
    Node n;
    n.loc = parentLoc;
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
      case LUA_TSTRING:
        n.type = Node::Type::String;
        n.string = lua_tostring(L, idx);
        break;
      case LUA_TFUNCTION: {
        n.type = Node::Type::Function;
        lua_pushvalue(L, idx);
        int ref = luaL_ref(L, LUA_REGISTRYINDEX);
        lua_State* state = L;
        SourceLoc loc = parentLoc;
        std::string where = path;
        n.function =
            std::make_shared<std::function<double(double)>>([state, ref, loc, where](double x) {
              lua_rawgeti(state, LUA_REGISTRYINDEX, ref);
              lua_pushnumber(state, x);
              if (lua_pcall(state, 1, 1, 0) != LUA_OK) {
                std::string msg = lua_tostring(state, -1) ? lua_tostring(state, -1) : "error";
                lua_pop(state, 1);
                throw InputError({parseLuaMessage(msg, loc.file)});
              }
              if (!lua_isnumber(state, -1)) {
                std::string t = luaL_typename(state, -1);
                lua_pop(state, 1);
                throw InputError(loc, where + ": function must return a number, got " + t);
              }
              double v = lua_tonumber(state, -1);
              lua_pop(state, 1);
              return v;
            });
        break;
      }
      case LUA_TTABLE: {
        n.type = Node::Type::Table;
        const void* ptr = lua_topointer(L, idx);
        if (active.count(ptr) || depth > 32) {
          diags.add(parentLoc, path + ": table refers to itself (cycle) or is nested too deeply");
          return n;
        }
        active.insert(ptr);
        lua_getfield(L, LUA_REGISTRYINDEX, kMetaKey);
        lua_pushvalue(L, idx);
        lua_gettable(L, -2);
        if (lua_istable(L, -1)) {
          lua_getfield(L, -1, "kind");
          n.kind = lua_tostring(L, -1);
          lua_getfield(L, -2, "file");
          n.loc.file = lua_tostring(L, -1);
          lua_getfield(L, -3, "line");
          n.loc.line = static_cast<int>(lua_tointeger(L, -1));
          lua_pop(L, 3);
        }
        lua_pop(L, 2);
        lua_Integer len = static_cast<lua_Integer>(lua_rawlen(L, idx));
        for (lua_Integer i = 1; i <= len; ++i) {
          lua_rawgeti(L, idx, i);
          n.items.push_back(convert(-1, n.loc, path + "[" + std::to_string(i) + "]", depth + 1));
          lua_pop(L, 1);
        }
        lua_pushnil(L);
        while (lua_next(L, idx)) {
          if (lua_type(L, -2) == LUA_TSTRING) {
            std::string key = lua_tostring(L, -2);
            n.setField(key, convert(-1, n.loc, path + "." + key, depth + 1));
          } else if (!(lua_isinteger(L, -2) && lua_tointeger(L, -2) >= 1 &&
                       lua_tointeger(L, -2) <= len)) {
            diags.add(n.loc, path + ": keys must be names or list positions 1.." +
                                 std::to_string(len) + ", got a " + luaL_typename(L, -2) + " key");
          }
          lua_pop(L, 1);
        }
        active.erase(ptr);
        break;
      }
      default:
        n.type = Node::Type::Nil;
        diags.add(parentLoc, path + ": values of type " + std::string(luaL_typename(L, idx)) +
                                 " are not allowed in a scenario");
    }
    return n;
  }
};

}  // namespace

Node LuaHost::runFile(const std::string& path) {
  lua_State* L = impl_->L;
  fs::path file(path);
  if (!fs::is_regular_file(file)) throw InputError({path, 0}, "cannot open scenario file");
  std::string text;
  if (!readText(file, text)) throw InputError({path, 0}, "cannot read scenario file");
  std::error_code ec;
  scenarioDir_ = fs::weakly_canonical(fs::absolute(file).parent_path(), ec).string();
  roots_ = {scenarioDir_};
  impl_->moduleRoots = {scenarioDir_};
  if (!options_.root.empty()) {
    roots_.push_back((fs::path(options_.root) / "scenarios").string());
    roots_.push_back((fs::path(options_.root) / "profiles").string());
    impl_->moduleRoots.push_back((fs::path(options_.root) / "scenarios").string());
  }
  std::string chunk = "@" + path;
  if (luaL_loadbufferx(L, text.data(), text.size(), chunk.c_str(), "t") != LUA_OK ||
      lua_pcall(L, 0, 0, 0) != LUA_OK) {
    std::string msg = lua_tostring(L, -1) ? lua_tostring(L, -1) : "unknown Lua error";
    lua_pop(L, 1);
    throw InputError({parseLuaMessage(msg, path)});
  }

  Diagnostics diags;
  Converter conv{L, diags, {}};
  Node root;
  root.type = Node::Type::Table;
  root.loc = {path, 0};
  lua_getfield(L, LUA_REGISTRYINDEX, kBlocksKey);
  lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, -1));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, -1, i);
    Node block = conv.convert(-1, {path, 0}, "", 0);
    lua_pop(L, 1);
    block.loc.file = block.loc.file.empty() ? path : block.loc.file;
    std::string kind = block.kind;
    if (const Node* prev = root.field(kind)) {
      diags.add(block.loc, kind + " block given twice (first at " + prev->loc.str() + ")");
      continue;
    }
    // Paths inside the tree are named from the block down, e.g. "track.segments[2]".
    root.setField(kind, std::move(block));
  }
  lua_pop(L, 1);
  diags.throwIfAny();
  return root;
}

std::string LuaHost::resolveDataFile(const std::string& name, const SourceLoc& loc) const {
  std::vector<fs::path> candidates;
  fs::path p(name);
  if (p.is_absolute()) {
    candidates.push_back(p);
  } else {
    candidates.push_back(fs::path(scenarioDir_) / p);
    if (!options_.root.empty()) candidates.push_back(fs::path(options_.root) / p);
  }
  for (const auto& c : candidates) {
    if (!fs::exists(c)) continue;
    bool allowed = false;
    for (const auto& r : roots_) allowed = allowed || isBelow(c, r);
    if (!allowed)
      throw InputError(loc, "file '" + name + "' is outside the folders a scenario may read (" +
                                "its own folder, scenarios/, profiles/)");
    return fs::weakly_canonical(c).string();
  }
  throw InputError(
      loc, "file '" + name + "' not found (looked in the scenario's folder and the project root)");
}

}  // namespace rb::scenario
