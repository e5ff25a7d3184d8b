#include "workbench/critical_speed/critical_speed.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/critical_speed/runs.hpp"
#include "workbench/dynamics/rails_along_track.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/io/critical_speed_file.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/stability/scene.hpp"
#include "workbench/stability/stability.hpp"
#include "workbench/study/option_checks.hpp"

namespace fs = std::filesystem;

namespace rb::critical_speed {

namespace {

// Probes above the start speed when --from is not given: x 1.2 per probe reaches 2x the start
// in 4 probes, fine enough that the first hunting probe is within 20 % of the onset.
constexpr double kProbeFactor = 1.2;

// The ramp starts this far above the linear critical speed (the ramp-down method: run above it
// with a kick, then decelerate), where the kicked motion grows whatever the limit-cycle branch.
// Where the 5 mm kick lifts a wheel at that speed (the LUT wagon), findStart probes upwards from
// the scene's speed instead.
constexpr double kLinearMargin = 1.1;

// Bounds of the options (docs/stability.md, "Options and their limits"): every run is bounded
// in simulated time, the ramp's (start - end) / deceleration too.
constexpr double kMaxDuration = 600.0;       // [s] a constant-speed run
constexpr double kMinDeceleration = 0.05;    // [m/s^2] a ramp from 200 m/s lasts at most 4000 s
constexpr double kMaxDeceleration = 20.0;    // [m/s^2]
constexpr double kMinWindow = 0.05;          // [s] a window holds a hunting period or more
constexpr double kToleranceFraction = 1e-4;  // the finest tolerance / the highest speed
constexpr int kMaxBisections = 40;           // guard behind the tolerance bound

void refuse(const std::string& option, const std::string& message) {
  throw InputError(SourceLoc{option, 0}, option + " " + message);
}

// The speeds and the findings of one search.
struct Search {
  RunSetup setup;
  std::vector<KickedRun> runs;
  std::vector<std::string> findings;  // what could not be answered, with time and speed
  double start = 0.0;                 // [m/s] the start speed showing hunting (0: none)
  double end = 0.0;                   // [m/s]
  double ramp_critical = std::nan("");
  double bisection_critical = std::nan("");
  double bracket_low = std::nan("");
  double bracket_high = std::nan("");
  // [m/s] The linear critical speed of the hunting modes (workbench modes), when found: where the
  // search starts.
  double linear = std::nan("");
  LinearAnswer linear_all;  // the linear answer of every mode (the lowest unstable one)
  double ramp_start_amplitude = std::nan("");  // [m] largest window amplitude of the ramp
  double ramp_end_amplitude = std::nan("");    // [m] last window amplitude of the ramp
  double ramp_max_ratio = std::nan("");        // EN 14363: largest sliding rms / limit of the ramp
  // What a reader must know beside the answers: runs whose motion neither died out nor reached
  // the threshold (sustained small-amplitude oscillations), with speed and amplitude.
  std::vector<std::string> caveats;
};

std::string mps(double v) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << v << " m/s";
  return s.str();
}

std::string mm(double v) {
  return formatNumber(v * 1e3, 3) + " mm";
}

std::string runName(const std::string& kind, std::size_t index, double v) {
  std::ostringstream s;
  s << kind << "_" << std::setw(2) << std::setfill('0') << index << "_V" << std::fixed
    << std::setprecision(3) << v;
  return s.str();
}

// One line on a constant-speed run: the numbers behind its verdict under the criterion.
std::string describe(const KickedRun& r, bool en) {
  const bool unstable = runUnstable(r, en);
  std::ostringstream m;
  m << (unstable                ? "unstable"
        : r.verdict.small_cycle ? "NOT stable: sustained small-amplitude oscillation"
                                : "stable")
    << " (";
  if (en) m << "EN 14363 sliding rms / limit " << r.en_max_ratio << "; ";
  m << r.verdict.why << ")";
  return m.str();
}

// A failed run as a finding: what stopped it, with time and speed.
void noteFailure(Search& s, const KickedRun& r) {
  if (r.ok) return;
  std::ostringstream m;
  m << r.kind << " run from " << mps(r.v0) << " failed at t = " << r.t_reached
    << " s, V = " << mps(r.v_reached) << ": " << r.message;
  s.findings.push_back(m.str());
}

const KickedRun& constantRun(Search& s, const std::string& kind, double v, double duration) {
  KickedRun r = runKicked(s.setup, kind, runName(kind, s.runs.size(), v), v, 0.0, duration);
  noteFailure(s, r);
  if (r.verdict.small_cycle) {
    std::ostringstream m;
    m << kind << " run at " << mps(v) << ": sustained small-amplitude oscillation of "
      << mm(r.verdict.a_last) << " (amplitude ratio per window " << std::setprecision(3)
      << r.verdict.trend << "), below the " << mm(s.setup.threshold)
      << " threshold: counted as not hunting by the threshold, but not stable";
    s.caveats.push_back(m.str());
  }
  s.runs.push_back(std::move(r));
  return s.runs.back();
}

// The start speed with hunting: the probe at the start speed, then (without --from) higher
// speeds. Returns false when none hunts.
bool findStart(const CriticalSpeedOptions& o, const stability::StabilityScene& scene, Search& s) {
  const bool en = o.criterion == "en14363";
  if (o.from <= 0.0 && std::isfinite(s.linear) && kLinearMargin * s.linear <= o.max_speed) {
    const double v = kLinearMargin * s.linear;
    const KickedRun& r = constantRun(s, "probe", v, o.duration);
    std::cout << "probe at " << mps(v) << " (1.1 x the linear critical speed): "
              << (r.ok ? describe(r, en) : "failed: " + r.message) << "\n";
    // A failed run (the kick lifting a wheel at this speed) is no start for a ramp.
    if (r.ok && runUnstable(r, en)) {
      s.start = v;
      return true;
    }
    // Not a gap in the answer: the search goes on from below, and the run stays in /runs with
    // its message.
    if (!r.ok) s.findings.pop_back();
    std::cout << "probing upwards from the scene's speed instead\n";
  }
  double v = o.from > 0.0 ? o.from : defaultStartSpeed(scene);
  for (;;) {
    const KickedRun& r = constantRun(s, "probe", v, o.duration);
    std::cout << "probe at " << mps(v) << ": " << describe(r, en) << "\n";
    if (runUnstable(r, en)) {
      s.start = v;
      return true;
    }
    if (o.from > 0.0 || v * kProbeFactor > o.max_speed) break;
    v *= kProbeFactor;
  }
  s.findings.push_back("no hunting at V0 = " + mps(v) + ": start higher (--from" +
                       (o.from > 0.0 ? "" : ", --max-speed") + ")");
  return false;
}

void rampDown(const CriticalSpeedOptions& o, Search& s) {
  const double duration = (s.start - s.end) / o.deceleration;
  KickedRun r = runKicked(s.setup, "ramp", "ramp", s.start, -o.deceleration, duration);
  noteFailure(s, r);
  const RampVerdict v = o.criterion == "en14363" ? lastExceedance(r.en_speed, r.en_ratio)
                                                 : rampCriticalSpeed(r.windows, s.setup.threshold);
  if (!r.en_ratio.empty())
    s.ramp_max_ratio = *std::max_element(r.en_ratio.begin(), r.en_ratio.end());
  if (!r.windows.empty()) {
    s.ramp_start_amplitude = rampCriticalSpeed(r.windows, s.setup.threshold).start_amplitude;
    s.ramp_end_amplitude = r.windows.back().amplitude;
    // Below the threshold at the end but not died out: the ramp's answer is where the cycle
    // fell below the threshold, not where the motion ceased.
    if (s.ramp_end_amplitude >= kRestFraction * s.setup.threshold &&
        s.ramp_end_amplitude < s.setup.threshold) {
      std::ostringstream m;
      m << "ramp: at its end speed " << mps(s.end) << " the lateral motion is still "
        << mm(s.ramp_end_amplitude) << " (below the " << mm(s.setup.threshold)
        << " threshold, not died out)";
      s.caveats.push_back(m.str());
    }
  }
  if (v.found) {
    s.ramp_critical = v.critical_speed;
  } else if (v.hunting_at_end && r.ok) {
    s.findings.push_back("ramp: the limit cycle lives down to the end speed " + mps(s.end) +
                         ": the critical speed is lower (--to)");
  } else if (r.ok) {
    s.findings.emplace_back(
        o.criterion == "en14363"
            ? "ramp: the EN 14363 sliding rms stayed below its limit during the "
              "ramp (the start speed is too close to the critical speed: "
              "start higher)"
            : "ramp: no limit cycle above the threshold during the ramp");
  } else {
    s.findings.emplace_back("ramp: the run stopped before the limit cycle died");
  }
  s.runs.push_back(std::move(r));
}

void bisect(const CriticalSpeedOptions& o, Search& s) {
  const bool en = o.criterion == "en14363";
  double lo = s.end;
  double hi = s.start;
  const KickedRun& low = constantRun(s, "bracket", lo, o.duration);
  std::cout << "bracket low end " << mps(lo) << ": " << describe(low, en) << "\n";
  if (runUnstable(low, en)) {
    s.findings.push_back("bisection: hunting at the low end " + mps(lo) +
                         " of the bracket: the critical speed is lower (--to)");
    return;
  }
  for (int probes = 0; hi - lo > o.tolerance; ++probes) {
    const double mid = 0.5 * (lo + hi);
    // The options bound the tolerance, so this is a guard: never the same probe twice, never more
    // than kMaxBisections probes.
    if (!(mid > lo && mid < hi) || probes >= kMaxBisections) {
      s.findings.push_back("bisection: stopped after " + std::to_string(probes) +
                           " probes at a bracket of " + mps(hi - lo) + " (--tolerance " +
                           formatNumber(o.tolerance) + " m/s)");
      break;
    }
    const KickedRun& r = constantRun(s, "bisection", mid, o.duration);
    const bool unstable = runUnstable(r, en);
    std::cout << "bisection " << mps(mid) << ": " << describe(r, en) << "\n";
    (unstable ? hi : lo) = mid;
  }
  s.bracket_low = lo;
  s.bracket_high = hi;
  s.bisection_critical = 0.5 * (lo + hi);
}

io::CriticalSpeedRun record(const KickedRun& r, const std::string& name, bool en) {
  io::CriticalSpeedRun o;
  o.name = name;
  o.kind = r.kind;
  o.file = r.file;
  o.message = r.message;
  o.v0 = r.v0;
  o.acceleration = r.acceleration;
  o.duration = r.duration;
  o.t_reached = r.t_reached;
  o.v_reached = r.v_reached;
  o.cpu_s = r.cpu_s;
  o.rhs_evals = r.rhs_evals;
  o.steps = r.steps;
  o.ok = r.ok;
  o.unstable = runUnstable(r, en);
  o.a_first = r.verdict.a_first;
  o.a_mid = r.verdict.a_mid;
  o.a_last = r.verdict.a_last;
  o.trend = r.verdict.trend;
  o.state = r.kind == "ramp" ? std::string("ramp") : r.verdict.state();
  for (const auto& w : r.windows) {
    o.window_t0.push_back(w.t0);
    o.window_t1.push_back(w.t1);
    o.window_speed.push_back(w.speed);
    o.window_amplitude.push_back(w.amplitude);
  }
  o.has_en14363 = en;
  o.en14363_ratio = std::isfinite(r.en_max_ratio) ? r.en_max_ratio : 0.0;
  o.en_speed = r.en_speed;
  o.en_ratio = r.en_ratio;
  return o;
}

void addRamp(const KickedRun& r, io::CriticalSpeedResult& res) {
  res.ramp_speed = r.speed;
  res.ramp_y = r.y_lead;
  for (const auto& w : r.windows) {
    res.ramp_window_speed.push_back(w.speed);
    res.ramp_window_amplitude.push_back(w.amplitude);
  }
}

io::CriticalSpeedResult resultOf(const CriticalSpeedOptions& o,
                                 const stability::StabilityScene& scene, const Search& s) {
  io::CriticalSpeedResult res;
  const bool en = o.criterion == "en14363";
  res.text = {{"scenario", scene.file},
              {"method", o.method},
              {"criterion", o.criterion},
              {"contact", !scene.spec.has_contact                                     ? "guided"
                          : scene.spec.contact.method == dynamics::ContactMethod::Lut ? "lut"
                                                                                      : "kec"},
              {"status", s.findings.empty() ? "ok" : "incomplete"},
              {"findings", join(s.findings, "\n")},
              {"caveats", join(s.caveats, "\n")},
              {"linear_mode", s.linear_all.mode},
              {"linear_note", s.linear_all.note}};
  auto number = [&](const char* name, double v) {
    if (std::isfinite(v)) res.numbers.emplace_back(name, v);
  };
  number("critical_speed_ramp", s.ramp_critical);
  number("critical_speed_bisection", s.bisection_critical);
  number("critical_speed_linear", s.linear);
  number("critical_speed_linear_any_mode", s.linear_all.any);
  number("bracket_low", s.bracket_low);
  number("bracket_high", s.bracket_high);
  number("start_speed", s.start);
  number("end_speed", s.end);
  number("kick", o.kick);
  number("deceleration", o.deceleration);
  number("duration", o.duration);
  number("window", o.window);
  number("transient", o.transient);
  number("threshold", s.setup.threshold);
  number("decay", o.decay);
  number("tolerance", o.tolerance);
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const KickedRun& r = s.runs[k];
    const std::string name = r.kind == "ramp" ? "ramp" : runName(r.kind, k, r.v0);
    res.runs.push_back(record(r, name, en));
    if (r.kind == "ramp") {
      addRamp(r, res);
    } else {
      res.bisection_speed.push_back(r.v0);
      res.bisection_amplitude.push_back(r.verdict.a_last);
      res.bisection_unstable.push_back(runUnstable(r, en) ? 1.0 : 0.0);
      res.bisection_small.push_back(r.verdict.small_cycle ? 1.0 : 0.0);
    }
  }
  return res;
}

