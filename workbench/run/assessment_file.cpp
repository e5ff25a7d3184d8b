// Reading the signals of an assessment back from a result file (`workbench assess`).
#include <algorithm>
#include <cmath>
#include <limits>

#include "workbench/run/assessment_run.hpp"

namespace rb::run {
namespace {

constexpr const char* kSides[] = {"left", "right"};

std::string fmt(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

// A dataset of n values, or a sentence in `missing`. Every sample must be finite (samples()
// throws BadResult naming the path): one NaN would make every quantity computed from it NaN.
std::vector<double> series(const io::ResultReader& f, const std::string& path, std::size_t n,
                           std::vector<std::string>& missing) {
  auto d = f.samples(path);
  if (!d) {
    missing.push_back("no dataset " + path);
    return std::vector<double>(n, 0.0);
  }
  if (d->size() != n) {
    missing.push_back(path + " has " + std::to_string(d->size()) + " values, not " +
                      std::to_string(n));
    d->resize(n, 0.0);
  }
  return std::move(*d);
}

// The wheels of /contact (wheelset names, sides as written).
std::vector<WheelSignals> wheelsOf(const io::ResultReader& f) {
  std::vector<WheelSignals> out;
  for (const auto& ws : f.members("/contact"))
    for (const char* side : kSides) {
      if (!f.has("/contact/" + ws + "/" + side)) continue;
      WheelSignals w;
      w.wheelset = ws;
      w.side = side;
      out.push_back(std::move(w));
    }
  return out;
}

// Safety and wear signals under `base` (/assessment/... of a run's assessment, or /contact).
void readWheel(const io::ResultReader& f, const std::string& safety_base,
               const std::string& wear_base, const assessment::AssessmentSpec& spec, std::size_t n,
               WheelSignals& w, std::vector<std::string>& missing) {
  if (spec.safety) {
    w.Y = series(f, safety_base + "/Y", n, missing);
    w.Q = series(f, safety_base + "/Q", n, missing);
    w.y_track = series(f, safety_base + "/y_track", n, missing);
  }
  for (int p = 0; p < 2 && spec.wear; ++p) {
    const std::string pg = wear_base + "/patch" + std::to_string(p);
    w.t_gamma[p] = series(f, pg + "/t_gamma", n, missing);
    w.power[p] = series(f, pg + "/power", n, missing);
  }
}

// The arc length of a body's first output minus the leading body's (0 when the file lacks them):
// the s_offset of a wheel written before the assessment kept it.
double offsetOf(const io::ResultReader& f, const std::string& body) {
  auto own = f.samples("/bodies/" + body + "/s");
  if (!own || own->empty()) return 0.0;
  double lead = own->front();
  for (const auto& b : f.members("/bodies")) {
    auto s = f.samples("/bodies/" + b + "/s");
    if (s && !s->empty()) lead = std::max(lead, s->front());
  }
  return own->front() - lead;
}

// The sections a run's assessment wrote (/assessment/sections, in their order).
std::vector<assessment::TrackSection> sectionsWritten(const io::ResultReader& f) {
  std::vector<assessment::TrackSection> out;
  const std::string names = f.text("/assessment/sections", "names").value_or("");
  std::size_t from = 0;
  while (from < names.size()) {
    const std::size_t end = std::min(names.find('\n', from), names.size());
    const std::string name = names.substr(from, end - from);
    from = end + 1;
    const std::string g = "/assessment/sections/" + name;
    assessment::TrackSection t;
    t.name = name;
    t.kind = parse<assessment::SectionKind>(f.text(g, "kind").value_or(""))
                 .value_or(assessment::SectionKind::Given);
    t.zone = parse<assessment::TestZone>(f.text(g, "zone").value_or(""))
                 .value_or(assessment::TestZone::None);
    const double nan = std::nan("");
    t.from = f.finiteNumber(g, "from").value_or(-std::numeric_limits<double>::infinity());
    t.to = f.finiteNumber(g, "to").value_or(std::numeric_limits<double>::infinity());
    t.radius = f.finiteNumber(g, "radius")
                   .value_or(t.kind == assessment::SectionKind::Tangent
                                 ? std::numeric_limits<double>::infinity()
                                 : nan);
    t.cant =
        f.finiteNumber(g, "cant").value_or(t.kind == assessment::SectionKind::Tangent ? 0.0 : nan);
    out.push_back(std::move(t));
  }
  return out;
}

// From the series a run's assessment wrote.
void fromAssessment(const io::ResultReader& f, const assessment::AssessmentSpec& spec,
                    AssessmentSignals& s, std::vector<std::string>& missing) {
  const std::string A = "/assessment";
  s.time = f.samples(A + "/time").value_or(std::vector<double>{});
  const std::size_t n = s.time.size();
  s.distance = series(f, A + "/distance", n, missing);
  s.dt = f.finiteNumber(A, "sample_every").value_or(n > 1 ? s.time[1] - s.time[0] : 0.0);
  // Every window and filter of the assessment is sized in samples from dt.
  if (!(s.dt > 0.0))
    missing.push_back("no sample interval: " + A + "@sample_every and the first step of " + A +
                      "/time are not > 0");
  if (spec.safety || spec.wear) s.wheels = wheelsOf(f);
  for (auto& w : s.wheels) {
    const std::string wheel = "/" + w.wheelset + "/" + w.side;
    w.q0 = f.finiteNumber(A + "/safety" + wheel, "q0").value_or(std::nan(""));
    w.s_offset =
        f.finiteNumber(A + "/safety" + wheel, "s_offset").value_or(offsetOf(f, w.wheelset));
    if (spec.safety && !std::isfinite(w.q0)) missing.push_back("no q0 on " + A + "/safety" + wheel);
    readWheel(f, A + "/safety" + wheel, A + "/wear" + wheel, spec, n, w, missing);
  }
  for (const auto& bogie :
       spec.stability ? f.members(A + "/stability") : std::vector<std::string>{})
    for (const auto& ws : f.members(A + "/stability/" + bogie)) {
      const std::string g = A + "/stability/" + bogie + "/" + ws;
      BogiePointSignals b;
      b.bogie = bogie;
      b.wheelset = ws;
      b.bogie_mass = f.finiteNumber(g, "bogie_mass").value_or(0.0);
      b.s_offset = f.finiteNumber(g, "s_offset").value_or(offsetOf(f, ws));
      b.ay = series(f, g + "/acceleration", n, missing);
      s.bogies.push_back(std::move(b));
    }
  s.sections = sectionsWritten(f);
  s.q0_source = f.text(A, "q0_source")
                    .value_or(
                        "the Q0 attributes the run wrote (a result written before Q0 came "
                        "from the statics: the load of the run's initial state)");
  if (spec.stability && s.bogies.empty())
    missing.push_back("stability: no bogie-frame accelerations in " + A +
                      "/stability (run with run.assessment.stability = true)");
  for (const auto& p : spec.comfort ? f.members(A + "/comfort") : std::vector<std::string>{}) {
    const std::string g = A + "/comfort/" + p;
    s.floor.push_back({p, f.finiteNumber(g, "x_offset").value_or(0.0),
                       series(f, g + "/a_x", n, missing), series(f, g + "/a_y", n, missing),
                       series(f, g + "/a_z", n, missing)});
  }
  if (spec.comfort && s.floor.empty())
    missing.push_back("comfort: no floor accelerations in " + A +
                      "/comfort (run with run.assessment.comfort = true)");
}

// The leading body's arc length (the body with the largest s at the first output).
std::vector<double> leadingDistance(const io::ResultReader& f, std::size_t n,
                                    std::vector<std::string>& missing) {
  std::vector<double> best;
  for (const auto& b : f.members("/bodies")) {
    auto s = f.samples("/bodies/" + b + "/s");
    if (s && s->size() == n && !s->empty() && (best.empty() || s->front() > best.front()))
      best = std::move(*s);
  }
  if (best.empty()) missing.push_back("no /bodies/<body>/s to measure the distance travelled");
  return best.empty() ? std::vector<double>(n, 0.0) : best;
}

// From the run's outputs (safety and wear only): /time, /contact, /bodies/<leading>/s.
void fromOutputs(const io::ResultReader& f, const assessment::AssessmentSpec& spec,
                 AssessmentSignals& s, std::vector<std::string>& missing) {
  s.time = f.samples("/time").value_or(std::vector<double>{});
  const std::size_t n = s.time.size();
  if (n < 2) {
    missing.push_back("no /time series");
    return;
  }
  s.dt = s.time[2 < n ? 2 : 1] - s.time[1];
  if (!(s.dt > 0.0)) missing.push_back("/time does not increase: no output interval");
  if (s.dt > kMaxFileSampleInterval * (1 + 1e-9))
    missing.push_back("the output interval " + fmt(s.dt) + " s is too coarse for the assessment " +
                      "(at most " + fmt(kMaxFileSampleInterval) +
                      " s: run with run.output.every <= " + fmt(kMaxFileSampleInterval) +
                      " or with run.assessment)");
  s.distance = leadingDistance(f, n, missing);
  if (spec.safety || spec.wear) s.wheels = wheelsOf(f);
  if (s.wheels.empty()) missing.push_back("no wheel/rail forces in /contact");
  for (auto& w : s.wheels) {
    const std::string base = "/contact/" + w.wheelset + "/" + w.side;
    readWheel(f, base, base, spec, n, w, missing);
    w.q0 = w.Q.empty() ? 0.0 : w.Q.front();  // the first output is the initial state
    w.s_offset = offsetOf(f, w.wheelset);
  }
  s.q0_source =
      "the Q of the first output (the run's initial state; on a curve or an irregular track "
      "that is not the static wheel load: rerun with run.assessment for the statics' Q0)";
  if (spec.stability)
    missing.push_back(
        "stability: the bogie-frame accelerations are sampled only by "
        "run.assessment (run with run.assessment.stability = true)");
  if (spec.comfort)
    missing.push_back(
        "comfort: the floor accelerations are sampled only by run.assessment "
        "(run with run.assessment.comfort = true)");
}

}  // namespace

AssessmentSignals signalsFromFile(const io::ResultReader& f, const assessment::AssessmentSpec& spec,
                                  std::vector<std::string>& missing) {
  AssessmentSignals s;
  if (f.has("/assessment/time"))
    fromAssessment(f, spec, s, missing);
  else
    fromOutputs(f, spec, s, missing);
  return s;
}

}  // namespace rb::run
