#include "workbench/run/vehicle_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "workbench/core/strings.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/io/initial_output.hpp"
#include "workbench/run/channels.hpp"
#include "workbench/run/simulate.hpp"
#include "workbench/run/start_state.hpp"
#include "workbench/run/vehicle_outputs.hpp"
#include "workbench/vehicle/initial_conditions.hpp"

namespace rb::run {
namespace {

// /schema/series: /time and every output channel, before the run so that the partial file of a
// failed run has it too.
void writeSeriesSchema(const std::vector<OutputChannel>& outputs,
                       const std::vector<OutputChannel>& derived, bool contact, io::ResultFile& f) {
  std::vector<io::SchemaEntry> rows = {{"/time", "s", "output time", ""}};
  for (const auto& o : outputs) rows.push_back({o.path, o.units, o.meaning, o.codes});
  for (const auto& o : derived) rows.push_back({o.path, o.units, o.meaning, o.codes});
  std::vector<std::pair<std::string, std::string>> enums;
  if (contact) enums.emplace_back(kRegimeEnum, io::codesOf<dynamics::ContactRegime>());
  // The names the failure record (/stats failure_kind, failure_reason) takes, in their tables.
  enums.emplace_back("failure_kind", io::codesOf<integ::FailureKind>());
  if (contact) enums.emplace_back("failure_reason", io::codesOf<dynamics::ContactFailure>());
  io::writeSchema(f, "series", rows, enums);
}

// /stats of the contact models (their counters summed over the run's vehicles) and the warnings
// of a contact run.
void writeContactStats(const Model& m, const dynamics::ContactStats& cs,
                       const CreepageMaximum& creepage, io::ResultFile& f, VehicleRunResult& out) {
  f.attr("/stats", "model_evaluations", static_cast<std::int64_t>(cs.evaluations));
  f.attr("/stats", "shared_evaluations", static_cast<std::int64_t>(cs.shared_evaluations));
  f.attr("/stats", "kec_iterations", static_cast<std::int64_t>(cs.kec_iterations));
  f.attr("/stats", "lift_evaluations", static_cast<std::int64_t>(cs.lift_evaluations));
  f.attr("/stats", "consistent_iterations", static_cast<std::int64_t>(cs.consistent_iterations));
  f.attr("/stats", "max_creepage", creepage.value);
  if (cs.lift_evaluations > 0 && out.result.ok)
    out.warnings.push_back("wheel lift was refused in " + std::to_string(cs.lift_evaluations) +
                           " trial evaluations (the integrator retried smaller steps); the "
                           "accepted solution never lifted");
  if (m.lead().contact->creep != dynamics::CreepModel::None && creepage.value > kCreepageWarning)
    out.warnings.push_back("creepage reached " + formatNumber(creepage.value) +
                           " at t = " + formatNumber(creepage.t) + " s, beyond " +
                           formatNumber(kCreepageWarning) +
                           " where the creep law is calibrated (docs/contact_dynamics.md)");
}

// /initial_conditions: the conditions as given and the state the run starts from, so the result
// alone says where the motion began (written only when vehicle.initial gives any).
std::vector<io::SchemaEntry> writeInitialConditions(
    const vehicle::VehicleOde& ode, std::span<const vehicle::InitialCondition> conditions,
    const Eigen::VectorXd& equilibrium, const Eigen::VectorXd& y0, const std::string& prefix,
    io::ResultFile& f) {
  io::InitialConditionsRecord rec;
  for (const auto& c : conditions) {
    rec.body.push_back(c.body);
    rec.key.push_back(vehicle::initialConditionKey(c.coord, c.rate));
    rec.value.push_back(c.value);
    const bool length = c.coord == vehicle::kY || c.coord == vehicle::kZ;
    rec.unit.push_back(std::string(length ? "m" : "rad") + (c.rate ? "/s" : ""));
  }
  for (int i = 0; i < ode.size(); ++i) rec.state_names.push_back(ode.componentName(i));
  rec.equilibrium.assign(equilibrium.begin(), equilibrium.end());
  rec.state.assign(y0.begin(), y0.end());
  return io::writeInitialConditions(f, rec, prefix + "/initial_conditions");
}

// One vehicle of the run: its part of the run's ODE and state, its outputs and its assessment.
struct RunPart {
  const RunVehicle* v = nullptr;
  vehicle::VehicleOde* ode = nullptr;
  int offset = 0;  // its first component in the run's state
  std::unique_ptr<VehicleOutputs> outputs;
  AssessmentSetup assessment;
  double lead = 0.0;  // [m] arc length of its foremost body at t = 0
};

// The parts of the run's ODE, vehicle by vehicle, with their output plans.
std::vector<RunPart> makeParts(const Model& m, train::TrainOde& ode, const VehicleRunOptions& o) {
  const bool fixed_step = integ::makeIntegrator(m.solver)->isFixedStep();
  std::vector<RunPart> parts(m.vehicles.size());
  for (std::size_t k = 0; k < parts.size(); ++k) {
    RunPart& p = parts[k];
    p.v = &m.vehicles[k];
    p.ode = &ode.vehicle(static_cast<int>(k));
    p.offset = ode.offset(static_cast<int>(k));
    p.ode->setStageSampling(o.stage_period);
    p.outputs = std::make_unique<VehicleOutputs>(m, *p.v, *p.ode);
    // A fixed-step run is observed at step ends only, where the integrator's next right-hand side
    // starts: the observer's evaluation of the state serves as that right-hand side too.
    if (p.outputs->contact() != nullptr && fixed_step)
      p.outputs->contact()->shareOutputEvaluations(true);
    p.lead = p.v->vehicle.start + p.v->leadingX();
  }
  return parts;
}

// The run's start state: each vehicle's equilibrium with its initial conditions (recorded in its
// /initial_conditions).
Eigen::VectorXd startState(const std::vector<RunPart>& parts, int size, io::ResultFile& f) {
  Eigen::VectorXd y0(size);
  std::vector<io::SchemaEntry> schema;
  for (const auto& p : parts) {
    Eigen::VectorXd y = p.ode->initialState(0.0);
    if (!p.v->initial.empty()) {
      const Eigen::VectorXd equilibrium = y;
      startWithInitialConditions(*p.ode, p.v->initial, y);
      const auto rows =
          writeInitialConditions(*p.ode, p.v->initial, equilibrium, y, p.v->prefix(), f);
      schema.insert(schema.end(), rows.begin(), rows.end());
    }
    y0.segment(p.offset, y.size()) = y;
  }
  if (!schema.empty()) io::writeSchema(f, "initial_conditions", schema, {});
  return y0;
}

// After the run: each vehicle's assessment into its group, the summary lines (each vehicle's
// under its name when there are several) and the warnings, and /schema/assessment.
void finishAssessments(const Model& m, const std::vector<RunPart>& parts, std::size_t samples,
                       io::ResultFile& f, VehicleRunResult& out) {
  f.attr("/stats", "assessment_samples", static_cast<std::int64_t>(samples));
  if (!out.result.ok) {
    out.assessment_notes.emplace_back("assessment skipped: the run failed");
    return;
  }
  const bool several = parts.size() > 1;
  double cpu = 0.0;
  std::vector<io::SchemaEntry> schema;
  for (const auto& p : parts) {
    AssessmentOutcome a = finishAssessment(m, p.assessment, f, p.v->prefix() + "/assessment");
    cpu += a.cpu_s;
    schema.insert(schema.end(), a.schema.begin(), a.schema.end());
    if (several && !a.summary.empty()) out.assessment_summary.push_back(p.v->name + ":");
    for (auto& line : a.summary) out.assessment_summary.push_back(std::move(line));
    for (auto& w : a.warnings)
      out.warnings.push_back(several ? p.v->name + ": " + w : std::move(w));
  }
  if (!schema.empty()) io::writeSchema(f, "assessment", schema, {});
  if (out.assessment_summary.empty()) return;
  f.attr("/stats", "assessment_cpu_s", cpu);
  for (auto& n : out.assessment_notes) out.assessment_summary.push_back("  " + n);
}

// The connections' channels, then every vehicle's motion when it is a state.
void declareTrainChannels(const train::TrainOde& ode, std::vector<OutputChannel>& out) {
  for (const auto& c : ode.connections())
    for (const auto& row : kConnectionChannels)
      out.push_back({"/train/connections/" + c.name + "/" + std::string(row.name),
                     std::string(row.unit), std::string(row.meaning), ""});
  if (!ode.longitudinal()) return;
  for (int k = 0; k < ode.vehicles(); ++k)
    for (const auto& row : kMotionChannels)
      out.push_back({"/vehicles/" + ode.name(k) + "/motion/" + std::string(row.name),
                     std::string(row.unit), std::string(row.meaning), ""});
}

// The jerk of each vehicle whose motion is a state: series computed after the run from its sampled
// acceleration (train::jerk), one value per output time.
constexpr double kComfortJerkWindow = 1.0;  // [s] the ramp comfort limits are stated over

struct JerkSeries {
  const char* name;
  double window;
  const char* meaning;
};
inline constexpr JerkSeries kJerkSeries[] = {
    {"jerk", 0.0,
     "rate of change of the acceleration along the track at the output interval (central "
     "differences of the sampled acceleration)"},
    {"jerk_1s", kComfortJerkWindow,
     "change of the acceleration along the track over 1 s centred on the sample, per second "
     "(the window shortened at the run's ends)"},
};

std::vector<OutputChannel> jerkChannels(const train::TrainOde& ode) {
  std::vector<OutputChannel> out;
  if (!ode.longitudinal()) return out;
  for (int k = 0; k < ode.vehicles(); ++k)
    for (const auto& j : kJerkSeries)
      out.push_back({"/vehicles/" + ode.name(k) + "/motion/" + j.name, "m/s^3", j.meaning, ""});
  return out;
}

// The samples' times and each vehicle's acceleration, as the sampler saw them.
struct AccelerationRecord {
  std::vector<double> t;
  std::vector<std::vector<double>> a;  // per vehicle
};

void writeJerk(const train::TrainOde& ode, AccelerationRecord rec, double t_reached,
               io::ResultFile& f) {
  // A sample the run did not write (non-finite, past the failure) is not the file's.
  std::size_t n = 0;
  while (n < rec.t.size() && rec.t[n] <= t_reached + 1e-12 * std::max(1.0, std::abs(t_reached)))
    ++n;
  rec.t.resize(n);
  for (int k = 0; k < ode.vehicles(); ++k) {
    auto& a = rec.a[static_cast<std::size_t>(k)];
    a.resize(n);
    for (const auto& j : kJerkSeries)
      f.dataset("/vehicles/" + ode.name(k) + "/motion/" + j.name, train::jerk(rec.t, a, j.window),
                "m/s^3");
  }
}

double* sampleTrain(const train::TrainOde& ode, double* out) {
  for (std::size_t i = 0; i < ode.connections().size(); ++i)
    for (const auto& row : kConnectionChannels)
      *out++ = row.get(ode.connectionState(static_cast<int>(i)));
  if (!ode.longitudinal()) return out;
  for (int k = 0; k < ode.vehicles(); ++k)
    for (const auto& row : kMotionChannels) *out++ = row.get(ode.motion(k));
  return out;
}

// The contact models' counters summed over the vehicles, and the largest creepage of any.
void writeContactCounters(const Model& m, const std::vector<RunPart>& parts, io::ResultFile& f,
                          VehicleRunResult& out) {
  dynamics::ContactStats cs;
  CreepageMaximum creepage;
  for (const auto& p : parts) {
    const dynamics::ContactVehicleOde* c = p.outputs->contact();
    if (c == nullptr) continue;
    const dynamics::ContactStats& s = c->stats();
    cs.evaluations += s.evaluations;
    cs.shared_evaluations += s.shared_evaluations;
    cs.kec_iterations += s.kec_iterations;
    cs.lift_evaluations += s.lift_evaluations;
    cs.consistent_iterations += s.consistent_iterations;
    if (p.outputs->creepage().value > creepage.value) creepage = p.outputs->creepage();
  }
  writeContactStats(m, cs, creepage, f, out);
  const bool several = parts.size() > 1;
  for (const auto& p : parts) {
    std::vector<std::string> band;
    p.outputs->bandOscillationWarnings(band);
    for (auto& w : band) out.warnings.push_back(several ? p.v->name + ": " + w : std::move(w));
  }
  for (const auto& p : parts) {
    std::vector<std::string> lines;
    p.outputs->writeRailAnswers(f, lines);
    if (lines.empty()) continue;
    if (several) out.rails_summary.push_back(p.v->name + ":");
    for (auto& l : lines) out.rails_summary.push_back(std::move(l));
  }
  if (!out.rails_summary.empty())
    out.rails_summary.insert(out.rails_summary.begin(),
                             "rails (where each wheel moved onto a further rail, the largest "
                             "normal force on each):");
}

}  // namespace

VehicleRunResult runVehicle(const Model& m, io::ResultFile& f, const VehicleRunOptions& o) {
  RB_CHECK(m.hasVehicle(), "runVehicle needs a vehicle");
  const std::unique_ptr<train::TrainOde> ode = makeRunOde(m);
  std::vector<RunPart> parts = makeParts(m, *ode, o);
  const bool contact = m.hasContact();
  const vehicle::VehicleModel& lead = m.lead().vehicle;

  SimulationRequest r;
  r.system = ode.get();
  r.solver = m.solver;
  r.y0 = startState(parts, ode->size(), f);
  ode->initialLongitudinal(r.y0);
  train::TrainOde* train = ode.get();
  r.t_end = m.t_end;
  r.output_every = m.spec.run.output_every;
  r.progress = o.progress;
  // Arc length of the leading body, the body compile() runs to the track end, so that a failure's
  // distance is where the first wheelset was.
  const double lead_s = parts.front().lead;
  r.distance = [lead_s, &lead, train](double t, const Eigen::VectorXd& y) {
    return lead_s + (train->longitudinal() ? y[train->travelIndex(0)] : lead.travel(t));
  };

  // Channels, in the order the sampler fills them: the run's speed, then vehicle by vehicle.
  r.outputs.push_back({"/vehicle/speed", "m/s", "speed of the vehicle along the track", ""});
  for (const auto& p : parts) p.outputs->declare(f, r.outputs);
  if (parts.size() > 1) {
    std::string names;
    for (const auto& v : m.vehicles) names += (names.empty() ? "" : "\n") + v.name;
    f.attr("/vehicles", "names", names);
  }
  declareTrainChannels(*train, r.outputs);
  writeSeriesSchema(r.outputs, jerkChannels(*train), contact, f);
  AccelerationRecord accelerations;
  accelerations.a.resize(train->longitudinal() ? static_cast<std::size_t>(train->vehicles()) : 0);
  r.sample = [&](double t, const Eigen::VectorXd& y, double* out) {
    // The vehicles' forward motion and the connections' loads at this state first.
    (void)train->prepare(t, y.data());
    *out++ = train->longitudinal() ? train->motion(0).speed : lead.speedAt(t);
    for (auto& p : parts) out = p.outputs->sample(t, y.data() + p.offset, out);
    train->updateAccelerations();  // from the contact forces the outputs just evaluated
    out = sampleTrain(*train, out);
    if (accelerations.a.empty()) return;
    accelerations.t.push_back(t);
    for (int k = 0; k < train->vehicles(); ++k)
      accelerations.a[static_cast<std::size_t>(k)].push_back(train->motion(k).acceleration);
  };
  f.attr("/", "solver", m.solver.method);
  f.attr("/", "contact_method",
         contact ? std::string(dynamics::ContactModel::methodName(m.lead().contact->method))
                 : std::string("none (wheelsets guided)"));
  VehicleRunResult out;
  out.warnings = m.run_warnings;
  if (m.step_limit.computed) {
    f.attr("/stats", "step_limit", m.step_limit.h_max);
    f.attr("/stats", "step_limit_mode", m.step_limit.mode);
  }
  // The assessment samples its own signals at its own interval (nothing when not asked), vehicle
  // by vehicle.
  for (std::size_t k = 0; k < parts.size(); ++k)
    parts[k].assessment = setupAssessment(m, k, parts[k].outputs->contact(), out.assessment_notes);
  const bool assess = parts.front().assessment.spec.any();
  ExtraSampling extra;
  if (assess) {
    extra.every = parts.front().assessment.signals.dt;
    extra.sample = [&](double t, const Eigen::VectorXd& y) {
      (void)train->prepare(t, y.data());
      for (std::size_t k = 0; k < parts.size(); ++k) {
        RunPart& p = parts[k];
        p.outputs->state().at(t, y.data() + p.offset);
        const double travel = train->longitudinal() ? train->motion(static_cast<int>(k)).travel
                                                    : p.v->vehicle.travel(t);
        sampleAssessment(p.assessment, p.outputs->state(), p.outputs->contact() != nullptr, t,
                         p.lead + travel);
      }
    };
    r.extra = &extra;
  }
  out.result = simulate(r, f);
  if (!accelerations.a.empty())
    writeJerk(*train, std::move(accelerations), out.result.t_reached, f);
  if (assess) finishAssessments(m, parts, extra.samples, f, out);
  if (contact) writeContactCounters(m, parts, f, out);
  out.effects = compiledEffects(m);
  out.costs = stageCosts(ode->vehicle(0).stageClock(), out.result.stats);
  writeRunStats(f, out.effects, out.costs);
  writeWarnings(f, out.warnings);
  return out;  // the caller's finalize() writes what is buffered
}

}  // namespace rb::run