void writeCsv(const std::string& path, const Search& s, bool en) {
  std::ofstream f(path);
  f << "run,kind,v0,acceleration,ok,unstable,cpu_s,rhs_evals,window_t0,window_t1,speed,"
       "amplitude\n";
  f << std::setprecision(10);
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const KickedRun& r = s.runs[k];
    const std::string head = std::to_string(k) + "," + r.kind + "," + formatNumberExact(r.v0) +
                             "," + formatNumberExact(r.acceleration) + "," + (r.ok ? "1" : "0") +
                             "," + (runUnstable(r, en) ? "1" : "0") + ",";
    for (const auto& w : r.windows)
      f << head << r.cpu_s << "," << r.rhs_evals << "," << w.t0 << "," << w.t1 << "," << w.speed
        << "," << w.amplitude << "\n";
    if (r.windows.empty()) f << head << r.cpu_s << "," << r.rhs_evals << ",,,,\n";
  }
  if (!f) throw io::WriteError("cannot write " + path);
}

// The last constant-speed run at speed v (nullptr when none).
const KickedRun* runAt(const Search& s, double v) {
  const KickedRun* out = nullptr;
  for (const auto& r : s.runs)
    if (r.kind != "ramp" && r.v0 == v) out = &r;
  return out;
}

// What a constant-speed run was judged on: amplitude and verdict, or the EN 14363 ratio.
std::string judged(const KickedRun* r, bool en) {
  if (r == nullptr) return "no run";
  std::ostringstream m;
  m << "V " << mps(r->v0) << ": ";
  if (en)
    m << "EN 14363 sliding rms / limit " << r->en_max_ratio;
  else
    m << "last-window amplitude " << mm(r->verdict.a_last) << " (" << r->verdict.state() << ")";
  return m.str();
}

