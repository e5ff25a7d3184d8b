#include "workbench/run/vehicle_run.hpp"

#include <unistd.h>

#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include "railbench/version.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/io/track_output.hpp"
#include "workbench/run/simulate.hpp"
#include "workbench/track/samples.hpp"
#include "workbench/vehicle/guided.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::run {
namespace {

using vehicle::ElementValue;
using vehicle::Vector6d;

// Absolute centre-of-mass accelerations a = Lv qddot + gamma_v of every body at (t, y), in the
// body track-frame components [m/s^2] (NaN when the evaluation fails).
void absoluteAccelerations(vehicle::VehicleOde& ode, double t, const double* y,
                           std::vector<Vector6d>& qdd, std::vector<Eigen::Vector3d>& a) {
  if (ode.bodyAccelerations(t, y, qdd) != 0) {
    for (auto& v : a) v.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  const auto& ws = ode.workspace();
  for (std::size_t b = 0; b < a.size(); ++b) a[b] = ws.kin[b].Lv * qdd[b] + ws.kin[b].gamma_v;
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

// Per wheel: the quantities a user expects of a contact run.
constexpr std::pair<const char*, const char*> kWheelQ[] = {{"normal_force", "N"},
                                                           {"normal_tread", "N"},
                                                           {"normal_flange", "N"},
                                                           {"creep_force_x", "N"},
                                                           {"creep_force_y", "N"},
                                                           {"creepage_x", "-"},
                                                           {"creepage_y", "-"},
                                                           {"spin", "1/m"},
                                                           {"wheel_s", "m"},
                                                           {"rail_s", "m"},
                                                           {"contact_angle", "rad"},
                                                           {"flange_indentation", "m"},
                                                           {"flange_force", "N"},
                                                           {"regime", "-"},
                                                           {"y_over_q", "-"},
                                                           {"X", "N"},
                                                           {"Y", "N"},
                                                           {"Q", "N"},
                                                           {"y_track", "N"}};
constexpr std::size_t kNq = std::size(kWheelQ);

// Per contact patch (/contact/<wheelset>/<side>/patch0, patch1): what an EN 14363 assessment and
// a wear (T gamma) analysis read. An inactive patch writes zeros (active = 0).
constexpr std::pair<const char*, const char*> kPatchQ[] = {{"active", "-"},
                                                           {"on_flange", "-"},
                                                           {"normal_force", "N"},
                                                           {"creep_force_x", "N"},
                                                           {"creep_force_y", "N"},
                                                           {"spin_moment", "N m"},
                                                           {"creepage_x", "-"},
                                                           {"creepage_y", "-"},
                                                           {"spin", "1/m"},
                                                           {"wheel_s", "m"},
                                                           {"rail_s", "m"},
                                                           {"y", "m"},
                                                           {"contact_angle", "rad"},
                                                           {"contact_angle_track", "rad"},
                                                           {"rolling_radius", "m"},
                                                           {"semi_axis_a", "m"},
                                                           {"semi_axis_b", "m"},
                                                           {"X", "N"},
                                                           {"Y", "N"},
                                                           {"Q", "N"},
                                                           {"y_track", "N"},
                                                           {"t_gamma", "N"},
                                                           {"power", "W"}};
constexpr std::size_t kNp = std::size(kPatchQ);
constexpr std::size_t kWheelValues = kNq + 2 * kNp;  // values per wheel and output time
// What patch 0 and 1 are, [KEC, LUT][patch].
constexpr const char* kPatchRole[2][2] = {
    {"KEC contact point, or point A in the band", "KEC point B (flange-side end of the band)"},
    {"LUT tread", "LUT flange (Hertz)"}};

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
         std::string("T gamma = |fx sx| + |fy sy| + |mz spin| [N] (mz only from the Kalker "
                     "linear law, 0 with Polach); power = T gamma V [W]"));
  f.attr("/contact", "patches",
         std::string(method == dynamics::ContactMethod::Kec
                         ? "KEC: patch0 = the contact point, or inside a regularised "
                           "tread-flange band point A (field-side end, weight 1 - w); patch1 = "
                           "point B (flange-side end, weight w), active only inside the band "
                           "(Eq. 26)"
                         : "LUT: patch0 = the tread contact (Eq. 17); patch1 = the Hertz flange "
                           "contact (Eq. 20-21), active while the flange indentation is positive"));
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

// Channels of the bodies and suspension elements, in the order sampleVehicle fills them, and the
// /bodies attributes.
void addVehicleChannels(const Model& m, io::ResultFile& f, std::vector<OutputChannel>& outputs) {
  const auto& v = *m.vehicle;
  const bool acc = m.spec.run.body_accelerations;
  static const char* coords[6] = {"s", "y", "z", "roll", "pitch", "yaw"};
  static const char* units[6] = {"m", "m", "m", "rad", "rad", "rad"};
  std::string names;
  for (const auto& b : v.bodies) {
    names += (names.empty() ? "" : "\n") + b.name;
    f.attr("/bodies/" + b.name, "kind", kindName(b.kind));
    for (int k = 0; k < 6; ++k)
      outputs.push_back({"/bodies/" + b.name + "/" + coords[k], units[k]});
    if (acc)
      for (const char* a : {"ax", "ay", "az"})
        outputs.push_back({"/bodies/" + b.name + "/" + a, "m/s^2"});
  }
  f.attr("/bodies", "names", names);
  if (acc)
    f.attr("/bodies", "acceleration_frame",
           std::string("absolute acceleration of the centre of mass, components in the body's "
                       "track frame (x along the track, y lateral, z vertical)"));
  for (auto id : m.output_elements) {
    const std::string base = "/elements/" + v.elementName(id) + "/";
    const bool bending = id.kind == vehicle::ElementKind::BendingSpring;
    outputs.push_back({base + "deflection", bending ? "rad" : "m"});
    outputs.push_back({base + "force", bending ? "N m" : "N"});
  }
}

// Channels of the wheels, in the order sampleWheels fills them, and the /contact attributes.
void addContactChannels(const Model& m, io::ResultFile& f, std::vector<OutputChannel>& outputs) {
  const auto& v = *m.vehicle;
  const auto& cm = *m.contact;
  const bool kec = cm.method == dynamics::ContactMethod::Kec;
  for (int w : cm.wheelsets)
    for (const char* side : {"left", "right"}) {
      const std::string base = "/contact/" + v.bodies[w].name + "/" + side + "/";
      for (const auto& [q, u] : kWheelQ) outputs.push_back({base + q, u});
      for (int p = 0; p < 2; ++p) {
        const std::string patch = base + "patch" + std::to_string(p);
        f.attr(patch, "role", std::string(kPatchRole[kec ? 0 : 1][p]));
        for (const auto& [q, u] : kPatchQ) outputs.push_back({patch + "/" + q, u});
      }
    }
  writeContactConventions(f, cm.method);
  f.attr("/contact", "method", std::string(dynamics::ContactModel::methodName(cm.method)));
  f.attr("/contact", "creep", std::string(dynamics::ContactModel::creepName(cm.creep)));
  f.attr("/contact", "normal_forces",
         std::string(dynamics::ContactModel::couplingName(cm.coupling)));
  f.attr("/contact", "min_normal_force", cm.min_normal_force);
  f.attr("/contact", "mu", m.spec.contact.mu);
  const auto& ts = cm.tableStats();
  f.attr("/contact", "table_build_time_s", ts.build_seconds);
  f.attr("/contact", "table_bytes", static_cast<std::int64_t>(ts.bytes));
}

// Per-patch values (kPatchQ order); returns the next output slot.
double* samplePatch(const dynamics::PatchOutput& p, double* out) {
  if (!p.active) {
    for (std::size_t k = 0; k < kNp; ++k) *out++ = 0.0;
    return out;
  }
  const double vals[] = {1.0,
                         p.on_flange ? 1.0 : 0.0,
                         p.normal,
                         p.fx,
                         p.fy,
                         p.mz,
                         p.sx,
                         p.sy,
                         p.spin,
                         p.s_w,
                         p.s_r,
                         p.y,
                         p.gamma,
                         p.gamma_track,
                         p.radius,
                         p.a,
                         p.b,
                         p.force.X,
                         p.force.Y,
                         p.force.Q,
                         p.force.y_track,
                         p.t_gamma,
                         p.power};
  static_assert(std::size(vals) == kNp);
  for (const double x : vals) *out++ = x;
  return out;
}

// Per-wheel values (kWheelQ order, then its patches); returns the next output slot.
double* sampleWheels(const std::vector<dynamics::WheelOutput>& wheels, double t, double* out,
                     CreepageMaximum& creepage) {
  for (const auto& w : wheels) {
    // The dominant patch (largest normal force) gives creepages and contact position.
    const auto& p = std::abs(w.patch[1].normal) > std::abs(w.patch[0].normal) && w.patch[1].active
                        ? w.patch[1]
                        : w.patch[0];
    const double vals[] = {w.normal,
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
                           w.y_over_q,
                           w.force.X,
                           w.force.Y,
                           w.force.Q,
                           w.force.y_track};
    static_assert(std::size(vals) == kNq);
    for (const double x : vals) *out++ = x;
    for (const auto& patch : w.patch) out = samplePatch(patch, out);
    creepage.update(w, t);
  }
  return out;
}

// /stats of the contact model and the warnings of a contact run.
void writeContactStats(const Model& m, const dynamics::ContactStats& cs,
                       const CreepageMaximum& creepage, io::ResultFile& f, VehicleRunResult& out) {
  f.attr("/stats", "model_evaluations", static_cast<std::int64_t>(cs.evaluations));
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

}  // namespace

VehicleRunResult runVehicle(const Model& m, io::ResultFile& f, const VehicleRunOptions& o) {
  RB_CHECK(m.vehicle.has_value(), "runVehicle needs a vehicle");
  const auto& v = *m.vehicle;
  const std::size_t nb = v.bodies.size();
  const std::unique_ptr<vehicle::VehicleOde> ode = makeVehicleOde(m);
  auto* contact = dynamic_cast<dynamics::ContactVehicleOde*>(ode.get());  // null: guided

  SimulationRequest r;
  r.system = ode.get();
  r.solver = m.solver;
  r.y0 = ode->initialState(0.0);
  r.t_end = m.t_end;
  r.output_every = m.spec.run.output_every;
  r.progress = o.progress;
  // Arc length of the leading body, the body compile() runs to the track end, so that a failure's
  // distance is where the first wheelset was.
  const double lead = v.start + m.leadingX();
  r.distance = [lead, &v](double t, const Eigen::VectorXd&) { return lead + v.travel(t); };

  // Channels, in the order the sampler fills them.
  r.outputs.push_back({"/vehicle/speed", "m/s"});
  addVehicleChannels(m, f, r.outputs);
  if (contact) addContactChannels(m, f, r.outputs);

  const bool acc = m.spec.run.body_accelerations;
  std::vector<Vector6d> q(nb), qdd(nb);
  std::vector<Eigen::Vector3d> a(nb);
  std::vector<ElementValue> values(m.output_elements.size());
  std::vector<dynamics::WheelOutput> wo(contact ? 2 * m.contact->wheelsets.size() : 0);
  CreepageMaximum creepage;
  r.sample = [&](double t, const Eigen::VectorXd& y, double* out) {
    *out++ = v.speedAt(t);
    ode->bodyCoordinates(t, y.data(), q);
    if (acc) absoluteAccelerations(*ode, t, y.data(), qdd, a);
    for (std::size_t b = 0; b < nb; ++b) {
      for (int k = 0; k < 6; ++k) *out++ = q[b][k];
      if (acc)
        for (int k = 0; k < 3; ++k) *out++ = a[b][k];
    }
    if (!values.empty()) {
      ode->elementOutputs(t, y.data(), m.output_elements, values);
      for (const auto& e : values) {
        *out++ = e.d;
        *out++ = e.force;
      }
    }
    if (!contact) return;
    if (contact->wheelOutputs(t, y.data(), wo) != 0) {
      for (std::size_t k = 0; k < wo.size() * kWheelValues; ++k)
        *out++ = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    sampleWheels(wo, t, out, creepage);
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
  out.result = simulate(r, f);
  if (contact) writeContactStats(m, contact->stats(), creepage, f, out);
  writeWarnings(f, out.warnings);
  f.flush();
  return out;
}

void writeProvenance(const Model& c, io::ResultFile& f, const std::string& created) {
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
  io::writeTrack(f, c.spec.track, track::sampleTrack(*c.track));
  f.attr("/track", "build_time_s", c.track_build_s);
}

}  // namespace rb::run
