#include "workbench/run/vehicle_assessment.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>

#include "workbench/core/strings.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/vehicle/names.hpp"

namespace rb::run {
namespace {

using vehicle::Vector6d;

std::vector<int> bodiesOfKind(const vehicle::VehicleModel& v, vehicle::BodyKind k) {
  std::vector<int> out;
  for (std::size_t b = 0; b < v.bodies.size(); ++b)
    if (v.bodies[b].kind == k) out.push_back(static_cast<int>(b));
  return out;
}

// The bogie each wheelset belongs to: the nearest bogie along the vehicle (-1: none).
int bogieOf(const vehicle::VehicleModel& v, int ws, const std::vector<int>& bogies) {
  int best = -1;
  for (const int b : bogies)
    if (best < 0 ||
        std::abs(v.bodies[b].x - v.bodies[ws].x) < std::abs(v.bodies[best].x - v.bodies[ws].x))
      best = b;
  return best;
}

// What applies to this vehicle: the groups it cannot give are dropped (with a note).
assessment::AssessmentSpec applicable(const Model& m, const RunVehicle& rv,
                                      std::vector<std::string>& notes) {
  assessment::AssessmentSpec a = m.spec.run.assessment;
  a.category = m.spec.vehicle.category;
  const auto& v = rv.vehicle;
  auto drop = [&](bool& flag, bool applies, const char* what) {
    if (flag && !applies) {
      flag = false;
      notes.push_back(std::string("assessment: ") + what);
    }
  };
  drop(a.safety, rv.contact.has_value(), "safety left out: the wheelsets are guided (no contact)");
  drop(a.wear, rv.contact.has_value(), "wear left out: the wheelsets are guided (no contact)");
  drop(a.stability, !bodiesOfKind(v, vehicle::BodyKind::Bogie).empty(),
       "stability left out: the vehicle has no bogie");
  drop(a.comfort, !bodiesOfKind(v, vehicle::BodyKind::CarBody).empty(),
       "comfort left out: the vehicle has no car body");
  return a;
}

// The interval of the assessment samples: on a fixed-step grid, rounded down to a multiple of the
// step (at least one step), so every sample is a step end.
double sampleInterval(const Model& m, double every) {
  if (!integ::makeIntegrator(m.solver)->isFixedStep()) return every;
  const double h = m.solver.step;
  return std::max(1.0, std::floor(every / h + 1e-6)) * h;
}

// The floor points of every car body: the scenario's offsets, or over the bogie centres and
// mid-car (over the extreme wheelsets of a vehicle without bogies).
void addFloorPoints(const vehicle::VehicleModel& v, AssessmentSetup& as) {
  const auto cars = bodiesOfKind(v, vehicle::BodyKind::CarBody);
  auto supports = bodiesOfKind(v, vehicle::BodyKind::Bogie);
  if (supports.empty()) supports = bodiesOfKind(v, vehicle::BodyKind::Wheelset);
  for (const int c : cars) {
    const std::string prefix = cars.size() > 1 ? v.bodies[c].name + "_" : "";
    std::vector<std::pair<std::string, double>> pts;
    if (!as.spec.floor_positions.empty()) {
      for (const double x : as.spec.floor_positions) pts.emplace_back("x_" + formatNumber(x), x);
    } else {
      double front = 0.0, rear = 0.0;
      for (const int b : supports) {
        front = std::max(front, v.bodies[b].x - v.bodies[c].x);
        rear = std::min(rear, v.bodies[b].x - v.bodies[c].x);
      }
      pts = {{"front", front}, {"centre", 0.0}, {"rear", rear}};
    }
    for (const auto& [name, x] : pts) {
      as.floor_points.push_back({c, x});
      FloorPointSignals fp;
      fp.name = prefix + name;
      fp.x_offset = x;
      as.signals.floor.push_back(std::move(fp));
    }
  }
}

void addBogiePoints(const RunVehicle& rv, AssessmentSetup& as) {
  const vehicle::VehicleModel& v = rv.vehicle;
  const auto bogies = bodiesOfKind(v, vehicle::BodyKind::Bogie);
  auto wheelsets = bodiesOfKind(v, vehicle::BodyKind::Wheelset);
  std::sort(wheelsets.begin(), wheelsets.end(),
            [&](int a, int b) { return v.bodies[a].x > v.bodies[b].x; });  // leading first
  for (const int b : bogies)
    for (const int w : wheelsets) {
      if (bogieOf(v, w, bogies) != b) continue;
      as.bogie_points.push_back({b, v.bodies[w].x - v.bodies[b].x});
      BogiePointSignals bp;
      bp.bogie = v.bodies[b].name;
      bp.wheelset = v.bodies[w].name;
      bp.bogie_mass = v.bodies[b].mass;
      bp.s_offset = v.bodies[w].x - rv.leadingX();
      as.signals.bogies.push_back(std::move(bp));
    }
}

// The wheels with their static loads Q0 and their places behind the leading wheelset.
void addWheels(const Model& m, std::size_t k_vehicle, AssessmentSetup& as) {
  const RunVehicle& rv = m.vehicles[k_vehicle];
  const StaticWheelLoads q0 = staticWheelLoads(m, k_vehicle);
  std::size_t k = 0;
  for (const int w : rv.contact->wheelsets)
    for (const char* side : {"left", "right"}) {
      WheelSignals ws;
      ws.wheelset = rv.vehicle.bodies[w].name;
      ws.side = side;
      ws.q0 = q0.load[k++];
      ws.s_offset = rv.vehicle.bodies[w].x - rv.leadingX();
      as.signals.wheels.push_back(std::move(ws));
    }
  as.signals.q0_source = q0.source;
}

// A given section's radius and cant where they are constant over it (every segment it overlaps
// a tangent, or a curve body of one radius and cant), NaN otherwise.
void constantGeometry(const track::TrackGeometry& g, assessment::TrackSection& t) {
  double radius = std::numeric_limits<double>::quiet_NaN(), cant = radius;
  bool first = true, constant = true;
  for (const auto& seg : g.segments()) {
    if (seg.s0 + seg.length <= t.from || seg.s0 >= t.to) continue;
    double r = std::numeric_limits<double>::quiet_NaN(), c = r;
    if (seg.kind == track::SegmentKind::Tangent) {
      r = std::numeric_limits<double>::infinity();
      c = 0.0;
    } else if (seg.kind == track::SegmentKind::Curve) {
      r = seg.radius;
      c = seg.cant;
    }
    constant = constant && !std::isnan(r) && (first || (r == radius && c == cant));
    radius = r;
    cant = c;
    first = false;
  }
  t.radius = constant && !first ? radius : std::numeric_limits<double>::quiet_NaN();
  t.cant = constant && !first ? cant : std::numeric_limits<double>::quiet_NaN();
  t.zone = std::isnan(t.radius) ? assessment::TestZone::None : assessment::testZone(t.radius);
}

}  // namespace

std::vector<assessment::TrackSection> assessmentSections(const Model& m) {
  std::vector<assessment::TrackSection> out;
  const auto& g = m.track->geometry();
  for (const auto& given : m.spec.run.assessment.sections) {
    assessment::TrackSection t;
    t.name = given.name;
    t.kind = assessment::SectionKind::Given;
    t.from = given.from;
    t.to = given.to;
    constantGeometry(g, t);
    out.push_back(std::move(t));
  }
  if (!out.empty()) return out;
  const auto& segs = g.segments();
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const auto& seg = segs[i];
    assessment::TrackSection t;
    t.from = seg.s0;
    t.to = seg.s0 + seg.length;
    switch (seg.kind) {
      case track::SegmentKind::Tangent:
        t.kind = assessment::SectionKind::Tangent;
        t.radius = std::numeric_limits<double>::infinity();
        t.cant = 0.0;
        break;
      case track::SegmentKind::Transition:
        t.kind = assessment::SectionKind::Transition;
        t.radius = t.cant = std::numeric_limits<double>::quiet_NaN();
        break;
      case track::SegmentKind::Curve:
        t.kind = assessment::SectionKind::Curve;
        t.radius = seg.radius;
        t.cant = seg.cant;
        break;
    }
    t.zone = t.kind == assessment::SectionKind::Transition ? assessment::TestZone::None
                                                           : assessment::testZone(t.radius);
    t.name = std::string(nameOf(t.kind)) + std::to_string(i + 1);
    out.push_back(std::move(t));
  }
  return out;
}

