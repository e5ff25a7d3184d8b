#include "workbench/run/assessment_run.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "workbench/assessment/signal.hpp"
#include "workbench/assessment/sperling.hpp"
#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"

namespace rb::run {
namespace {

namespace a14 = assessment::en14363;
namespace a12 = assessment::en12299;
using assessment::Check;

constexpr const char* kEn14363 = "EN 14363:2005 / UIC 518";
constexpr double kInf = std::numeric_limits<double>::infinity();
// Range searched for the instability frequency when the scenario gives none: the hunting of
// bogie vehicles at service speeds lies there (EN 14363 asks for f0 from the measured signal).
constexpr double kF0Low = 3.0, kF0High = 9.0, kF0Step = 0.05;  // [Hz]

std::string wheelName(const WheelSignals& w) {
  return w.wheelset + " " + w.side;
}

// The position of the largest |value| of a distance series (NaN when empty).
double positionOfMaxAbs(const assessment::DistanceSeries& s) {
  double best = -1.0, at = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < s.value.size(); ++k)
    if (std::abs(s.value[k]) > best) {
      best = std::abs(s.value[k]);
      at = s.position[k];
    }
  return at;
}

// Keeps the largest value of one summary key (a new key is appended).
void summarize(std::vector<SummaryItem>& items, const std::string& key, const std::string& unit,
               const Assessed& a) {
  for (auto& it : items)
    if (it.key == key) {
      if (a.check.value > it.a.check.value || (!a.check.ok() && it.a.check.ok())) it.a = a;
      return;
    }
  items.push_back({key, unit, a});
}

Assessed assessed(const Check& c, const char* unit, const std::string& clause,
                  const std::string& where,
                  double at_s = std::numeric_limits<double>::quiet_NaN()) {
  return {c, unit, clause, where, at_s};
}

// The distance series shifted by a body's offset: its own arc length at every sample [m].
std::vector<double> ownDistance(const AssessmentSignals& sig, double s_offset) {
  std::vector<double> s(sig.distance);
  for (double& x : s) x += s_offset;
  return s;
}

WheelSafety wheelSafety(const WheelSignals& w, const AssessmentSignals& sig,
                        const assessment::AssessmentSpec& spec, double mu) {
  WheelSafety r;
  const double dt = sig.dt;
  r.s = ownDistance(sig, w.s_offset);
  const std::vector<double>& s = r.s;
  // Y and Q filtered once for every quantity of the wheel.
  a14::FilteredWheelForces f = a14::filterWheelForces(w.Y, w.Q, dt);
  r.y_over_q = a14::derailmentQuotient(f, s, spec.yq_limit);
  r.nadal_limit = a14::nadalLimit(spec.flange_angle, mu);
  r.nadal_mu = mu;
  r.yq = assessed(r.y_over_q.check, "-", std::string(kEn14363) + ": (Y/Q)_2m, 2 m sliding mean",
                  wheelName(w), positionOfMaxAbs(r.y_over_q.series));
  const std::vector<double>& qf = f.Q;
  r.dq_series.resize(qf.size());
  std::size_t kmax = 0;
  for (std::size_t k = 0; k < qf.size(); ++k) {
    r.dq_series[k] = (w.q0 - qf[k]) / w.q0;
    if (r.dq_series[k] > r.dq_series[kmax]) kmax = k;
  }
  r.dq =
      assessed(a14::wheelUnloading(f, w.q0), "-", std::string(kEn14363) + ": wheel unloading dQ/Q0",
               wheelName(w), qf.empty() ? std::numeric_limits<double>::quiet_NaN() : s[kmax]);
  r.y_qst =
      assessed(a14::quasiStaticGuidingForce(f), "N",
               std::string(kEn14363) + ": quasi-static guiding force Y_qst (50 %)", wheelName(w));
  r.q_qst =
      assessed(a14::quasiStaticWheelForce(f), "N",
               std::string(kEn14363) + ": quasi-static wheel force Q_qst (50 %)", wheelName(w));
  r.q_max = assessed(a14::maximumWheelForce(f, w.q0), "N",
                     std::string(kEn14363) + ": maximum wheel force Q (99.85 %), 90 kN + Q0",
                     wheelName(w));
  r.y_filtered = std::move(f.Y);
  r.q_filtered = std::move(f.Q);
  return r;
}

// ---- per section ------------------------------------------------------------------------------

// The samples k with from <= s[k] < to.
std::vector<double> within(const std::vector<double>& x, const std::vector<double>& s, double from,
                           double to) {
  std::vector<double> out;
  for (std::size_t k = 0; k < x.size() && k < s.size(); ++k)
    if (s[k] >= from && s[k] < to) out.push_back(x[k]);
  return out;
}

// A sliding-mean quantity over the windows lying wholly in [from, to]: max(|F1|, |F2|) of them
// against `limit` and where the largest |value| is; value NaN when no window fits.
Assessed slidingInSection(const assessment::DistanceSeries& series, double from, double to,
                          double limit, const char* unit, const std::string& clause,
                          const std::string& where) {
  std::vector<double> v;
  double best = -1.0, at = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < series.value.size(); ++k) {
    const double p = series.position[k];
    if (p < from + a14::kSlidingWindow - 1e-9 || p > to + 1e-9) continue;
    v.push_back(series.value[k]);
    if (std::abs(series.value[k]) > best) {
      best = std::abs(series.value[k]);
      at = p;
    }
  }
  if (v.empty())
    return assessed(assessment::check(std::numeric_limits<double>::quiet_NaN(), limit), unit,
                    clause, where);
  const a14::Extremes e = a14::extremes(v);
  return assessed(assessment::check(std::max(std::abs(e.upper), std::abs(e.lower)), limit), unit,
                  clause, where, at);
}

