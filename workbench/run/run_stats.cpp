#include "workbench/run/run_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "workbench/dynamics/names.hpp"
#include "workbench/run/vehicle_run.hpp"

namespace rb::run {
namespace {

void addCount(std::vector<EffectUse>& out, Effect e, std::size_t n) {
  if (n > 0) out.push_back({e, std::to_string(n)});
}

// Effects of the wheel/rail contact model (nothing for guided wheelsets).
void contactEffects(const dynamics::ContactModel& c, std::vector<EffectUse>& out) {
  const dynamics::ContactMethodInfo& method = dynamics::methodInfo(c.method);
  out.push_back({Effect::WheelRailContact, std::string(nameOf(c.method))});
  if (c.creep != dynamics::CreepModel::None) {
    out.push_back({Effect::CreepForces, std::string(nameOf(c.creep))});
    // The elastic method's normal forces come from the approach: nothing to couple.
    if (method.coupling)
      out.push_back({Effect::NormalForceCoupling, std::string(nameOf(c.coupling))});
  }
  out.push_back({Effect::FlangeContact, std::string(method.flange_contact)});
  out.push_back({Effect::WheelsetSpin, std::string(nameOf(c.spin))});
  if (c.railSupport()) out.push_back({Effect::TrackSupport, "moving_rail_masses"});
}

// `add` into `out` by effect: an effect already there with another detail lists both, in the
// order they came ("kec+elastic": a train whose vehicles run on different contact models).
void mergeEffects(std::vector<EffectUse>& out, const std::vector<EffectUse>& add) {
  for (const auto& e : add) {
    const auto it = std::find_if(out.begin(), out.end(),
                                 [&](const EffectUse& o) { return o.effect == e.effect; });
    if (it == out.end()) {
      out.push_back(e);
      continue;
    }
    const std::string joined = "+" + it->detail + "+";
    if (joined.find("+" + e.detail + "+") == std::string::npos) it->detail += "+" + e.detail;
  }
}

std::string assessmentGroups(const assessment::AssessmentSpec& a) {
  std::string out;
  const std::pair<bool, const char*> groups[] = {
      {a.safety, "safety"}, {a.stability, "stability"}, {a.comfort, "comfort"}, {a.wear, "wear"}};
  for (const auto& [on, name] : groups)
    if (on) out += (out.empty() ? "" : "+") + std::string(name);
  return out;
}

// The printed label of an effect: the contact method and creep law by their names, the others as
// "name (detail)" with spaces.
std::string label(const EffectUse& e) {
  if (e.effect == Effect::WheelRailContact || e.effect == Effect::CreepForces) return e.detail;
  std::string name(nameOf(e.effect));
  std::replace(name.begin(), name.end(), '_', ' ');
  return e.detail.empty() ? name : name + " (" + e.detail + ")";
}

std::string percent(double share) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.0f %%", 100.0 * share);
  return buf;
}

}  // namespace

std::vector<EffectUse> compiledEffects(const Model& m) {
  std::vector<EffectUse> out;
  if (!m.hasVehicle()) return out;
  // Every vehicle's contact model (a train's may differ) and the elements of all of them.
  std::size_t spring_dampers = 0, series = 0, shear = 0, bending = 0, bumpstops = 0, outputs = 0;
  bool patches = false;
  for (const auto& rv : m.vehicles) {
    std::vector<EffectUse> own;
    if (rv.contact)
      contactEffects(*rv.contact, own);
    else
      own.push_back({Effect::GuidedWheelsets, ""});
    mergeEffects(out, own);
    const vehicle::VehicleModel& v = rv.vehicle;
    spring_dampers += v.spring_dampers.size();
    series += v.series_dampers.size();
    shear += v.shear_springs.size();
    bending += v.bending_springs.size();
    bumpstops += v.bumpstops.size();
    outputs += rv.output_elements.size();
    patches = patches || (rv.contact && m.spec.run.output_patches);
  }
  if (m.track && m.track->irregularities())
    out.push_back({Effect::Irregularities,
                   m.spec.track.irregularities.source == track::IrregularitySource::Psd
                       ? "psd"
                       : "measured"});
  addCount(out, Effect::SpringDampers, spring_dampers);
  addCount(out, Effect::SeriesDampers, series);
  addCount(out, Effect::ShearSprings, shear);
  addCount(out, Effect::BendingSprings, bending);
  addCount(out, Effect::BumpStops, bumpstops);
  if (patches) out.push_back({Effect::Patches, ""});
  addCount(out, Effect::ElementOutputs, outputs);
  if (m.spec.run.body_accelerations) out.push_back({Effect::BodyAccelerations, ""});
  const assessment::AssessmentSpec a = applicableAssessment(m);
  if (a.any()) out.push_back({Effect::Assessment, assessmentGroups(a)});
  return out;
}