StaticWheelLoads staticWheelLoads(const Model& m, std::size_t k) {
  RB_CHECK(k < m.vehicles.size() && m.vehicles[k].contact && m.track,
           "staticWheelLoads needs a contact vehicle");
  const RunVehicle& rv = m.vehicles[k];
  // The same track without its design geometry and irregularities: one level tangent as long as
  // the run's track, same gauge, rail positions and inclination.
  track::TrackSpec spec = m.track->spec();
  track::SegmentSpec tangent;
  tangent.kind = track::SegmentKind::Tangent;
  tangent.length = m.track->geometry().length();
  tangent.loc = spec.loc;
  spec.segments = {tangent};
  spec.irregularities = track::IrregularitySpec{};
  const track::TrackModel perfect = track::compileTrack(spec);
  dynamics::ContactVehicleOde ode(rv.vehicle, *rv.contact, perfect);
  const Eigen::VectorXd y = ode.initialState(0.0);
  std::vector<dynamics::WheelOutput> wo(2 * rv.contact->wheelsets.size());
  RB_CHECK(ode.wheelOutputs(0.0, y.data(), wo) == 0,
           "the wheel outputs of the static equilibrium failed");
  StaticWheelLoads out;
  for (const auto& w : wo) out.load.push_back(w.force.Q);
  out.source =
      "static wheel loads of the vehicle's equilibrium on perfect level tangent track (the "
      "run's wheel and rail profiles, gauge and rail inclination; no curvature, cant or "
      "irregularities), the same for every run of this vehicle";
  return out;
}

