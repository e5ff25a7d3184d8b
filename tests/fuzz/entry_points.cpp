#include "entry_points.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "workbench/assessment/signal_metrics.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"
#include "workbench/contact/table_io.hpp"
#include "workbench/core/error.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/profile_io.hpp"
#include "workbench/profiles/rail60e1.hpp"
#include "workbench/profiles/s1002.hpp"
#include "workbench/scenario/metric_lua.hpp"
#include "workbench/scenario/override_check.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/scenario/study.hpp"
#include "workbench/track/irregularities.hpp"

#ifndef RB_SOURCE_DIR
#error "RB_SOURCE_DIR must name the source tree (scenarios/, profiles/)"
#endif

namespace rb::fuzz {
namespace {

namespace fs = std::filesystem;

// A private folder for the files the readers need on disk, removed at exit.
class ScratchDir {
 public:
  ScratchDir() {
    std::string templ = (fs::temp_directory_path() / "railbench_fuzz_XXXXXX").string();
    if (::mkdtemp(templ.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = templ;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  std::string write(const std::string& name, std::string_view data) const {
    const std::string file = (path_ / name).string();
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    out.close();
    if (!out) throw std::runtime_error("cannot write " + file);
    return file;
  }

 private:
  fs::path path_;
};

const ScratchDir& scratch() {
  static const ScratchDir dir;
  return dir;
}

// Splits off the leading "--@set key=value" lines as overrides (the rest stays in the script,
// where they are comments, so that line numbers do not move).
std::vector<std::string> overridesOf(std::string_view data) {
  constexpr std::string_view tag = "--@set ";
  std::vector<std::string> out;
  std::size_t b = 0;
  while (b < data.size() && data.substr(b, tag.size()) == tag) {
    std::size_t e = data.find('\n', b);
    if (e == std::string_view::npos) e = data.size();
    out.emplace_back(data.substr(b + tag.size(), e - b - tag.size()));
    b = e + 1;
  }
  return out;
}

// Lua instructions per input (the program allows 2e9): an endless loop the guard catches ends as
// an InputError well within the smoke runs' 10 s per input; one it misses shows as a timeout.
constexpr long long kFuzzInstructionLimit = 20'000'000;

// The host's wall-clock guard (30 s by default) must end a script well within the smoke runs'
// 10 s per input: a loop that catches the error of a costly C function (an unknown name's
// "did you mean" search) runs few Lua instructions per second and is stopped by the clock.
// The study harnesses take 2 s: a study file may run three times per input (the study, its own
// base scenario in the check of the overrides, and once more for the parameter labels).
void limitLuaClock(const char* seconds) {
  static const bool clock_set = ::setenv("RAILBENCH_LUA_SECONDS", seconds, 0) == 0;
  (void)clock_set;
}

std::string sourceFile(const char* rel) {
  std::ifstream in(fs::path(RB_SOURCE_DIR) / rel, std::ios::binary);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (text.empty()) throw std::runtime_error(std::string("cannot read ") + rel);
  return text;
}

// The study input as study.lua beside the base scenarios it can name (written once).
std::string writeStudy(std::string_view data) {
  static const bool bases = [] {
    scratch().write("base.lua", sourceFile("scenarios/validation/case1_R300_kec.lua"));
    scratch().write("wagon.lua", sourceFile("scenarios/vehicle/manchester_guided_r500.lua"));
    return true;
  }();
  (void)bases;
  return scratch().write("study.lua", data);
}

// RB_FUZZ_VERBOSE=1: the study harnesses say what each input gave (to check that seeds load).
void verbose(const char* what, const std::string& text) {
  static const bool on = std::getenv("RB_FUZZ_VERBOSE") != nullptr;
  if (on) std::fprintf(stderr, "%s: %s\n", what, text.c_str());
}

// A study as the workbench loads it, and the metrics' definitions (hashed into /metrics).
std::optional<scenario::StudySpec> loadStudyInput(std::string_view data, std::string& path) {
  limitLuaClock("2");
  path = writeStudy(data);
  try {
    scenario::StudySpec st = scenario::loadStudy(path, RB_SOURCE_DIR);
    std::size_t n = 0;
    for (const auto& m : st.metrics) n += m.definition().size();
    volatile std::size_t sink = n;
    (void)sink;
    verbose("study", "loaded, " + std::to_string(st.cases.size()) + " cases, " +
                         std::to_string(st.metrics.size()) + " metrics");
    return st;
  } catch (const InputError& e) {
    verbose("study", e.what());
    return std::nullopt;
  }
}

// Signals (abscissa x, values y) the metrics are evaluated on: ordinary samples over 400 m,
// non-finite values, no samples, a single sample, repeated abscissae (a halted body).
struct SyntheticSignal {
  std::vector<double> x, y;
};

const std::vector<SyntheticSignal>& syntheticSignals() {
  static const std::vector<SyntheticSignal> sets = [] {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<SyntheticSignal> out;
    SyntheticSignal a;
    for (int i = 0; i <= 40; ++i) {
      a.x.push_back(10.0 * i);
      a.y.push_back(1e-3 * std::sin(0.3 * i) + 1e-4 * i);
    }
    out.push_back(std::move(a));
    out.push_back({{0, 1, 2, 3, 4, 5, 6}, {0, nan, inf, -inf, 1e308, -0.0, 5e-324}});
    out.push_back({{}, {}});
    out.push_back({{5}, {1.5}});
    out.push_back({{0, 0, 1, 1, 2}, {1, 2, 3, 4, 5}});
    return out;
  }();
  return sets;
}

// A metric's value or its reason, as the summary records it: NaN exactly when there is a reason.
void checkMetricValue(const assessment::metrics::Value& v, const scenario::MetricSpec& m) {
  if (v.ok() && std::isnan(v.value))
    throw std::logic_error("metric " + m.name + " (" + m.kind + "): NaN without a reason");
  if (!v.ok() && !std::isnan(v.value))
    throw std::logic_error("metric " + m.name + " (" + m.kind + "): a value and a reason");
}

// The statistics of kinds signal, steady and error on every synthetic signal (error: against
// every synthetic reference).
void evaluateStatistics(const scenario::MetricSpec& m) {
  namespace sm = assessment::metrics;
  const sm::Window w{m.from, m.to};
  for (const auto& s : syntheticSignals()) {
    if (m.kind == "signal") {
      sm::Stat stat{};
      if (sm::statFromName(m.stat, stat)) checkMetricValue(sm::statistic(s.x, s.y, w, stat), m);
    } else if (m.kind == "steady") {
      checkMetricValue(sm::steady(s.x, s.y, w, m.length, m.tolerance), m);
    } else if (m.kind == "error") {
      for (const auto& r : syntheticSignals())
        checkMetricValue(sm::maxAbsDifference(s.x, s.y, r.x, r.y, w), m);
    }
  }
}

// Budgets of the metric functions per call (the program's: 1e9 instructions, 30 s, 1 GiB), and
// the time after which the harness makes no further call: each input ends well within the smoke
// runs' 10 s even with many slow functions.
scenario::MetricBudget fuzzMetricBudget() {
  scenario::MetricBudget b;
  b.instructions = 20'000'000;
  b.seconds = 1.0;
  b.memory = std::size_t{256} << 20;
  return b;
}
constexpr std::chrono::seconds kMetricCallsTime{2};

// Every function metric through LuaMetrics, called as the study summary calls it: s.time and
// s.distance (the abscissa) and each declared signal (the values).
void evaluateLuaMetrics(const scenario::StudySpec& st, const std::string& path) {
  std::unique_ptr<scenario::LuaMetrics> lua;
  try {
    lua = std::make_unique<scenario::LuaMetrics>(path, RB_SOURCE_DIR, fuzzMetricBudget());
  } catch (const InputError& e) {
    verbose("metric functions", e.what());
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  auto call = [&](int index, const std::vector<std::pair<std::string, std::vector<double>>>& in) {
    if (std::chrono::steady_clock::now() - start > kMetricCallsTime) return;
    double v = 0.0;
    std::string why;
    const bool ok = lua->call(index, in, v, why);
    verbose(("metric " + std::to_string(index)).c_str(), ok ? std::to_string(v) : why);
    if (ok != why.empty())
      throw std::logic_error("LuaMetrics::call: success and reason disagree: '" + why + "'");
    if (ok && !std::isfinite(v)) throw std::logic_error("LuaMetrics::call: a non-finite value");
  };
  for (const auto& m : st.metrics) {
    if (m.kind != "lua") continue;
    for (const auto& s : syntheticSignals()) {
      std::vector<std::pair<std::string, std::vector<double>>> in = {{"time", s.x},
                                                                     {"distance", s.x}};
      for (const auto& sig : m.signals) in.emplace_back(sig.first, s.y);
      call(m.index, in);
    }
  }
  // An index that names no function, and a call without signals.
  call(static_cast<int>(st.metrics.size()) + 1, {});
  if (!st.metrics.empty()) call(st.metrics.front().index, {});
}

void touchProfile(const profiles::Profile& p) {
  volatile double sink = 0.0;
  const double a = p.sMin(), b = p.sMax();
  for (int i = 0; i <= 8; ++i) {
    const double s = a + (b - a) * i / 8.0;
    sink = sink + p.at(s).h + p.curvature(s);
  }
  (void)sink;
}

// The CSV reader's entry point: the only call to adapt when its interface changes.
std::optional<track::IrregularityTable> parseCsv(std::string_view data, Diagnostics& diags) {
  std::istringstream in{std::string(data)};
  return track::parseIrregularityCsv(in, "fuzz.csv", diags);
}

std::string wrapPayload(bool kec, std::string_view payload) {
  const contact::TableKind kind = kec ? contact::TableKind::Kec : contact::TableKind::Lut;
  return contact::tableFileBytes(kind, contact::tableInputKey(seedTableConfig(), kind), payload);
}

void touchLut(const contact::LutTable& t) {
  volatile double sink = 0.0;
  contact::LutSample out;
  const auto& y = t.yGrid();
  const auto& g = t.gaugeGrid();
  for (const double fy : {-0.1, 0.0, 0.37, 1.0, 1.1}) {
    for (const double fg : {-0.1, 0.0, 0.5, 1.0, 1.1}) {
      const double yy = y.min + fy * (y.max - y.min), gg = g.min + fg * (g.max - g.min);
      t.eval(yy, gg, out);
      t.evalValues(yy, gg, out);
      sink = sink + out.value[0] + t.evalChannel(0, yy, gg).v;
    }
  }
  (void)sink;
}

void touchKec(const contact::KecTable& t) {
  volatile double sink = 0.0;
  contact::KecPoint out;
  const auto& g = t.grid();
  for (const contact::Side side : {contact::Side::Left, contact::Side::Right}) {
    for (const double f : {-0.1, 0.0, 0.37, 1.0, 1.1}) {
      const double s = g.min + f * (g.max - g.min);
      t.eval(side, s, out);
      t.evalValues(side, s, out);
      sink = sink + out.value[0] + t.f(side, s) + (t.inTransition(side, s) ? 1.0 : 0.0);
    }
  }
  (void)sink;
}

}  // namespace

void scenario(std::string_view data) {
  limitLuaClock("3");
  const std::string file = scratch().write("fuzz.lua", data);
  scenario::LoadOptions options;
  options.root = RB_SOURCE_DIR;
  options.overrides = overridesOf(data);
  options.instruction_limit = kFuzzInstructionLimit;
  try {
    (void)scenario::loadScenario(file, options);
  } catch (const InputError&) {
  }
}

void study(std::string_view data) {
  std::string path;
  const auto st = loadStudyInput(data, path);
  if (!st) return;
  // What the study command derives before running anything: the figure labels of the swept
  // parameters (each base scenario run once more).
  std::size_t n = 0;
  for (const auto& l : scenario::studyParameterLabels(*st)) n += l.label.size() + l.unit.size();
  volatile std::size_t sink = n;
  (void)sink;
}

void metric(std::string_view data) {
  std::string path;
  const auto st = loadStudyInput(data, path);
  if (!st) return;
  for (const auto& m : st->metrics) evaluateStatistics(m);
  evaluateLuaMetrics(*st, path);
}

void profile(std::string_view data) {
  if (data.empty()) return;
  const auto mode = static_cast<unsigned char>(data.front());
  data.remove_prefix(1);
  const int format = mode & 3;
  const auto units =
      (mode & 4) != 0 ? profiles::LengthUnit::Metre : profiles::LengthUnit::Millimetre;
  profiles::ProfileReadOptions opt;
  opt.smoothingLength = (mode & 8) != 0 ? 1e-3 : 0.0;
  opt.mirrorY = (mode & 16) != 0;
  opt.rotate = (mode & 32) != 0 ? -std::atan(1.0 / 40.0) : 0.0;
  opt.r0 = (mode & 64) != 0 ? 0.0 : 0.46;
  opt.maxSlope = (mode & 128) != 0 ? 2.0 : 10.0;
  try {
    const profiles::ProfilePoints pts =
        format == 0   ? profiles::parseSimpackPoints(data, "fuzz.prw")
        : format == 1 ? profiles::parseSimpackPoints(data, "fuzz.prr")
        : format == 2
            ? profiles::parseTextPoints(data, "fuzz.txt", profiles::ProfileKind::Wheel, units)
            : profiles::parseTextPoints(data, "fuzz.txt", profiles::ProfileKind::Rail, units);
    touchProfile(profiles::profileFromPoints(pts, opt, "fuzz"));
  } catch (const InputError&) {
  }
}

void irregularityCsv(std::string_view data) {
  Diagnostics diags;
  std::optional<track::IrregularityTable> table;
  try {
    table = parseCsv(data, diags);
  } catch (const InputError&) {
    return;
  }
  if (!table || !diags.empty()) return;
  const track::Irregularities irr(std::move(*table), 0.75);
  volatile double sink = 0.0;
  const double a = irr.sBegin(), b = irr.sEnd();
  for (int i = -1; i <= 9; ++i) sink = sink + irr.at(a + (b - a) * i / 8.0).delta;
  (void)sink;
}

void tables(std::string_view data) {
  (void)loadTable(data);
}

bool loadTable(std::string_view data) {
  if (data.empty()) return false;
  const auto mode = static_cast<unsigned char>(data.front());
  data.remove_prefix(1);
  const bool kec = (mode & 1) != 0;
  const std::string file = (mode & 2) != 0 ? wrapPayload(kec, data) : std::string(data);
  const std::string path = scratch().write(kec ? "fuzz.kec" : "fuzz.lut", file);
  if (kec) {
    const auto t = contact::loadKec(path, seedTableConfig());
    if (t) touchKec(*t);
    return t.has_value();
  }
  const auto t = contact::loadLut(path, seedTableConfig());
  if (t) touchLut(*t);
  return t.has_value();
}

const contact::ContactGeometryConfig& seedTableConfig() {
  static const contact::ContactGeometryConfig config = [] {
    const double r0 = 0.46;
    const auto pos = profiles::positionS1002On60E1(1.360, 1.435, r0, 1.0 / 40.0);
    contact::ContactGeometryConfig c;
    c.left_wheel =
        std::make_shared<const profiles::Profile>(profiles::s1002Wheel(r0, profiles::Side::Left));
    c.right_wheel =
        std::make_shared<const profiles::Profile>(profiles::s1002Wheel(r0, profiles::Side::Right));
    c.left_rail =
        std::make_shared<const profiles::Profile>(profiles::rail60E1(profiles::Side::Left));
    c.right_rail =
        std::make_shared<const profiles::Profile>(profiles::rail60E1(profiles::Side::Right));
    c.wheel_lw = pos.Lw;
    c.rail_lr = pos.Lr;
    c.beta = pos.beta;
    c.r0 = r0;
    // Coarse grids keep the seeds a few kilobytes.
    c.lut_y = {-0.008, 0.008, 2e-3};
    c.lut_gauge = {-1e-3, 1e-3, 1e-3};
    c.kec_s = {-0.012, 0.012, 1e-3};
    return c;
  }();
  return config;
}

EntryPoint entryPoint(const std::string& harness) {
  if (harness == "scenario") return &scenario;
  if (harness == "profile") return &profile;
  if (harness == "csv") return &irregularityCsv;
  if (harness == "tables") return &tables;
  if (harness == "study") return &study;
  if (harness == "metric") return &metric;
  if (harness == "result") return &resultFiles;
  return nullptr;
}

}  // namespace rb::fuzz
