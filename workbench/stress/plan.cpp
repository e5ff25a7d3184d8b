#include "workbench/stress/plan.hpp"

#include <algorithm>
#include <functional>
#include <optional>
#include <sstream>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/dynamics/rails_along_track.hpp"
#include "workbench/scenario/any_vehicle.hpp"

namespace rb::stress {

namespace {

using scenario::ScenarioSpec;

// Paper Table 3, first column: the Hertz flange stiffness of S1002 from Hertz theory and its
// damping D = K / 100.
constexpr double kHertzK = 7.075e13;    // [N/m^1.5]
constexpr double kDampingOverK = 1e-2;  // [s]
constexpr double kPaperMaxStep = 1e-3;  // [s] paper section 5.4

struct Axis {
  std::string name;
  std::vector<double> defaults;  // the last is the hardest (the --quick value)
  // "" when the axis applies to `spec`, else why not.
  std::function<std::string(const ScenarioSpec&)> applies;
  // The overrides of one value, and its label in the map.
  std::function<std::vector<std::string>(const ScenarioSpec&, double)> overrides;
  std::function<std::string(double)> label;
};

std::string compactNumber(double v) {
  std::string s = formatNumber(v);
  for (const char* from : {"e+0", "e+", "e-0"}) {
    const auto p = s.find(from);
    if (p != std::string::npos) s.replace(p, std::string(from).size(), from[1] == '-' ? "e-" : "e");
  }
  return s;
}

std::string factorLabel(double v) {
  return "x" + compactNumber(v);
}

// One contact model the contact axes change, and the key prefix of its --set overrides: the
// scenario's contact{} ("contact."), and in a train every vehicle's own contact{} block
// ("train.vehicles[k].contact."), so that a hardened case hardens every vehicle of the train.
struct ContactTarget {
  std::string prefix;
  dynamics::ContactMethod method;
};

std::vector<ContactTarget> contactTargets(const ScenarioSpec& s) {
  if (s.train.empty())
    return s.has_contact ? std::vector<ContactTarget>{{"contact.", s.contact.method}}
                         : std::vector<ContactTarget>{};
  std::vector<ContactTarget> out;
  bool scene = false;
  for (std::size_t k = 0; k < s.train.size(); ++k) {
    const auto& v = s.train[k];
    if (!v.has_contact) continue;
    if (v.own_contact)
      out.push_back({"train.vehicles[" + std::to_string(k + 1) + "].contact.", v.contact.method});
    else if (!scene)
      out.push_back({"contact.", v.contact.method});
    scene = scene || !v.own_contact;
  }
  return out;
}

bool anyMethod(const ScenarioSpec& s, dynamics::ContactMethod m) {
  const auto t = contactTargets(s);
  return std::any_of(t.begin(), t.end(), [&](const ContactTarget& c) { return c.method == m; });
}

// `key=value` for every contact model of `method` (every one when `method` is empty).
std::vector<std::string> contactOverrides(const ScenarioSpec& s,
                                          std::optional<dynamics::ContactMethod> method,
                                          const std::vector<std::pair<std::string, double>>& kv) {
  std::vector<std::string> o;
  for (const auto& t : contactTargets(s))
    if (!method || t.method == *method)
      for (const auto& [key, v] : kv) o.push_back(t.prefix + key + "=" + formatNumber(v, 12));
  return o;
}

std::string contactNote(const ScenarioSpec& s) {
  return contactTargets(s).empty() ? "no wheel/rail contact in the scenario (guided wheelsets)"
                                   : "";
}

std::string methodNote(const ScenarioSpec& s, dynamics::ContactMethod m, const char* why) {
  if (const auto n = contactNote(s); !n.empty()) return n;
  if (anyMethod(s, m)) return "";
  return (s.train.empty() ? "the contact method is " + std::string(nameOf(s.contact.method))
                          : "no vehicle of the train runs on " + std::string(nameOf(m))) +
         " (" + why + ")";
}

std::string lutNote(const ScenarioSpec& s) {
  return methodNote(s, dynamics::ContactMethod::Lut,
                    "the Hertz flange stiffness belongs to the LUT");
}

std::string kecNote(const ScenarioSpec& s) {
  return methodNote(s, dynamics::ContactMethod::Kec,
                    "the transition lengths dhat, dbar belong to the KEC");
}

std::string speedNote(const ScenarioSpec& s) {
  return s.has_vehicle && s.vehicle.speed > 0 ? "" : "no vehicle speed in the scenario";
}

std::string irregularityNote(const ScenarioSpec& s) {
  switch (s.track.irregularities.source) {
    case track::IrregularitySource::Psd:
      return "";
    case track::IrregularitySource::Csv:
      return "measured irregularities (the amplitude factor applies to PSD irregularities)";
    default:
      return "no irregularities in the scenario";
  }
}

bool hasRadius(const track::SegmentSpec& g) {
  return g.kind != track::SegmentKind::Tangent && g.radius > 0;
}

std::string curveNote(const ScenarioSpec& s) {
  // Rails laid along the track by slices (a turnout's stock rail and blade follow its radius).
  if (scenario::anyProfiles(s, dynamics::railsAlongTrack))
    return "rails laid along the track by slices (profiles.rail_slices / extra_rails), placed "
           "for its curves: a scaled radius would not move them";
  return std::any_of(s.track.segments.begin(), s.track.segments.end(), hasRadius)
             ? ""
             : "a tangent-only track (no curve radius to scale)";
}

std::vector<std::string> speedOverrides(const ScenarioSpec& s, double f) {
  // A train starts at one speed: every vehicle's is scaled.
  std::vector<std::string> o;
  if (s.train.empty()) o.push_back("vehicle.speed=" + formatNumber(s.vehicle.speed * f, 12));
  for (std::size_t k = 0; k < s.train.size(); ++k)
    o.push_back("train.vehicles[" + std::to_string(k + 1) +
                "].vehicle.speed=" + formatNumber(s.train[k].vehicle.speed * f, 12));
  // A run given by duration keeps its length of track: faster, shorter in time.
  if (s.run.duration > 0) o.push_back("run.duration=" + formatNumber(s.run.duration / f, 12));
  return o;
}

std::vector<std::string> radiusOverrides(const ScenarioSpec& s, double f) {
  std::vector<std::string> o;
  for (std::size_t i = 0; i < s.track.segments.size(); ++i)
    if (hasRadius(s.track.segments[i]))
      o.push_back("track.segments[" + std::to_string(i + 1) +
                  "].radius=" + formatNumber(s.track.segments[i].radius * f, 12));
  return o;
}

// Blades and noses whose tops are lowered (slices of profiles.extra_rails with dz < 0): the
// rail_drop axis lowers them further, a harder transfer onto them (the scenario's own profiles;
// a train's vehicles with their own profiles{} keep theirs).
bool loweredRails(const dynamics::ProfilesSpec& p) {
  for (const auto& side : p.extra_rails)
    for (const auto& r : side)
      for (const auto& sl : r.slices)
        if (sl.dz < 0.0) return true;
  return false;
}

std::string dropNote(const ScenarioSpec& s) {
  return loweredRails(s.profiles) ? ""
                                  : "no lowered blade or nose (profiles.extra_rails slices with dz "
                                    "< 0) to lower further";
}

std::vector<std::string> dropOverrides(const ScenarioSpec& s, double f) {
  std::vector<std::string> o;
  for (std::size_t side = 0; side < 2; ++side) {
    const auto& rails = s.profiles.extra_rails[side];
    for (std::size_t k = 0; k < rails.size(); ++k)
      for (std::size_t j = 0; j < rails[k].slices.size(); ++j)
        if (const double dz = rails[k].slices[j].dz; dz < 0.0)
          o.push_back(std::string("profiles.extra_rails.") + (side == 0 ? "left" : "right") + "[" +
                      std::to_string(k + 1) + "].slices[" + std::to_string(j + 1) +
                      "].dz=" + formatNumber(dz * f, 12));
  }
  return o;
}

const std::vector<Axis>& axes() {
  static const std::vector<Axis> all = {
      {"nominal",
       {0.0},
       [](const ScenarioSpec&) { return std::string(); },
       [](const ScenarioSpec&, double) { return std::vector<std::string>(); },
       [](double) { return std::string("as given"); }},
      {"flange_stiffness",
       {1e11, 1e12, kHertzK},
       lutNote,
       [](const ScenarioSpec& s, double k) {
         return contactOverrides(s, dynamics::ContactMethod::Lut,
                                 {{"flange_stiffness", k}, {"flange_damping", k * kDampingOverK}});
       },
       compactNumber},
      {"transition",
       {0.5e-3, 0.25e-3, 0.1e-3},
       kecNote,
       [](const ScenarioSpec& s, double d) {
         return contactOverrides(s, dynamics::ContactMethod::Kec, {{"dhat", d}, {"dbar", d}});
       },
       [](double d) { return compactNumber(d * 1e3) + " mm"; }},
      {"speed", {1.25, 1.5, 2.0}, speedNote, speedOverrides, factorLabel},
      {"irregularity",
       {2.0, 4.0},
       irregularityNote,
       [](const ScenarioSpec& s, double f) {
         return std::vector<std::string>{"track.irregularities.scale=" +
                                         formatNumber(s.track.irregularities.scale * f, 12)};
       },
       factorLabel},
      {"friction",
       {0.1, 0.4, 0.6},
       contactNote,
       [](const ScenarioSpec& s, double mu) {
         return contactOverrides(s, std::nullopt, {{"mu", mu}});
       },
       compactNumber},
      {"curve_radius", {0.75, 0.5}, curveNote, radiusOverrides, factorLabel},
      {"rail_drop", {1.5, 2.0}, dropNote, dropOverrides, factorLabel},
  };
  return all;
}

const Axis* findAxis(const std::string& name) {
  for (const auto& a : axes())
    if (a.name == name) return &a;
  return nullptr;
}

std::string axisList() {
  std::string s;
  for (const auto& n : axisNames()) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

const std::vector<std::string>& axisNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& a : axes()) n.push_back(a.name);
    return n;
  }();
  return names;
}