namespace {

// Room for every sample of a run to t_end (its count bounded by run.output.max_samples, see
// checkSampling), so sampling appends without growing (copying) the signals.
void reserveSamples(AssessmentSignals& sig, double t_end) {
  const auto n = static_cast<std::size_t>(std::ceil(t_end / sig.dt - 1e-9)) + 1;
  const auto reserve = [n](std::vector<double>& v) { v.reserve(n); };
  reserve(sig.time);
  reserve(sig.distance);
  for (auto& w : sig.wheels)
    for (auto* v : {&w.Y, &w.Q, &w.y_track, &w.t_gamma[0], &w.t_gamma[1], &w.power[0], &w.power[1]})
      reserve(*v);
  for (auto& b : sig.bogies) reserve(b.ay);
  for (auto& p : sig.floor)
    for (auto* v : {&p.ax, &p.ay, &p.az}) reserve(*v);
}

// a_P = a_cm + alpha x r + omega x (omega x r) of the point r = (r_x, 0, 0) of a body, in the
// body's track-frame components (rigid-body kinematics at the state of qdd).
Eigen::Vector3d pointAcceleration(const vehicle::BodyKinematics& k, const Vector6d& qdd,
                                  double r_x) {
  const Eigen::Vector3d a_cm = k.Lv * qdd + k.gamma_v;
  const Eigen::Vector3d alpha_b = k.Lw * qdd + k.gamma_w;
  const Eigen::Vector3d r(r_x, 0.0, 0.0);
  const Eigen::Vector3d rel = alpha_b.cross(r) + k.omega_b.cross(k.omega_b.cross(r));
  return a_cm + k.body.A * rel;
}

void sampleBodies(AssessmentSetup& as, StateOutputs& state) {
  const bool ok = state.accelerations();
  const auto& kin = state.workspace().kin;
  const auto& qdd = state.qdd();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < as.bogie_points.size(); ++k) {
    const auto& p = as.bogie_points[k];
    const std::size_t b = static_cast<std::size_t>(p.body);
    as.signals.bogies[k].ay.push_back(ok ? pointAcceleration(kin[b], qdd[b], p.r_x).y() : nan);
  }
  for (std::size_t k = 0; k < as.floor_points.size(); ++k) {
    const auto& p = as.floor_points[k];
    const std::size_t b = static_cast<std::size_t>(p.body);
    const Eigen::Vector3d a =
        ok ? pointAcceleration(kin[b], qdd[b], p.r_x) : Eigen::Vector3d::Constant(nan);
    auto& s = as.signals.floor[k];
    s.ax.push_back(a.x());
    s.ay.push_back(a.y());
    s.az.push_back(a.z());
  }
}

