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

#include "workbench/assessment/signal_metrics.hpp"
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

// Bounds that keep the expansion of a study small before it is made: a value or label (every
// case copies its values and label), the keys of one entry of `cases`, and the text of all cases
// together (max_cases alone bounds their number, not their size).
constexpr std::size_t kMaxValueChars = 4096;
constexpr std::size_t kMaxEntryKeys = 1000;
constexpr double kMaxStudyTextBytes = 256.0 * 1024 * 1024;

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
// A matrix axis: the key, its values as override text and where each value is written.
struct Axis {
  std::string key;
  std::vector<std::string> values;
  std::vector<SourceLoc> locs;
};
using Axes = std::vector<Axis>;

// An entry of `cases`: overrides plus the study keys label, base (as written and resolved), role.
struct Variant {
  std::vector<std::string> overrides;
  std::vector<SourceLoc> locs;  // where each override is written
  std::string label, base, baseResolved, role;
  SourceLoc loc;  // the entry's own line
};

// A base scenario path relative to the study file (else as given); "" when not found.
std::string resolveBase(const std::string& studyPath, const std::string& name) {
  // The error_code forms: a name the system refuses (too long, a loop, no permission) is "not
  // found" here, and the caller reports it with the study's file:line.
  std::error_code ec;
  fs::path p = fs::path(studyPath).parent_path() / name;
  if (!fs::is_regular_file(p, ec)) p = fs::path(name);
  return fs::is_regular_file(p, ec) ? p.lexically_normal().string() : std::string();
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

// A whole-number key of study{} in its schema range; the schema's default if absent or wrong
// (reported at the key's own line).
int wholeNumber(const Node& n, const char* key, Diagnostics& d) {
  const KeySpec& k = *block("study").key(key);
  const int def = static_cast<int>(k.num_default);
  const Node* v = n.field(key);
  if (!v) return def;
  // Range first: converting a double beyond int's range is undefined.
  if (v->type != Node::Type::Number || !(v->number >= k.min && v->number <= k.max) ||
      v->number != std::floor(v->number)) {
    d.add(v->loc, "study: " + std::string(key) + " must be a whole number in [" +
                      formatNumber(k.min, 17) + ", " + formatNumber(k.max, 17) + "], got " +
                      v->describe());
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
    Axis axis{k, {}, {}};
    std::size_t tooLong = 0;
    for (const auto& item : v.items) {
      std::string t;
      if (!scalarText(item, t))
        err("matrix[\"" + k + "\"]: values must be numbers, strings or booleans");
      if (t.size() > kMaxValueChars) {
        ++tooLong;
        t.resize(kMaxValueChars);
      }
      axis.values.push_back(t);
      axis.locs.push_back(item.loc);
    }
    if (tooLong > 0)
      err("matrix[\"" + k + "\"]: " + std::to_string(tooLong) + " of its values longer than " +
          std::to_string(kMaxValueChars) + " characters, the most a value may have");
    axes.push_back(std::move(axis));
  }
  return axes;
}

// One study key or --set path of an entry of `cases`.
void readCaseKey(const std::string& where, const std::string& k, const std::string& t,
                 const SourceLoc& loc, const std::string& studyPath, Variant& var,
                 const ErrorFn& err) {
  if (k.find('.') != std::string::npos) {
    var.overrides.push_back(k + "=" + t);
    var.locs.push_back(loc);
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
      var.loc = item.loc;
      if (item.fields.size() > kMaxEntryKeys)
        err(where + ": " + std::to_string(item.fields.size()) + " keys; an entry has at most " +
            std::to_string(kMaxEntryKeys));
      for (const auto& [k, v] : item.fields) {
        std::string t;
        if (!scalarText(v, t)) {
          err(where + "[\"" + k + "\"] must be a scalar");
          continue;
        }
        if (t.size() > kMaxValueChars) {
          err(where + "[\"" + k + "\"]: a value of " + std::to_string(t.size()) +
              " characters; values (and labels) are at most " + std::to_string(kMaxValueChars));
          t.resize(kMaxValueChars);
        }
        readCaseKey(where, k, t, v.loc, studyPath, var, err);
      }
      variants.push_back(var);
    }
  }
  if (variants.empty()) variants.push_back({});
  return variants;
}