SectionWheel sectionWheel(const WheelSignals& w, const WheelSafety& ws,
                          const assessment::AssessmentSpec& spec,
                          const assessment::TrackSection& sec) {
  SectionWheel r;
  const std::vector<double>& s = ws.s;
  const double lo = std::max(sec.from, s.front()), hi = std::min(sec.to, s.back());
  if (hi - lo < a14::kSlidingWindow) return r;  // this wheel did not run through the section
  r.assessed = true;
  const std::string name = wheelName(w);
  r.yq = slidingInSection(ws.y_over_q.series, sec.from, sec.to, spec.yq_limit, "-",
                          std::string(kEn14363) + ": (Y/Q)_2m, 2 m sliding mean", name);
  const std::vector<double> dq = within(ws.dq_series, s, sec.from, sec.to);
  const std::vector<double> pos = within(s, s, sec.from, sec.to);
  std::size_t kmax = 0;
  for (std::size_t k = 1; k < dq.size(); ++k)
    if (dq[k] > dq[kmax]) kmax = k;
  r.dq = assessed(assessment::check(dq[kmax], a14::kWheelUnloadingLimit), "-",
                  std::string(kEn14363) + ": wheel unloading dQ/Q0", name, pos[kmax]);
  const std::vector<double> q = within(ws.q_filtered, s, sec.from, sec.to);
  r.q_max =
      assessed(assessment::check(assessment::percentile(q, a14::kUpperPercentile), 90e3 + w.q0),
               "N", std::string(kEn14363) + ": maximum wheel force Q (99.85 %), 90 kN + Q0", name);
  r.quasi_static = assessment::hasQuasiStatic(sec.kind);
  if (r.quasi_static) {
    const std::vector<double> y = within(ws.y_filtered, s, sec.from, sec.to);
    r.y_qst =
        assessed(assessment::check(std::abs(assessment::percentile(y, a14::kMedianPercentile)),
                                   a14::kQuasiStaticGuidingLimit),
                 "N", std::string(kEn14363) + ": quasi-static guiding force Y_qst (50 %)", name);
    r.q_qst =
        assessed(assessment::check(assessment::percentile(q, a14::kMedianPercentile),
                                   a14::kQuasiStaticWheelLimit),
                 "N", std::string(kEn14363) + ": quasi-static wheel force Q_qst (50 %)", name);
  }
  return r;
}

// Keeps the worst of one key among the section's wheels (NaN values are not assessed).
void worst(std::vector<SummaryItem>& items, const std::string& key, const std::string& unit,
           const Assessed& a) {
  if (!std::isnan(a.check.value)) summarize(items, key, unit, a);
}

SectionResult assessSection(const AssessmentSignals& sig, const assessment::AssessmentSpec& spec,
                            const assessment::TrackSection& sec, const AssessmentResult& r) {
  SectionResult out;
  out.section = sec;
  const double lead_lo = std::max(sec.from, sig.distance.front());
  const double lead_hi = std::min(sec.to, sig.distance.back());
  out.covered = std::max(0.0, lead_hi - lead_lo);
  for (std::size_t k = 0; k < sig.wheels.size(); ++k) {
    out.wheels.push_back(sectionWheel(sig.wheels[k], r.wheel_safety[k], spec, sec));
    const SectionWheel& w = out.wheels.back();
    if (!w.assessed) continue;
    worst(out.summary, "y_over_q", "-", w.yq);
    worst(out.summary, "dq_over_q", "-", w.dq);
    worst(out.summary, "q_max", "N", w.q_max);
    if (w.quasi_static) {
      worst(out.summary, "y_qst", "N", w.y_qst);
      worst(out.summary, "q_qst", "N", w.q_qst);
    }
  }
  for (const auto& ws : r.wheelset_safety) {
    out.sum_y.push_back(slidingInSection(ws.sum_y.series, sec.from, sec.to, ws.sum_y.check.limit,
                                         "N", ws.sy.clause, ws.wheelset));
    worst(out.summary, "sum_y", "N", out.sum_y.back());
  }
  if (out.summary.empty())
    out.notes.push_back("section " + sec.name + ": no wheel ran 2 m through it; not assessed");
  return out;
}

// The sections of a run: the given ones, or one covering the whole run.
std::vector<assessment::TrackSection> sectionsOf(const AssessmentSignals& sig) {
  if (!sig.sections.empty()) return sig.sections;
  assessment::TrackSection whole;
  whole.name = "run";
  whole.kind = assessment::SectionKind::Given;
  whole.from = -std::numeric_limits<double>::infinity();
  whole.to = std::numeric_limits<double>::infinity();
  whole.radius = whole.cant = std::numeric_limits<double>::quiet_NaN();
  whole.zone = assessment::TestZone::None;
  return {whole};
}