// Every answer the command computed, each with what it is, what to use it for, and the amplitude
// (or EN 14363 ratio) it was judged on against its threshold.
void printSummary(const CriticalSpeedOptions& o, const Search& s) {
  double cpu = 0.0;
  long evals = 0;
  for (const auto& r : s.runs) {
    cpu += r.cpu_s;
    evals += r.rhs_evals;
    std::cout << "  " << std::left << std::setw(9) << r.kind << " V0 " << mps(r.v0) << " a "
              << r.acceleration << " m/s^2, " << r.duration << " s: " << (r.ok ? "ok" : "FAILED")
              << ", CPU " << r.cpu_s << " s, " << r.rhs_evals << " rhs evaluations\n";
  }
  const bool en = o.criterion == "en14363";
  std::cout << "critical speed (" << o.criterion << " criterion, kick " << o.kick * 1e3 << " mm, "
            << (en ? std::string("sliding rms against its EN 14363 limit")
                   : "threshold " + mm(s.setup.threshold))
            << "):\n";
  if (std::isfinite(s.linear_all.any) || !s.linear_all.mode.empty()) {
    std::cout
        << "  linear, any mode (eigenvalues, workbench modes): "
        << (std::isfinite(s.linear_all.any) ? mps(s.linear_all.any) : s.linear_all.note)
        << "\n      the lowest speed at which a mode of the linearised vehicle on the centred "
           "track loses its damping"
        << (s.linear_all.mode.empty() ? "" : " (" + s.linear_all.mode + ")")
        << ";\n      use it for small-disturbance stability and design comparison; no "
           "amplitude is judged (eigenvalues: any small motion grows above it)\n";
  }
  if (std::isfinite(s.linear))
    std::cout << "  linear, hunting modes: " << mps(s.linear)
              << "\n      where the wheelset/bogie hunting modes lose their damping; the nonlinear "
                 "search starts above it;\n      hunting limit cycles can exist below it "
                 "(subcritical): it is no safe speed by itself\n";
  if (std::isfinite(s.ramp_critical))
    std::cout << "  ramp-down: " << mps(s.ramp_critical) << " (deceleration " << o.deceleration
              << " m/s^2 from " << mps(s.start) << ")\n      the speed at which the kicked "
              << (en ? "EN 14363 sliding rms fell below its limit"
                     : "limit cycle fell below the threshold")
              << " for the last time while decelerating;\n      use it as the nonlinear critical "
                 "speed (the lowest speed with sustained hunting); judged: "
              << (en ? "EN 14363 sliding rms / limit against 1 (largest " +
                           formatNumber(s.ramp_max_ratio, 3) + ")"
                     : "window amplitude " + mm(s.ramp_start_amplitude) +
                           " at the start against the threshold " + mm(s.setup.threshold) + ", " +
                           mm(s.ramp_end_amplitude) + " at the end")
              << "\n";
  if (std::isfinite(s.bisection_critical))
    std::cout << "  bisection: " << mps(s.bisection_critical) << " (bracket " << mps(s.bracket_low)
              << " .. " << mps(s.bracket_high)
              << ")\n      between the fastest constant-speed kicked run judged not hunting and "
                 "the slowest judged hunting;\n      use it to check the ramp (no deceleration "
                 "effect); judged: "
              << judged(runAt(s, s.bracket_low), en) << "; " << judged(runAt(s, s.bracket_high), en)
              << (en ? "" : "; threshold " + mm(s.setup.threshold)) << "\n";
  if (en)
    std::cout << "  the EN 14363 criterion (sliding rms of the bogie-frame lateral acceleration "
                 "against its limit) decided the ramp and the bisection: the answers are the "
                 "acceptance criterion's, for a report\n";
  for (const auto& f : s.findings) std::cout << "  finding: " << f << "\n";
  for (const auto& c : s.caveats) std::cout << "  caveat: " << c << "\n";
  std::cout << "runs: " << s.runs.size() << ", CPU " << cpu << " s, " << evals
            << " rhs evaluations\n";
}