// The number of cases before expanding them: a matrix of a few long axes multiplies to more
// cases than memory holds (each a list of strings), so it is refused here, with the sizes.
// Their text is bounded too: every case holds its overrides and its label (a label is made of
// the overrides, or copied), so a long value or many keys times many cases is refused with its
// estimate before anything is copied.
void checkCaseCount(const Node& n, const Axes& axes, const std::vector<Variant>& variants,
                    long long maxCases) {
  const Node* m = n.field("matrix");
  const SourceLoc where = m ? m->loc : n.loc;
  double count = static_cast<double>(variants.size());
  double caseBytes = 0.0;  // the largest text of one case (overrides, label), estimated
  std::string sizes;
  for (const auto& axis : axes) {
    count *= static_cast<double>(axis.values.size());
    sizes += std::to_string(axis.values.size()) + " x ";
    std::size_t longest = 0;
    for (const auto& v : axis.values) longest = std::max(longest, v.size());
    caseBytes += 2.0 * static_cast<double>(axis.key.size() + longest + 2);
  }
  double variantBytes = 0.0;
  for (const auto& v : variants) {
    double b = static_cast<double>(v.label.size());
    for (const auto& o : v.overrides) b += 2.0 * static_cast<double>(o.size() + 1);
    variantBytes = std::max(variantBytes, b);
  }
  caseBytes += variantBytes;
  sizes += std::to_string(variants.size());
  if (count <= static_cast<double>(maxCases) && count * caseBytes > kMaxStudyTextBytes)
    throw InputError(
        where, "study: " + std::to_string(static_cast<long long>(count)) + " cases of up to " +
                   formatNumber(caseBytes / 1024.0, 3) + " kB of overrides and label each: about " +
                   formatNumber(count * caseBytes / (1024.0 * 1024.0), 3) + " MB, more than the " +
                   formatNumber(kMaxStudyTextBytes / (1024.0 * 1024.0), 3) +
                   " MB a study may hold; use fewer or shorter values");
  if (count > static_cast<double>(maxCases)) {
    char buf[32];  // a whole number of any size, never in exponent form
    std::snprintf(buf, sizeof buf, "%.0f", count);
    throw InputError(where, "study: " + std::string(buf) + " cases (" + sizes +
                                ") exceed max_cases = " + std::to_string(maxCases) +
                                "; raise study.max_cases if that many are meant");
  }
}

// One matrix combination: its overrides and where each value is written.
struct Combination {
  std::vector<std::string> overrides;
  std::vector<SourceLoc> locs;
};

// Cartesian product of the matrix axes (first key slowest).
std::vector<Combination> combinations(const Axes& axes) {
  std::vector<Combination> combos = {{}};
  for (const auto& axis : axes) {
    std::vector<Combination> next;
    for (const auto& c : combos)
      for (std::size_t i = 0; i < axis.values.size(); ++i) {
        auto e = c;
        e.overrides.push_back(axis.key + "=" + axis.values[i]);
        e.locs.push_back(axis.locs[i]);
        next.push_back(std::move(e));
      }
    combos = std::move(next);
  }
  return combos;
}