void assessSafety(const AssessmentSignals& sig, const assessment::AssessmentSpec& spec, double mu,
                  AssessmentResult& r) {
  if (sig.distance.back() - sig.distance.front() < a14::kSlidingWindow) {
    r.notes.push_back("safety: the run is shorter than the 2 m sliding window; not assessed");
    r.spec.safety = false;
    return;
  }
  for (const auto& w : sig.wheels) r.wheel_safety.push_back(wheelSafety(w, sig, spec, mu));
  for (std::size_t k = 0; k + 1 < sig.wheels.size(); k += 2) {
    const auto& l = sig.wheels[k];
    const auto& rr = sig.wheels[k + 1];
    WheelsetSafety ws;
    ws.wheelset = l.wheelset;
    ws.q0 = 0.5 * (l.q0 + rr.q0);
    ws.sum_y = a14::trackShiftForce(l.y_track, rr.y_track, ownDistance(sig, l.s_offset), sig.dt,
                                    ws.q0, r.spec.alpha);
    ws.sy = assessed(ws.sum_y.check, "N",
                     std::string(kEn14363) + ": track shift force (sum Y)_2m, Prud'homme",
                     ws.wheelset, positionOfMaxAbs(ws.sum_y.series));
    r.wheelset_safety.push_back(std::move(ws));
  }
  // EN 14363 evaluates per track section: the summary is the worst section, named in `where`.
  bool quasi_static = false;
  for (const auto& sec : sectionsOf(sig)) {
    r.sections.push_back(assessSection(sig, spec, sec, r));
    const SectionResult& sr = r.sections.back();
    for (const auto& n : sr.notes) r.notes.push_back("safety: " + n);
    for (SummaryItem it : sr.summary) {
      quasi_static = quasi_static || it.key == "y_qst";
      if (!sig.sections.empty()) it.a.where += " in " + sec.name;
      summarize(r.summary, it.key, it.unit, it.a);
    }
  }
  if (!quasi_static)
    r.notes.push_back(
        "safety: no curve section was run through; the quasi-static forces Y_qst and Q_qst "
        "(evaluated per curve section) are not assessed");
  // The summary in a fixed order (the readers show it so).
  static constexpr std::array<std::string_view, 6> kOrder = {"y_over_q", "dq_over_q", "y_qst",
                                                             "q_qst",    "q_max",     "sum_y"};
  const auto rank = [](const std::string& k) {
    return std::find(kOrder.begin(), kOrder.end(), k) - kOrder.begin();
  };
  std::stable_sort(
      r.summary.begin(), r.summary.end(),
      [&](const SummaryItem& a, const SummaryItem& b) { return rank(a.key) < rank(b.key); });
}

// f0 of every bogie point: the scenario's, or the spectrum peak of its frame signal.
std::vector<double> instabilityFrequencies(const AssessmentSignals& sig,
                                           const assessment::AssessmentSpec& spec) {
  if (spec.instability_frequency > 0.0)
    return std::vector<double>(sig.bogies.size(), spec.instability_frequency);
  std::vector<const std::vector<double>*> signals;
  for (const auto& b : sig.bogies) signals.push_back(&b.ay);
  const double nyquist = 0.5 / sig.dt;
  return spectrumPeaks(signals, sig.dt, kF0Low, std::min(kF0High, 0.8 * nyquist), kF0Step);
}

void assessStability(const AssessmentSignals& sig, const assessment::AssessmentSpec& spec,
                     AssessmentResult& r) {
  if (sig.distance.back() - sig.distance.front() < a14::kStabilityWindow) {
    r.notes.push_back(
        "stability: the run is shorter than the 100 m sliding rms window; not "
        "assessed");
    r.spec.stability = false;
    return;
  }
  const std::vector<double> f0 = instabilityFrequencies(sig, spec);
  for (std::size_t k = 0; k < sig.bogies.size(); ++k) {
    const BogiePointSignals& b = sig.bogies[k];
    StabilityResult s;
    s.bogie = b.bogie;
    s.wheelset = b.wheelset;
    s.bogie_mass = b.bogie_mass;
    s.f0 = f0[k];
    s.st = a14::stability(b.ay, ownDistance(sig, b.s_offset), sig.dt, s.f0, b.bogie_mass);
    s.a = assessed(s.st.check, "m/s^2",
                   std::string(kEn14363) +
                       ": running stability, simplified method (sliding rms 100 m of the "
                       "bogie-frame lateral acceleration, band-pass f0 +- 2 Hz)",
                   b.bogie + " over " + b.wheelset, s.st.position);
    summarize(r.summary, "stability_rms", "m/s^2", s.a);
    r.stability.push_back(std::move(s));
  }
}