void search(const CriticalSpeedOptions& o, const stability::StabilityScene& scene, Search& s) {
  if (!findStart(o, scene, s)) return;
  s.end = o.to > 0.0 ? o.to : 0.5 * s.start;
  if (s.end >= s.start) {
    s.findings.push_back("--to " + mps(s.end) + " is not below the start speed " + mps(s.start));
    return;
  }
  if (o.method != "bisection") rampDown(o, s);
  if (o.method != "ramp") bisect(o, s);
}

// The first run must fit on the scene's track: a --duration (or a ramp) that carries the vehicle
// beyond its end at the start speed is refused as the option, before any run (a later run at a
// higher probe speed that does not fit is a finding of the search).
void checkTrackReach(const CriticalSpeedOptions& o, const stability::StabilityScene& scene) {
  const double reach = study::trackReach(scene.spec);
  const double v0 = o.from_given ? o.from : defaultStartSpeed(scene);
  Diagnostics d;
  if (v0 * o.duration > reach)
    study::badOption(d, "--duration", o.duration,
                     "a constant-speed run at " + formatNumber(v0) + " m/s covers " +
                         formatNumber(v0 * o.duration) +
                         " m, beyond the end of the track (at most " + formatNumber(reach / v0) +
                         " s at that speed)");
  if (o.from_given && o.method != "bisection") {
    const double end = o.to_given ? o.to : 0.5 * o.from;
    const double ramp = (o.from * o.from - end * end) / (2.0 * o.deceleration);
    if (ramp > reach)
      study::badOption(d, "--deceleration", o.deceleration,
                       "the ramp from " + formatNumber(o.from) + " to " + formatNumber(end) +
                           " m/s covers " + formatNumber(ramp) +
                           " m, beyond the end of the track (at "
                           "most " +
                           formatNumber(reach) + " m)");
  }
  d.throwIfAny();
}

