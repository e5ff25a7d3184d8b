#include "workbench/scenario/study.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

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

// A number as short text: 1e-06 -> 1e-6, 0.00025 -> 0.00025.
std::string compact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  std::string t = buf;
  for (const char* e : {"e-0", "e+0", "e+"}) {
    auto p = t.find(e);
    if (p != std::string::npos) t.replace(p, std::string(e).size(), e[1] == '-' ? "e-" : "e");
  }
  return t;
}

bool number(const std::string& text, double& v) {
  char* end = nullptr;
  v = std::strtod(text.c_str(), &end);
  return !text.empty() && end && *end == '\0';
}

// Study keys inside an entry of `cases` (everything else is a --set path "block.key").
const std::vector<std::string> kCaseKeys = {"label", "base", "role"};
const std::vector<std::string> kRoles = {"reference", "reference_check", "reference_same_tables",
                                         "baseline"};

}  // namespace

std::string caseLabel(const std::vector<std::string>& overrides) {
  std::map<std::string, std::string> kv;
  std::vector<std::string> order;
  for (const auto& o : overrides) {
    auto eq = o.find('=');
    std::string k = o.substr(0, eq), v = eq == std::string::npos ? "" : o.substr(eq + 1);
    if (!kv.count(k)) order.push_back(k);
    kv[k] = v;
  }
  auto num = [&](const std::string& k, double scale, const char* unit) {
    double v = 0;
    return number(kv[k], v) ? compact(v * scale) + unit : kv[k];
  };
  std::vector<std::string> parts;
  auto take = [&](const std::string& k, const std::string& text) {
    if (!kv.count(k)) return;
    if (!text.empty()) parts.push_back(text);
    kv.erase(k);
  };
  if (kv.count("contact.method")) {
    std::string m = kv["contact.method"];
    for (auto& ch : m) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    take("contact.method", m);
  }
  if (kv.count("contact.flange_stiffness"))
    take("contact.flange_stiffness", "K=" + num("contact.flange_stiffness", 1, ""));
  if (kv.count("contact.flange_damping"))
    take("contact.flange_damping", "D=" + num("contact.flange_damping", 1, ""));
  if (kv.count("profiles.refined_tables"))
    take("profiles.refined_tables",
         kv["profiles.refined_tables"] == "true" ? "refined" : "default tables");
  if (kv.count("solver.method")) take("solver.method", kv["solver.method"]);
  if (kv.count("solver.step")) take("solver.step", "h=" + num("solver.step", 1e3, "ms"));
  if (kv.count("solver.rtol") && kv.count("solver.atol") &&
      kv["solver.rtol"] == kv["solver.atol"]) {
    std::string t = "tol=" + num("solver.rtol", 1, "");
    take("solver.rtol", t);
    take("solver.atol", "");
  }
  if (kv.count("solver.rtol")) take("solver.rtol", "rtol=" + num("solver.rtol", 1, ""));
  if (kv.count("solver.atol")) take("solver.atol", "atol=" + num("solver.atol", 1, ""));
  if (kv.count("solver.max_step"))
    take("solver.max_step", "hmax=" + num("solver.max_step", 1e3, "ms"));
  if (kv.count("contact.normal_forces")) take("contact.normal_forces", kv["contact.normal_forces"]);
  take("solver.max_steps", "");  // a work limit, not an accuracy setting: not in labels
  for (const auto& k : order)
    if (kv.count(k)) parts.push_back(k + "=" + kv[k]);
  return parts.empty() ? "base" : join(parts, " ");
}

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

  // A base scenario path relative to the study file (else as given); "" when not found.
  auto resolve = [&](const std::string& name) {
    fs::path p = fs::path(path).parent_path() / name;
    if (!fs::is_regular_file(p)) p = fs::path(name);
    return fs::is_regular_file(p) ? p.lexically_normal().string() : std::string();
  };
  const Node* base = n->field("base");
  if (!base || base->type != Node::Type::String) {
    err("base must name the base scenario file");
  } else {
    st.base = resolve(base->string);
    if (st.base.empty())
      err("base scenario '" + base->string + "' not found (relative to the study file)");
  }
  auto intKey = [&](const char* key, int def, int lo, int hi) {
    const Node* v = n->field(key);
    if (!v) return def;
    // Range first: converting a double beyond int's range is undefined.
    if (v->type != Node::Type::Number || !(v->number >= lo && v->number <= hi) ||
        v->number != std::floor(v->number)) {
      err(std::string(key) + " must be a whole number in [" + std::to_string(lo) + ", " +
          std::to_string(hi) + "]");
      return def;
    }
    return static_cast<int>(v->number);
  };
  st.repeats = intKey("repeats", 1, 1, 100);
  st.jobs = intKey("jobs", 0, 0, 64);
  st.max_cases = intKey("max_cases", static_cast<int>(StudySpec::kDefaultMaxCases), 1, 100000000);

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
  // Explicit cases: overrides plus the study keys label, base (as written and resolved), role.
  struct Variant {
    std::vector<std::string> overrides;
    std::string label, base, baseResolved, role;
  };
  std::vector<Variant> variants;
  if (const Node* c = n->field("cases")) {
    if (c->type != Node::Type::Table || !c->fields.empty()) err("cases must be a list of tables");
    for (std::size_t i = 0; i < c->items.size(); ++i) {
      const Node& item = c->items[i];
      const std::string where = "cases[" + std::to_string(i + 1) + "]";
      Variant var;
      if (item.type != Node::Type::Table || !item.items.empty()) {
        err(where + " must be { [\"key\"] = value, ... }");
        continue;
      }
      for (const auto& [k, v] : item.fields) {
        std::string t;
        if (!scalarText(v, t)) {
          err(where + "[\"" + k + "\"] must be a scalar");
          continue;
        }
        if (k.find('.') != std::string::npos) {
          var.overrides.push_back(k + "=" + t);
        } else if (k == "label") {
          var.label = t;
        } else if (k == "role") {
          if (std::find(kRoles.begin(), kRoles.end(), t) == kRoles.end())
            err(where + ": role must be one of " + join(kRoles, ", ") + ", got '" + t + "'");
          var.role = t;
        } else if (k == "base") {
          var.base = t;
          var.baseResolved = resolve(t);
          if (var.baseResolved.empty())
            err(where + ": base scenario '" + t + "' not found (relative to the study file)");
        } else {
          std::string hint = closestMatch(k, kCaseKeys);
          err(where + ": unknown key '" + k + "'" +
              (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
              "; keys are --set paths block.key, or label, base, role");
        }
      }
      variants.push_back(var);
    }
  }
  if (variants.empty()) variants.push_back({});
  d.throwIfAny();

  // The number of cases before expanding them: a matrix of a few long axes multiplies to more
  // cases than memory holds (each a list of strings), so it is refused here, with the sizes.
  {
    const auto where = [&]() {
      const Node* m = n->field("matrix");
      return m ? m->loc : n->loc;
    }();
    double count = static_cast<double>(variants.size());
    std::string sizes;
    for (const auto& [k, vals] : axes) {
      count *= static_cast<double>(vals.size());
      sizes += std::to_string(vals.size()) + " x ";
    }
    sizes += std::to_string(variants.size());
    if (count > static_cast<double>(st.max_cases)) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.0f", count);
      throw InputError(where, "study: " + std::string(buf) + " cases (" + sizes +
                                  ") exceed max_cases = " + std::to_string(st.max_cases) +
                                  "; raise study.max_cases if that many are meant");
    }
  }

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
  std::set<std::string> ids;
  std::vector<std::string> given;                    // label given in the case, per case
  std::vector<std::vector<std::string>> matrixPart;  // its matrix overrides
  for (const auto& c : combos)
    for (const auto& v : variants) {
      StudyCase sc;
      sc.overrides = c;
      sc.overrides.insert(sc.overrides.end(), v.overrides.begin(), v.overrides.end());
      sc.base = v.base.empty() ? st.base : v.baseResolved;
      sc.role = v.role;
      given.push_back(v.label);
      matrixPart.push_back(c);
      // Named by its overrides (and its own base) only, so adding values to a study, or
      // relabelling, keeps old results resumable.
      std::string key = join(sc.overrides, ";");
      if (!v.base.empty()) key += ";base=" + v.base;
      char buf[32];
      std::snprintf(buf, sizeof buf, "case_%016llx", static_cast<unsigned long long>(fnv1a(key)));
      sc.id = buf;
      if (!ids.insert(sc.id).second)
        d.add(n->loc, "study: two cases have the same overrides and base (" +
                          (v.label.empty() ? join(sc.overrides, " ") : v.label) +
                          "); give them different values");
      st.cases.push_back(sc);
    }
  d.throwIfAny();

  // Labels: overrides shared by every case (e.g. run.distance) are left out of the made ones.
  std::vector<std::string> common;
  if (st.cases.size() > 1)
    for (const auto& o : st.cases[0].overrides) {
      bool all = true;
      for (const auto& sc : st.cases)
        all = all && std::find(sc.overrides.begin(), sc.overrides.end(), o) != sc.overrides.end();
      if (all) common.push_back(o);
    }
  auto without = [&](const std::vector<std::string>& ov) {
    std::vector<std::string> out;
    for (const auto& o : ov)
      if (std::find(common.begin(), common.end(), o) == common.end()) out.push_back(o);
    return out;
  };
  for (std::size_t i = 0; i < st.cases.size(); ++i) {
    auto& sc = st.cases[i];
    if (given[i].empty())
      sc.label = caseLabel(without(sc.overrides));
    else if (auto m = without(matrixPart[i]); !m.empty())
      sc.label = caseLabel(m) + " " + given[i];
    else
      sc.label = given[i];
  }
  return st;
}

}  // namespace rb::scenario