void assessComfort(const AssessmentSignals& sig, const assessment::AssessmentSpec& spec,
                   AssessmentResult& r) {
  // The blocks are counted in samples at the sample interval, as meanComfort counts them: a
  // file whose /assessment@sample_every disagrees with its time axis (a forged or damaged one)
  // must not pass this test on its times and then have no block.
  const double duration = sig.time.back() - sig.time.front();
  const double block = std::round(a12::kBlockDuration / sig.dt);
  const bool noBlock =
      std::any_of(sig.floor.begin(), sig.floor.end(), [&](const FloorPointSignals& p) {
        return static_cast<double>(std::min({p.ax.size(), p.ay.size(), p.az.size()})) < block;
      });
  if (duration < a12::kBlockDuration || noBlock) {
    r.notes.push_back("comfort: the run is shorter than one 5 s block of EN 12299; not assessed");
    r.spec.comfort = false;
    return;
  }
  namespace sp = assessment::sperling;
  for (const auto& p : sig.floor) {
    ComfortResult c;
    c.name = p.name;
    c.x_offset = p.x_offset;
    c.n_mv = a12::meanComfort(p.ax, p.ay, p.az, sig.dt, spec.comfort_limit);
    c.n = assessed(c.n_mv.check, "-", "EN 12299:2009 6.7.2: mean comfort N_MV (standard method)",
                   p.name);
    if (c.n_mv.blocks < static_cast<std::size_t>(assessment::kComfortBlocksRequired))
      c.n.where += " (" + std::to_string(c.n_mv.blocks) + " of the " +
                   std::to_string(assessment::kComfortBlocksRequired) +
                   " 5 s blocks EN 12299 asks for: indicative)";
    c.nc[0] = a12::continuousComfort(p.ax, a12::Axis::X, sig.dt);
    c.nc[1] = a12::continuousComfort(p.ay, a12::Axis::Y, sig.dt);
    c.nc[2] = a12::continuousComfort(p.az, a12::Axis::Z, sig.dt);
    const Check wl = sp::index(p.ay, sig.dt, sp::Direction::Lateral);
    const Check wv = sp::index(p.az, sig.dt, sp::Direction::Vertical);
    c.wz_lateral = wl.value;
    c.wz_vertical = wv.value;
    const std::string sperling = "Sperling ride index Wz (target 2.5, not a standard's limit)";
    summarize(r.summary, "n_mv", "-", c.n);
    summarize(r.summary, "wz_lateral", "-", assessed(wl, "-", sperling, p.name));
    summarize(r.summary, "wz_vertical", "-", assessed(wv, "-", sperling, p.name));
    r.comfort.push_back(std::move(c));
  }
}

void assessWear(const AssessmentSignals& sig, AssessmentResult& r) {
  for (const auto& w : sig.wheels) {
    WearResult wr;
    wr.t_gamma.assign(sig.time.size(), 0.0);
    wr.power.assign(sig.time.size(), 0.0);
    for (int p = 0; p < 2; ++p) {
      assessment::wear::addPatch(wr.t_gamma, w.t_gamma[p]);
      assessment::wear::addPatch(wr.power, w.power[p]);
      wr.patch[p] = assessment::wear::summarize(w.t_gamma[p], sig.distance);
    }
    wr.wheel = assessment::wear::summarize(wr.t_gamma, sig.distance);
    const Assessed a =
        assessed(assessment::check(wr.wheel.max, kInf), "N",
                 "T gamma wear number (Pearce & Sherratt 1991), no limit", wheelName(w));
    summarize(r.summary, "t_gamma_max", "N", a);
    r.wear.push_back(std::move(wr));
  }
}

// The rows of /schema/assessment: every dataset written below, with its unit and meaning.
using SchemaRows = std::vector<io::SchemaEntry>;
void put(io::ResultFile& f, SchemaRows& rows, const std::string& path,
         const std::vector<double>& values, const char* unit, std::string meaning) {
  f.dataset(path, values, unit);
  rows.push_back({path, unit, std::move(meaning), ""});
}

// The attributes every quantity's group carries (ASSESSMENT_LAYOUT).
void writeAssessed(io::ResultFile& f, const std::string& g, const Assessed& a) {
  f.attr(g, "unit", a.unit);
  f.attr(g, "value", a.check.value);
  f.attr(g, "limit", a.check.limit);
  f.attr(g, "margin", a.check.margin);
  f.attr(g, "ok", std::int64_t{a.check.ok() ? 1 : 0});
  f.attr(g, "clause", a.clause);
  f.attr(g, "where", a.where);
  if (std::isfinite(a.at_s)) f.attr(g, "at_s", a.at_s);
}

void writeSliding(io::ResultFile& f, SchemaRows& rows, const std::string& g, const Assessed& a,
                  const a14::SlidingAssessment& s, const char* unit) {
  writeAssessed(f, g, a);
  put(f, rows, g + "/value", s.series.value, unit,
      "the sliding quantity at each window end (the group's clause attribute)");
  f.attr(g, "upper", s.stats.upper);
  f.attr(g, "lower", s.stats.lower);
}