// The kick becomes an initial condition of the first wheelset: a kick beyond its flangeway is
// refused as --kick (with the largest admissible offset) before any run, on the first run's
// settings, not as the vehicle.initial key it becomes.
void checkKick(const CriticalSpeedOptions& o, const stability::StabilityScene& scene,
               const RunSetup& setup) {
  if (setup.first_wheelset.empty()) return;
  const double v0 = o.from_given ? o.from : defaultStartSpeed(scene);
  double duration = o.duration;
  if (setup.step_grid > 0.0)
    duration = std::ceil(duration / setup.step_grid - 1e-9) * setup.step_grid;
  std::vector<std::string> base = scene.overrides;
  base.push_back("vehicle.speed=" + formatNumberExact(v0));
  base.push_back("vehicle.acceleration=0");
  base.push_back("run.duration=" + formatNumberExact(duration));
  if (setup.drop_irregularities) base.emplace_back("run.effects.irregularities=false");
  study::ScenarioCommandOptions sc;
  sc.scenario = scene.file;
  sc.root = o.root;
  (void)checkOptionOverrides(
      sc, base,
      {{"--kick", formatNumber(o.kick),
        "vehicle.initial." + setup.first_wheelset + ".y=" + formatNumberExact(o.kick)}});
}

bool hasBogie(const stability::StabilityScene& scene) {
  for (const auto& b : scene.spec.vehicle.bodies)
    if (b.kind == vehicle::BodyKind::Bogie) return true;
  return false;
}