// Labels: overrides shared by every case (e.g. run.distance) are left out of the made ones.
void labelCases(StudySpec& st, const std::vector<std::string>& given,
                const std::vector<std::vector<std::string>>& matrixPart) {
  // Sets, not searches of lists: a case may hold thousands of overrides.
  std::set<std::string> common;
  if (st.cases.size() > 1) {
    common.insert(st.cases[0].overrides.begin(), st.cases[0].overrides.end());
    for (const auto& sc : st.cases) {
      if (common.empty()) break;
      const std::set<std::string> own(sc.overrides.begin(), sc.overrides.end());
      for (auto it = common.begin(); it != common.end();)
        it = own.count(*it) != 0 ? std::next(it) : common.erase(it);
    }
  }
  auto without = [&](const std::vector<std::string>& ov) {
    std::vector<std::string> out;
    for (const auto& o : ov)
      if (common.count(o) == 0) out.push_back(o);
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

const std::vector<std::string> kMetricKinds = {
    "signal", "steady", "assessment", "error", "linear_critical_speed", "lua"};
const std::vector<std::string> kMetricKeys = {
    "name",   "kind",      "signal",   "stat",   "from",    "to", "along",
    "length", "tolerance", "quantity", "speeds", "signals", "fn"};
// The summary names of /assessment/summary a metric may give alone (docs/assessment.md).
const std::vector<std::string> kAssessmentNames = {
    "y_over_q", "dq_over_q",  "y_qst",       "q_qst",       "q_max",        "sum_y",
    "n_mv",     "wz_lateral", "wz_vertical", "t_gamma_max", "stability_rms"};

std::string unknownWithHint(const std::string& what, const std::string& got,
                            const std::vector<std::string>& names) {
  std::string hint = closestMatch(got, names);
  return "unknown " + what + " '" + got + "'" +
         (hint.empty() ? "" : " (did you mean '" + hint + "'?)") + "; one of " + join(names, ", ");
}

// A metric name: a summary column metric_<name>, so letters, digits and '_' only.
bool columnName(const std::string& s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

// The string key `k` of a metric entry ("" when absent; an error when not a string).
std::string metricText(const Node& m, const char* k, const ErrorFn& err) {
  const Node* v = m.field(k);
  if (!v) return {};
  if (v->type != Node::Type::String) {
    err(std::string(k) + " must be a string, got " + v->describe());
    return {};
  }
  return v->string;
}

// The number key `k` of a metric entry (`def` when absent).
double metricNumber(const Node& m, const char* k, double def, const ErrorFn& err) {
  const Node* v = m.field(k);
  if (!v) return def;
  if (v->type != Node::Type::Number || !std::isfinite(v->number)) {
    err(std::string(k) + " must be a finite number, got " + v->describe());
    return def;
  }
  return v->number;
}

// A dataset path of the result file: "/group/.../name".
void checkPath(const std::string& key, const std::string& p, const ErrorFn& err) {
  if (p.size() < 2 || p[0] != '/' || p.back() == '/' || p.find("//") != std::string::npos)
    err(key + " must be a dataset path such as \"/bodies/ws1/y\", got '" + p + "'");
}

// signals = { name = "/path", ... } of a Lua metric.
void readLuaSignals(const Node& m, MetricSpec& ms, const ErrorFn& err) {
  const Node* s = m.field("signals");
  if (!s || s->type != Node::Type::Table || !s->items.empty() || s->fields.empty()) {
    err("a function metric needs signals = { name = \"/dataset/path\", ... }");
    return;
  }
  for (const auto& [k, v] : s->fields) {
    if (v.type != Node::Type::String) {
      err("signals." + k + " must be a dataset path string");
      continue;
    }
    checkPath("signals." + k, v.string, err);
    ms.signals.emplace_back(k, v.string);
  }
}

// speeds = { lo, hi, n } of a linear critical speed metric.
void readSpeeds(const Node& m, MetricSpec& ms, const ErrorFn& err) {
  const Node* s = m.field("speeds");
  const bool shape = s && s->type == Node::Type::Table && s->fields.empty() &&
                     s->items.size() == 3 &&
                     std::all_of(s->items.begin(), s->items.end(),
                                 [](const Node& v) { return v.type == Node::Type::Number; });
  if (!shape) {
    err("linear_critical_speed needs speeds = { lowest [m/s], highest [m/s], count }");
    return;
  }
  ms.v_lo = s->items[0].number;
  ms.v_hi = s->items[1].number;
  const double n = s->items[2].number;
  if (!(ms.v_lo > 0.0 && ms.v_hi > ms.v_lo && n >= 2 && n <= 1000 && n == std::floor(n)))
    err("speeds = { lo, hi, n } needs 0 < lo < hi and a whole n in [2, 1000]");
  else
    ms.speeds = static_cast<int>(n);
}

// The keys a kind needs, and the ones it does not take.
void checkKind(const Node& m, MetricSpec& ms, const ErrorFn& err) {
  const bool needsSignal = ms.kind == "signal" || ms.kind == "steady" || ms.kind == "error";
  if (needsSignal && ms.signal.empty()) err("kind " + ms.kind + " needs signal = \"/path\"");
  if (!ms.signal.empty()) checkPath("signal", ms.signal, err);
  if (ms.kind == "signal") {
    assessment::metrics::Stat st{};
    if (ms.stat.empty())
      err("a signal metric needs stat = one of " + join(assessment::metrics::statNames(), ", "));
    else if (!assessment::metrics::statFromName(ms.stat, st))
      err(unknownWithHint("stat", ms.stat, assessment::metrics::statNames()));
  } else if (!ms.stat.empty()) {
    err("stat belongs to kind signal, not " + ms.kind);
  }
  if (ms.kind == "assessment") {
    if (ms.quantity.empty())
      err("an assessment metric needs quantity = one of " + join(kAssessmentNames, ", ") +
          " or a path \"/assessment/...@attribute\"");
    else if (ms.quantity[0] != '/' && std::find(kAssessmentNames.begin(), kAssessmentNames.end(),
                                                ms.quantity) == kAssessmentNames.end())
      err(unknownWithHint("assessment quantity", ms.quantity, kAssessmentNames));
    else if (ms.quantity[0] == '/' && ms.quantity.rfind("/assessment/", 0) != 0)
      err("quantity path must lie below /assessment/, got '" + ms.quantity + "'");
  }
  const bool windowed = needsSignal;
  if (!windowed && (m.field("from") || m.field("to") || m.field("along")))
    err("from, to and along apply to kinds signal, steady and error, not " + ms.kind);
  if (ms.kind == "linear_critical_speed") readSpeeds(m, ms, err);
  if (ms.kind == "lua") readLuaSignals(m, ms, err);
  if (ms.kind != "lua" && m.field("signals")) err("signals belongs to a function metric (fn)");
}

// One entry of study.metrics.
MetricSpec readMetric(const Node& m, int index, const SourceLoc& loc, const ErrorFn& err) {
  MetricSpec ms;
  ms.index = index;
  ms.loc = loc;
  for (const auto& [k, v] : m.fields)
    if (std::find(kMetricKeys.begin(), kMetricKeys.end(), k) == kMetricKeys.end())
      err(unknownWithHint("key", k, kMetricKeys));
  ms.name = metricText(m, "name", err);
  if (!columnName(ms.name))
    err("name must be letters, digits and '_' (it names the column metric_<name>), got '" +
        ms.name + "'");
  // /metrics stores <name>, <name>_why and <name>_note beside `names` and `definitions_hash`
  // (io/metrics_output): a name that is another metric's reason or note would overwrite it.
  auto endsWith = [&](const std::string& tail) {
    return ms.name.size() > tail.size() &&
           ms.name.compare(ms.name.size() - tail.size(), tail.size(), tail) == 0;
  };
  if (endsWith("_why") || endsWith("_note") || ms.name == "names" || ms.name == "definitions_hash")
    err("name '" + ms.name +
        "' is reserved (names ending in _why or _note, names, definitions_hash)");
  const Node* fn = m.field("fn");
  if (fn && fn->type != Node::Type::Function) err("fn must be a function(s) ... end");
  ms.kind = metricText(m, "kind", err);
  if (ms.kind.empty()) ms.kind = fn ? "lua" : "signal";
  if (std::find(kMetricKinds.begin(), kMetricKinds.end(), ms.kind) == kMetricKinds.end()) {
    err(unknownWithHint("kind", ms.kind, kMetricKinds));
    return ms;
  }
  if (ms.kind == "lua" && !fn) err("kind lua needs fn = function(s) ... end");
  if (ms.kind != "lua" && fn) err("fn belongs to kind lua, not " + ms.kind);
  ms.signal = metricText(m, "signal", err);
  ms.stat = metricText(m, "stat", err);
  ms.quantity = metricText(m, "quantity", err);
  const std::string along = metricText(m, "along", err);
  if (!along.empty() && along != "distance" && along != "time")
    err("along must be \"distance\" or \"time\", got '" + along + "'");
  if (!along.empty()) ms.along = along;
  ms.from = metricNumber(m, "from", ms.from, err);
  ms.to = metricNumber(m, "to", ms.to, err);
  if (!(ms.from < ms.to)) err("from must be less than to");
  ms.length = metricNumber(m, "length", 0.0, err);
  ms.tolerance = metricNumber(m, "tolerance", -1.0, err);
  if (ms.kind != "steady" && (m.field("length") || m.field("tolerance")))
    err("length and tolerance belong to kind steady");
  if (m.field("length") && ms.length <= 0.0) err("length must be positive");
  if (m.field("tolerance") && ms.tolerance < 0.0) err("tolerance must not be negative");
  checkKind(m, ms, err);
  return ms;
}

// study.metrics: a list of metric tables with distinct names.
std::vector<MetricSpec> readMetrics(const Node& n, Diagnostics& d) {
  std::vector<MetricSpec> out;
  const Node* ms = n.field("metrics");
  if (!ms) return out;
  if (ms->type != Node::Type::Table || !ms->fields.empty()) {
    d.add(ms->loc, "study: metrics must be a list of { name = ..., ... } tables");
    return out;
  }
  std::set<std::string> names;
  for (std::size_t i = 0; i < ms->items.size(); ++i) {
    const Node& m = ms->items[i];
    const Node* nm = m.field("name");
    const std::string where = "study: metrics[" + std::to_string(i + 1) + "]" +
                              (nm && nm->type == Node::Type::String ? " (" + nm->string + ")" : "");
    const ErrorFn err = [&](const std::string& msg) { d.add(m.loc, where + ": " + msg); };
    if (m.type != Node::Type::Table || !m.items.empty()) {
      err("must be { name = ..., ... }");
      continue;
    }
    MetricSpec spec = readMetric(m, static_cast<int>(i + 1), m.loc, err);
    if (!spec.name.empty() && !names.insert(spec.name).second) err("name given twice");
    out.push_back(std::move(spec));
  }
  return out;
}

}  // namespace

std::string MetricSpec::definition() const {
  std::string t = "name=" + name + ";kind=" + kind + ";signal=" + signal + ";stat=" + stat +
                  ";along=" + along + ";from=" + formatNumberExact(from) +
                  ";to=" + formatNumberExact(to) + ";length=" + formatNumberExact(length) +
                  ";tolerance=" + formatNumberExact(tolerance) + ";quantity=" + quantity;
  if (kind == "linear_critical_speed")
    t += ";speeds=" + formatNumberExact(v_lo) + "," + formatNumberExact(v_hi) + "," +
         std::to_string(speeds);
  for (const auto& [k, p] : signals) t += ";signals." + k + "=" + p;
  return t;
}

std::string studyCaseId(const std::vector<std::string>& overrides, const std::string& ownBase) {
  std::string key = join(overrides, ";");
  if (!ownBase.empty()) key += ";base=" + ownBase;
  char buf[32];
  std::snprintf(buf, sizeof buf, "case_%016llx", static_cast<unsigned long long>(fnv1a(key)));
  return buf;
}

bool isStudyFile(const std::string& path, const std::string& root) {
  HostOptions ho;
  ho.root = root;
  ho.collect_missing_modules = true;
  LuaHost host(ho);
  try {
    const Node top = host.runFile(path);
    return top.fields.size() == 1 && top.field("study") != nullptr;
  } catch (const InputError&) {
    return false;
  }
}

StudySpec loadStudy(const std::string& path, const std::string& root) {
  HostOptions ho;
  ho.root = root;
  LuaHost host(ho);
  Node top = host.runFile(path);
  Diagnostics d;
  reportNulBytes(top, "", d);  // before a base or a metric's text is used (node.hpp)
  d.throwIfAny();
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
  st.repeats = wholeNumber(*n, "repeats", d);
  st.jobs = wholeNumber(*n, "jobs", d);
  st.max_cases = wholeNumber(*n, "max_cases", d);
  st.output = "compact";
  if (const Node* out = n->field("output")) {
    if (out->type != Node::Type::String || (out->string != "compact" && out->string != "full"))
      d.add(out->loc, "study: output must be \"compact\" or \"full\"");
    else
      st.output = out->string;
  }
  st.text = host.text();
  for (const auto& [module, text] : host.modules())
    st.modules_text += "-- file: " + module + "\n" + text;
  st.root = root;
  st.metrics = readMetrics(*n, d);
  const Axes axes = readMatrix(*n, err);
  const std::vector<Variant> variants = readCases(*n, path, err);
  d.throwIfAny();
  checkCaseCount(*n, axes, variants, st.max_cases);

  // Matrix combinations x explicit variants.
  std::set<std::string> ids;
  std::vector<std::string> given;                    // label given in the case, per case
  std::vector<std::vector<std::string>> matrixPart;  // its matrix overrides
  const Node* matrix = n->field("matrix");
  for (const auto& c : combinations(axes))
    for (const auto& v : variants) {
      StudyCase sc;
      sc.overrides = c.overrides;
      sc.overrides.insert(sc.overrides.end(), v.overrides.begin(), v.overrides.end());
      sc.override_locs = c.locs;
      sc.override_locs.insert(sc.override_locs.end(), v.locs.begin(), v.locs.end());
      sc.loc = !v.loc.file.empty() ? v.loc : matrix ? matrix->loc : n->loc;
      sc.base = v.base.empty() ? st.base : v.baseResolved;
      sc.role = v.role;
      given.push_back(v.label);
      matrixPart.push_back(c.overrides);
      // Named by its overrides (and its own base) only, so adding values to a study, or
      // relabelling, keeps old results resumable.
      sc.id = studyCaseId(sc.overrides, v.base);
      if (!ids.insert(sc.id).second)
        d.add(n->loc, "study: two cases have the same overrides and base (" +
                          (v.label.empty() ? join(sc.overrides, " ") : v.label) +
                          "); give them different values");
      st.cases.push_back(sc);
    }
  const bool hasReference = std::any_of(st.cases.begin(), st.cases.end(),
                                        [](const StudyCase& c) { return c.role == "reference"; });
  for (const auto& m : st.metrics)
    if (m.kind == "error" && !hasReference)
      d.add(m.loc, "study: metric " + m.name +
                       ": kind error needs a case with role = \"reference\" in cases");
  d.throwIfAny();
  st.matrix_parts = matrixPart;
  labelCases(st, given, matrixPart);
  checkStudyOverrides(st, host.text(), root);
  return st;
}

}  // namespace rb::scenario