void writeSafety(io::ResultFile& f, SchemaRows& rows, const std::string& root,
                 const AssessmentSignals& sig, const AssessmentResult& r) {
  for (std::size_t k = 0; k < r.wheel_safety.size(); ++k) {
    const auto& w = sig.wheels[k];
    const auto& s = r.wheel_safety[k];
    const std::string base = root + "/safety/" + w.wheelset + "/" + w.side + "/";
    writeSliding(f, rows, base + "y_over_q", s.yq, s.y_over_q, "-");
    // Window ends in this wheel's own arc length.
    put(f, rows, base + "y_over_q/s", s.y_over_q.series.position, "m",
        "window end in the wheel's own arc length");
    f.attr(root + "/safety/" + w.wheelset + "/" + w.side, "s_offset", w.s_offset);
    f.attr(base + "y_over_q", "nadal_limit", s.nadal_limit);
    f.attr(base + "y_over_q", "flange_angle", r.spec.flange_angle);
    f.attr(base + "y_over_q", "mu", s.nadal_mu);
    writeAssessed(f, base + "dq_over_q", s.dq);
    put(f, rows, base + "dq_over_q/value", s.dq_series, "-",
        "wheel unloading (Q0 - Q) / Q0 at the samples");
    f.attr(base + "dq_over_q", "q0", w.q0);
    writeAssessed(f, base + "y_qst", s.y_qst);
    writeAssessed(f, base + "q_qst", s.q_qst);
    writeAssessed(f, base + "q_max", s.q_max);
    f.attr(base + "q_max", "q0", w.q0);
    // The sampled wheel forces, so that `workbench assess` can recompute from the file.
    f.attr(root + "/safety/" + w.wheelset + "/" + w.side, "q0", w.q0);
    put(f, rows, base + "Y", w.Y, "N", "sampled lateral wheel force Y (EN 14363 sign)");
    put(f, rows, base + "Q", w.Q, "N", "sampled vertical wheel force Q");
    put(f, rows, base + "y_track", w.y_track, "N",
        "sampled lateral force in the track frame, positive to the left");
  }
  for (const auto& ws : r.wheelset_safety) {
    const std::string g = root + "/safety/" + ws.wheelset + "/sum_y";
    writeSliding(f, rows, g, ws.sy, ws.sum_y, "N");
    put(f, rows, g + "/s", ws.sum_y.series.position, "m",
        "window end in the wheelset's own arc length");
    f.attr(g, "alpha", r.spec.alpha);
    f.attr(g, "q0", ws.q0);
  }
}

// The summary attributes of one set of items under group g (/assessment/summary, a section).
void writeItems(io::ResultFile& f, const std::string& g, const std::vector<SummaryItem>& items) {
  for (const auto& it : items) {
    f.attr(g, it.key, it.a.check.value);
    // A quantity without a limit (T gamma) has no Q_limit and Q_ok: readers show its value alone.
    if (std::isfinite(it.a.check.limit)) {
      f.attr(g, it.key + "_limit", it.a.check.limit);
      f.attr(g, it.key + "_ok", std::int64_t{it.a.check.ok() ? 1 : 0});
    }
    f.attr(g, it.key + "_where", it.a.where);
    f.attr(g, it.key + "_unit", it.unit);
    if (std::isfinite(it.a.at_s)) f.attr(g, it.key + "_at_s", it.a.at_s);
  }
}

void writeSectionWheel(io::ResultFile& f, const std::string& g, const SectionWheel& w) {
  const auto put = [&](const char* key, const Assessed& a) {
    if (std::isnan(a.check.value)) return;
    f.attr(g, key, a.check.value);
    f.attr(g, std::string(key) + "_limit", a.check.limit);
    if (std::isfinite(a.at_s)) f.attr(g, std::string(key) + "_at_s", a.at_s);
  };
  put("y_over_q", w.yq);
  put("dq_over_q", w.dq);
  put("q_max", w.q_max);
  if (w.quasi_static) {
    put("y_qst", w.y_qst);
    put("q_qst", w.q_qst);
  }
}

// /assessment/sections/<name>: the section (kind, test zone, range, radius, cant) and its
// quantities, worst first (as /assessment/summary) and per wheel and wheelset.
void writeSections(io::ResultFile& f, const std::string& root, const AssessmentSignals& sig,
                   const AssessmentResult& r) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < r.sections.size(); ++i) {
    const SectionResult& sr = r.sections[i];
    const auto& sec = sr.section;
    names.push_back(sec.name);
    const std::string g = root + "/sections/" + sec.name;
    f.attr(g, "order", static_cast<std::int64_t>(i));
    f.attr(g, "kind", std::string(nameOf(sec.kind)));
    f.attr(g, "zone", std::string(nameOf(sec.zone)));
    if (std::isfinite(sec.from)) f.attr(g, "from", sec.from);
    if (std::isfinite(sec.to)) f.attr(g, "to", sec.to);
    if (std::isfinite(sec.radius)) f.attr(g, "radius", sec.radius);
    if (std::isfinite(sec.cant)) f.attr(g, "cant", sec.cant);
    f.attr(g, "covered", sr.covered);
    f.attr(g, "notes", join(sr.notes, "\n"));
    writeItems(f, g, sr.summary);
    for (std::size_t k = 0; k < sr.wheels.size(); ++k)
      if (sr.wheels[k].assessed)
        writeSectionWheel(f, g + "/" + sig.wheels[k].wheelset + "/" + sig.wheels[k].side,
                          sr.wheels[k]);
    for (std::size_t k = 0; k < sr.sum_y.size(); ++k) {
      const Assessed& a = sr.sum_y[k];
      if (std::isnan(a.check.value)) continue;
      const std::string wg = g + "/" + r.wheelset_safety[k].wheelset;
      f.attr(wg, "sum_y", a.check.value);
      f.attr(wg, "sum_y_limit", a.check.limit);
      if (std::isfinite(a.at_s)) f.attr(wg, "sum_y_at_s", a.at_s);
    }
  }
  if (!names.empty()) f.attr(root + "/sections", "names", join(names, "\n"));
}

