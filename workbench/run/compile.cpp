#include "workbench/run/compile.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "workbench/core/strings.hpp"
#include "workbench/dynamics/contact_methods.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/run/start_state.hpp"
#include "workbench/run/vehicle_run.hpp"
#include "workbench/track/psd.hpp"
#include "workbench/vehicle/guided.hpp"
#include "workbench/vehicle/initial_conditions.hpp"

namespace rb::run {
namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Checks of the speed ramp: V(t) = V0 + a t must stay >= 0 over the run (no clamping: a vehicle
// that stops and reverses is not what a ramp scenario means).
void checkRamp(const Model& c, Diagnostics& d) {
  const auto& spec = c.spec;
  const double a = spec.vehicle.acceleration;
  if (a >= 0.0) return;
  const double t_stop = spec.vehicle.speed / -a;
  if (spec.run.duration > 0 && spec.run.duration > t_stop)
    d.add(spec.vehicle.loc, "vehicle: acceleration " + formatNumber(a) +
                                " m/s^2 stops the vehicle at t = " + formatNumber(t_stop) +
                                " s, before run.duration = " + formatNumber(spec.run.duration) +
                                " s");
  if (!(spec.run.duration > 0)) {
    const double dist = spec.run.distance > 0 ? spec.run.distance
                                              : c.track->geometry().length() -
                                                    (c.lead().vehicle.start + c.leadingX());
    if (spec.vehicle.speed * spec.vehicle.speed + 2.0 * a * dist < 0.0)
      d.add(spec.vehicle.loc,
            "vehicle: acceleration " + formatNumber(a) + " m/s^2 stops the vehicle after " +
                formatNumber(spec.vehicle.speed * t_stop / 2.0) + " m, before the run's distance " +
                formatNumber(dist) + " m; give run.duration or a smaller deceleration");
  }
}

// Simulated time of a vehicle run: run.duration, or run.distance (default: until the leading
// body reaches the end of the track) at the vehicle's speed.
double endTime(const Model& c) {
  const auto& run = c.spec.run;
  if (run.duration > 0) return run.duration;
  const auto& v = c.lead().vehicle;
  double distance =
      run.distance > 0 ? run.distance : c.track->geometry().length() - (v.start + c.leadingX());
  distance = std::max(distance, 0.0);
  const double a = v.acceleration;
  double t = distance / v.speed;
  if (a != 0.0) {
    // Speed ramp: V0 t + a t^2 / 2 = distance (the root reached first; checkRamp() made sure it
    // is reached before the speed would become negative).
    const double disc = v.speed * v.speed + 2.0 * a * distance;
    t = disc <= 0.0 ? 0.0 : 2.0 * distance / (v.speed + std::sqrt(disc));
  }
  // A fixed-step method ends on its step grid: the last grid time at or before the distance is
  // reached (the leading body stops less than one step's travel short; never beyond the track).
  if (c.solver.step > 0 && integ::isFixedStep(c.solver.method)) {
    const double n = std::floor(t / c.solver.step + 1e-6);
    t = n * c.solver.step;
  }
  return t;
}

// Where vehicle k of the run is given and how a message names it: the vehicle{} block, or its
// entry of train.vehicles (a train's problem belongs to the vehicle that has it).
std::pair<SourceLoc, std::string> vehicleAt(const Model& c, std::size_t k) {
  if (c.spec.train.empty() || k >= c.spec.train.size()) return {c.spec.vehicle.loc, "vehicle"};
  return {c.spec.train[k].loc,
          "train.vehicles[" + std::to_string(k + 1) + "] '" + c.vehicles[k].name + "'"};
}

// Every body must stay on the track for the whole run: beyond the end the geometry would be
// extrapolated, which no result may silently rest on. Before s = 0 the track continues as the
// straight extension of its start (TrackGeometry::at), which is exact when the track starts with
// a tangent without gradient: the rear bodies of a vehicle whose reference point starts at s = 0
// stand there (the paper's validation runs); before any other first segment it is an error.
void checkTrackRange(const Model& c, Diagnostics& d) {
  const auto& v = c.lead().vehicle;
  const double length = c.track->geometry().length();
  const double tol = 1e-9 * std::max(1.0, length);
  const Model::Stretch covered = c.coveredStretch();
  const double rear = covered.s_from;
  const double lead0 = v.start + c.leadingX();
  const auto& segs = c.spec.track.segments;
  const bool straight_start = !segs.empty() && segs.front().kind == track::SegmentKind::Tangent &&
                              segs.front().gradient == 0.0 && segs.front().cant == 0.0;
  if (rear < -tol && !straight_start) {
    // The vehicle that stands furthest back (a train's last one, as a rule) is the one to move.
    std::size_t last = 0;
    for (std::size_t k = 0; k < c.vehicles.size(); ++k)
      if (c.vehicles[k].vehicle.start + c.vehicles[k].trailingX() <
          c.vehicles[last].vehicle.start + c.vehicles[last].trailingX())
        last = k;
    const RunVehicle& rv = c.vehicles[last];
    const auto [loc, who] = vehicleAt(c, last);
    d.add(loc, who + ": the rearmost body starts at s = " + formatNumber(rear) +
                   " m, before the start of the track (s = 0), which does not start with a level "
                   "tangent; give " +
                   (c.spec.train.empty() ? "vehicle.start" : "its vehicle.start") +
                   " >= " + formatNumber(rv.vehicle.start - rear) + " m");
  }
  // A start at or beyond the track's end is the vehicle's problem, not the run's length.
  if (lead0 >= length - tol) {
    const auto [loc, who] = vehicleAt(c, 0);
    d.add(loc, who + ": the leading body starts at s = " + formatNumber(lead0) +
                   " m, at or beyond the end of the track at " + formatNumber(length) +
                   " m; give vehicle.start < " + formatNumber(v.start + length - lead0) + " m");
    return;
  }
  if (!(c.t_end > 0)) {
    d.add(c.spec.run.loc,
          "run: nothing to simulate: the leading body starts at s = " + formatNumber(lead0) +
              " m and the track ends at " + formatNumber(length) + " m");
    return;
  }
  const double lead_end = covered.s_to;
  if (lead_end > length + tol)
    d.add(c.spec.run.loc,
          "run: the leading body would reach s = " + formatNumber(lead_end) + " m after " +
              formatNumber(c.t_end) + " s, beyond the end of the track at " + formatNumber(length) +
              " m (the geometry would be extrapolated); shorten run.distance or run.duration "
              "(at most " +
              formatNumber(length - lead0) + " m) or lengthen the track");
}

// The output grid and size are known before the run: a fixed-step method needs every output
// time on its step grid, and the number of samples is bounded.
void checkOutputs(const Model& c, Diagnostics& d) {
  const auto& run = c.spec.run;
  const double n = std::ceil(c.t_end / run.output_every - 1e-9);
  if (n > run.max_output_samples) {
    d.add(
        run.output_every_loc.file.empty() ? run.loc : run.output_every_loc,
        "run.output.every: " + formatNumber(run.output_every) + " s over " + formatNumber(c.t_end) +
            " s gives " + formatNumber(n) + " output times, more than run.output.max_samples = " +
            formatNumber(run.max_output_samples) + " (raise it if the memory and disk are there)");
    return;
  }
  try {
    auto integ = integ::makeIntegrator(c.solver);
    if (!integ->isFixedStep()) return;
    const double h = c.solver.step;
    auto onGrid = [h](double t) {
      const double r = t / h;
      return std::abs(r - std::round(r)) <= 1e-6;
    };
    if (!onGrid(run.output_every))
      d.add(
          c.solver.loc.file.empty() ? run.loc : c.solver.loc,
          "solver.step: the output interval run.output.every = " + formatNumber(run.output_every) +
              " s is not a multiple of the " + std::string(integ->name()) + " step " +
              formatNumber(h) + " s; choose an output interval that is a multiple of the step");
    else if (!onGrid(c.t_end))
      d.add(c.solver.loc.file.empty() ? run.loc : c.solver.loc,
            "solver.step: the run ends at t = " + formatNumber(c.t_end) +
                " s, which is not on the " + std::string(integ->name()) + " step grid k * " +
                formatNumber(h) + " s; choose run.duration (or run.distance / speed) on the grid");
  } catch (const InputError& e) {
    d.add(e);
  }
}

}  // namespace

double RunVehicle::leadingX() const {
  double lead = -1e300;
  for (const auto& b : vehicle.bodies) lead = std::max(lead, b.x);
  return lead;
}

double RunVehicle::trailingX() const {
  double rear = 1e300;
  for (const auto& b : vehicle.bodies) rear = std::min(rear, b.x);
  return rear;
}

Model::Stretch Model::coveredStretch() const {
  // A computed motion (train.longitudinal) is bounded by the train as one mass (its connections
  // are internal) under every vehicle's largest traction and the steepest downhill slope of the
  // track, from V0; the run itself refuses a vehicle past the track's end.
  double bound = 0.0;  // [m/s^2]
  if (longitudinal.spec.on) {
    double traction = 0.0, mass = 0.0;
    for (std::size_t k = 0; k < vehicles.size(); ++k) {
      mass += train::longitudinalMass(vehicles[k].vehicle, false);
      double most = 0.0;
      for (const double f : longitudinal.traction[k].force) most = std::max(most, f);
      traction += most;
    }
    double downhill = 0.0;
    const track::TrackGeometry& g = track->geometry();
    for (double s = 0.0; s <= g.length(); s += 10.0)
      downhill = std::max(downhill, -g.at(s).gradient);
    bound = traction / mass + vehicles.front().vehicle.gravity * downhill;
  }
  Stretch out{1e300, -1e300};
  for (const auto& v : vehicles) {
    const double travel = longitudinal.spec.on
                              ? v.vehicle.speedAt(0.0) * t_end + 0.5 * bound * t_end * t_end
                              : v.vehicle.travel(t_end);
    out.s_from = std::min(out.s_from, v.vehicle.start + v.trailingX());
    out.s_to = std::max(out.s_to, v.vehicle.start + v.leadingX() + travel);
  }
  return out;
}

namespace {

// Track, integrator, vehicle and contact model: every problem of each part, all at once.
void compileParts(const CompileOptions& o, Model& c, Diagnostics& d) {
  const auto& spec = c.spec;
  auto t0 = std::chrono::steady_clock::now();
  try {
    c.track = track::compileTrack(spec.track);
  } catch (const InputError& e) {
    d.add(e);
  }
  c.track_build_s = seconds(t0);
  if (spec.has_solver) {
    c.solver = spec.solver;
    try {
      (void)integ::makeIntegrator(c.solver);
    } catch (const InputError& e) {
      d.add(e);
    }
  } else {
    // The paper's validation runs: ABM with 1 ms steps (section 5.2).
    c.solver.method = integ::kAbm;
    c.solver.step = 1e-3;
  }
  if (!spec.has_vehicle || !c.track) return;
  // One vehicle{} block, or every vehicle of train{} (each with its own profiles and contact).
  std::vector<scenario::TrainVehicleSpec> entries = spec.train;
  if (entries.empty())
    entries.push_back({"",
                       spec.vehicle,
                       spec.has_profiles,
                       spec.profiles,
                       spec.has_contact,
                       spec.guided,
                       false,
                       spec.contact,
                       spec.vehicle.loc,
                       {},
                       {}});
  dynamics::TableCache cache =
      o.table_cache.empty() ? dynamics::TableCache() : dynamics::TableCache(o.table_cache);
  for (const auto& e : entries) {
    try {
      RunVehicle v;
      v.name = e.name;
      v.vehicle = vehicle::compileVehicle(e.vehicle, *c.track);
      v.initial = e.vehicle.initial;
      if (e.has_contact)
        v.contact = dynamics::compileContact(e.profiles, e.contact, v.vehicle, *c.track, &cache);
      c.vehicles.push_back(std::move(v));
    } catch (const InputError& err) {
      d.add(err);
    }
  }
  // A vehicle that did not compile leaves the run incomplete: nothing after this may assume the
  // train's vehicles are all there.
  if (c.vehicles.size() != entries.size()) c.vehicles.clear();
}

// The vehicles of a train behind the first: each behind the one before it without overlap (the
// foremost body of each behind the rearmost body of the one in front). The track range of the
// whole train is checkTrackRange's: from the last vehicle's rearmost body to the first's
// foremost.
void checkTrainPlaces(const Model& c, Diagnostics& d) {
  for (std::size_t k = 1; k < c.vehicles.size(); ++k) {
    const RunVehicle& v = c.vehicles[k];
    const RunVehicle& front = c.vehicles[k - 1];
    const SourceLoc& loc = c.spec.train[k].loc;
    const double lead = v.vehicle.start + v.leadingX();
    const double front_rear = front.vehicle.start + front.trailingX();
    if (!(lead < front_rear))
      d.add(loc, "train: vehicle '" + v.name + "' overlaps '" + front.name +
                     "': its foremost body starts at s = " + formatNumber(lead) +
                     " m, not behind the rearmost body of '" + front.name +
                     "' at s = " + formatNumber(front_rear) + " m");
  }
}

// The car body a connection acts on: by name, or the vehicle's only car body.
int connectionBody(const RunVehicle& v, const std::string& name, const SourceLoc& loc,
                   const std::string& what, Diagnostics& d) {
  const vehicle::VehicleModel& m = v.vehicle;
  if (!name.empty()) {
    const int b = m.findBody(name);
    if (b < 0 || (m.bodies[static_cast<std::size_t>(b)].kind != vehicle::BodyKind::CarBody &&
                  m.bodies[static_cast<std::size_t>(b)].kind != vehicle::BodyKind::Bogie))
      d.add(loc, what + ": vehicle '" + v.name + "' has no car body or bogie named '" + name + "'");
    return b;
  }
  int found = -1, count = 0;
  for (std::size_t b = 0; b < m.bodies.size(); ++b)
    if (m.bodies[b].kind == vehicle::BodyKind::CarBody) {
      found = static_cast<int>(b);
      ++count;
    }
  if (count != 1)
    d.add(loc, what + ": vehicle '" + v.name + "' has " + std::to_string(count) +
                   " car bodies: name the one the connection acts on (front_body, rear_body)");
  return found;
}

// train.connections and train.longitudinal on the compiled vehicles.
void compileTrain(Model& c, Diagnostics& d) {
  const auto& spec = c.spec;
  const auto place = [&](const std::string& name) {
    for (std::size_t k = 0; k < c.vehicles.size(); ++k)
      if (c.vehicles[k].name == name) return static_cast<int>(k);
    return -1;
  };
  for (const auto& cs : spec.train_connections) {
    train::validateConnection(cs, d);
    train::Connection con;
    con.name = cs.front + "-" + cs.rear;
    con.front = place(cs.front);
    con.rear = place(cs.rear);
    if (con.front < 0 || con.rear != con.front + 1) continue;  // refused by the scenario check
    const std::string what = "train.connections '" + con.name + "'";
    const RunVehicle& f = c.vehicles[static_cast<std::size_t>(con.front)];
    const RunVehicle& r = c.vehicles[static_cast<std::size_t>(con.rear)];
    con.front_body = connectionBody(f, cs.front_body, cs.loc, what, d);
    con.rear_body = connectionBody(r, cs.rear_body, cs.loc, what, d);
    if (con.front_body < 0 || con.rear_body < 0) continue;
    // The buffer faces' gap at the start, along the track: they may touch, not overlap.
    const double gap = f.vehicle.start +
                       f.vehicle.bodies[static_cast<std::size_t>(con.front_body)].x + cs.front_end -
                       (r.vehicle.start +
                        r.vehicle.bodies[static_cast<std::size_t>(con.rear_body)].x + cs.rear_end);
    if (gap < -1e-9)
      d.add(cs.loc, what + ": the buffer faces overlap by " + formatNumber(-gap) +
                        " m at the start (place '" + r.name + "' so that they touch: its start " +
                        formatNumber(r.vehicle.start + gap) + " m or less)");
    else if (gap > 1.0)
      d.add(cs.loc, what + ": the buffer faces are " + formatNumber(gap) +
                        " m apart at the start (more than 1 m: are the vehicles' starts and the "
                        "headstocks' x right?)");
    con.spec = cs;
    c.connections.push_back(std::move(con));
  }
  c.longitudinal.spec = spec.train_longitudinal;
  if (!spec.train_longitudinal.on) return;
  if (!(spec.run.duration > 0))
    d.add(spec.train_longitudinal.loc,
          "train.longitudinal: give run.duration (the distance a train with a computed motion "
          "covers is not known before it runs)");
  for (std::size_t k = 0; k < c.vehicles.size(); ++k) {
    const auto& e = spec.train[k];
    const std::string what = "train.vehicles[" + std::to_string(k + 1) + "]";
    train::validateTraction(e.traction, what, d);
    train::validateResistance(e.resistance, what, d);
    const RunVehicle& rv = c.vehicles[k];
    if (e.traction.given() &&
        spec.train_longitudinal.traction_at == train::TractionPath::Wheelsets &&
        !(rv.contact && rv.contact->spin == dynamics::WheelsetSpin::Free))
      d.add(e.loc, what +
                       ": traction at the wheelsets (train.longitudinal.traction_at) needs "
                       "wheel/rail contact with a free wheelset spin (contact.wheelset_spin = "
                       "\"free\"); give traction_at = \"vehicle\" to apply it as a force");
    c.longitudinal.traction.push_back(e.traction);
    c.longitudinal.resistance.push_back(e.resistance);
    // The longitudinal equation sums traction, resistance, slope and connections only.
    for (const auto& f : rv.vehicle.external_forces)
      c.warnings.push_back(f.loc.str() + ": warning: element '" + f.name +
                           "' (external_force): its component along the track is not in the "
                           "vehicle's longitudinal motion (train.longitudinal), only in its "
                           "bodies' other coordinates; give a load along the track as traction");
  }
}

// Blocks and outputs that need a vehicle in a scene that has none.
// The model of a loaded scenario: its parts, and a train's connections and longitudinal motion.
void compileModelParts(const CompileOptions& o, Model& c, Diagnostics& d) {
  compileParts(o, c, d);
  if (c.vehicles.size() > 1) compileTrain(c, d);
}

void checkWithoutVehicle(const Model& c, Diagnostics& d) {
  const auto& spec = c.spec;
  if (spec.has_contact) d.add(spec.contact.loc, "contact: needs a vehicle { ... } block");
  if (!spec.run.output_elements.empty())
    d.add(spec.run.loc, "run.output.elements: the scene has no vehicle");
  if (spec.run.body_accelerations)
    d.add(spec.run.loc, "run.output.body_accelerations: the scene has no vehicle");
}

// The element outputs by name, the speed ramp, the end time, the track range and the outputs.
void checkVehicleRun(Model& c, Diagnostics& d) {
  const auto& spec = c.spec;
  // An element named in run.output.elements is written for every vehicle that has one of that
  // name (in a train, vehicles of the same file share their names); a name no vehicle has is an
  // error. External forces are written anyway: naming one asks for nothing more.
  for (const auto& name : spec.run.output_elements) {
    bool found = false;
    for (auto& rv : c.vehicles) {
      if (auto id = rv.vehicle.findElement(name)) {
        rv.output_elements.push_back(*id);
        found = true;
      }
      found = found || rv.vehicle.findExternalForce(name) >= 0;
    }
    if (found) continue;
    const vehicle::VehicleModel& v = c.lead().vehicle;
    std::vector<std::string> names;
    for (auto id : v.elements()) names.push_back(v.elementName(id));
    for (const auto& e : v.external_forces) names.push_back(e.name);
    std::string hint = closestMatch(name, names);
    d.add(spec.run.loc, "run.output.elements: no element named '" + name + "'" +
                            (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }
  if (!(spec.vehicle.speed > 0) && !(spec.run.duration > 0)) {
    d.add(spec.vehicle.loc, "vehicle: speed is 0, so give run.duration");
    return;
  }
  checkRamp(c, d);
  if (d.empty()) {
    c.t_end = endTime(c);
    checkTrackRange(c, d);
    checkTrainPlaces(c, d);
  }
  if (d.empty()) checkOutputs(c, d);
}

// Irregularities that begin at s = 0 without a fade-in under wheelsets that start before s = 0, on
// the perfect track: those wheelsets meet a step in the rails at s = 0 (the paper's case 3 keeps
// it for its values). The constraint methods follow the step kinematically; wheels that can leave
// the rail (a method without constraint tables) lose contact over it and land hard, so there it
// is a warning of the run as well. Empty when nothing starts before a step of 0.01 mm or more.
std::string irregularityStepWarning(const Model& c) {
  if (!c.hasVehicle() || !c.track->irregularities()) return {};
  const track::IrregularityPoint p = c.track->irregularities()->at(0.0);
  const double step =
      std::max({std::abs(p.y_l), std::abs(p.y_r), std::abs(p.z_l), std::abs(p.z_r)});
  if (!(step >= 1e-5)) return {};
  std::vector<std::string> behind;
  for (const auto& v : c.vehicles)
    for (const auto& b : v.vehicle.bodies)
      if (b.kind == vehicle::BodyKind::Wheelset && v.vehicle.start + b.x < 0.0)
        behind.push_back(v.name.empty() ? b.name : v.name + "." + b.name);
  if (behind.empty()) return {};
  return "track.irregularities begin at s = 0 without a fade-in and " + join(behind, ", ") +
         (behind.size() == 1 ? " starts" : " start") +
         " before s = 0 on the perfect track: a step of up to " + formatNumber(step * 1e3, 3) +
         " mm in the rails at s = 0 (give track.irregularities.fade_in, or vehicle.start so that "
         "every wheelset starts at s >= 0)";
}

// Warnings of the track, the tables and the scene, each as file:line: warning: ...
void collectWarnings(Model& c) {
  const auto& spec = c.spec;
  const auto& irr = spec.track.irregularities;
  if (irr.source == track::IrregularitySource::Psd && !track::psdVerified(irr.spectrum))
    c.warnings.push_back(irr.loc.str() + ": warning: the parameters of spectrum '" + irr.spectrum +
                         "' are UNVERIFIED against a primary source (see docs/track.md)");
  for (const auto& w : c.track->warnings())
    c.warnings.push_back(w.loc.str() + ": warning: " + w.message);
  if (c.hasContact()) {
    for (const auto& w : c.lead().contact->warnings)
      c.warnings.push_back(w);  // already "file:line: warning: ..."
    // Printed by check and run, and recorded in the result's /stats/warnings.
    for (const auto& w : c.lead().contact->gauge_warnings) {
      c.warnings.push_back(irr.loc.str() + ": warning: " + w);
      c.run_warnings.push_back(w);
    }
    // A law that does not saturate at mu N overstates every sliding patch (flange contact,
    // curves, traction): its Y/Q and sum Y are not a safety answer (docs/creep.md).
    if (!dynamics::creepLawSaturates(spec.contact.creep)) {
      const std::string w = "contact.creep = '" + std::string(nameOf(spec.contact.creep)) +
                            "' does not saturate at mu N: forces on sliding patches (flange, "
                            "tight curves, traction) exceed the friction limit; use it for the "
                            "linear range only";
      c.warnings.push_back(spec.contact.loc.str() + ": warning: " + w);
      c.run_warnings.push_back(w);
    }
  }
  if (const std::string w = irregularityStepWarning(c); !w.empty()) {
    c.warnings.push_back(irr.loc.str() + ": warning: " + w);
    if (c.hasContact() && !dynamics::methodInfo(spec.contact.method).table)
      c.run_warnings.push_back(w + "; wheels may lose contact over it and land hard");
  }
}

// A fixed step beyond the linear stability limit of the model's stiffest decaying mode makes that
// mode grow from step to step; in the contact vehicle it is then bounded only by the saturation
// of the creep law, and the run ends "ok" on a wrong answer (the free spin with ABM at 1 ms: 0.5
// mm off on case 3). Refused unless the scenario accepts it; a step within 20 % of the limit is
// a warning, because the limit moves with the normal loads and the speed during the run.
void checkStepLimit(Model& c, integ::OdeSystem& ode, const Eigen::VectorXd& y0, Diagnostics& d) {
  const auto& s = c.solver;
  if (!integ::isFixedStep(s.method) || !(s.step > 0)) return;
  const FixedStepMethod method =
      s.method == integ::kRk4 ? FixedStepMethod::Rk4 : FixedStepMethod::Abm;
  const std::vector<int> expo =
      s.stiff == integ::StiffTreatment::Exponential ? ode.stiffComponents() : std::vector<int>{};
  c.step_limit = fixedStepLimit(ode, 0.0, y0, method, expo);
  const StepLimit& lim = c.step_limit;
  if (!lim.computed) {
    c.run_warnings.push_back(
        "the stability limit of the fixed step could not be computed at "
        "the initial state (" +
        lim.why_not + ")");
    return;
  }
  if (!std::isfinite(lim.h_max) || s.step <= 0.8 * lim.h_max) return;
  const std::string what =
      "solver.step " + formatNumber(s.step * 1e3) + " ms " +
      (s.step > lim.h_max ? "is beyond" : "is within 20 % of") + " the stability limit of " +
      s.method + (expo.empty() ? "" : " (stiff components exponential)") +
      " on the model's stiffest mode at the start: eigenvalue " + formatNumber(lim.lambda.real()) +
      (lim.lambda.imag() != 0.0 ? " +/- " + formatNumber(std::abs(lim.lambda.imag())) + "i" : "") +
      " 1/s, dominated by " + lim.mode + "; largest stable step " + formatNumber(lim.h_max * 1e3) +
      " ms";
  if (s.step <= lim.h_max) {
    c.run_warnings.push_back(what + " (the limit moves with the normal loads and the speed)");
    return;
  }
  if (s.accept_unstable_step) {
    c.run_warnings.push_back(what +
                             "; run anyway (solver.accept_unstable_step): the mode grows "
                             "from step to step and the result is not reliable");
    return;
  }
  std::vector<std::string> adaptive;
  for (const auto& m : integ::methods())
    if (!m.fixed_step) adaptive.push_back(m.name);
  const bool can_expo =
      s.stiff == integ::StiffTreatment::Explicit && !ode.stiffComponents().empty();
  const SourceLoc& loc = !s.loc.file.empty()            ? s.loc
                         : !c.spec.run.loc.file.empty() ? c.spec.run.loc
                                                        : c.spec.vehicle.loc;
  d.add(loc, what + ". Choose solver.step <= " + formatNumber(0.8 * lim.h_max * 1e3) + " ms" +
                 (can_expo ? ", solver.stiff = \"exponential\"" : "") + ", an adaptive method (" +
                 join(adaptive, ", ") +
                 "), or solver.accept_unstable_step = true to run it "
                 "anyway (the result would not be reliable)");
}

// WheelOutput::regime of a wheel in contact on its flange alone.
constexpr int kFlangeOnly = 2;

// The first wheel (2 w + side) that touches its tread in the equilibrium (tread_before) but is
// on its flange alone at `at`, or has no contact state there (lift); -1 when none. Two-point
// contact (tread and flange) is inside the flangeway: a kick there is a valid start.
int wheelOffTread(dynamics::ContactVehicleOde& ode, const std::vector<int>& tread_before,
                  const Eigen::VectorXd& at, std::vector<dynamics::WheelOutput>& wo) {
  const bool ok = ode.wheelOutputs(0.0, at.data(), wo) == 0;
  for (std::size_t k = 0; k < wo.size(); ++k)
    if (tread_before[k] != 0 && (!ok || wo[k].regime == kFlangeOnly)) return static_cast<int>(k);
  return -1;
}

// A kick must leave every wheel that rolls on its tread in the equilibrium on its tread: a
// wheelset placed at rest inside its flange is thrown back by the flange contact and lifts a
// wheel within milliseconds (or at once: a negative constraint normal force), which would show
// as a confusing failure of the run. The flangeway is found by bisection on the scale of the
// offsets (wheel outputs only, about 30 evaluations, only when a wheel leaves its tread).
void checkFlangeway(const std::vector<vehicle::InitialCondition>& initial,
                    dynamics::ContactVehicleOde& ode, const Eigen::VectorXd& equilibrium,
                    const Eigen::VectorXd& y0, Diagnostics& d) {
  std::vector<dynamics::WheelOutput> wo(2 * static_cast<std::size_t>(ode.layout().n_ws));
  if (ode.wheelOutputs(0.0, equilibrium.data(), wo) != 0) return;
  std::vector<int> tread(wo.size());
  for (std::size_t k = 0; k < wo.size(); ++k) tread[k] = wo[k].regime != kFlangeOnly ? 1 : 0;
  const int wheel = wheelOffTread(ode, tread, y0, wo);
  if (wheel < 0) return;
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    const Eigen::VectorXd y = equilibrium + mid * (y0 - equilibrium);
    (wheelOffTread(ode, tread, y, wo) < 0 ? lo : hi) = mid;
  }
  const int w = wheel / 2;
  const std::string body = ode.model().bodies[ode.layout().wheelset(w)].name;
  std::string limit = "the wheels stay on their treads up to " + formatNumber(lo) + " times them";
  if (initial.size() == 1)
    limit += " (here " + formatNumber(std::abs(lo * initial.front().value)) + " in magnitude)";
  d.add(initial.front().loc,
        "vehicle.initial: the offsets put the " + std::string(wheel % 2 == 0 ? "left" : "right") +
            " wheel of wheelset '" + body +
            "' beyond its flangeway at the start (flange contact or lift): a wheelset placed "
            "at rest on its flange is thrown back and lifts a wheel at once; " +
            limit);
}

// vehicle.initial on the compiled model: every condition names a state of it (the ODE layout
// decides: a wheelset's z and roll on contact are dependent, frames and guided wheelsets have no
// state), and the start state y0 + offsets is one the model can evaluate. The contact
// constraints give every lateral offset inside the contact tables a contact state, so a wheelset
// pushed into or beyond its flangeway is refused only where the model itself refuses it: outside
// the tables, or a wheel lifted (contact.min_normal_force), or a wheel moved off its tread onto
// its flange (checkFlangeway), reported here before anything runs rather than as a failure at
// the start. y0 becomes the start state.
void checkInitialState(const std::vector<vehicle::InitialCondition>& initial,
                       vehicle::VehicleOde& ode, Eigen::VectorXd& y0, Diagnostics& d) {
  if (initial.empty()) return;
  vehicle::checkInitialConditions(ode, initial, d);
  if (!d.empty()) return;
  const Eigen::VectorXd equilibrium = y0;
  if (auto* contact = dynamic_cast<dynamics::ContactVehicleOde*>(&ode)) {
    Eigen::VectorXd offset = y0;
    vehicle::applyInitialConditions(ode, initial, offset);
    checkFlangeway(initial, *contact, equilibrium, offset, d);
    if (!d.empty()) return;
  }
  try {
    startWithInitialConditions(ode, initial, y0);
  } catch (const InputError& e) {
    for (const Diagnostic& g : e.diagnostics())
      d.add(initial.front().loc, "vehicle.initial: the start these offsets give: " + g.message);
    return;
  }
  Eigen::VectorXd ydot(y0.size());
  if (ode.rhs(0.0, y0.data(), ydot.data()) == 0 && ydot.allFinite()) return;
  const std::string why = ode.lastError().empty() ? "a derivative is not finite" : ode.lastError();
  d.add(initial.front().loc,
        "vehicle.initial: the model cannot be evaluated in the start state these offsets give (" +
            why + "); give smaller offsets");
}

// The start of a train is each vehicle's equilibrium: a connection loaded there (buffers
// pressed, a draw gear stretched beyond its slack) would not be one; the vehicles' starts place
// them.
constexpr double kStartForceTolerance = 1.0;  // [N]

void checkTrainStart(const Model& c, train::TrainOde& ode, const Eigen::VectorXd& y0,
                     Diagnostics& d) {
  if (ode.prepare(0.0, y0.data()) != 0) {
    d.add(c.spec.vehicle.loc, "train: the start state cannot be evaluated: " + ode.lastError());
    return;
  }
  for (std::size_t i = 0; i < ode.connections().size(); ++i) {
    const train::ConnectionState& st = ode.connectionState(static_cast<int>(i));
    const train::Connection& con = ode.connections()[i];
    // 1 N: the rounding of touching faces gives forces of 1e-27 N, a real preload kilonewtons.
    if (std::max({st.buffer_left, st.buffer_right, std::abs(st.draw_gear)}) > kStartForceTolerance)
      d.add(con.spec.loc, "train.connections '" + con.name + "': loaded at the start (gap " +
                              formatNumber(st.gap) + " m: buffers " + formatNumber(st.buffer_left) +
                              " N and " + formatNumber(st.buffer_right) + " N, " +
                              (con.spec.coupler ? "coupler " : "draw gear ") +
                              formatNumber(st.draw_gear) +
                              " N), so the start is not an equilibrium; place the vehicles so "
                              "that the buffer faces touch or stand apart by at most the " +
                              (con.spec.coupler ? "coupler's" : "draw gear's") + " slack");
    if (const auto& g = con.spec.coupler; g && (train::stopTorque(*g, st.angle_front) != 0.0 ||
                                                train::stopTorque(*g, st.angle_rear) != 0.0))
      d.add(g->loc, "train.connections '" + con.name +
                        "': the coupler is against its stop at "
                        "the start (angles " +
                        formatNumber(st.angle_front) + " and " + formatNumber(st.angle_rear) +
                        " rad, angle_stop " + formatNumber(g->angle_stop) +
                        " rad), so the start is not an equilibrium; give a larger angle_stop");
  }
  Eigen::VectorXd ydot(y0.size());
  if (ode.rhs(0.0, y0.data(), ydot.data()) != 0 || !ydot.allFinite())
    d.add(c.spec.vehicle.loc, "train: the start state cannot be evaluated: " + ode.lastError());
}

}  // namespace

std::unique_ptr<vehicle::VehicleOde> makeVehicleOde(const Model& m, std::size_t k) {
  RB_CHECK(k < m.vehicles.size(), "makeVehicleOde needs a vehicle");
  const RunVehicle& v = m.vehicles[k];
  if (v.contact)
    return std::make_unique<dynamics::ContactVehicleOde>(v.vehicle, *v.contact, *m.track);
  return std::make_unique<vehicle::GuidedVehicleOde>(v.vehicle);
}

std::unique_ptr<train::TrainOde> makeRunOde(const Model& m) {
  std::vector<train::TrainOde::Part> parts;
  for (std::size_t k = 0; k < m.vehicles.size(); ++k)
    parts.push_back({m.vehicles[k].name, makeVehicleOde(m, k)});
  return std::make_unique<train::TrainOde>(std::move(parts), m.connections, m.longitudinal);
}

void addVehicle(Model& m, RunVehicle v) {
  RB_CHECK(m.hasVehicle() && m.track.has_value(), "addVehicle needs a compiled vehicle run");
  Diagnostics d;
  const SourceLoc& loc = m.spec.vehicle.loc;
  for (const auto& name : {m.lead().name, v.name})
    if (name.empty())
      d.add(loc, "a run of several vehicles: every vehicle needs a name of its own");
  for (const auto& other : m.vehicles)
    if (!v.name.empty() && other.name == v.name)
      d.add(loc, "a run of several vehicles: two vehicles are named '" + v.name + "'");
  const double length = m.track->geometry().length();
  const double rear = v.vehicle.start + v.trailingX();
  const double lead_end = v.vehicle.start + v.leadingX() + v.vehicle.travel(m.t_end);
  if (rear < 0.0 || lead_end > length)
    d.add(loc, "vehicle '" + v.name + "': its bodies cover s = " + formatNumber(rear) + " to " +
                   formatNumber(lead_end) + " m over the run, beyond the track (0 to " +
                   formatNumber(length) + " m)");
  d.throwIfAny();
  m.vehicles.push_back(std::move(v));
}

Model compileModel(scenario::ScenarioSpec spec, const CompileOptions& o) {
  Model c;
  c.spec = std::move(spec);
  Diagnostics d;
  compileModelParts(o, c, d);
  d.throwIfAny();
  return c;
}

Model compile(const CompileOptions& o) {
  scenario::LoadOptions lo;
  lo.root = o.root;
  lo.overrides = o.overrides;
  Model c;
  c.spec = scenario::loadScenario(o.scenario, lo);
  Diagnostics d;
  compileModelParts(o, c, d);
  if (!c.spec.has_vehicle) checkWithoutVehicle(c, d);
  if (c.hasVehicle()) checkVehicleRun(c, d);
  d.throwIfAny();
  // An assessment group the vehicle cannot give (safety without wheel/rail contact, comfort
  // without a car body) is an error of the scenario, whoever compiles it.
  checkAssessment(c);

  // The initial state must exist: a contact vehicle's static equilibrium on its constraints
  // (the contact points inside the tables, no wheel lift), a guided vehicle's on its suspension.
  // The run computes it again on its own system (the lagged normal-force memory starts there).
  // A fixed step must also be stable on the stiffest mode there (step_limit.hpp).
  if (c.vehicles.size() == 1) {
    const std::unique_ptr<vehicle::VehicleOde> ode = makeVehicleOde(c);
    Eigen::VectorXd y0 = ode->initialState(0.0);
    checkInitialState(c.lead().initial, *ode, y0, d);
    d.throwIfAny();
    checkStepLimit(c, *ode, y0, d);
    d.throwIfAny();
  } else if (c.hasVehicle()) {
    // A train: every vehicle's start state, and the fixed step on the stiffest mode of all.
    const std::unique_ptr<train::TrainOde> ode = makeRunOde(c);
    Eigen::VectorXd y0(ode->size());
    for (int k = 0; k < ode->vehicles(); ++k) {
      Eigen::VectorXd yk;
      try {
        yk = ode->vehicle(k).initialState(0.0);
      } catch (const InputError& e) {
        // The vehicle's own file names its type, which several entries may share: the entry
        // that places it (its start, hence the track under it) is where it is fixed.
        const auto [loc, who] = vehicleAt(c, static_cast<std::size_t>(k));
        for (const Diagnostic& g : e.diagnostics()) d.add(loc, who + ": " + g.message);
        continue;
      }
      checkInitialState(c.vehicles[static_cast<std::size_t>(k)].initial, ode->vehicle(k), yk, d);
      y0.segment(ode->offset(k), yk.size()) = yk;
    }
    ode->initialLongitudinal(y0);
    d.throwIfAny();
    checkTrainStart(c, *ode, y0, d);
    d.throwIfAny();
    checkStepLimit(c, *ode, y0, d);
    d.throwIfAny();
  }
  collectWarnings(c);
  return c;
}

}  // namespace rb::run