double endTime(const ScenarioSpec& spec) {
  return spec.run.duration > 0 ? spec.run.duration : 0.0;
}

Plan planAxes(const ScenarioSpec& spec, const PlanRequest& request) {
  for (const auto& [name, v] : request.values)
    if (!findAxis(name) || name == "nominal")
      throw InputError({"--values", 0}, "unknown axis '" + name + "' (axes: " + axisList() + ")");
  for (const auto& name : request.axes)
    if (!findAxis(name))
      throw InputError({"--axes", 0}, "unknown axis '" + name + "' (axes: " + axisList() + ")");
  Plan plan;
  for (const auto& axis : axes()) {
    const bool asked = request.axes.empty() || std::find(request.axes.begin(), request.axes.end(),
                                                         axis.name) != request.axes.end();
    if (!asked) continue;
    if (const std::string why = axis.applies(spec); !why.empty()) {
      plan.notes.push_back("axis " + axis.name + " skipped: " + why);
      continue;
    }
    std::vector<double> values = axis.defaults;
    if (auto it = request.values.find(axis.name); it != request.values.end())
      values = it->second;
    else if (request.quick)
      values = {axis.defaults.back()};
    for (double v : values) {
      Hardened h{axis.name, v, axis.label(v), axis.overrides(spec, v), endTime(spec)};
      if (axis.name == "speed" && h.tEnd > 0) h.tEnd /= v;
      plan.cases.push_back(std::move(h));
    }
  }
  return plan;
}

