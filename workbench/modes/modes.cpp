#include "workbench/modes/modes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/rails_along_track.hpp"
#include "workbench/io/modes_file.hpp"
#include "workbench/stability/scene.hpp"
#include "workbench/stability/stability.hpp"
#include "workbench/study/option_checks.hpp"

namespace fs = std::filesystem;

namespace rb::modes {

namespace {

constexpr int kMaxSpeeds = 200;

[[noreturn]] void badSpeeds(const std::string& why) {
  throw InputError({"--speeds", 0}, "--speeds " + why);
}

double speedNumber(const std::string& text) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    badSpeeds("expects a:b:n (speeds in m/s, n an integer), got '" + text + "'");
  }
  if (used != text.size() || !std::isfinite(v))
    badSpeeds("expects a:b:n (speeds in m/s, n an integer), got '" + text + "'");
  return v;
}

// "a:b:n" -> n speeds from a to b (n = 1: a alone).
std::vector<double> parseSpeeds(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string p; std::getline(ss, p, ':');) parts.push_back(p);
  if (parts.size() != 3 || text.back() == ':')
    badSpeeds("expects a:b:n (e.g. 20:90:15), got '" + text + "'");
  const double a = speedNumber(parts[0]);
  const double b = speedNumber(parts[1]);
  const double nd = speedNumber(parts[2]);
  if (!(a > 0.0)) badSpeeds("a must be > 0 m/s, got " + parts[0]);
  if (!(b >= a)) badSpeeds("b must be >= a, got " + parts[1]);
  if (b > study::kMaxOptionSpeed)
    badSpeeds("b must be at most " + formatNumber(study::kMaxOptionSpeed) +
              " m/s (the range of vehicle.speed), got " + parts[1]);
  if (nd != std::floor(nd) || nd < 1.0) badSpeeds("n must be an integer >= 1, got " + parts[2]);
  if (nd > kMaxSpeeds)
    badSpeeds("n must be at most " + std::to_string(kMaxSpeeds) + ", got " + parts[2]);
  const int n = static_cast<int>(nd);
  if (n > 1 && b == a) badSpeeds("b must be > a when n > 1");
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(n == 1 ? a : a + (b - a) * i / (n - 1));
  return v;
}

io::ModesAtSpeed toFile(const stability::Analysis& a) {
  io::ModesAtSpeed s;
  s.speed = a.speed;
  for (const auto& c : a.coordinates) s.coordinates.push_back(c.name);
  for (const auto& m : a.modes) {
    s.re.push_back(m.eigenvalue.real());
    s.im.push_back(m.eigenvalue.imag());
    s.frequency.push_back(m.frequency_hz);
    s.damping.push_back(m.damping_ratio);
    s.step_change.push_back(m.step_change);
    s.labels.push_back(m.label);
    s.dominant.push_back(m.dominant);
    s.hunting.push_back(m.hunting ? 1.0 : 0.0);
    s.unstable.push_back(stability::unstable(m) ? 1.0 : 0.0);
    s.participation.insert(s.participation.end(), m.participation.begin(), m.participation.end());
  }
  s.residual = a.steady.residual;
  s.residual_raw = a.steady.residual_raw;
  s.max_ws_lateral = a.steady.max_ws_lateral;
  s.iterations = a.steady.iterations;
  s.fallback = a.steady.fallback;
  s.states = a.states;
  s.rhs_evaluations = a.rhs_evaluations;
  s.step_check = a.step_check;
  s.step_check_ok = a.step_check_ok;
  s.hunting_damping = a.huntingDamping();
  s.least_damping = a.leastDamping();
  s.cpu_s = a.cpu_s;
  return s;
}

void writeCsv(const std::string& path, const std::vector<stability::Analysis>& all) {
  std::ofstream f(path);
  f << "speed_m_s,mode,re_1_s,im_1_s,frequency_hz,damping_ratio,label,dominant,hunting,"
       "step_change,unstable\n";
  f.precision(10);
  for (const auto& a : all)
    for (std::size_t i = 0; i < a.modes.size(); ++i) {
      const auto& m = a.modes[i];
      f << a.speed << "," << i << "," << m.eigenvalue.real() << "," << m.eigenvalue.imag() << ","
        << m.frequency_hz << "," << m.damping_ratio << "," << m.label << "," << m.dominant << ","
        << (m.hunting ? 1 : 0) << "," << m.step_change << "," << (stability::unstable(m) ? 1 : 0)
        << "\n";
    }
  if (!f) throw InputError({path, 0}, "cannot write the modes table");
}

// "V m/s: mode; mode" naming every unstable mode at one speed ("" when none).
std::string unstableLine(const stability::Analysis& a) {
  std::string s;
  for (std::size_t i : a.unstableModes())
    s += (s.empty() ? "" : "; ") + stability::describe(a.modes[i]);
  if (s.empty()) return s;
  return formatNumber(a.speed) + " m/s: " + s;
}