void sampleContact(AssessmentSetup& as, StateOutputs& state) {
  const bool ok = state.wheels();
  const auto& wo = state.wheelOutputs();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < as.signals.wheels.size(); ++k) {
    auto& w = as.signals.wheels[k];
    const auto& o = wo[k];
    w.Y.push_back(ok ? o.force.Y : nan);
    w.Q.push_back(ok ? o.force.Q : nan);
    w.y_track.push_back(ok ? o.force.y_track : nan);
    for (int p = 0; p < 2; ++p) {
      const bool on = ok && o.patch[p].active;
      w.t_gamma[p].push_back(on ? o.patch[p].t_gamma : (ok ? 0.0 : nan));
      w.power[p].push_back(on ? o.patch[p].power : (ok ? 0.0 : nan));
    }
  }
}

bool allFinite(const AssessmentSignals& s) {
  auto fin = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
  };
  bool ok = true;
  for (const auto& w : s.wheels) ok = ok && fin(w.Y) && fin(w.Q) && fin(w.y_track);
  for (const auto& b : s.bogies) ok = ok && fin(b.ay);
  for (const auto& p : s.floor) ok = ok && fin(p.ax) && fin(p.ay) && fin(p.az);
  return ok;
}

}  // namespace

AssessmentSetup setupAssessment(const Model& m, std::size_t k,
                                const dynamics::ContactVehicleOde* contact,
                                std::vector<std::string>& notes) {
  AssessmentSetup as;
  as.spec = applicable(m, m.vehicles[k], notes);
  if (!as.spec.any()) return as;
  as.signals.dt = sampleInterval(m, as.spec.sample_every);
  if (as.signals.dt > as.spec.sample_every * (1 + 1e-9))
    notes.push_back("assessment: sample_every " + formatNumber(as.spec.sample_every) +
                    " s is below the solver step; the signals are sampled at every step (" +
                    formatNumber(as.signals.dt) + " s)");
  if ((as.spec.safety || as.spec.wear) && contact != nullptr) addWheels(m, k, as);
  if (as.spec.safety) as.signals.sections = assessmentSections(m);
  if (as.spec.stability) addBogiePoints(m.vehicles[k], as);
  if (as.spec.comfort) addFloorPoints(m.vehicles[k].vehicle, as);
  reserveSamples(as.signals, m.t_end);
  return as;
}

// Not inlined: its cost stays a named function (tests/stages: what a scene without assessment
// pays for it).
[[gnu::noinline]] void sampleAssessment(AssessmentSetup& as, StateOutputs& state, bool contact,
                                        double t, double s) {
  as.signals.time.push_back(t);
  as.signals.distance.push_back(s);
  if (contact && !as.signals.wheels.empty()) sampleContact(as, state);
  if (!as.bogie_points.empty() || !as.floor_points.empty()) sampleBodies(as, state);
}

AssessmentOutcome finishAssessment(const Model& m, const AssessmentSetup& as, io::ResultFile& f,
                                   const std::string& root) {
  AssessmentOutcome out;
  if (!allFinite(as.signals)) {
    out.warnings.emplace_back("assessment skipped: a sampled signal is not finite");
    return out;
  }
  const auto t0 = std::clock();
  const AssessmentResult res = assess(as.signals, as.spec, m.spec.contact.mu);
  out.schema = writeAssessment(f, as.signals, res, root);
  out.cpu_s = static_cast<double>(std::clock() - t0) / static_cast<double>(CLOCKS_PER_SEC);
  out.summary = summaryLines(res);
  out.warnings = exceededWarnings(res);
  return out;
}

assessment::AssessmentSpec applicableAssessment(const Model& m) {
  std::vector<std::string> notes;
  return applicable(m, m.lead(), notes);
}