bool complete(const CriticalSpeedOptions& o, const Search& s) {
  const bool ramp = o.method == "bisection" || std::isfinite(s.ramp_critical);
  const bool bis = o.method == "ramp" || std::isfinite(s.bisection_critical);
  return ramp && bis;
}

}  // namespace

double thresholdOf(const CriticalSpeedOptions& o, bool irregular_track) {
  if (o.threshold) return *o.threshold;
  return irregular_track ? 1e-3 : 1e-4;
}

double defaultStartSpeed(const stability::StabilityScene& scene) {
  // A scene at rest (speed 0 with a run.duration) would probe 0 m/s forever: start at 10 m/s.
  return std::max(scene.spec.vehicle.speed, 10.0);
}

LinearAnswer linearCriticalSpeed(const stability::StabilityScene& scene, double max_speed,
                                 const std::string& table_cache) {
  LinearAnswer out;
  if (!scene.spec.has_contact || max_speed <= 10.0) return out;
  stability::Options so;
  so.table_cache = table_cache;
  try {
    // The sweep of `workbench modes` (10 m/s steps up to the probe limit), refined to 0.1 m/s.
    const int n = std::max(2, static_cast<int>(std::ceil((max_speed - 10.0) / 10.0)) + 1);
    const stability::CriticalSpeed c =
        stability::linearCriticalSpeed(scene.spec, 10.0, max_speed, n, so, 0.1);
    if (c.found) out.any = c.speed;
    out.mode = c.mode;
    if (!c.found) out.note = c.why;
    if (c.hunting_found)
      out.hunting = c.hunting_speed;
    else
      out.hunting_note = "linear critical speed of the hunting modes: " + c.hunting_why;
  } catch (const stability::Failure& e) {
    out.note = e.what();
    out.hunting_note = std::string("linear critical speed: ") + e.what();
  }
  return out;
}