namespace {

bool isFixedStep(const std::string& m) {
  return m == "rk4" || m == "abm";
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) out.push_back(cur);
  return out;
}

}  // namespace

Setting parseSetting(const std::string& text, const std::vector<std::string>& couplings,
                     const std::string& option, double maxStep) {
  const auto parts = split(text, ':');
  auto bad = [&](const std::string& why) {
    return InputError(
        {option, 0}, "'" + text + "': " + why + " (METHOD:VALUE[:paper], e.g. rk4:1e-3, bdf:1e-9)");
  };
  if (parts.size() < 2 || parts.size() > 3) throw bad("expected METHOD:VALUE");
  const std::string& m = parts[0];
  if (!isFixedStep(m) && m != "dopri5" && m != "bdf" && m != "ida")
    throw bad("unknown method '" + m + "' (rk4, abm, dopri5, bdf, ida)");
  double v = 0;
  try {
    std::size_t used = 0;
    v = std::stod(parts[1], &used);
    if (used != parts[1].size() || !(v > 0)) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw bad("the value must be a positive number");
  }
  const bool paper = parts.size() == 3;
  if (paper && parts[2] != "paper") throw bad("unknown suffix '" + parts[2] + "'");
  Setting s;
  s.overrides.push_back("solver.method=" + m);
  if (isFixedStep(m)) {
    s.label = m + " " + compactNumber(v * 1e3) + " ms";
    s.overrides.push_back("solver.step=" + formatNumber(v, 12));
    if (paper) {
      s.overrides.push_back("solver.stiff=explicit");
      s.overrides.push_back("solver.accept_unstable_step=true");
    }
  } else {
    s.adaptive = true;
    s.label = m + " " + compactNumber(v);
    s.overrides.push_back("solver.rtol=" + formatNumber(v, 12));
    s.overrides.push_back("solver.atol=" + formatNumber(v, 12));
    s.overrides.push_back(
        "solver.max_step=" +
        formatNumber(maxStep > 0 && maxStep < kPaperMaxStep ? maxStep : kPaperMaxStep, 12));
  }
  const bool implicit = m == "bdf" || m == "ida";
  if (paper || implicit)
    for (const auto& prefix : couplings)
      s.overrides.push_back(prefix +
                            "normal_forces=" + (paper && !implicit ? "lagged" : "consistent"));
  if (paper) s.label += " paper";
  return s;
}

std::vector<std::string> normalForceCouplings(const ScenarioSpec& spec) {
  std::vector<std::string> out;
  for (const auto& t : contactTargets(spec))
    if (dynamics::methodInfo(t.method).coupling) out.push_back(t.prefix);
  return out;
}

std::vector<std::string> shortenRun(const ScenarioSpec& spec, double seconds) {
  const double v = spec.has_vehicle ? spec.vehicle.speed : 0.0;
  if (spec.run.duration > 0)
    return spec.run.duration > seconds
               ? std::vector<std::string>{"run.duration=" + formatNumber(seconds, 12)}
               : std::vector<std::string>{};
  if (spec.run.distance > 0)
    return v > 0 && spec.run.distance > v * seconds
               ? std::vector<std::string>{"run.distance=" + formatNumber(v * seconds, 12)}
               : std::vector<std::string>{};
  return {"run.duration=" + formatNumber(seconds, 12)};
}

}  // namespace rb::stress