namespace {
// The assessment's samples are bounded like the outputs (run.output.max_samples), and its floor
// points lie on the vehicle: between its foremost and rearmost bodies, with at most
// kFloorOverhang beyond them (assumption: the car-body ends overhang the end axles by less).
constexpr double kFloorOverhang = 5.0;  // [m]
void checkSampling(const Model& m) {
  const auto& a = m.spec.run.assessment;
  Diagnostics d;
  const SourceLoc& at = a.sample_every_loc.file.empty() ? a.loc : a.sample_every_loc;
  // A fixed step samples at most once per step: an interval asked for below it would silently
  // become the step. The default (no key given) keeps that rounding, with its note at the run.
  const auto integ = integ::makeIntegrator(m.solver);
  if (!a.sample_every_loc.file.empty() && integ->isFixedStep() &&
      a.sample_every < m.solver.step * (1.0 - 1e-6))
    d.add(at, "run.assessment: sample_every " + formatNumber(a.sample_every) + " s is below the " +
                  std::string(integ->name()) + " step " + formatNumber(m.solver.step) +
                  " s (a fixed step samples at most once per step); give sample_every >= " +
                  formatNumber(m.solver.step) + " s or a smaller solver.step");
  const double n = std::ceil(m.t_end / sampleInterval(m, a.sample_every) - 1e-9);
  if (n > m.spec.run.max_output_samples)
    d.add(at, "run.assessment.sample_every: " + formatNumber(a.sample_every) + " s over " +
                  formatNumber(m.t_end) + " s gives " + formatNumber(n) +
                  " samples, more than run.output.max_samples = " +
                  formatNumber(m.spec.run.max_output_samples));
  double lo = 0.0, hi = 0.0;
  const vehicle::VehicleModel& v = m.lead().vehicle;
  const auto cars = bodiesOfKind(v, vehicle::BodyKind::CarBody);
  for (const auto& b : v.bodies) {
    const double x = b.x - (cars.empty() ? 0.0 : v.bodies[cars.front()].x);
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  for (const double x : a.floor_positions)
    if (x < lo - kFloorOverhang || x > hi + kFloorOverhang)
      d.add(a.loc, "run.assessment.floor_positions: " + formatNumber(x) +
                       " m is not on the vehicle (its bodies lie between " + formatNumber(lo) +
                       " and " + formatNumber(hi) + " m from the car body's centre; at most " +
                       formatNumber(kFloorOverhang) + " m beyond)");
  d.throwIfAny();
}

// Given sections must lie on the track.
void checkSections(const Model& m) {
  Diagnostics d;
  const double length = m.track->geometry().length();
  for (const auto& sec : m.spec.run.assessment.sections)
    if (sec.to > length)
      d.add(sec.loc, "run.assessment.sections: section '" + sec.name + "' ends at " +
                         formatNumber(sec.to) + " m, beyond the track's end at " +
                         formatNumber(length) + " m");
  d.throwIfAny();
}
}  // namespace

void checkAssessment(const Model& m) {
  const auto& a = m.spec.run.assessment;
  if (!a.any()) return;
  if (!m.hasVehicle())
    throw InputError(a.loc,
                     "run.assessment: the scenario has no vehicle to assess (a track-only "
                     "scenario); remove run.assessment or add a vehicle");
  checkSampling(m);
  if (a.all) {
    checkSections(m);
    return;
  }
  std::vector<std::string> notes;
  const assessment::AssessmentSpec applied = applicable(m, m.lead(), notes);
  std::string msg;
  auto need = [&](bool asked, bool applies, const char* what) {
    if (asked && !applies) msg += (msg.empty() ? "" : "; ") + std::string(what);
  };
  need(a.safety, applied.safety, "safety needs wheel/rail contact (the wheelsets are guided)");
  need(a.wear, applied.wear, "wear needs wheel/rail contact (the wheelsets are guided)");
  need(a.stability, applied.stability, "stability needs a bogie");
  need(a.comfort, applied.comfort, "comfort needs a car body");
  if (!msg.empty()) throw InputError(a.loc, "run.assessment: " + msg);
  checkSections(m);
}

}  // namespace rb::run