void writeStability(io::ResultFile& f, SchemaRows& rows, const std::string& root,
                    const AssessmentSignals& sig, const AssessmentResult& r) {
  for (std::size_t k = 0; k < r.stability.size(); ++k) {
    const auto& s = r.stability[k];
    const std::string g = root + "/stability/" + s.bogie + "/" + s.wheelset;
    writeAssessed(f, g, s.a);
    put(f, rows, g + "/s", s.st.series.position, "m",
        "window end in the wheelset's own arc length");
    put(f, rows, g + "/rms", s.st.series.value, "m/s^2",
        "sliding rms of the band-passed bogie-frame lateral acceleration (EN 14363)");
    put(f, rows, g + "/acceleration", sig.bogies[k].ay, "m/s^2",
        "sampled lateral acceleration of the bogie frame over the wheelset");
    f.attr(g, "f0", s.f0);
    f.attr(g, "bogie_mass", s.bogie_mass);
    f.attr(g, "s_offset", sig.bogies[k].s_offset);
  }
}

void writeComfort(io::ResultFile& f, SchemaRows& rows, const std::string& root,
                  const AssessmentSignals& sig, const AssessmentResult& r) {
  for (std::size_t k = 0; k < r.comfort.size(); ++k) {
    const auto& c = r.comfort[k];
    const auto& p = sig.floor[k];
    const std::string g = root + "/comfort/" + c.name;
    put(f, rows, g + "/a_x", p.ax, "m/s^2", "sampled longitudinal floor acceleration");
    put(f, rows, g + "/a_y", p.ay, "m/s^2", "sampled lateral floor acceleration");
    put(f, rows, g + "/a_z", p.az, "m/s^2", "sampled vertical floor acceleration");
    put(f, rows, g + "/nc_x", c.nc[0], "-", "EN 12299 comfort index of the x axis per 5 s block");
    put(f, rows, g + "/nc_y", c.nc[1], "-", "EN 12299 comfort index of the y axis per 5 s block");
    put(f, rows, g + "/nc_z", c.nc[2], "-", "EN 12299 comfort index of the z axis per 5 s block");
    writeAssessed(f, g, c.n);
    f.attr(g, "n_mv", c.n.check.value);
    f.attr(g, "x_offset", c.x_offset);
    f.attr(g, "wz_lateral", c.wz_lateral);
    f.attr(g, "wz_vertical", c.wz_vertical);
    f.attr(g, "a_x95", c.n_mv.a_x95);
    f.attr(g, "a_y95", c.n_mv.a_y95);
    f.attr(g, "a_z95", c.n_mv.a_z95);
    f.attr(g, "blocks", static_cast<std::int64_t>(c.n_mv.blocks));
  }
}

void writeWearSummary(io::ResultFile& f, const std::string& g,
                      const assessment::wear::WearSummary& s) {
  f.attr(g, "max", s.max);
  f.attr(g, "mean", s.mean);
  f.attr(g, "energy", s.energy);
}

void writeWear(io::ResultFile& f, SchemaRows& rows, const std::string& root,
               const AssessmentSignals& sig, const AssessmentResult& r) {
  for (std::size_t k = 0; k < r.wear.size(); ++k) {
    const auto& w = r.wear[k];
    const std::string g = root + "/wear/" + sig.wheels[k].wheelset + "/" + sig.wheels[k].side;
    put(f, rows, g + "/t_gamma", w.t_gamma, "N", "T gamma wear number of the wheel");
    put(f, rows, g + "/power", w.power, "W", "frictional power T gamma V of the wheel");
    writeWearSummary(f, g, w.wheel);
    f.attr(g, "unit", std::string("N"));
    for (int p = 0; p < 2; ++p) {
      const std::string pg = g + "/patch" + std::to_string(p);
      writeWearSummary(f, pg, w.patch[p]);
      put(f, rows, pg + "/t_gamma", sig.wheels[k].t_gamma[p], "N", "T gamma of the patch");
      put(f, rows, pg + "/power", sig.wheels[k].power[p], "W", "frictional power of the patch");
    }
  }
}

void writeSummary(io::ResultFile& f, const std::string& root, const AssessmentResult& r) {
  const std::string g = root + "/summary";
  writeItems(f, g, r.summary);
  bool all_ok = true;
  for (const auto& it : r.summary) all_ok = all_ok && it.a.check.ok();
  f.attr(g, "all_ok", std::int64_t{all_ok ? 1 : 0});
}

std::string joinLines(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : "\n") + x;
  return s;
}

}  // namespace