void checkCriticalSpeedOptions(const CriticalSpeedOptions& o) {
  Diagnostics d;
  // A speed option given as 0 is no default: 0 m/s (or less) never hunts.
  auto speed = [&](const std::string& option, double v) {
    if (!(std::isfinite(v) && v > 0.0 && v <= study::kMaxOptionSpeed))
      study::badOption(d, option, v,
                       "must be a speed in (0, " + formatNumber(study::kMaxOptionSpeed) +
                           "] m/s (the range of vehicle.speed)");
  };
  auto positive = [&](const std::string& option, double v, double lo, double hi,
                      const std::string& unit) {
    if (!(std::isfinite(v) && v >= lo && v <= hi))
      study::badOption(d, option, v,
                       "must be in [" + formatNumber(lo) + ", " + formatNumber(hi) + "] " + unit);
  };
  if (o.from_given) speed("--from", o.from);
  if (o.to_given) speed("--to", o.to);
  if (o.from_given && o.to_given && o.from > 0.0 && o.to >= o.from)
    study::badOption(d, "--to", o.to, "must be below --from (" + formatNumber(o.from) + " m/s)");
  speed("--max-speed", o.max_speed);
  positive("--deceleration", o.deceleration, kMinDeceleration, kMaxDeceleration, "m/s^2");
  positive("--window", o.window, kMinWindow, kMaxDuration / 3.0, "s");
  if (o.threshold) positive("--threshold", *o.threshold, 1e-7, 0.02, "m");
  // The bracket is bisected down to the tolerance: one far below the speed's resolution repeats
  // one probe forever, so it is bounded relative to the highest speed of the search.
  const double top = o.from_given ? o.from : o.max_speed;
  const double finest = kToleranceFraction * (std::isfinite(top) && top > 0.0 ? top : 1.0);
  positive("--tolerance", o.tolerance, finest, study::kMaxOptionSpeed, "m/s");
  if (!(std::isfinite(o.kick) && o.kick != 0.0 && std::abs(o.kick) <= 0.02))
    study::badOption(
        d, "--kick", o.kick,
        "must be a lateral offset with 0 < |kick| <= 0.02 m (the first run then checks it "
        "against the flangeway)");
  if (!(std::isfinite(o.transient) && o.transient >= 0.0 && o.transient <= kMaxDuration))
    study::badOption(d, "--transient", o.transient,
                     "must be in [0, " + formatNumber(kMaxDuration) + "] s");
  if (!(std::isfinite(o.decay) && o.decay > 0.0 && o.decay <= 1.0))
    study::badOption(d, "--decay", o.decay, "must be in (0, 1]");
  if (!(std::isfinite(o.duration) && o.duration > 0.0 && o.duration <= kMaxDuration))
    study::badOption(
        d, "--duration", o.duration,
        "must be in (0, " + formatNumber(kMaxDuration) + "] s (one constant-speed run)");
  else if (o.duration < o.transient + 3.0 * o.window)
    study::badOption(d, "--duration", o.duration,
                     "must hold the transient and at least 3 windows (--transient + 3 --window = " +
                         formatNumber(o.transient + 3.0 * o.window) + " s)");
  study::checkJobs(d, o.jobs, true);
  d.throwIfAny();
}

