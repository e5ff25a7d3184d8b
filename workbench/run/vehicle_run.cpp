#include "workbench/run/vehicle_run.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <memory>
#include <sstream>

#include "railbench/version.hpp"
#include "workbench/contact/interpolation.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/io/initial_output.hpp"
#include "workbench/io/track_output.hpp"
#include "workbench/io/track_store.hpp"
#include "workbench/run/assessment_run.hpp"
#include "workbench/run/channels.hpp"
#include "workbench/run/simulate.hpp"
#include "workbench/run/state_outputs.hpp"
#include "workbench/track/samples.hpp"
#include "workbench/vehicle/guided.hpp"
#include "workbench/vehicle/initial_conditions.hpp"
#include "workbench/vehicle/names.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::run {
namespace {

using vehicle::ElementValue;
using vehicle::Vector6d;

// Absolute centre-of-mass accelerations a = Lv qddot + gamma_v of every body at the state, in
// the body track-frame components [m/s^2] (NaN when the evaluation fails).
void absoluteAccelerations(StateOutputs& state, std::vector<Eigen::Vector3d>& a) {
  if (!state.accelerations()) {
    for (auto& v : a) v.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  const auto& kin = state.workspace().kin;
  const auto& qdd = state.qdd();
  for (std::size_t b = 0; b < a.size(); ++b) a[b] = kin[b].Lv * qdd[b] + kin[b].gamma_v;
}

// Values per wheel and output time, with its two patches.
constexpr std::size_t kWheelValues = kWheelChannelCount + 2 * kPatchChannelCount;
// The conventions of the track-frame forces (dynamics::TrackForces) and of the patches.
void writeContactConventions(io::ResultFile& f, dynamics::ContactMethod method) {
  f.attr("/contact", "force_frame",
         std::string("X, Y, Q, y_track: force of the rail on the wheel (per wheel: the sum over "
                     "its patches, normal and creep forces) in the wheelset's track frame: x "
                     "along the track, y in the track plane (design cant included, irregularities "
                     "not), z perpendicular to the track plane, as EN 14363"));
  f.attr("/contact", "sign_X", std::string("positive forward (direction of travel)"));
  f.attr("/contact", "sign_Y",
         std::string("positive toward the track centre on either wheel (EN 14363: positive when "
                     "it pushes the flange away from its rail); Y = -y_track on the left wheel, "
                     "+y_track on the right; y_over_q = Y / Q"));
  f.attr("/contact", "sign_Q", std::string("positive upward on the wheel (wheel load)"));
  f.attr("/contact", "sign_y_track",
         std::string("positive to the left on both wheels; the sum over a wheelset's wheels is "
                     "its track-shifting force"));
  f.attr("/contact", "patch_contact_frame",
         std::string("creep_force_x/y, spin_moment act on the wheel in the patch's contact frame: "
                     "x the wheel's rolling direction, n the rail normal into the wheel, y = n x "
                     "x; contact_angle from the contact table, contact_angle_track including the "
                     "rails' cross-level angle, both positive toward the track centre; y: "
                     "lateral track-frame position of the contact point, positive to the left"));
  f.attr("/contact", "t_gamma",
         std::string("T gamma = |fx sx| + |fy sy| + |mz spin| [N] (mz from the laws that give a "
                     "spin moment; 0 with polach); power = T gamma V [W]"));
  // What patch 0 and 1 are: the method's row of the registry (dynamics/contact_methods.hpp).
  f.attr("/contact", "patches", std::string(dynamics::methodInfo(method).patches));
}

std::string num(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

// Largest creepage of any active patch at the output times, and when.
struct CreepageMaximum {
  double value = 0.0, t = 0.0;
  void update(const dynamics::WheelOutput& w, double t_now) {
    for (const auto& pp : w.patch) {
      if (!pp.active) continue;
      const double c = std::max(std::abs(pp.sx), std::abs(pp.sy));
      if (c > value) {
        value = c;
        t = t_now;
      }
    }
  }
};

// The channels of one group (`base` ends with '/'), in the order of the rows.
template <class In, std::size_t N>
void addChannels(const std::string& base, const ChannelRow<In> (&rows)[N],
                 std::vector<OutputChannel>& outputs) {
  for (const auto& c : rows)
    outputs.push_back({base + std::string(c.name), std::string(c.unit), std::string(c.meaning),
                       std::string(c.codes)});
}

// Channels of the bodies and suspension elements, in the order sampleVehicle fills them, and the
// /bodies attributes.
void addVehicleChannels(const Model& m, io::ResultFile& f, std::vector<OutputChannel>& outputs) {
  const auto& v = *m.vehicle;
  const bool acc = m.spec.run.body_accelerations;
  std::string names;
  for (const auto& b : v.bodies) {
    names += (names.empty() ? "" : "\n") + b.name;
    f.attr("/bodies/" + b.name, "kind", std::string(nameOf(b.kind)));
    addChannels("/bodies/" + b.name + "/", kBodyCoordChannels, outputs);
    if (acc) addChannels("/bodies/" + b.name + "/", kBodyAccelerationChannels, outputs);
  }
  f.attr("/bodies", "names", names);
  if (acc)
    f.attr("/bodies", "acceleration_frame",
           std::string("absolute acceleration of the centre of mass, components in the body's "
                       "track frame (x along the track, y lateral, z vertical)"));
  for (auto id : m.output_elements) {
    const std::string base = "/elements/" + v.elementName(id) + "/";
    const bool bending = id.kind == vehicle::ElementKind::BendingSpring;
    outputs.push_back(
        {base + "deflection", bending ? "rad" : "m",
         "deflection of the element (" + std::string(vehicle::elementKindName(id.kind)) + ")", ""});
    outputs.push_back(
        {base + "force", bending ? "N m" : "N",
         "force of the element (" + std::string(vehicle::elementKindName(id.kind)) + ")", ""});
  }
}

// Channels of the wheels, in the order sampleWheels fills them, and the /contact attributes.
void addContactChannels(const Model& m, io::ResultFile& f, std::vector<OutputChannel>& outputs) {
  const auto& v = *m.vehicle;
  const auto& cm = *m.contact;
  const dynamics::ContactMethodInfo& info = dynamics::methodInfo(cm.method);
  for (int w : cm.wheelsets)
    for (const char* side : {"left", "right"}) {
      const std::string base = "/contact/" + v.bodies[w].name + "/" + side + "/";
      addChannels(base, kWheelChannels, outputs);
      if (!m.spec.run.output_patches) continue;
      for (int p = 0; p < 2; ++p) {
        const std::string patch = base + "patch" + std::to_string(p);
        f.attr(patch, "role", std::string(info.patch_role[static_cast<std::size_t>(p)]));
        addChannels(patch + "/", kPatchChannels, outputs);
      }
    }
  writeContactConventions(f, cm.method);
  f.attr("/contact", "method", std::string(dynamics::ContactModel::methodName(cm.method)));
  f.attr("/contact", "creep", std::string(dynamics::ContactModel::creepName(cm.creep)));
  if (cm.creep == dynamics::CreepModel::Fastsim) {
    // FASTSIM's result depends on its grid (docs/creep.md): recorded with the law.
    f.attr("/contact", "fastsim_strips", static_cast<std::int64_t>(cm.fastsim.strips));
    f.attr("/contact", "fastsim_elements", static_cast<std::int64_t>(cm.fastsim.elements));
    f.attr("/contact", "fastsim_bound", std::string(nameOf(cm.fastsim.bound)));
  }
  f.attr("/contact", "normal_forces",
         std::string(dynamics::ContactModel::couplingName(cm.coupling)));
  f.attr("/contact", "min_normal_force", cm.min_normal_force);
  f.attr("/contact", "mu", m.spec.contact.mu);
  // The flange angle of Nadal's limit (run.assessment.flange_angle, default S1002's): the contact
  // figures draw the same limit as the assessment.
  f.attr("/contact", "flange_angle", m.spec.run.assessment.flange_angle);
  // Which interpolation the tables were read with (cubic/bicubic or the paper's linear, section
  // 5.5): results of the two are not interchangeable.
  f.attr("/contact", "table_interpolation", std::string(nameOf(cm.geometry.interpolation)));
  const auto& ts = cm.tableStats();
  f.attr("/contact", "table_build_time_s", ts.build_seconds);
  f.attr("/contact", "table_bytes", static_cast<std::int64_t>(ts.bytes));
  if (const auto* e = cm.elastic.get()) {
    // The elastic method's assumptions and derived constants (docs/elastic_contact.md).
    f.attr("/contact", "elastic_damping_ratio", e->damping_ratio);
    f.attr("/contact", "elastic_damping_s_per_m", e->damping);
    f.attr("/contact", "elastic_static_load_N", e->static_load);
    f.attr("/contact", "elastic_static_approach_m", e->static_approach);
    f.attr("/contact", "elastic_vertical_frequency_hz", e->vertical_frequency);
    f.attr("/contact", "elastic_sample_step_m", e->search.front().spec().sample_step);
    f.attr("/contact", "elastic_min_curvature_ratio", e->normal.min_ratio);
    f.attr("/contact", "elastic_flange_height_m", e->flange_height);
    f.attr("/contact", "derailment_lift_m", e->derailment_lift);
  }
}

// /schema/series: /time and every output channel, before the run so that the partial file of a
// failed run has it too.
void writeSeriesSchema(const std::vector<OutputChannel>& outputs, bool contact, io::ResultFile& f) {
  std::vector<io::SchemaEntry> rows = {{"/time", "s", "output time", ""}};
  for (const auto& o : outputs) rows.push_back({o.path, o.units, o.meaning, o.codes});
  std::vector<std::pair<std::string, std::string>> enums;
  if (contact) enums.emplace_back(kRegimeEnum, io::codesOf<dynamics::ContactRegime>());
  io::writeSchema(f, "series", rows, enums);
}

// Per-patch values (kPatchChannels order); returns the next output slot.
double* samplePatch(const dynamics::PatchOutput& p, double* out) {
  for (const auto& c : kPatchChannels) *out++ = p.active ? c.get(p) : 0.0;
  return out;
}

// Per-wheel values (kWheelChannels order, then its patches); returns the next output slot.
double* sampleWheels(const std::vector<dynamics::WheelOutput>& wheels, double t, double* out,
                     CreepageMaximum& creepage, bool patches) {
  for (const auto& w : wheels) {
    // The dominant patch (largest normal force) gives creepages and contact position.
    const auto& p = std::abs(w.patch[1].normal) > std::abs(w.patch[0].normal) && w.patch[1].active
                        ? w.patch[1]
                        : w.patch[0];
    const WheelSample sample{w, p};
    for (const auto& c : kWheelChannels) *out++ = c.get(sample);
    if (patches)
      for (const auto& patch : w.patch) out = samplePatch(patch, out);
    creepage.update(w, t);
  }
  return out;
}

// /stats of the contact model and the warnings of a contact run.
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
  if (m.contact->creep != dynamics::CreepModel::None && creepage.value > kCreepageWarning)
    out.warnings.push_back("creepage reached " + num(creepage.value) +
                           " at t = " + num(creepage.t) + " s, beyond " + num(kCreepageWarning) +
                           " where the creep law is calibrated (docs/contact_dynamics.md)");
}

// The values of the output elements at the state (deflection, force of each) into out.
void sampleElements(StateOutputs& state, std::span<const vehicle::ElementId> ids,
                    std::vector<ElementValue>& values, double*& out) {
  if (ids.empty()) return;
  state.elements(ids, values);
  for (const auto& e : values) {
    *out++ = e.d;
    *out++ = e.force;
  }
}

// A point fixed on a body at x offset r_x from its centre of mass (at its height).
struct BodyPoint {
  int body = 0;
  double r_x = 0.0;  // [m]
};

struct AssessmentSetup {
  assessment::AssessmentSpec spec;  // what applies
  AssessmentSignals signals;
  std::vector<BodyPoint> bogie_points, floor_points;
};

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
assessment::AssessmentSpec applicable(const Model& m, std::vector<std::string>& notes) {
  assessment::AssessmentSpec a = m.spec.run.assessment;
  a.category = m.spec.vehicle.category;
  const auto& v = *m.vehicle;
  auto drop = [&](bool& flag, bool applies, const char* what) {
    if (flag && !applies) {
      flag = false;
      notes.push_back(std::string("assessment: ") + what);
    }
  };
  drop(a.safety, m.contact.has_value(), "safety left out: the wheelsets are guided (no contact)");
  drop(a.wear, m.contact.has_value(), "wear left out: the wheelsets are guided (no contact)");
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
      for (const double x : as.spec.floor_positions) pts.emplace_back("x_" + num(x), x);
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

void addBogiePoints(const Model& m, AssessmentSetup& as) {
  const vehicle::VehicleModel& v = *m.vehicle;
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
      bp.s_offset = v.bodies[w].x - m.leadingX();
      as.signals.bogies.push_back(std::move(bp));
    }
}

// The wheels with their static loads Q0 and their places behind the leading wheelset.
void addWheels(const Model& m, AssessmentSetup& as) {
  const StaticWheelLoads q0 = staticWheelLoads(m);
  std::size_t k = 0;
  for (const int w : m.contact->wheelsets)
    for (const char* side : {"left", "right"}) {
      WheelSignals ws;
      ws.wheelset = m.vehicle->bodies[w].name;
      ws.side = side;
      ws.q0 = q0.load[k++];
      ws.s_offset = m.vehicle->bodies[w].x - m.leadingX();
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

StaticWheelLoads staticWheelLoads(const Model& m) {
  RB_CHECK(m.vehicle && m.contact && m.track, "staticWheelLoads needs a contact vehicle");
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
  dynamics::ContactVehicleOde ode(*m.vehicle, *m.contact, perfect);
  const Eigen::VectorXd y = ode.initialState(0.0);
  std::vector<dynamics::WheelOutput> wo(2 * m.contact->wheelsets.size());
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

AssessmentSetup setupAssessment(const Model& m, dynamics::ContactVehicleOde* contact,
                                std::vector<std::string>& notes) {
  AssessmentSetup as;
  as.spec = applicable(m, notes);
  if (!as.spec.any()) return as;
  as.signals.dt = sampleInterval(m, as.spec.sample_every);
  if (as.signals.dt > as.spec.sample_every * (1 + 1e-9))
    notes.push_back("assessment: sample_every " + num(as.spec.sample_every) +
                    " s is below the solver step; the signals are sampled at every step (" +
                    num(as.signals.dt) + " s)");
  if ((as.spec.safety || as.spec.wear) && contact != nullptr) addWheels(m, as);
  if (as.spec.safety) as.signals.sections = assessmentSections(m);
  if (as.spec.stability) addBogiePoints(m, as);
  if (as.spec.comfort) addFloorPoints(*m.vehicle, as);
  reserveSamples(as.signals, m.t_end);
  return as;
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

// Not inlined: its cost stays a named function (tests/stages: what a scene without assessment
// pays for it).
[[gnu::noinline]] void sampleAssessment(AssessmentSetup& as, StateOutputs& state, bool contact,
                                        double t, double s) {
  as.signals.time.push_back(t);
  as.signals.distance.push_back(s);
  if (contact && !as.signals.wheels.empty()) sampleContact(as, state);
  if (!as.bogie_points.empty() || !as.floor_points.empty()) sampleBodies(as, state);
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

// After the run: the assessment from the samples into /assessment, the summary lines and a
// warning per limit exceeded (a result, not a failure).
void finishAssessment(const Model& m, AssessmentSetup& as, std::size_t samples, io::ResultFile& f,
                      VehicleRunResult& out) {
  f.attr("/stats", "assessment_samples", static_cast<std::int64_t>(samples));
  if (!out.result.ok) {
    out.assessment_notes.emplace_back("assessment skipped: the run failed");
    return;
  }
  if (!allFinite(as.signals)) {
    out.warnings.push_back("assessment skipped: a sampled signal is not finite");
    return;
  }
  const auto t0 = std::clock();
  const AssessmentResult res = assess(as.signals, as.spec, m.spec.contact.mu);
  writeAssessment(f, as.signals, res);
  f.attr("/stats", "assessment_cpu_s",
         static_cast<double>(std::clock() - t0) / static_cast<double>(CLOCKS_PER_SEC));
  out.assessment_summary = summaryLines(res);
  for (auto& n : out.assessment_notes) out.assessment_summary.push_back("  " + n);
  for (auto& w : exceededWarnings(res)) out.warnings.push_back(std::move(w));
}

// /initial_conditions: the conditions as given and the state the run starts from, so the result
// alone says where the motion began (written only when vehicle.initial gives any).
void writeInitialConditions(const vehicle::VehicleOde& ode,
                            std::span<const vehicle::InitialCondition> conditions,
                            const Eigen::VectorXd& equilibrium, const Eigen::VectorXd& y0,
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
  io::writeInitialConditions(f, rec);
}

}  // namespace

assessment::AssessmentSpec applicableAssessment(const Model& m) {
  std::vector<std::string> notes;
  return applicable(m, notes);
}

namespace {
// The assessment's samples are bounded like the outputs (run.output.max_samples), and its floor
// points lie on the vehicle: between its foremost and rearmost bodies, with at most
// kFloorOverhang beyond them (assumption: the car-body ends overhang the end axles by less).
constexpr double kFloorOverhang = 5.0;  // [m]
void checkSampling(const Model& m) {
  const auto& a = m.spec.run.assessment;
  Diagnostics d;
  const double n = std::ceil(m.t_end / sampleInterval(m, a.sample_every) - 1e-9);
  if (n > m.spec.run.max_output_samples)
    d.add(a.loc, "run.assessment.sample_every: " + num(a.sample_every) + " s over " + num(m.t_end) +
                     " s gives " + num(n) + " samples, more than run.output.max_samples = " +
                     num(m.spec.run.max_output_samples));
  double lo = 0.0, hi = 0.0;
  const auto cars = bodiesOfKind(*m.vehicle, vehicle::BodyKind::CarBody);
  for (const auto& b : m.vehicle->bodies) {
    const double x = b.x - (cars.empty() ? 0.0 : m.vehicle->bodies[cars.front()].x);
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  for (const double x : a.floor_positions)
    if (x < lo - kFloorOverhang || x > hi + kFloorOverhang)
      d.add(a.loc, "run.assessment.floor_positions: " + num(x) +
                       " m is not on the vehicle (its bodies lie between " + num(lo) + " and " +
                       num(hi) + " m from the car body's centre; at most " + num(kFloorOverhang) +
                       " m beyond)");
  d.throwIfAny();
}

// Given sections must lie on the track.
void checkSections(const Model& m) {
  Diagnostics d;
  const double length = m.track->geometry().length();
  for (const auto& sec : m.spec.run.assessment.sections)
    if (sec.to > length)
      d.add(sec.loc, "run.assessment.sections: section '" + sec.name + "' ends at " + num(sec.to) +
                         " m, beyond the track's end at " + num(length) + " m");
  d.throwIfAny();
}
}  // namespace

void checkAssessment(const Model& m) {
  const auto& a = m.spec.run.assessment;
  if (!a.any()) return;
  if (!m.vehicle)
    throw InputError(a.loc,
                     "run.assessment: the scenario has no vehicle to assess (a track-only "
                     "scenario); remove run.assessment or add a vehicle");
  checkSampling(m);
  if (a.all) {
    checkSections(m);
    return;
  }
  std::vector<std::string> notes;
  const assessment::AssessmentSpec applied = applicable(m, notes);
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

VehicleRunResult runVehicle(const Model& m, io::ResultFile& f, const VehicleRunOptions& o) {
  RB_CHECK(m.vehicle.has_value(), "runVehicle needs a vehicle");
  const auto& v = *m.vehicle;
  const std::size_t nb = v.bodies.size();
  const std::unique_ptr<vehicle::VehicleOde> ode = makeVehicleOde(m);
  auto* contact = dynamic_cast<dynamics::ContactVehicleOde*>(ode.get());  // null: guided
  ode->setStageSampling(o.stage_period);
  // A fixed-step run is observed at step ends only, where the integrator's next right-hand side
  // starts: the observer's evaluation of the state serves as that right-hand side too.
  if (contact && integ::makeIntegrator(m.solver)->isFixedStep())
    contact->shareOutputEvaluations(true);

  SimulationRequest r;
  r.system = ode.get();
  r.solver = m.solver;
  r.y0 = ode->initialState(0.0);
  // The equilibrium the initial conditions offset (recorded in /initial_conditions).
  const Eigen::VectorXd equilibrium = r.y0;
  if (!m.spec.vehicle.initial.empty()) {
    vehicle::applyInitialConditions(*ode, m.spec.vehicle.initial, r.y0);
    writeInitialConditions(*ode, m.spec.vehicle.initial, equilibrium, r.y0, f);
  }
  r.t_end = m.t_end;
  r.output_every = m.spec.run.output_every;
  r.progress = o.progress;
  // Arc length of the leading body, the body compile() runs to the track end, so that a failure's
  // distance is where the first wheelset was.
  const double lead = v.start + m.leadingX();
  r.distance = [lead, &v](double t, const Eigen::VectorXd&) { return lead + v.travel(t); };

  // Channels, in the order the sampler fills them.
  r.outputs.push_back({"/vehicle/speed", "m/s", "speed of the vehicle along the track", ""});
  addVehicleChannels(m, f, r.outputs);
  if (contact) addContactChannels(m, f, r.outputs);

  writeSeriesSchema(r.outputs, contact != nullptr, f);

  const bool acc = m.spec.run.body_accelerations;
  std::vector<Vector6d> q(nb);
  std::vector<Eigen::Vector3d> a(nb);
  std::vector<ElementValue> values(m.output_elements.size());
  // The output series and the assessment's samples share the model's outputs of a state they
  // both observe.
  StateOutputs state(*ode, contact);
  CreepageMaximum creepage;
  const bool patches = m.spec.run.output_patches;
  const std::size_t wheelValues = patches ? kWheelValues : kWheelChannelCount;
  r.sample = [&](double t, const Eigen::VectorXd& y, double* out) {
    *out++ = v.speedAt(t);
    state.at(t, y.data());
    ode->bodyCoordinates(t, y.data(), q);
    if (acc) absoluteAccelerations(state, a);
    for (std::size_t b = 0; b < nb; ++b) {
      const BodySample body{q[b], a[b]};
      for (const auto& c : kBodyCoordChannels) *out++ = c.get(body);
      if (acc)
        for (const auto& c : kBodyAccelerationChannels) *out++ = c.get(body);
    }
    if (!contact) {
      sampleElements(state, m.output_elements, values, out);
      return;
    }
    // The wheel outputs first: their evaluation also gives the element values.
    const bool wheels = state.wheels();
    sampleElements(state, m.output_elements, values, out);
    if (!wheels) {
      for (std::size_t k = 0; k < state.wheelOutputs().size() * wheelValues; ++k)
        *out++ = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    sampleWheels(state.wheelOutputs(), t, out, creepage, patches);
  };
  f.attr("/", "solver", m.solver.method);
  f.attr("/", "contact_method",
         contact ? std::string(dynamics::ContactModel::methodName(m.contact->method))
                 : std::string("none (wheelsets guided)"));
  VehicleRunResult out;
  out.warnings = m.run_warnings;
  if (m.step_limit.computed) {
    f.attr("/stats", "step_limit", m.step_limit.h_max);
    f.attr("/stats", "step_limit_mode", m.step_limit.mode);
  }
  // The assessment samples its own signals at its own interval (nothing when not asked).
  AssessmentSetup as = setupAssessment(m, contact, out.assessment_notes);
  ExtraSampling extra;
  if (as.spec.any()) {
    extra.every = as.signals.dt;
    extra.sample = [&](double t, const Eigen::VectorXd& y) {
      state.at(t, y.data());
      sampleAssessment(as, state, contact != nullptr, t, lead + v.travel(t));
    };
    r.extra = &extra;
  }
  out.result = simulate(r, f);
  if (as.spec.any()) finishAssessment(m, as, extra.samples, f, out);
  if (contact) writeContactStats(m, contact->stats(), creepage, f, out);
  out.effects = compiledEffects(m);
  out.costs = stageCosts(ode->stageClock(), out.result.stats);
  writeRunStats(f, out.effects, out.costs);
  writeWarnings(f, out.warnings);
  return out;  // the caller's finalize() writes what is buffered
}

std::string writeProvenance(const Model& c, io::ResultFile& f, const std::string& created,
                            const std::string& track_store) {
  f.attr("/", "version", std::string(kVersion));
  f.attr("/", "created", created);
  f.attr("/", "scenario_file", c.spec.file);
  f.attr("/", "scenario_text", c.spec.text);
  // The files the scenario required (tracks, vehicles, shared set-ups), so the result alone says
  // exactly what was run.
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
  // A result file holds the stretch the vehicle covers, from its rearmost body at the start to
  // its leading body at the end; a track store holds the whole track, which the cases of a study
  // share whatever stretch each covers (and a model without a vehicle writes it whole too).
  double s_from = -std::numeric_limits<double>::infinity();
  double s_to = std::numeric_limits<double>::infinity();
  if (track_store.empty() && c.vehicle && c.t_end > 0.0) {
    const Model::Stretch covered = c.coveredStretch();
    s_from = covered.s_from;
    s_to = covered.s_to;
  }
  const io::TrackContent track =
      io::trackContent(c.spec.track, track::sampleTrack(*c.track, s_from, s_to));
  // With a track store the rows describe the /track datasets of the store file.
  io::writeSchema(f, "track", io::trackSchema(track), io::trackEnums());
  std::string note;
  if (track_store.empty()) {
    io::writeTrackContent(f, track);
  } else {
    const io::StoredTrack stored = io::storeTrack(track, track_store);
    io::writeTrackReference(f, track, stored);
    note = "track " + std::string(stored.written ? "stored in " : "found in ") + stored.file;
  }
  f.attr("/track", "build_time_s", c.track_build_s);
  return note;
}

namespace {

// The parts of a dataset path: "/bodies/ws1/y" -> {"bodies", "ws1", "y"}.
std::vector<std::string> pathParts(const std::string& path) {
  std::vector<std::string> out;
  std::size_t at = 1;
  while (at <= path.size()) {
    const std::size_t next = std::min(path.find('/', at), path.size());
    out.push_back(path.substr(at, next - at));
    at = next + 1;
  }
  return out;
}

// "'x' is not one of a, b (did you mean 'a'?)" for a name that is not among `names`.
std::string notAmong(const std::string& what, const std::string& x,
                     const std::vector<std::string>& names) {
  const std::string hint = closestMatch(x, names);
  return "no " + what + " '" + x + "'" +
         (hint.empty() ? " (there are: " + join(names, ", ") + ")"
                       : " (did you mean '" + hint + "'?)");
}

}  // namespace

namespace {

bool among(const std::string& x, const std::vector<std::string>& names) {
  return std::find(names.begin(), names.end(), x) != names.end();
}

std::string bodySignalProblem(const scenario::ScenarioSpec& spec,
                              const std::vector<std::string>& p) {
  if (p.size() != 3) return "a body's signal is /bodies/<body>/<coordinate>";
  std::vector<std::string> bodies;
  for (const auto& b : spec.vehicle.bodies) bodies.push_back(b.name);
  if (!among(p[1], bodies)) return notAmong("body", p[1], bodies);
  std::vector<std::string> q;
  for (const auto& c : kBodyCoordChannels) q.emplace_back(c.name);
  const bool acc = spec.run.body_accelerations;
  if (acc)
    for (const auto& c : kBodyAccelerationChannels) q.emplace_back(c.name);
  if (among(p[2], q)) return {};
  const bool asks_acc =
      std::any_of(std::begin(kBodyAccelerationChannels), std::end(kBodyAccelerationChannels),
                  [&](const auto& c) { return p[2] == c.name; });
  return notAmong("body signal", p[2], q) +
         (acc || !asks_acc ? "" : "; ax, ay, az need run.output.body_accelerations = true");
}

std::string elementSignalProblem(const scenario::ScenarioSpec& spec,
                                 const std::vector<std::string>& p) {
  const auto& out = spec.run.output_elements;
  if (p.size() != 3) return "an element's signal is /elements/<name>/deflection or force";
  if (!among(p[1], out))
    return "element '" + p[1] + "' is not written: name it in run.output.elements" +
           (out.empty() ? "" : " (written: " + join(out, ", ") + ")");
  if (p[2] != "deflection" && p[2] != "force")
    return notAmong("element signal", p[2], {"deflection", "force"});
  return {};
}

std::string contactSignalProblem(const scenario::ScenarioSpec& spec,
                                 const std::vector<std::string>& p) {
  if (!spec.has_contact)
    return "the scenario has no wheel/rail contact model, so its result has no /contact";
  if (p.size() < 4) return "a wheel's signal is /contact/<wheelset>/<left|right>/<quantity>";
  std::vector<std::string> wheelsets;
  for (const auto& b : spec.vehicle.bodies)
    if (b.kind == vehicle::BodyKind::Wheelset) wheelsets.push_back(b.name);
  if (!among(p[1], wheelsets)) return notAmong("wheelset", p[1], wheelsets);
  if (p[2] != "left" && p[2] != "right") return notAmong("side", p[2], {"left", "right"});
  std::vector<std::string> q;
  if (p.size() == 4) {
    for (const auto& c : kWheelChannels) q.emplace_back(c.name);
    return among(p[3], q) ? std::string() : notAmong("wheel signal", p[3], q);
  }
  if (p.size() != 5 || (p[3] != "patch0" && p[3] != "patch1"))
    return "a patch's signal is /contact/<wheelset>/<side>/patch0|patch1/<quantity>";
  for (const auto& c : kPatchChannels) q.emplace_back(c.name);
  return among(p[4], q) ? std::string() : notAmong("patch signal", p[4], q);
}

}  // namespace

std::string signalProblem(const scenario::ScenarioSpec& spec, const std::string& path) {
  if (path.size() < 2 || path[0] != '/') return {};
  const std::vector<std::string> p = pathParts(path);
  const std::string& group = p[0];
  if (group != "vehicle" && group != "bodies" && group != "elements" && group != "contact")
    return {};
  if (!spec.has_vehicle) return "the scenario has no vehicle, so its result has no /" + group;
  if (group == "vehicle")
    return p.size() == 2 && p[1] == "speed" ? std::string()
                                            : "the vehicle group holds /vehicle/speed only";
  if (group == "bodies") return bodySignalProblem(spec, p);
  if (group == "elements") return elementSignalProblem(spec, p);
  return contactSignalProblem(spec, p);
}

}  // namespace rb::run