std::vector<io::SchemaEntry> writeAssessment(io::ResultFile& f, const AssessmentSignals& sig,
                                             const AssessmentResult& r, const std::string& root) {
  SchemaRows rows;
  const std::string& g = root;
  f.attr(g, "standards",
         std::string("EN 14363:2005 / UIC 518 (running safety, track loading, stability); EN "
                     "12299:2009 (ride comfort); Sperling Wz; T gamma wear number"));
  f.attr(g, "sample_every", r.sample_every);
  f.attr(g, "assumptions", joinLines(r.assumptions));
  f.attr(g, "quantities", joinLines(r.quantities));
  f.attr(g, "notes", joinLines(r.notes));
  // The parameters as applied (workbench assess starts from them).
  f.attr(g, "alpha", r.spec.alpha);
  f.attr(g, "flange_angle", r.spec.flange_angle);
  f.attr(g, "mu", r.mu);
  f.attr(g, "yq_limit", r.spec.yq_limit);
  f.attr(g, "instability_frequency", r.spec.instability_frequency);
  f.attr(g, "comfort_limit", r.spec.comfort_limit);
  put(f, rows, g + "/time", sig.time, "s", "assessment sample time");
  put(f, rows, g + "/distance", sig.distance, "m",
      "arc length of the vehicle's foremost body at the samples");
  writeSummary(f, root, r);
  f.attr(g, "q0_source", sig.q0_source);
  f.attr(g, "category", std::string(nameOf(r.spec.category)));
  if (r.spec.safety) writeSafety(f, rows, root, sig, r);
  if (r.spec.safety) writeSections(f, root, sig, r);
  if (r.spec.stability) writeStability(f, rows, root, sig, r);
  if (r.spec.comfort) writeComfort(f, rows, root, sig, r);
  if (r.spec.wear) writeWear(f, rows, root, sig, r);
  return rows;
}

double spectrumPeak(const std::vector<double>& x, double dt, double f_low, double f_high,
                    double df) {
  return spectrumPeaks({&x}, dt, f_low, f_high, df).front();
}

std::vector<double> spectrumPeaks(const std::vector<const std::vector<double>*>& xs, double dt,
                                  double f_low, double f_high, double df) {
  const std::size_t m = xs.size();
  const std::size_t n = m == 0 ? 0 : xs.front()->size();
  // The series with their means removed, once (not at every frequency), interleaved sample by
  // sample: centred[k m + i] is sample k of series i.
  std::vector<double> centred(n * m);
  for (std::size_t i = 0; i < m; ++i) {
    const std::vector<double>& x = *xs[i];
    RB_CHECK(x.size() == n, "spectrum series differ in length");
    double mean = 0.0;
    for (const double v : x) mean += v;
    mean /= static_cast<double>(std::max<std::size_t>(n, 1));
    for (std::size_t k = 0; k < n; ++k) centred[k * m + i] = x[k] - mean;
  }
  std::vector<double> best(m, -1.0), f_best(m, f_low), re(m), im(m);
  for (double f = f_low; f <= f_high + 1e-9; f += df) {
    // One DFT bin by the recurrence rot_k = exp(-j w k dt) (no trigonometry per sample), shared
    // by the series (they have one sampling interval). Written out in real arithmetic: the very
    // operations of std::complex's products and sums of finite values (the signals are checked
    // finite), without its branch for infinite operands.
    const std::complex<double> step = std::polar(1.0, -2.0 * std::numbers::pi * f * dt);
    const double c = step.real(), d = step.imag();
    double a = 1.0, b = 0.0;  // rot
    std::fill(re.begin(), re.end(), 0.0);
    std::fill(im.begin(), im.end(), 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const double* v = &centred[k * m];
      for (std::size_t i = 0; i < m; ++i) {
        re[i] += v[i] * a;
        im[i] += v[i] * b;
      }
      const double a_next = a * c - b * d;
      b = a * d + b * c;
      a = a_next;
    }
    for (std::size_t i = 0; i < m; ++i) {
      const double power = re[i] * re[i] + im[i] * im[i];
      if (power > best[i]) {
        best[i] = power;
        f_best[i] = f;
      }
    }
  }
  return f_best;
}

AssessmentResult assess(const AssessmentSignals& sig, const assessment::AssessmentSpec& spec,
                        double contact_mu) {
  AssessmentResult r;
  r.spec = spec;
  r.sample_every = sig.dt;
  const double mu = spec.mu > 0.0 ? spec.mu : contact_mu;
  r.mu = mu;
  if (r.spec.alpha <= 0.0) {
    r.spec.alpha = assessment::trackShiftAlpha(spec.category);
    if (spec.category == assessment::VehicleCategory::Unstated && spec.safety)
      r.notes.push_back(
          "safety: the vehicle states no vehicle.category; alpha = 1.0 of the track shift limit "
          "(locomotives, passenger vehicles) assumed: a freight wagon has alpha = 0.85 "
          "(vehicle.category = \"freight\" or run.assessment.alpha)");
  }
  r.assumptions = {
      "wheel forces low-pass filtered at 20 Hz (4th-order Butterworth) before processing",
      "positions: every wheel's, wheelset's and bogie point's own arc length along the track",
      "Q0 per wheel: " + (sig.q0_source.empty() ? std::string("as given") : sig.q0_source),
      sig.sections.empty()
          ? std::string("whole run assessed as one section (no track sections known)")
          : std::string("running safety and track loading per track section (each wheel over "
                        "its own stretch of it); the summary gives the worst section; Y_qst "
                        "and Q_qst in curve and given sections only"),
      std::string("floor points at the car body's centre-of-mass height; absolute "
                  "accelerations in the body's track frame, gravity not included (the comfort "
                  "weightings remove the static part)"),
      std::string("bogie-frame lateral acceleration at the frame point above each axle, "
                  "centre-of-mass height"),
      "Nadal's limit with flange angle " + formatNumber(spec.flange_angle, 4) + " rad and mu " +
          formatNumber(mu, 4),
      "sum Y limit alpha (10 kN + 2 Q0 / 3) with alpha " + formatNumber(r.spec.alpha, 4) +
          " and Q0 the mean static wheel load of the wheelset"};
  if (sig.time.size() < 2) {
    r.notes.push_back("assessment: fewer than 2 samples; nothing assessed");
    r.spec.safety = r.spec.stability = r.spec.comfort = r.spec.wear = false;
    return r;
  }
  if (r.spec.safety) assessSafety(sig, spec, mu, r);
  if (r.spec.stability) assessStability(sig, spec, r);
  if (r.spec.comfort) assessComfort(sig, spec, r);
  if (!r.comfort.empty() &&
      r.comfort.front().n_mv.blocks < static_cast<std::size_t>(assessment::kComfortBlocksRequired))
    r.notes.push_back("comfort: N_MV rests on " + std::to_string(r.comfort.front().n_mv.blocks) +
                      " blocks of 5 s; EN 12299 asks for " +
                      std::to_string(assessment::kComfortBlocksRequired) +
                      " (5 minutes): the value and its verdict are indicative only");
  if (r.spec.wear) assessWear(sig, r);
  for (const auto& it : r.summary) r.quantities.push_back(it.key);
  return r;
}