int runCriticalSpeed(const CriticalSpeedOptions& o) {
  checkCriticalSpeedOptions(o);
  const study::StudyOptions so = commandStudyOptions(o, "critical_speed");
  const stability::StabilityScene scene =
      stability::loadStabilityScene(o.scenario, o.contact, o.overrides, o.root, so.out);
  // Its runs ramp one vehicle's speed (vehicle.speed, vehicle.acceleration); `workbench modes`
  // gives a train's linear stability.
  scenario::refuseTrain(scene.spec, "critical-speed");
  if (!scene.spec.has_vehicle) refuse(o.scenario, "has no vehicle");
  // Its runs need a track that is the same everywhere along the ramp.
  if (dynamics::railsAlongTrack(scene.spec.profiles))
    refuse(o.scenario,
           "has rails that change along the track (profiles.rail_slices / extra_rails): a "
           "critical speed needs the same rails everywhere along its runs");
  if (o.criterion == "en14363" && !hasBogie(scene))
    refuse("--criterion",
           "en14363 needs a bogie frame (EN 14363 bogie-frame acceleration); the "
           "vehicle has none");
  if (o.irregular && scene.spec.track.irregularities.source == track::IrregularitySource::None)
    refuse("--irregular", "given, but the scene has no track irregularities");
  checkTrackReach(o, scene);
  Search s;
  s.setup.scenario = scene.file;
  s.setup.overrides = scene.overrides;
  s.setup.root = o.root;
  s.setup.table_cache = (fs::path(so.out) / ".table-cache").string();
  s.setup.run_dir = (fs::path(so.out) / "runs").string();
  s.setup.kick = o.kick;
  for (const auto& b : scene.spec.vehicle.bodies)
    if (b.kind == vehicle::BodyKind::Wheelset && s.setup.first_wheelset.empty())
      s.setup.first_wheelset = b.name;
  s.setup.drop_irregularities =
      !o.irregular && scene.spec.track.irregularities.source != track::IrregularitySource::None;
  s.setup.en14363 = o.criterion == "en14363";
  s.setup.window = o.window;
  s.setup.transient = o.transient;
  s.setup.threshold = thresholdOf(o, o.irregular);
  s.setup.decay = o.decay;
  if (integ::isFixedStep(scene.spec.solver.method)) s.setup.step_grid = scene.spec.solver.step;
  checkKick(o, scene, s.setup);
  if (o.from <= 0.0) {
    s.linear_all = linearCriticalSpeed(scene, o.max_speed, s.setup.table_cache);
    s.linear = s.linear_all.hunting;
    if (!s.linear_all.hunting_note.empty())
      std::cout << s.linear_all.hunting_note << "; the start is probed from the scene's speed\n";
    // A mode other than hunting loses its damping first: the nonlinear answers below are the
    // hunting limit, and the vehicle is not stable below them.
    const bool earlier = !std::isfinite(s.linear_all.any) || !std::isfinite(s.linear) ||
                         s.linear_all.any < s.linear - 1e-9;
    if (!s.linear_all.mode.empty() && earlier)
      s.caveats.push_back("linear: a mode is unstable below the hunting speed (" +
                          s.linear_all.mode +
                          "): the ramp and bisection answers are the hunting limit, not the "
                          "lower end of a stable range");
  }
  try {
    search(o, scene, s);
  } catch (const InputError& e) {
    if (s.runs.empty()) throw;  // the scene refused the first run: nothing ran
    s.findings.push_back(std::string("a run was refused: ") + e.what());
  }
  const std::string h5 = (fs::path(so.out) / "critical_speed.h5").string();
  io::writeCriticalSpeedFile(h5, resultOf(o, scene, s));
  writeCsv((fs::path(so.out) / "critical_speed.csv").string(), s, s.setup.en14363);
  printSummary(o, s);
  std::cout << "wrote " << h5 << "\n";
  // The figure also shows what an incomplete search found; it never decides the exit code
  // beyond 4 (only the figure failed).
  const int plots = o.no_plots ? 0 : study::runPlots(so, {"critical-speed", so.out});
  // Any finding (a failed run among them: it may have decided a bisection step) makes the
  // answer incomplete: exit 2, as the file's status says.
  return complete(o, s) && s.findings.empty() ? plots : 2;
}

}  // namespace rb::critical_speed
