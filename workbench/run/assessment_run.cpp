#include "workbench/run/assessment_run.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <numbers>
#include <sstream>

#include "workbench/assessment/signal.hpp"
#include "workbench/assessment/sperling.hpp"

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

WheelSafety wheelSafety(const WheelSignals& w, const AssessmentSignals& sig,
                        const assessment::AssessmentSpec& spec, double mu) {
  WheelSafety r;
  const double dt = sig.dt;
  r.y_over_q = a14::derailmentQuotient(w.Y, w.Q, sig.distance, dt, spec.yq_limit);
  r.nadal_limit = a14::nadalLimit(spec.flange_angle, mu);
  r.nadal_mu = mu;
  r.yq = assessed(r.y_over_q.check, "-", std::string(kEn14363) + ": (Y/Q)_2m, 2 m sliding mean",
                  wheelName(w), positionOfMaxAbs(r.y_over_q.series));
  const std::vector<double> qf = a14::lowPassForce(w.Q, dt);
  r.dq_series.resize(qf.size());
  std::size_t kmax = 0;
  for (std::size_t k = 0; k < qf.size(); ++k) {
    r.dq_series[k] = (w.q0 - qf[k]) / w.q0;
    if (r.dq_series[k] > r.dq_series[kmax]) kmax = k;
  }
  r.dq = assessed(a14::wheelUnloading(w.Q, dt, w.q0), "-",
                  std::string(kEn14363) + ": wheel unloading dQ/Q0", wheelName(w),
                  qf.empty() ? std::numeric_limits<double>::quiet_NaN() : sig.distance[kmax]);
  r.y_qst =
      assessed(a14::quasiStaticGuidingForce(w.Y, dt), "N",
               std::string(kEn14363) + ": quasi-static guiding force Y_qst (50 %)", wheelName(w));
  r.q_qst =
      assessed(a14::quasiStaticWheelForce(w.Q, dt), "N",
               std::string(kEn14363) + ": quasi-static wheel force Q_qst (50 %)", wheelName(w));
  r.q_max = assessed(a14::maximumWheelForce(w.Q, dt, w.q0), "N",
                     std::string(kEn14363) + ": maximum wheel force Q (99.85 %), 90 kN + Q0",
                     wheelName(w));
  return r;
}

void assessSafety(const AssessmentSignals& sig, const assessment::AssessmentSpec& spec, double mu,
                  AssessmentResult& r) {
  if (sig.distance.back() - sig.distance.front() < a14::kSlidingWindow) {
    r.notes.push_back("safety: the run is shorter than the 2 m sliding window; not assessed");
    r.spec.safety = false;
    return;
  }
  for (const auto& w : sig.wheels) {
    r.wheel_safety.push_back(wheelSafety(w, sig, spec, mu));
    const auto& s = r.wheel_safety.back();
    summarize(r.summary, "y_over_q", "-", s.yq);
    summarize(r.summary, "dq_over_q", "-", s.dq);
    summarize(r.summary, "y_qst", "N", s.y_qst);
    summarize(r.summary, "q_qst", "N", s.q_qst);
    summarize(r.summary, "q_max", "N", s.q_max);
  }
  for (std::size_t k = 0; k + 1 < sig.wheels.size(); k += 2) {
    const auto& l = sig.wheels[k];
    const auto& rr = sig.wheels[k + 1];
    WheelsetSafety ws;
    ws.wheelset = l.wheelset;
    ws.q0 = 0.5 * (l.q0 + rr.q0);
    ws.sum_y = a14::trackShiftForce(l.y_track, rr.y_track, sig.distance, sig.dt, ws.q0, spec.alpha);
    ws.sy = assessed(ws.sum_y.check, "N",
                     std::string(kEn14363) + ": track shift force (sum Y)_2m, Prud'homme",
                     ws.wheelset, positionOfMaxAbs(ws.sum_y.series));
    summarize(r.summary, "sum_y", "N", ws.sy);
    r.wheelset_safety.push_back(std::move(ws));
  }
}