std::vector<std::string> summaryLines(const AssessmentResult& r) {
  std::vector<std::string> out;
  out.emplace_back("assessment (" + formatNumber(1.0 / r.sample_every, 4) + " Hz samples):");
  for (const auto& it : r.summary) {
    std::ostringstream os;
    os << "  " << it.key;
    os << std::string(it.key.size() < 14 ? 14 - it.key.size() : 1, ' ');
    os << formatNumber(it.a.check.value, 4) << " " << it.unit;
    if (std::isfinite(it.a.check.limit))
      os << "  limit " << formatNumber(it.a.check.limit, 4) << "  "
         << (it.a.check.ok() ? "ok" : "EXCEEDED");
    os << "  (" << it.a.where;
    if (std::isfinite(it.a.at_s)) os << " at s = " << formatNumber(it.a.at_s, 4) << " m";
    os << ")";
    out.push_back(os.str());
  }
  for (const auto& line : sectionLines(r)) out.push_back("  " + line);
  for (const auto& n : r.notes) out.push_back("  " + n);
  return out;
}

std::vector<std::string> sectionLines(const AssessmentResult& r) {
  std::vector<std::string> out;
  if (r.sections.size() < 2 && (r.sections.empty() || std::isinf(r.sections[0].section.to)))
    return out;  // the whole run is the only section: the summary says it all
  static constexpr std::array<std::pair<const char*, double>, 6> kCols = {{{"y_over_q", 1.0},
                                                                           {"sum_y", 1e-3},
                                                                           {"dq_over_q", 1.0},
                                                                           {"y_qst", 1e-3},
                                                                           {"q_qst", 1e-3},
                                                                           {"q_max", 1e-3}}};
  out.emplace_back("per section (EN 14363; the worst wheel or wheelset of each):");
  char buf[256];
  std::snprintf(buf, sizeof buf, "  %-14s %-22s %-15s %7s %6s %7s %6s %7s %7s %7s", "section",
                "kind, zone", "s [m]", "run [m]", "Y/Q", "SY[kN]", "dQ/Q0", "Yqst", "Qqst", "Qmax");
  out.emplace_back(buf);
  for (const auto& sr : r.sections) {
    const auto& sec = sr.section;
    std::string kind = std::string(nameOf(sec.kind));
    if (sec.zone != assessment::TestZone::None) kind += ", " + std::string(nameOf(sec.zone));
    const std::string range = formatNumber(sec.from, 4) + "-" + formatNumber(sec.to, 4);
    std::string line;
    std::snprintf(buf, sizeof buf, "  %-14s %-22s %-15s %7.1f", sec.name.c_str(), kind.c_str(),
                  range.c_str(), sr.covered);
    line = buf;
    for (const auto& col : kCols) {
      const std::string key = col.first;
      const double scale = col.second;
      const auto it = std::find_if(sr.summary.begin(), sr.summary.end(),
                                   [&](const SummaryItem& i) { return i.key == key; });
      const int width = key == "y_over_q" || key == "dq_over_q" ? 6 : 7;
      if (it == sr.summary.end()) {
        std::snprintf(buf, sizeof buf, " %*s", width, "-");
      } else {
        std::snprintf(buf, sizeof buf, " %*.*f%s", width - 1, scale < 1.0 ? 1 : 3,
                      it->a.check.value * scale, it->a.check.ok() ? " " : "!");
      }
      line += buf;
    }
    out.push_back(line);
  }
  out.emplace_back(
      "  (run: the length of the section the leading wheelset ran; ! = limit exceeded; forces "
      "in kN; Y_qst, Q_qst in curve and given sections only)");
  return out;
}

std::vector<std::string> exceededWarnings(const AssessmentResult& r) {
  std::vector<std::string> out;
  for (const auto& it : r.summary)
    if (!it.a.check.ok())
      out.push_back("assessment: " + it.key + " = " + formatNumber(it.a.check.value, 4) + " " +
                    it.unit + " exceeds its limit " + formatNumber(it.a.check.limit, 4) + " (" +
                    it.a.where + ")");
  return out;
}

}  // namespace rb::run