std::string effectLine(const EffectUse& e) {
  std::string line(nameOf(e.effect));
  return e.detail.empty() ? line : line + ": " + e.detail;
}

std::string effectsSummary(const std::vector<EffectUse>& effects) {
  std::string out;
  for (const auto& e : effects) out += (out.empty() ? "" : ", ") + label(e);
  return out;
}

StageCosts stageCosts(const vehicle::StageClock& clock, const integ::Stats& stats) {
  StageCosts c;
  c.samples = clock.samples();
  c.rejected = clock.rejected();
  c.evaluations = clock.evaluations();
  c.period = clock.period();
  if (c.samples == 0) return c;
  const double scale = static_cast<double>(c.evaluations) / static_cast<double>(c.samples);
  double rhs = 0.0;
  for (const auto& entry : vehicle::kStageNames) {
    if (!clock.uses(entry.value)) continue;
    const double s = clock.sampledSeconds(entry.value) * scale;
    c.parts.push_back({std::string(entry.name), s, 0.0});
    rhs += s;
  }
  // The integration's time: its process CPU time (descheduled time is no cost of the run; the
  // sampled stages leave it out too, StageClock::finish), its wall time when no CPU time is known.
  // The observer is timed by the wall clock only (integ::Stats): its descheduled time is taken
  // out in the proportion of the whole integration's, CPU / wall.
  const bool cpu = stats.cpu_time_s > 0.0 && stats.wall_time_s > 0.0;
  const double total = cpu ? stats.cpu_time_s : stats.wall_time_s;
  const double running = cpu ? std::min(1.0, stats.cpu_time_s / stats.wall_time_s) : 1.0;
  const double observer = std::max(0.0, stats.callback_wall_time_s * running);
  c.parts.push_back({"integrator", std::max(0.0, total - observer - rhs), 0.0});
  c.parts.push_back({"observer", observer, 0.0});
  double sum = 0.0;
  for (const auto& p : c.parts) sum += p.seconds;
  if (!(sum > 0.0)) {
    c.parts.clear();
    return c;
  }
  for (auto& p : c.parts) p.share = p.seconds / sum;
  return c;
}

std::string costSummary(const StageCosts& c) {
  if (c.parts.empty()) return "rhs cost: not sampled";
  std::vector<StageShare> parts = c.parts;
  std::stable_sort(parts.begin(), parts.end(),
                   [](const StageShare& a, const StageShare& b) { return a.share > b.share; });
  std::string out;
  for (const auto& p : parts) {
    if (p.share < 0.005) continue;
    std::string name = p.name;
    std::replace(name.begin(), name.end(), '_', ' ');
    out += (out.empty() ? "" : ", ") + name + " " + percent(p.share);
  }
  return "rhs cost: " + out + " (1 in " + std::to_string(c.period) + " evaluations timed, " +
         std::to_string(c.samples) + " samples)";
}

void writeRunStats(io::ResultFile& f, const std::vector<EffectUse>& effects, const StageCosts& c) {
  std::string lines;
  for (const auto& e : effects) lines += (lines.empty() ? "" : "\n") + effectLine(e);
  f.attr("/stats", "effects", lines);
  f.attr("/stats", "stage_period", static_cast<std::int64_t>(c.period));
  f.attr("/stats", "stage_samples", static_cast<std::int64_t>(c.samples));
  f.attr("/stats", "stage_rejected", static_cast<std::int64_t>(c.rejected));
  if (c.parts.empty()) return;
  std::vector<std::string> names;
  std::vector<double> share, seconds;
  for (const auto& p : c.parts) {
    names.push_back(p.name);
    share.push_back(p.share);
    seconds.push_back(p.seconds);
  }
  f.stringDataset("/stats/stage_names", names);
  f.dataset("/stats/stage_share", share, "-");
  f.dataset("/stats/stage_seconds", seconds, "s");
}

}  // namespace rb::run