// f0 of one bogie: the scenario's, or the spectrum peak of its (first) frame signal.
double instabilityFrequency(const BogiePointSignals& b, double dt,
                            const assessment::AssessmentSpec& spec) {
  if (spec.instability_frequency > 0.0) return spec.instability_frequency;
  const double nyquist = 0.5 / dt;
  return spectrumPeak(b.ay, dt, kF0Low, std::min(kF0High, 0.8 * nyquist), kF0Step);
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
  for (const auto& b : sig.bogies) {
    StabilityResult s;
    s.bogie = b.bogie;
    s.wheelset = b.wheelset;
    s.bogie_mass = b.bogie_mass;
    s.f0 = instabilityFrequency(b, sig.dt, spec);
    s.st = a14::stability(b.ay, sig.distance, sig.dt, s.f0, b.bogie_mass);
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
  const double duration = sig.time.back() - sig.time.front();
  if (duration < a12::kBlockDuration) {
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

std::string fmt(double v) {
  std::ostringstream os;
  os.precision(4);
  os << v;
  return os.str();
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

void writeSliding(io::ResultFile& f, const std::string& g, const Assessed& a,
                  const a14::SlidingAssessment& s, const char* unit) {
  writeAssessed(f, g, a);
  f.dataset(g + "/value", s.series.value, unit);
  f.attr(g, "upper", s.stats.upper);
  f.attr(g, "lower", s.stats.lower);
}

void writeSafety(io::ResultFile& f, const AssessmentSignals& sig, const AssessmentResult& r) {
  if (!r.wheelset_safety.empty())
    f.dataset("/assessment/safety/s", r.wheelset_safety.front().sum_y.series.position, "m");
  for (std::size_t k = 0; k < r.wheel_safety.size(); ++k) {
    const auto& w = sig.wheels[k];
    const auto& s = r.wheel_safety[k];
    const std::string base = "/assessment/safety/" + w.wheelset + "/" + w.side + "/";
    writeSliding(f, base + "y_over_q", s.yq, s.y_over_q, "-");
    f.attr(base + "y_over_q", "nadal_limit", s.nadal_limit);
    f.attr(base + "y_over_q", "flange_angle", r.spec.flange_angle);
    f.attr(base + "y_over_q", "mu", s.nadal_mu);
    writeAssessed(f, base + "dq_over_q", s.dq);
    f.dataset(base + "dq_over_q/value", s.dq_series, "-");
    f.attr(base + "dq_over_q", "q0", w.q0);
    writeAssessed(f, base + "y_qst", s.y_qst);
    writeAssessed(f, base + "q_qst", s.q_qst);
    writeAssessed(f, base + "q_max", s.q_max);
    f.attr(base + "q_max", "q0", w.q0);
    // The sampled wheel forces, so that `workbench assess` can recompute from the file.
    f.attr("/assessment/safety/" + w.wheelset + "/" + w.side, "q0", w.q0);
    f.dataset(base + "Y", w.Y, "N");
    f.dataset(base + "Q", w.Q, "N");
    f.dataset(base + "y_track", w.y_track, "N");
  }
  for (const auto& ws : r.wheelset_safety) {
    const std::string g = "/assessment/safety/" + ws.wheelset + "/sum_y";
    writeSliding(f, g, ws.sy, ws.sum_y, "N");
    f.attr(g, "alpha", r.spec.alpha);
    f.attr(g, "q0", ws.q0);
  }
}

void writeStability(io::ResultFile& f, const AssessmentSignals& sig, const AssessmentResult& r) {
  for (std::size_t k = 0; k < r.stability.size(); ++k) {
    const auto& s = r.stability[k];
    const std::string g = "/assessment/stability/" + s.bogie + "/" + s.wheelset;
    writeAssessed(f, g, s.a);
    f.dataset(g + "/s", s.st.series.position, "m");
    f.dataset(g + "/rms", s.st.series.value, "m/s^2");
    f.dataset(g + "/acceleration", sig.bogies[k].ay, "m/s^2");
    f.attr(g, "f0", s.f0);
    f.attr(g, "bogie_mass", s.bogie_mass);
  }
}

void writeComfort(io::ResultFile& f, const AssessmentSignals& sig, const AssessmentResult& r) {
  for (std::size_t k = 0; k < r.comfort.size(); ++k) {
    const auto& c = r.comfort[k];
    const auto& p = sig.floor[k];
    const std::string g = "/assessment/comfort/" + c.name;
    f.dataset(g + "/a_x", p.ax, "m/s^2");
    f.dataset(g + "/a_y", p.ay, "m/s^2");
    f.dataset(g + "/a_z", p.az, "m/s^2");
    f.dataset(g + "/nc_x", c.nc[0], "-");
    f.dataset(g + "/nc_y", c.nc[1], "-");
    f.dataset(g + "/nc_z", c.nc[2], "-");
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

void writeWear(io::ResultFile& f, const AssessmentSignals& sig, const AssessmentResult& r) {
  for (std::size_t k = 0; k < r.wear.size(); ++k) {
    const auto& w = r.wear[k];
    const std::string g = "/assessment/wear/" + sig.wheels[k].wheelset + "/" + sig.wheels[k].side;
    f.dataset(g + "/t_gamma", w.t_gamma, "N");
    f.dataset(g + "/power", w.power, "W");
    writeWearSummary(f, g, w.wheel);
    f.attr(g, "unit", std::string("N"));
    for (int p = 0; p < 2; ++p) {
      const std::string pg = g + "/patch" + std::to_string(p);
      writeWearSummary(f, pg, w.patch[p]);
      f.dataset(pg + "/t_gamma", sig.wheels[k].t_gamma[p], "N");
      f.dataset(pg + "/power", sig.wheels[k].power[p], "W");
    }
  }
}

void writeSummary(io::ResultFile& f, const AssessmentResult& r) {
  const std::string g = "/assessment/summary";
  for (const auto& it : r.summary) {
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

void writeAssessment(io::ResultFile& f, const AssessmentSignals& sig, const AssessmentResult& r) {
  const std::string g = "/assessment";
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
  f.dataset(g + "/time", sig.time, "s");
  f.dataset(g + "/distance", sig.distance, "m");
  writeSummary(f, r);
  if (r.spec.safety) writeSafety(f, sig, r);
  if (r.spec.stability) writeStability(f, sig, r);
  if (r.spec.comfort) writeComfort(f, sig, r);
  if (r.spec.wear) writeWear(f, sig, r);
}

double spectrumPeak(const std::vector<double>& x, double dt, double f_low, double f_high,
                    double df) {
  double mean = 0.0;
  for (const double v : x) mean += v;
  mean /= static_cast<double>(std::max<std::size_t>(x.size(), 1));
  double best = -1.0, f_best = f_low;
  for (double f = f_low; f <= f_high + 1e-9; f += df) {
    // One DFT bin by the recurrence of exp(-j w k dt) (no trigonometry per sample).
    const std::complex<double> step = std::polar(1.0, -2.0 * std::numbers::pi * f * dt);
    std::complex<double> rot(1.0, 0.0), sum(0.0, 0.0);
    for (const double v : x) {
      sum += (v - mean) * rot;
      rot *= step;
    }
    if (std::norm(sum) > best) {
      best = std::norm(sum);
      f_best = f;
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
  r.assumptions = {
      "wheel forces low-pass filtered at 20 Hz (4th-order Butterworth) before processing",
      "distance axis: travelled distance of the leading wheelset for every wheel",
      "Q0 per wheel: the wheel load Q of the initial (static) state",
      "whole run assessed as one section (no split into tangent and curve zones)",
      std::string("floor points at the car body's centre-of-mass height; absolute "
                  "accelerations in the body's track frame, gravity not included (the comfort "
                  "weightings remove the static part)"),
      std::string("bogie-frame lateral acceleration at the frame point above each axle, "
                  "centre-of-mass height"),
      "Nadal's limit with flange angle " + fmt(spec.flange_angle) + " rad and mu " + fmt(mu),
      "sum Y limit alpha (10 kN + 2 Q0 / 3) with alpha " + fmt(spec.alpha) +
          " and Q0 the mean static wheel load of the wheelset"};
  if (sig.time.size() < 2) {
    r.notes.push_back("assessment: fewer than 2 samples; nothing assessed");
    r.spec.safety = r.spec.stability = r.spec.comfort = r.spec.wear = false;
    return r;
  }
  if (r.spec.safety) assessSafety(sig, spec, mu, r);
  if (r.spec.stability) assessStability(sig, spec, r);
  if (r.spec.comfort) assessComfort(sig, spec, r);
  if (r.spec.wear) assessWear(sig, r);
  for (const auto& it : r.summary) r.quantities.push_back(it.key);
  return r;
}

std::vector<std::string> summaryLines(const AssessmentResult& r) {
  std::vector<std::string> out;
  out.emplace_back("assessment (" + fmt(1.0 / r.sample_every) + " Hz samples):");
  for (const auto& it : r.summary) {
    std::ostringstream os;
    os << "  " << it.key;
    os << std::string(it.key.size() < 14 ? 14 - it.key.size() : 1, ' ');
    os << fmt(it.a.check.value) << " " << it.unit;
    if (std::isfinite(it.a.check.limit))
      os << "  limit " << fmt(it.a.check.limit) << "  " << (it.a.check.ok() ? "ok" : "EXCEEDED");
    os << "  (" << it.a.where;
    if (std::isfinite(it.a.at_s)) os << " at s = " << fmt(it.a.at_s) << " m";
    os << ")";
    out.push_back(os.str());
  }
  for (const auto& n : r.notes) out.push_back("  " + n);
  return out;
}

std::vector<std::string> exceededWarnings(const AssessmentResult& r) {
  std::vector<std::string> out;
  for (const auto& it : r.summary)
    if (!it.a.check.ok())
      out.push_back("assessment: " + it.key + " = " + fmt(it.a.check.value) + " " + it.unit +
                    " exceeds its limit " + fmt(it.a.check.limit) + " (" + it.a.where + ")");
  return out;
}

}  // namespace rb::run
