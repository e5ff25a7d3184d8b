#include "workbench/scenario/study.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "workbench/core/strings.hpp"
#include "workbench/scenario/lua_host.hpp"
#include "workbench/scenario/schema.hpp"

namespace fs = std::filesystem;

namespace rb::scenario {
namespace {

// A scalar as it would be typed after --set key=.
bool scalarText(const Node& n, std::string& out) {
  char buf[64];
  switch (n.type) {
    case Node::Type::Number:
      // Shortest text that reads back as the same double.
      for (int prec = 6; prec <= 17; ++prec) {
        std::snprintf(buf, sizeof buf, "%.*g", prec, n.number);
        if (std::strtod(buf, nullptr) == n.number) break;
      }
      out = buf;
      return true;
    case Node::Type::String:
      out = n.string;
      return true;
    case Node::Type::Bool:
      out = n.boolean ? "true" : "false";
      return true;
    default:
      return false;
  }
}

std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace

StudySpec loadStudy(const std::string& path, const std::string& root) {
  HostOptions ho;
  ho.root = root;
  LuaHost host(ho);
  Node top = host.runFile(path);
  Diagnostics d;
  StudySpec st;
  st.file = path;
  const Node* n = top.field("study");
  if (!n) throw InputError({path, 0}, "study file has no study { ... } block");
  st.loc = n->loc;
  const BlockSpec& bs = block("study");
  auto err = [&](const std::string& m) { d.add(n->loc, "study: " + m); };
  for (const auto& [k, v] : n->fields) {
    if (bs.key(k)) continue;
    std::string hint = closestMatch(k, bs.keyNames());
    err("unknown key '" + k + "'" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }
  for (const auto& [k, v] : top.fields)
    if (k != "study") d.add(v.loc, k + " block in a study file: put it in the base scenario");

  const Node* base = n->field("base");
  if (!base || base->type != Node::Type::String) {
    err("base must name the base scenario file");
  } else {
    fs::path p = fs::path(path).parent_path() / base->string;
    if (!fs::is_regular_file(p)) p = fs::path(base->string);
    if (!fs::is_regular_file(p))
      err("base scenario '" + base->string + "' not found (relative to the study file)");
    else
      st.base = p.lexically_normal().string();
  }
  auto intKey = [&](const char* key, int def, int lo, int hi) {
    const Node* v = n->field(key);
    if (!v) return def;
    if (v->type != Node::Type::Number || v->number != static_cast<int>(v->number) ||
        v->number < lo || v->number > hi) {
      err(std::string(key) + " must be a whole number in [" + std::to_string(lo) + ", " +
          std::to_string(hi) + "]");
      return def;
    }
    return static_cast<int>(v->number);
  };
  st.repeats = intKey("repeats", 1, 1, 100);
  st.jobs = intKey("jobs", 0, 0, 64);

  // Matrix: ordered keys (Node fields are sorted), each a list of scalars.
  std::vector<std::pair<std::string, std::vector<std::string>>> axes;
  if (const Node* m = n->field("matrix")) {
    if (m->type != Node::Type::Table || !m->items.empty())
      err("matrix must be { [\"key\"] = {values...}, ... }");
    for (const auto& [k, v] : m->fields) {
      std::vector<std::string> vals;
      if (v.type != Node::Type::Table || !v.fields.empty() || v.items.empty()) {
        err("matrix[\"" + k + "\"] must be a non-empty list of values");
        continue;
      }
      for (const auto& item : v.items) {
        std::string t;
        if (!scalarText(item, t))
          err("matrix[\"" + k + "\"]: values must be numbers, strings or booleans");
        vals.push_back(t);
      }
      axes.emplace_back(k, vals);
    }
  }
  std::vector<std::vector<std::string>> variants;  // explicit cases
  if (const Node* c = n->field("cases")) {
    if (c->type != Node::Type::Table || !c->fields.empty()) err("cases must be a list of tables");
    for (std::size_t i = 0; i < c->items.size(); ++i) {
      const Node& item = c->items[i];
      std::vector<std::string> ov;
      if (item.type != Node::Type::Table || !item.items.empty()) {
        err("cases[" + std::to_string(i + 1) + "] must be { [\"key\"] = value, ... }");
        continue;
      }
      for (const auto& [k, v] : item.fields) {
        std::string t;
        if (!scalarText(v, t))
          err("cases[" + std::to_string(i + 1) + "][\"" + k + "\"] must be a scalar");
        ov.push_back(k + "=" + t);
      }
      variants.push_back(ov);
    }
  }
  if (variants.empty()) variants.push_back({});
  d.throwIfAny();

  // Cartesian product: matrix combinations (first key slowest) x explicit variants.
  std::vector<std::vector<std::string>> combos = {{}};
  for (const auto& [k, vals] : axes) {
    std::vector<std::vector<std::string>> next;
    for (const auto& c : combos)
      for (const auto& v : vals) {
        auto e = c;
        e.push_back(k + "=" + v);
        next.push_back(e);
      }
    combos = next;
  }
  for (const auto& c : combos)
    for (const auto& v : variants) {
      StudyCase sc;
      sc.overrides = c;
      sc.overrides.insert(sc.overrides.end(), v.begin(), v.end());
      char buf[32];
      // Named by its overrides only, so adding values to a study keeps old results resumable.
      std::snprintf(
          buf, sizeof buf, "case_%08llx",
          static_cast<unsigned long long>(fnv1a(join(sc.overrides, ";")) & 0xffffffffull));
      sc.id = buf;
      st.cases.push_back(sc);
    }
  return st;
}

}  // namespace rb::scenario