// The body modes below 30 Hz (the stiff creep and series modes are in the files), and every
// unstable mode whatever its kind or frequency.
void printSpeed(const stability::Analysis& a) {
  std::printf(
      "\nV = %.2f m/s (%s, %s, spin %s): steady residual %.2e (%d Newton iterations%s), max |ws "
      "y| %.2e m, step check %.2e (%s), %ld rhs, %.2f s CPU\n",
      a.speed, a.method.c_str(), a.creep.c_str(), a.spin.c_str(), a.steady.residual,
      a.steady.iterations, a.steady.fallback ? ", after a BDF settle" : "", a.steady.max_ws_lateral,
      a.step_check, a.step_check_ok ? "passed" : "FAILED", a.rhs_evaluations, a.cpu_s);
  std::printf("  %-34s %10s %10s %9s  %s\n", "mode", "f [Hz]", "zeta [-]", "Re [1/s]", "dominant");
  for (const auto& m : a.modes) {
    const bool bad = stability::unstable(m);
    if (!bad && (!m.oscillatory || m.frequency_hz >= 30.0)) continue;
    std::printf("  %-34s %10.3f %10.4f %9.3f  %s%s\n", m.label.c_str(), m.frequency_hz,
                m.damping_ratio, m.eigenvalue.real(), m.dominant.c_str(), bad ? "  UNSTABLE" : "");
  }
  const std::size_t n = a.unstableModes().size();
  if (n == 0)
    std::printf("  every mode damped\n");
  else
    std::printf("  %zu unstable mode%s at %.2f m/s\n", n, n == 1 ? "" : "s", a.speed);
}

io::ModesSummary summaryOf(const stability::CriticalSpeed& c, const stability::Analysis& first,
                           const std::string& scenario, bool sweep) {
  io::ModesSummary s;
  s.method = first.method;
  s.creep = first.creep;
  s.spin = first.spin;
  s.scenario = scenario;
  s.notes = first.notes;
  s.cpu_s = c.cpu_s;
  s.rhs_evaluations = c.rhs_evaluations;
  for (const auto& r : c.refinement) {
    if (!std::isfinite(r.leastDamping())) continue;  // no damped mode there: c.why says so
    s.refinement_speeds.push_back(r.speed);
    s.refinement_damping.push_back(r.leastDamping());
  }
  for (const auto& a : c.sweep)
    if (const std::string u = unstableLine(a); !u.empty()) s.unstable.push_back(u);
  s.critical_mode = c.mode;
  if (c.hunting_found) {
    s.hunting_speed = c.hunting_speed;
    std::ostringstream t;
    t << c.hunting_speed;
    s.hunting = t.str();
  } else {
    s.hunting = sweep ? c.hunting_why : "none in range (one speed: no sweep)";
  }
  if (c.found && !c.why.empty()) s.notes.push_back("linear critical speed: " + c.why);
  if (c.found) {
    s.critical_speed = c.speed;
    s.bracket_lo = c.bracket_lo;
    s.bracket_hi = c.bracket_hi;
    // -1 when unknown (no hunting mode at the nearest analysis): never NaN in the file.
    s.step_uncertainty = std::isfinite(c.step_uncertainty) ? c.step_uncertainty : -1.0;
    std::ostringstream t;
    t << c.speed;
    s.critical = t.str();
  } else if (c.below_range) {
    s.critical = c.why;
  } else {
    s.critical = sweep ? c.why : "none in range (one speed: no sweep)";
  }
  return s;
}

}  // namespace

namespace {

// The options that need no scenario, all at once, before anything is loaded or written.
void checkModesOptions(const ModesOptions& o) {
  Diagnostics d;
  if (!(o.fd_scale > 0.0) || !std::isfinite(o.fd_scale) || o.fd_scale > 1e3)
    study::badOption(d, "--fd-scale", o.fd_scale, "must be in (0, 1000]");
  if (!(o.distance >= 0.0) || !std::isfinite(o.distance))
    study::badOption(d, "--distance", o.distance, "must be a finite distance >= 0 m");
  study::checkJobs(d, o.jobs, true);
  if (!o.speeds.empty()) {
    try {
      (void)parseSpeeds(o.speeds);
    } catch (const InputError& e) {
      d.add(e);
    }
  }
  d.throwIfAny();
}

// The linearisation point must lie on the track: beyond its end the geometry is extrapolated
// (and the settling run of a curve integrates up to it before failing).
void checkDistance(const ModesOptions& o, const scenario::ScenarioSpec& spec) {
  if (o.distance <= 0.0) return;
  const double most = study::trackReach(spec);
  if (o.distance > most) {
    Diagnostics d;
    study::badOption(
        d, "--distance", o.distance,
        "puts the leading body beyond the end of the track (at most " + formatNumber(most) + " m)");
    d.throwIfAny();
  }
}

}  // namespace

