#include "workbench/app/run.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "railbench/version.hpp"
#include "workbench/app/simulate.hpp"
#include "workbench/contact/table_io.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/contact_model.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/io/track_output.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/track/psd.hpp"
#include "workbench/track/samples.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/guided.hpp"
#include "workbench/vehicle/model.hpp"

namespace fs = std::filesystem;

namespace rb::app {
namespace {

struct Compiled {
  scenario::ScenarioSpec spec;
  std::optional<track::TrackModel> track;
  std::optional<vehicle::VehicleModel> vehicle;
  std::optional<dynamics::ContactModel> contact;
  integ::SolverSpec solver;  // the scenario's, or the paper's default (ABM, 1 ms)
  std::vector<vehicle::ElementId> output_elements;
  double track_build_s = 0.0;
  std::vector<std::string> warnings;
};

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Spec -> Model: every problem of every block is collected before anything runs.
Compiled compile(const RunOptions& o) {
  scenario::LoadOptions lo;
  lo.root = o.root;
  lo.overrides = o.overrides;
  Compiled c{scenario::loadScenario(o.scenario, lo),
             std::nullopt,
             std::nullopt,
             std::nullopt,
             {},
             {},
             0.0,
             {}};
  const auto& spec = c.spec;
  Diagnostics d;
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
    c.solver.method = "abm";  // the paper's validation runs: ABM with 1 ms steps (section 5.2)
    c.solver.step = 1e-3;
  }
  if (spec.has_vehicle && c.track) {
    try {
      c.vehicle = vehicle::compileVehicle(spec.vehicle, *c.track);
    } catch (const InputError& e) {
      d.add(e);
    }
  }
  if (c.vehicle && spec.has_contact) {
    try {
      // Tables are cached on disk by the hash of their inputs (issue 4), beside the results:
      // a study's cases share them. RAILBENCH_TABLE_CACHE overrides the folder.
      const char* env = std::getenv("RAILBENCH_TABLE_CACHE");
      fs::path out = o.out.empty() ? fs::path("out") : fs::path(o.out).parent_path();
      dynamics::TableCache cache(env ? std::string(env) : (out / ".table-cache").string());
      c.contact =
          dynamics::compileContact(spec.profiles, spec.contact, *c.vehicle, *c.track, &cache);
    } catch (const InputError& e) {
      d.add(e);
    }
  }
  if (!spec.has_vehicle) {
    if (spec.has_contact) d.add(spec.contact.loc, "contact: needs a vehicle { ... } block");
    if (!spec.run.output_elements.empty())
      d.add(spec.run.loc, "run.output.elements: the scene has no vehicle");
  }
  if (c.vehicle) {
    for (const auto& name : spec.run.output_elements) {
      if (auto id = c.vehicle->findElement(name)) {
        c.output_elements.push_back(*id);
        continue;
      }
      std::vector<std::string> names;
      for (auto id : c.vehicle->elements()) names.push_back(c.vehicle->elementName(id));
      std::string hint = closestMatch(name, names);
      d.add(spec.run.loc, "run.output.elements: no element named '" + name + "'" +
                              (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
    }
    if (!(spec.vehicle.speed > 0) && !(spec.run.duration > 0))
      d.add(spec.vehicle.loc, "vehicle: speed is 0, so give run.duration");
    // Speed ramp: V(t) = V0 + a t must stay >= 0 over the run (no clamping: a vehicle that stops
    // and reverses is not what a ramp scenario means). Without run.duration the run ends at
    // run.distance (or the track end), reached only if V0^2 + 2 a distance >= 0.
    const double a = spec.vehicle.acceleration;
    if (a < 0.0) {
      const auto g = [](double v) {
        std::ostringstream os;
        os << v;
        return os.str();
      };
      const double t_stop = spec.vehicle.speed / -a;
      if (spec.run.duration > 0 && spec.run.duration > t_stop)
        d.add(spec.vehicle.loc, "vehicle: acceleration " + g(a) +
                                    " m/s^2 stops the vehicle at t = " + g(t_stop) +
                                    " s, before run.duration = " + g(spec.run.duration) + " s");
      if (!(spec.run.duration > 0)) {
        double lead = -1e300;
        for (const auto& b : c.vehicle->bodies) lead = std::max(lead, b.x);
        const double dist = spec.run.distance > 0
                                ? spec.run.distance
                                : c.track->geometry().length() - (c.vehicle->start + lead);
        if (spec.vehicle.speed * spec.vehicle.speed + 2.0 * a * dist < 0.0)
          d.add(spec.vehicle.loc,
                "vehicle: acceleration " + g(a) + " m/s^2 stops the vehicle after " +
                    g(spec.vehicle.speed * t_stop / 2.0) + " m, before the run's distance " +
                    g(dist) + " m; give run.duration or a smaller deceleration");
      }
    }
  }
  d.throwIfAny();
  const auto& irr = spec.track.irregularities;
  if (irr.source == track::IrregularitySource::Psd && !track::psdVerified(irr.spectrum))
    c.warnings.push_back(irr.loc.str() + ": warning: the parameters of spectrum '" + irr.spectrum +
                         "' are UNVERIFIED against a primary source (see docs/track.md)");
  if (c.contact)
    for (const auto& w : c.contact->warnings)
      c.warnings.push_back(w);  // already "file:line: warning: ..."
  if (c.vehicle && !spec.has_contact)
    c.warnings.push_back(spec.vehicle.loc.str() +
                         ": note: no contact{} block: wheelsets follow the track kinematically");
  return c;
}

std::string isoNow() {
  std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

std::string kindName(vehicle::BodyKind k) {
  switch (k) {
    case vehicle::BodyKind::CarBody:
      return "car";
    case vehicle::BodyKind::Bogie:
      return "bogie";
    case vehicle::BodyKind::Wheelset:
      return "wheelset";
    case vehicle::BodyKind::Frame:
      return "frame";
  }
  return "?";
}

// Position x of the leading body (largest x: the first wheelset of the wagon), relative to the
// vehicle's reference point. Both the run's distance and the distance reported with a failure
// are measured at this body.
double leadingX(const vehicle::VehicleModel& v) {
  double lead = -1e300;
  for (const auto& b : v.bodies) lead = std::max(lead, b.x);
  return lead;
}

// Simulated time of a vehicle run: run.duration, or run.distance (default: until the leading
// body reaches the end of the track) at the vehicle's speed.
double endTime(const Compiled& c) {
  const auto& run = c.spec.run;
  if (run.duration > 0) return run.duration;
  const auto& v = *c.vehicle;
  const double lead = leadingX(v);
  double distance =
      run.distance > 0 ? run.distance : c.track->geometry().length() - (v.start + lead);
  distance = std::max(distance, 0.0);
  const double a = v.acceleration;
  if (a == 0.0) return distance / v.speed;
  // Speed ramp: V0 t + a t^2 / 2 = distance (the root reached first). compile() has checked that
  // it is reached before the speed would become negative.
  const double disc = v.speed * v.speed + 2.0 * a * distance;
  return disc <= 0.0 ? 0.0 : 2.0 * distance / (v.speed + std::sqrt(disc));
}

// The request shared by vehicle runs, with the body coordinate channels (s, y, z, roll, pitch,
// yaw per body, then optionally ax, ay, az) in /bodies/<name>/.
SimulationRequest vehicleRequest(const Compiled& c, const RunOptions& options,
                                 integ::OdeSystem& ode, const Eigen::VectorXd& y0,
                                 io::ResultFile& f, bool accelerations) {
  SimulationRequest r;
  r.system = &ode;
  r.solver = c.solver;
  r.y0 = y0;
  r.t_end = endTime(c);
  r.output_every = c.spec.run.output_every;
  // Progress line only for a person watching a terminal (issue 3).
  r.progress = !options.quiet && isatty(STDERR_FILENO);
  // Arc length of the leading body (the same body endTime() runs to the track end), so that a
  // failure's "distance" is where the first wheelset was (it used to be the first body in the
  // file, the car body centre: 10.9 m behind the leading wheelset of the Manchester wagon).
  const double lead = c.vehicle->start + leadingX(*c.vehicle);
  const vehicle::VehicleModel* vm = &*c.vehicle;
  r.distance = [lead, vm](double t, const Eigen::VectorXd&) { return lead + vm->travel(t); };
  // The imposed forward speed V(t) = V0 + a t (a speed ramp when vehicle.acceleration != 0).
  r.outputs.push_back({"/vehicle/speed", "m/s"});
  static const char* coords[6] = {"s", "y", "z", "roll", "pitch", "yaw"};
  static const char* units[6] = {"m", "m", "m", "rad", "rad", "rad"};
  std::string names;
  for (const auto& b : c.vehicle->bodies) {
    names += (names.empty() ? "" : "\n") + b.name;
    f.attr("/bodies/" + b.name, "kind", kindName(b.kind));
    for (int k = 0; k < 6; ++k)
      r.outputs.push_back({"/bodies/" + b.name + "/" + coords[k], units[k]});
    if (accelerations)
      for (const char* a : {"ax", "ay", "az"})
        r.outputs.push_back({"/bodies/" + b.name + "/" + a, "m/s^2"});
  }
  f.attr("/bodies", "names", names);
  return r;
}

// Issue 5: wheelsets guided along the track, the other bodies free; suspension outputs.
int runGuided(const Compiled& c, const RunOptions& options, io::ResultFile& f) {
  const auto& v = *c.vehicle;
  vehicle::GuidedVehicleOde ode(v);
  SimulationRequest r =
      vehicleRequest(c, options, ode, ode.staticState(0.0), f, c.spec.run.body_accelerations);
  for (auto id : c.output_elements) {
    std::string base = "/elements/" + v.elementName(id) + "/";
    bool bending = id.kind == vehicle::ElementKind::BendingSpring;
    r.outputs.push_back({base + "deflection", bending ? "rad" : "m"});
    r.outputs.push_back({base + "force", bending ? "N m" : "N"});
  }
  auto layout = vehicle::guidedLayout(v);
  auto ws = vehicle::makeWorkspace(v);
  std::vector<vehicle::ElementValue> values(c.output_elements.size());
  const bool acc = c.spec.run.body_accelerations;
  r.sample = [&](double t, const Eigen::VectorXd& y, double* out) {
    *out++ = v.speedAt(t);
    vehicle::guidedCoordinates(v, layout, t, y.data(), ws);
    for (std::size_t b = 0; b < v.bodies.size(); ++b) {
      for (int k = 0; k < 6; ++k) *out++ = ws.q[b][k];
      if (acc) {
        auto bo = ode.bodyOutput(t, y.data(), static_cast<int>(b));
        for (int k = 0; k < 3; ++k) *out++ = bo.acceleration[k];
      }
    }
    if (!values.empty()) {
      ode.elementOutputs(t, y.data(), c.output_elements, values);
      for (const auto& e : values) {
        *out++ = e.d;
        *out++ = e.force;
      }
    }
  };
  f.attr("/", "solver", c.solver.method);
  f.attr("/", "contact_method", std::string("none (wheelsets guided)"));
  integ::RunResult res = simulate(r, f);
  std::cout << statsLine(res, res.t_reached) << "\n";
  if (!res.ok) {
    std::cerr << c.spec.file << ": run failed: " << res.message << "\n";
    return 2;
  }
  return 0;
}

// Issue 6: wheel/rail contact by the KEC or LUT constraint method.
int runContact(const Compiled& c, const RunOptions& options, io::ResultFile& f) {
  const auto& v = *c.vehicle;
  const auto& cm = *c.contact;
  dynamics::ContactVehicleOde ode(v, cm, *c.track);
  SimulationRequest r = vehicleRequest(c, options, ode, ode.initialState(0.0), f, false);
  // Per wheel: the quantities a user expects (issue 6, item 5).
  static const std::pair<const char*, const char*> wheelQ[] = {
      {"normal_force", "N"},  {"normal_tread", "N"},    {"normal_flange", "N"},
      {"creep_force_x", "N"}, {"creep_force_y", "N"},   {"creepage_x", "-"},
      {"creepage_y", "-"},    {"spin", "1/m"},          {"wheel_s", "m"},
      {"rail_s", "m"},        {"contact_angle", "rad"}, {"flange_indentation", "m"},
      {"flange_force", "N"},  {"regime", "-"},          {"y_over_q", "-"}};
  const std::size_t nq = std::size(wheelQ);
  for (int w : cm.wheelsets) {
    for (const char* side : {"left", "right"})
      for (const auto& [q, u] : wheelQ)
        r.outputs.push_back({"/contact/" + v.bodies[w].name + "/" + side + "/" + q, u});
  }
  f.attr("/contact", "method", std::string(dynamics::ContactModel::methodName(cm.method)));
  f.attr("/contact", "creep", std::string(dynamics::ContactModel::creepName(cm.creep)));
  f.attr("/contact", "normal_forces",
         std::string(dynamics::ContactModel::couplingName(cm.coupling)));
  const auto& ts = cm.tableStats();
  f.attr("/contact", "table_build_time_s", ts.build_seconds);
  f.attr("/contact", "table_bytes", static_cast<std::int64_t>(ts.bytes));
  std::vector<vehicle::Vector6d> q(v.bodies.size());
  std::vector<dynamics::WheelOutput> wo(2 * cm.wheelsets.size());
  r.sample = [&](double t, const Eigen::VectorXd& y, double* out) {
    *out++ = v.speedAt(t);
    ode.bodyCoordinates(t, y.data(), q);
    for (const auto& qb : q)
      for (int k = 0; k < 6; ++k) *out++ = qb[k];
    ode.wheelOutputs(t, y.data(), wo);
    for (const auto& w : wo) {
      // The dominant patch (largest normal force) gives creepages and contact position.
      const auto& p = std::abs(w.patch[1].normal) > std::abs(w.patch[0].normal) && w.patch[1].active
                          ? w.patch[1]
                          : w.patch[0];
      double vals[] = {w.normal,
                       w.normal_tread,
                       w.normal_flange,
                       w.patch[0].fx + w.patch[1].fx,
                       w.patch[0].fy + w.patch[1].fy,
                       p.sx,
                       p.sy,
                       p.spin,
                       p.s_w,
                       p.s_r,
                       p.gamma,
                       w.flange_indentation,
                       w.flange_force,
                       static_cast<double>(w.regime),
                       w.y_over_q};
      for (std::size_t k = 0; k < nq; ++k) *out++ = vals[k];
    }
  };
  f.attr("/", "solver", c.solver.method);
  f.attr("/", "contact_method", std::string(dynamics::ContactModel::methodName(cm.method)));
  integ::RunResult res = simulate(r, f);
  const auto& cs = ode.stats();
  f.attr("/stats", "model_evaluations", static_cast<std::int64_t>(cs.evaluations));
  f.attr("/stats", "kec_iterations", static_cast<std::int64_t>(cs.kec_iterations));
  f.attr("/stats", "lift_evaluations", static_cast<std::int64_t>(cs.lift_evaluations));
  f.attr("/stats", "consistent_iterations", static_cast<std::int64_t>(cs.consistent_iterations));
  std::cout << statsLine(res, res.t_reached) << "\n";
  if (!res.ok) {
    std::cerr << c.spec.file << ": run failed: " << res.message << "\n";
    return 2;
  }
  return 0;
}

}  // namespace

void checkScenario(const RunOptions& options) {
  Compiled c = compile(options);
  for (const auto& w : c.warnings) std::cerr << w << "\n";
}

int runScenario(const RunOptions& options) {
  Compiled c = compile(options);
  for (const auto& w : c.warnings) std::cerr << w << "\n";

  std::string out = options.out;
  if (out.empty()) out = "out/" + fs::path(options.scenario).stem().string() + ".h5";
  if (fs::path(out).has_parent_path()) fs::create_directories(fs::path(out).parent_path());

  io::ResultFile f(out);
  f.attr("/", "version", std::string(kVersion));
  f.attr("/", "created", isoNow());
  f.attr("/", "scenario_file", c.spec.file);
  f.attr("/", "scenario_text", c.spec.text);
  // The files the scenario required (tracks, vehicles, shared set-ups), so the result alone
  // says exactly what was run.
  std::string modules;
  for (const auto& [name, text] : c.spec.modules)
    modules += "-- file: " + name + "\n" + text + "\n";
  f.attr("/", "scenario_modules", modules);
  f.attr("/", "overrides", join(c.spec.overrides, "\n"));
  std::vector<std::string> effects = {"track_geometry"};
  std::string seeds;
  if (c.track->irregularities()) {
    effects.push_back("irregularities");
    if (c.spec.track.irregularities.source == track::IrregularitySource::Psd)
      seeds = "track.irregularities.seed=" + std::to_string(c.spec.track.irregularities.seed);
  }
  if (c.vehicle)
    for (const auto& k : c.vehicle->element_kinds) effects.push_back("suspension:" + k);
  if (c.contact) {
    effects.push_back(std::string("contact:") +
                      dynamics::ContactModel::methodName(c.contact->method));
    effects.push_back(std::string("creep:") + dynamics::ContactModel::creepName(c.contact->creep));
  }
  f.attr("/", "effects", join(effects, "\n"));
  f.attr("/", "seeds", seeds);
  io::writeTrack(f, c.spec.track, track::sampleTrack(*c.track));
  f.attr("/track", "build_time_s", c.track_build_s);

  std::ostringstream msg;
  msg << "wrote " << out << ": track " << c.track->geometry().length() << " m, "
      << c.spec.track.segments.size() << " segments";
  if (c.track->irregularities()) {
    const auto& irr = c.spec.track.irregularities;
    if (irr.source == track::IrregularitySource::Psd)
      msg << ", irregularities " << irr.spectrum << " seed " << irr.seed;
    else
      msg << ", measured irregularities";
  }
  msg << " (built in " << c.track_build_s * 1e3 << " ms)";

  int rc = 0;
  if (c.contact) {
    rc = runContact(c, options, f);
    msg << "; vehicle " << c.vehicle->name << " with "
        << dynamics::ContactModel::methodName(c.contact->method) << " contact";
  } else if (c.vehicle) {
    rc = runGuided(c, options, f);
    msg << "; vehicle " << c.vehicle->name << " (" << c.vehicle->bodies.size() << " bodies, "
        << c.vehicle->elementCount() << " elements)";
  } else {
    // No vehicle in the scene: nothing is integrated. The stats group still says what was done
    // so every result file has the same shape.
    f.attr("/stats", "status", std::string("ok"));
    f.attr("/stats", "message",
           std::string("no vehicle in the scene: track only, nothing integrated"));
    msg << "; no vehicle in the scene, nothing integrated";
  }
  f.finalize();
  std::cout << msg.str() << "\n";
  return rc;
}

}  // namespace rb::app
