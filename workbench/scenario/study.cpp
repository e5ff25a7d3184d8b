#include "workbench/scenario/study.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <set>

#include "workbench/core/strings.hpp"
#include "workbench/scenario/lua_host.hpp"
#include "workbench/scenario/override_check.hpp"
#include "workbench/scenario/schema.hpp"

namespace fs = std::filesystem;

namespace rb::scenario {
namespace {

// A scalar as it would be typed after --set key=.
bool scalarText(const Node& n, std::string& out) {
  switch (n.type) {
    case Node::Type::Number:
      out = formatNumberExact(n.number);
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
  std::string t = formatNumber(v);
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
  if (kv.count("solver.stiff") && kv["solver.stiff"] != "explicit")
    take("solver.stiff", kv["solver.stiff"]);
  take("solver.stiff", "");
  take("solver.max_steps", "");             // a work limit, not an accuracy setting: not in labels
  take("solver.accept_unstable_step", "");  // a permission, not a setting: not in labels
  for (const auto& k : order)
    if (kv.count(k)) parts.push_back(k + "=" + kv[k]);
  return parts.empty() ? "base" : join(parts, " ");
}

namespace {

using ErrorFn = std::function<void(const std::string&)>;
using Axes = std::vector<std::pair<std::string, std::vector<std::string>>>;

// An entry of `cases`: overrides plus the study keys label, base (as written and resolved), role.
struct Variant {
  std::vector<std::string> overrides;
  std::string label, base, baseResolved, role;
};

// A base scenario path relative to the study file (else as given); "" when not found.
std::string resolveBase(const std::string& studyPath, const std::string& name) {
  fs::path p = fs::path(studyPath).parent_path() / name;
  if (!fs::is_regular_file(p)) p = fs::path(name);
  return fs::is_regular_file(p) ? p.lexically_normal().string() : std::string();
}

// Unknown keys of study{} and blocks that belong in the base scenario.
void checkStudyKeys(const Node& top, const Node& n, Diagnostics& d, const ErrorFn& err) {
  const BlockSpec& bs = block("study");
  for (const auto& [k, v] : n.fields) {
    if (bs.key(k)) continue;
    std::string hint = closestMatch(k, bs.keyNames());
    err("unknown key '" + k + "'" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }
  for (const auto& [k, v] : top.fields)
    if (k != "study") d.add(v.loc, k + " block in a study file: put it in the base scenario");
}

// A whole-number key of study{} in its schema range; the schema's default if absent or wrong.
int wholeNumber(const Node& n, const char* key, const ErrorFn& err) {
  const KeySpec& k = *block("study").key(key);
  const int def = static_cast<int>(k.num_default);
  const Node* v = n.field(key);
  if (!v) return def;
  // Range first: converting a double beyond int's range is undefined.
  if (v->type != Node::Type::Number || !(v->number >= k.min && v->number <= k.max) ||
      v->number != std::floor(v->number)) {
    err(std::string(key) + " must be a whole number in [" + formatNumber(k.min, 17) + ", " +
        formatNumber(k.max, 17) + "]");
    return def;
  }
  return static_cast<int>(v->number);
}

// Matrix: ordered keys (Node fields are sorted), each a list of scalars.
Axes readMatrix(const Node& n, const ErrorFn& err) {
  Axes axes;
  const Node* m = n.field("matrix");
  if (!m) return axes;
  if (m->type != Node::Type::Table || !m->items.empty())
    err("matrix must be { [\"key\"] = {values...}, ... }");
  for (const auto& [k, v] : m->fields) {
    if (v.type != Node::Type::Table || !v.fields.empty() || v.items.empty()) {
      err("matrix[\"" + k + "\"] must be a non-empty list of values");
      continue;
    }
    std::vector<std::string> vals;
    for (const auto& item : v.items) {
      std::string t;
      if (!scalarText(item, t))
        err("matrix[\"" + k + "\"]: values must be numbers, strings or booleans");
      vals.push_back(t);
    }
    axes.emplace_back(k, vals);
  }
  return axes;
}

// One study key or --set path of an entry of `cases`.
void readCaseKey(const std::string& where, const std::string& k, const std::string& t,
                 const std::string& studyPath, Variant& var, const ErrorFn& err) {
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
    var.baseResolved = resolveBase(studyPath, t);
    if (var.baseResolved.empty())
      err(where + ": base scenario '" + t + "' not found (relative to the study file)");
  } else {
    std::string hint = closestMatch(k, kCaseKeys);
    err(where + ": unknown key '" + k + "'" +
        (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
        "; keys are --set paths block.key, or label, base, role");
  }
}

// Explicit cases; one empty variant when there are none.
std::vector<Variant> readCases(const Node& n, const std::string& studyPath, const ErrorFn& err) {
  std::vector<Variant> variants;
  if (const Node* c = n.field("cases")) {
    if (c->type != Node::Type::Table || !c->fields.empty()) err("cases must be a list of tables");
    for (std::size_t i = 0; i < c->items.size(); ++i) {
      const Node& item = c->items[i];
      const std::string where = "cases[" + std::to_string(i + 1) + "]";
      if (item.type != Node::Type::Table || !item.items.empty()) {
        err(where + " must be { [\"key\"] = value, ... }");
        continue;
      }
      Variant var;
      for (const auto& [k, v] : item.fields) {
        std::string t;
        if (scalarText(v, t))
          readCaseKey(where, k, t, studyPath, var, err);
        else
          err(where + "[\"" + k + "\"] must be a scalar");
      }
      variants.push_back(var);
    }
  }
  if (variants.empty()) variants.push_back({});
  return variants;
}

// The number of cases before expanding them: a matrix of a few long axes multiplies to more
// cases than memory holds (each a list of strings), so it is refused here, with the sizes.
void checkCaseCount(const Node& n, const Axes& axes, std::size_t variants, long long maxCases) {
  const Node* m = n.field("matrix");
  const SourceLoc where = m ? m->loc : n.loc;
  double count = static_cast<double>(variants);
  std::string sizes;
  for (const auto& [k, vals] : axes) {
    count *= static_cast<double>(vals.size());
    sizes += std::to_string(vals.size()) + " x ";
  }
  sizes += std::to_string(variants);
  if (count > static_cast<double>(maxCases)) {
    char buf[32];  // a whole number of any size, never in exponent form
    std::snprintf(buf, sizeof buf, "%.0f", count);
    throw InputError(where, "study: " + std::string(buf) + " cases (" + sizes +
                                ") exceed max_cases = " + std::to_string(maxCases) +
                                "; raise study.max_cases if that many are meant");
  }
}

// Cartesian product of the matrix axes (first key slowest).
std::vector<std::vector<std::string>> combinations(const Axes& axes) {
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
  return combos;
}

// Labels: overrides shared by every case (e.g. run.distance) are left out of the made ones.
void labelCases(StudySpec& st, const std::vector<std::string>& given,
                const std::vector<std::vector<std::string>>& matrixPart) {
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
}

}  // namespace

std::string studyCaseId(const std::vector<std::string>& overrides, const std::string& ownBase) {
  std::string key = join(overrides, ";");
  if (!ownBase.empty()) key += ";base=" + ownBase;
  char buf[32];
  std::snprintf(buf, sizeof buf, "case_%016llx", static_cast<unsigned long long>(fnv1a(key)));
  return buf;
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
  const ErrorFn err = [&](const std::string& m) { d.add(n->loc, "study: " + m); };
  checkStudyKeys(top, *n, d, err);

  const Node* base = n->field("base");
  if (!base || base->type != Node::Type::String) {
    err("base must name the base scenario file");
  } else {
    st.base = resolveBase(path, base->string);
    if (st.base.empty())
      err("base scenario '" + base->string + "' not found (relative to the study file)");
  }
  st.repeats = wholeNumber(*n, "repeats", err);
  st.jobs = wholeNumber(*n, "jobs", err);
  st.max_cases = wholeNumber(*n, "max_cases", err);
  const Axes axes = readMatrix(*n, err);
  const std::vector<Variant> variants = readCases(*n, path, err);
  d.throwIfAny();
  checkCaseCount(*n, axes, variants.size(), st.max_cases);

  // Matrix combinations x explicit variants.
  std::set<std::string> ids;
  std::vector<std::string> given;                    // label given in the case, per case
  std::vector<std::vector<std::string>> matrixPart;  // its matrix overrides
  for (const auto& c : combinations(axes))
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
      sc.id = studyCaseId(sc.overrides, v.base);
      if (!ids.insert(sc.id).second)
        d.add(n->loc, "study: two cases have the same overrides and base (" +
                          (v.label.empty() ? join(sc.overrides, " ") : v.label) +
                          "); give them different values");
      st.cases.push_back(sc);
    }
  d.throwIfAny();
  labelCases(st, given, matrixPart);
  checkStudyOverrides(st, host.text(), root);
  return st;
}

}  // namespace rb::scenario
