#include "workbench/study/metrics.hpp"

#include <cmath>
#include <exception>
#include <sstream>

#include "workbench/assessment/signal_metrics.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/scenario/metric_lua.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/stability/stability.hpp"
#include "workbench/study/jobs.hpp"

namespace rb::study::detail {
namespace {

namespace sm = assessment::metrics;
using scenario::MetricSpec;

constexpr const char* kAtSummary = "computed when the summary is written (against the reference)";

// A signal with its abscissa (track coordinate s [m] or time [s]).
struct Signal {
  std::vector<double> x, y;
  std::string why;
};

std::string parentOf(const std::string& p) {
  return p.substr(0, p.rfind('/'));
}

// The body names of the vehicle whose outputs are under `vehicle` ("" for a run of one vehicle,
// "/vehicles/<name>" in a train), in the vehicle's order.
std::vector<std::string> bodies(const io::ResultReader& r, const std::string& vehicle) {
  std::vector<std::string> out;
  if (auto names = r.text(vehicle + "/bodies", "names")) {
    std::istringstream in(*names);
    std::string n;
    while (std::getline(in, n, '\n'))
      if (!n.empty()) out.push_back(n);
  }
  if (out.empty()) out = r.members(vehicle + "/bodies");
  return out;
}

// The vehicle group a path lies in: "/vehicles/<name>" for a train's vehicle, else "".
std::string vehicleOf(const std::string& path) {
  const std::string head = "/vehicles/";
  if (path.rfind(head, 0) != 0) return "";
  const auto end = path.find('/', head.size());
  return end == std::string::npos ? "" : path.substr(0, end);
}

// The distance axis of `path`: the `s` beside it, the s of a body its path names, the
// assessment's distance axes, else the first body's s; each only with as many samples, and in a
// train each of the vehicle the path belongs to.
std::optional<std::vector<double>> distanceAxis(const io::ResultReader& r, const std::string& path,
                                                std::size_t n) {
  const std::string v = vehicleOf(path);
  const std::string local = path.substr(v.size());
  std::vector<std::string> candidates = {parentOf(path) + "/s"};
  const auto names = bodies(r, v);
  for (const auto& b : names)
    if (local.find("/" + b + "/") != std::string::npos)
      candidates.push_back(v + "/bodies/" + b + "/s");
  if (local.rfind("/assessment/", 0) == 0) {
    candidates.push_back(v + "/assessment/distance");
    candidates.push_back(v + "/assessment/safety/s");
  }
  for (const auto& b : names) candidates.push_back(v + "/bodies/" + b + "/s");
  for (const auto& c : candidates)
    if (auto x = r.dataset(c); x && x->size() == n && c != path) return x;
  return std::nullopt;
}

Signal readSignal(const io::ResultReader& r, const std::string& path, const std::string& along) {
  Signal s;
  auto y = r.dataset(path);
  if (!y) {
    s.why = "no 1-D dataset " + path + " in the result";
    return s;
  }
  std::optional<std::vector<double>> x;
  if (along == "time") {
    for (const std::string& t : {std::string("/time"), vehicleOf(path) + "/assessment/time"})
      if (!x)
        if (auto c = r.dataset(t); c && c->size() == y->size()) x = c;
  } else {
    x = distanceAxis(r, path, y->size());
  }
  if (!x) {
    s.why = "no " + along + " axis with the " + std::to_string(y->size()) + " samples of " + path;
    return s;
  }
  // A NaN or infinite sample (of a forged or diverged file) would make the statistic
  // meaningless: the metric is not computed, and its reason names the dataset.
  if (auto why = r.nonFiniteSample(path, *y)) {
    s.why = *why;
    return s;
  }
  if (auto why = r.nonFiniteSample(along + " axis of " + path, *x)) {
    s.why = *why;
    return s;
  }
  s.x = std::move(*x);
  s.y = std::move(*y);
  return s;
}

sm::Window windowOf(const MetricSpec& m) {
  return {m.from, m.to};
}

sm::Value signalMetric(const io::ResultReader& r, const MetricSpec& m) {
  const Signal s = readSignal(r, m.signal, m.along);
  if (!s.why.empty()) return sm::Value::fail(s.why);
  if (m.kind == "steady") return sm::steady(s.x, s.y, windowOf(m), m.length, m.tolerance);
  sm::Stat stat{};
  sm::statFromName(m.stat, stat);
  return sm::statistic(s.x, s.y, windowOf(m), stat);
}

// quantity: a summary name (/assessment/summary@name), "/assessment/...@attr", or a group whose
// `value` attribute is the assessed quantity.
sm::Value assessmentMetric(const io::ResultReader& r, const MetricSpec& m) {
  if (!r.has("/assessment"))
    return sm::Value::fail("the case has no /assessment (set run.assessment = true)");
  std::string object = "/assessment/summary", attr = m.quantity;
  if (m.quantity[0] == '/') {
    const auto at = m.quantity.find('@');
    object = m.quantity.substr(0, at);
    attr = at == std::string::npos ? "value" : m.quantity.substr(at + 1);
  }
  const auto v = r.number(object, attr);
  if (!v)
    return sm::Value::fail("no number " + attr + " on " + object +
                           " (not assessed in this run: see /assessment notes)");
  // A forged or damaged file may hold NaN or an infinity there: no value, the reason instead
  // (the summary would print it as a number).
  if (!std::isfinite(*v))
    return sm::Value::fail(object + "@" + attr + " is " + (std::isnan(*v) ? "NaN" : "infinite") +
                           " in the result (not a number that can be compared)");
  sm::Value out;
  out.value = *v;
  return out;
}

sm::Value errorMetric(const io::ResultReader& r, const MetricSpec& m, const std::string& refH5) {
  if (refH5.empty()) return sm::Value::fail(kAtSummary);
  io::ResultReader ref(refH5);
  if (!ref.ok()) return sm::Value::fail("the reference's result cannot be read");
  const Signal s = readSignal(r, m.signal, m.along);
  if (!s.why.empty()) return sm::Value::fail(s.why);
  const Signal rs = readSignal(ref, m.signal, m.along);
  if (!rs.why.empty()) return sm::Value::fail("reference: " + rs.why);
  return sm::maxAbsDifference(s.x, s.y, rs.x, rs.y, windowOf(m));
}

sm::Value criticalSpeedMetric(const scenario::StudySpec& st, const scenario::StudyCase& c,
                              const MetricSpec& m) {
  try {
    scenario::LoadOptions lo;
    lo.root = st.root;
    lo.overrides = c.overrides;
    const scenario::ScenarioSpec spec = scenario::loadScenario(c.base, lo);
    const stability::CriticalSpeed cs =
        stability::linearCriticalSpeed(spec, m.v_lo, m.v_hi, m.speeds);
    if (!cs.found) return sm::Value::fail("no linear critical speed: " + cs.why);
    sm::Value v;
    v.value = cs.speed;
    // Which mode loses its damping there (a car-body mode can go before hunting).
    v.note = cs.why.empty() ? "mode: " + cs.mode : cs.why + "; mode: " + cs.mode;
    return v;
  } catch (const std::exception& e) {
    return sm::Value::fail(std::string("linear critical speed: ") + e.what());
  }
}

sm::Value luaMetric(MetricContext& ctx, const io::ResultReader& r, const MetricSpec& m) {
  if (!ctx.lua && ctx.luaError.empty()) {
    try {
      ctx.lua = std::make_unique<scenario::LuaMetrics>(ctx.st.file, ctx.st.root);
    } catch (const std::exception& e) {
      ctx.luaError = e.what();
    }
  }
  if (!ctx.lua) return sm::Value::fail(ctx.luaError);
  std::vector<std::pair<std::string, std::vector<double>>> in;
  for (const auto& [name, path] : m.signals) {
    Signal s = readSignal(r, path, "distance");
    if (!s.why.empty()) s = readSignal(r, path, "time");
    if (!s.why.empty()) return sm::Value::fail("signals." + name + ": " + s.why);
    if (in.empty()) {
      if (auto t = r.dataset("/time"); t && t->size() == s.y.size()) in.emplace_back("time", *t);
      if (distanceAxis(r, path, s.y.size())) in.emplace_back("distance", s.x);
    }
    in.emplace_back(name, std::move(s.y));
  }
  sm::Value v;
  std::string why;
  if (!ctx.lua->call(m.index, in, v.value, why)) return sm::Value::fail(why);
  return v;
}

sm::Value oneMetric(MetricContext& ctx, const scenario::StudyCase& c, const io::ResultReader& r,
                    const MetricSpec& m, const std::string& refH5) {
  if (m.kind == "signal" || m.kind == "steady") return signalMetric(r, m);
  if (m.kind == "assessment") return assessmentMetric(r, m);
  if (m.kind == "error") return errorMetric(r, m, refH5);
  if (m.kind == "linear_critical_speed") return criticalSpeedMetric(ctx.st, c, m);
  return luaMetric(ctx, r, m);
}

io::MetricRecord record(const MetricSpec& m, const sm::Value& v) {
  return {m.name, v.ok() ? v.value : std::nan(""), v.why, v.note};
}

}  // namespace

MetricContext::MetricContext(const scenario::StudySpec& s) : st(s) {}
MetricContext::~MetricContext() = default;

std::string metricsHash(const scenario::StudySpec& st) {
  Hasher h;
  bool lua = false;
  for (const auto& m : st.metrics) {
    h.field("metric", m.definition());
    lua = lua || m.kind == "lua";
  }
  if (lua) {
    h.field("study_text", st.text);
    h.field("study_modules", st.modules_text);
  }
  return hex16(h.value());
}

std::vector<io::MetricRecord> caseMetrics(MetricContext& ctx, const scenario::StudyCase& c,
                                          const std::string& h5, const std::string& referenceH5) {
  std::vector<io::MetricRecord> out;
  io::ResultReader r(h5);
  // A fresh sandbox per case: a function's globals or a budget one case exhausted never carry
  // over, so a value is the same whether the runner stored it or a summary computed it.
  ctx.lua.reset();
  ctx.luaError.clear();
  for (const auto& m : ctx.st.metrics) {
    if (!r.ok()) {
      out.push_back(record(m, sm::Value::fail("the result file cannot be read")));
      continue;
    }
    out.push_back(record(m, oneMetric(ctx, c, r, m, referenceH5)));
  }
  return out;
}

bool storeCaseMetrics(const scenario::StudySpec& st, const scenario::StudyCase& c,
                      const std::string& h5, std::string& why) {
  if (st.metrics.empty()) return true;
  try {
    MetricContext ctx(st);
    io::MetricsBlock b;
    b.hash = metricsHash(st);
    b.values = caseMetrics(ctx, c, h5, "");
    io::writeMetrics(h5, b);
    return true;
  } catch (const std::exception& e) {
    why = std::string("storing the metrics: ") + e.what();
    return false;
  }
}

namespace {

// Whether the stored /metrics can stand for the metrics of `st`: the same names in the study's
// order, each a finite value without a reason or NaN with one (what caseMetrics stores). The
// block is read from a result file, which may be forged or damaged: anything else is computed
// afresh rather than printed in the summary.
bool storedUsable(const io::MetricsBlock& b, const scenario::StudySpec& st) {
  if (b.hash != metricsHash(st) || b.values.size() != st.metrics.size()) return false;
  for (std::size_t k = 0; k < b.values.size(); ++k) {
    const io::MetricRecord& m = b.values[k];
    if (m.name != st.metrics[k].name ||
        !(m.why.empty() ? std::isfinite(m.value) : std::isnan(m.value)))
      return false;
  }
  return true;
}

}  // namespace

std::vector<io::MetricRecord> summaryMetrics(MetricContext& ctx, const scenario::StudyCase& c,
                                             const std::string& h5,
                                             const std::string& referenceH5) {
  const auto stored = io::readMetrics(h5);
  if (!stored || !storedUsable(*stored, ctx.st)) return caseMetrics(ctx, c, h5, referenceH5);
  std::vector<io::MetricRecord> out = stored->values;
  for (std::size_t k = 0; k < ctx.st.metrics.size(); ++k)
    if (ctx.st.metrics[k].kind == "error") {
      io::ResultReader r(h5);
      out[k] = record(ctx.st.metrics[k], errorMetric(r, ctx.st.metrics[k], referenceH5));
    }
  return out;
}

}  // namespace rb::study::detail