int runModes(const ModesOptions& o) {
  checkModesOptions(o);
  std::vector<double> speeds;
  if (!o.speeds.empty()) speeds = parseSpeeds(o.speeds);
  const study::StudyOptions so = commandStudyOptions(o, "modes");
  const stability::StabilityScene scene =
      stability::loadStabilityScene(o.scenario, o.contact, o.overrides, o.root, so.out);
  if (speeds.empty()) speeds.push_back(scene.spec.vehicle.speed);
  if (!(speeds.front() > 0.0))
    throw InputError(scene.spec.vehicle.loc, "vehicle.speed must be > 0 for workbench modes");
  checkDistance(o, scene.spec);
  std::error_code ec;
  fs::create_directories(so.out, ec);
  if (ec) throw InputError({so.out, 0}, "cannot create the output folder: " + ec.message());
  stability::Options so_opts;
  so_opts.step_scale = o.fd_scale;
  so_opts.distance = o.distance;
  // A scene the analysis cannot take (rails along the track, a train with guided wheelsets) is an
  // input problem of the scene: nothing is run.
  if (dynamics::railsAlongTrack(scene.spec.profiles))
    throw InputError(scene.spec.profiles.loc,
                     "profiles: the rails change along the track (rail_slices / extra_rails): "
                     "there is no steady state to linearise about; run the scene instead");
  if (!scene.spec.contact.elastic.rail_support.empty())
    throw InputError(scene.spec.contact.elastic.loc,
                     "contact.elastic.rail_support (the track under the rail) is not part of the "
                     "modes analysis: remove it for the modes, or run the scene instead");
  std::optional<stability::Analyser> analyser;
  try {
    analyser.emplace(scene.spec, so_opts);
  } catch (const stability::Failure& e) {
    throw InputError({scene.file, 0}, e.what());
  }
  stability::Analyser& an = *analyser;
  std::vector<stability::Analysis> sweep;
  std::string failure;
  for (double v : speeds) {
    try {
      sweep.push_back(an.analyse(v));
      printSpeed(sweep.back());
    } catch (const stability::Failure& e) {
      failure = e.what();
      break;
    }
  }
  if (sweep.empty()) {
    std::fprintf(stderr, "workbench modes: %s\n", failure.c_str());
    return 2;
  }
  const bool swept = sweep.size() > 1;
  const stability::CriticalSpeed crit = stability::linearCriticalSpeed(an, std::move(sweep));
  std::vector<io::ModesAtSpeed> rows;
  for (const auto& a : crit.sweep) rows.push_back(toFile(a));
  const io::ModesSummary sum = summaryOf(crit, crit.sweep.front(), scene.file, swept);
  const std::string h5 = (fs::path(so.out) / "modes.h5").string();
  io::writeModesFile(h5, rows, sum);
  writeCsv((fs::path(so.out) / "modes.csv").string(), crit.sweep);
  // Every unstable mode of the sweep, then the linear critical speed: the lowest speed at which
  // any mode is unstable (a car-body mode can go before hunting), and the hunting modes' own.
  if (sum.unstable.empty()) {
    std::printf("\nunstable modes: none at the speeds analysed\n");
  } else {
    std::printf("\nunstable modes (every one, at every speed analysed):\n");
    for (const auto& u : sum.unstable) std::printf("  %s\n", u.c_str());
  }
  std::printf("linear critical speed (lowest speed with any unstable mode): %s%s\n",
              sum.critical.c_str(), crit.found ? " m/s" : "");
  if (!sum.critical_mode.empty())
    std::printf("  %s mode: %s\n", crit.found ? "first unstable" : "least damped unstable",
                sum.critical_mode.c_str());
  std::printf("hunting modes (wheelset/bogie hunting) unstable from: %s%s\n", sum.hunting.c_str(),
              crit.hunting_found ? " m/s" : "");
  std::printf("cost: %.2f s CPU, %lld rhs evaluations\nwrote %s\n", sum.cpu_s,
              static_cast<long long>(sum.rhs_evaluations), h5.c_str());
  if (crit.found && std::isfinite(crit.step_uncertainty))
    std::printf("finite-difference step: the critical speed moves by up to %.2g m/s (step check)\n",
                crit.step_uncertainty);
  if (crit.found && !crit.why.empty()) std::printf("note: %s\n", crit.why.c_str());
  if (!failure.empty()) {
    std::fprintf(stderr, "workbench modes: stopped: %s\n", failure.c_str());
    return 2;
  }
  if (o.no_plots) return 0;
  return study::runPlots(so, {"modes", so.out});
}

}  // namespace rb::modes
