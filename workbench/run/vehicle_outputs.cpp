#include "workbench/run/vehicle_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "workbench/dynamics/names.hpp"
#include "workbench/dynamics/wheel_measures.hpp"
#include "workbench/run/channels.hpp"
#include "workbench/suspension/external_force.hpp"
#include "workbench/vehicle/names.hpp"

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

// The rails of a side with further rails (profiles.extra_rails): "rail" (the running rail) and
// theirs; none for a side with the running rail alone.
std::vector<std::string> railNames(const dynamics::ContactModel& cm, std::size_t side) {
  if (!cm.elastic || cm.elastic->extra_names[side].empty()) return {};
  std::vector<std::string> out = {"rail"};
  for (const std::string& n : cm.elastic->extra_names[side]) out.push_back(n);
  return out;
}
// The conventions of the track-frame forces (dynamics::TrackForces) and of the patches.
void writeContactConventions(io::ResultFile& f, const std::string& contact,
                             dynamics::ContactMethod method) {
  f.attr(contact, "force_frame",
         std::string("X, Y, Q, y_track: force of the rail on the wheel (per wheel: the sum over "
                     "its patches, normal and creep forces) in the wheelset's track frame: x "
                     "along the track, y in the track plane (design cant included, irregularities "
                     "not), z perpendicular to the track plane, as EN 14363"));
  f.attr(contact, "sign_X", std::string("positive forward (direction of travel)"));
  f.attr(contact, "sign_Y",
         std::string("positive toward the track centre on either wheel (EN 14363: positive when "
                     "it pushes the flange away from its rail); Y = -y_track on the left wheel, "
                     "+y_track on the right; y_over_q = Y / Q"));
  f.attr(contact, "sign_Q", std::string("positive upward on the wheel (wheel load)"));
  f.attr(contact, "sign_y_track",
         std::string("positive to the left on both wheels; the sum over a wheelset's wheels is "
                     "its track-shifting force"));
  f.attr(contact, "patch_contact_frame",
         std::string("creep_force_x/y, spin_moment act on the wheel in the patch's contact frame: "
                     "x the wheel's rolling direction, n the rail normal into the wheel, y = n x "
                     "x; contact_angle from the contact table, contact_angle_track including the "
                     "rails' cross-level angle, both positive toward the track centre; y: "
                     "lateral track-frame position of the contact point, positive to the left"));
  f.attr(contact, "t_gamma",
         std::string("T gamma = |fx sx| + |fy sy| + |mz spin| [N] (mz from the laws that give a "
                     "spin moment; 0 with polach); power = T gamma V [W]"));
  // What patch 0 and 1 are: the method's row of the registry (dynamics/contact_methods.hpp).
  f.attr(contact, "patches", std::string(dynamics::methodInfo(method).patches));
}

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
void addVehicleChannels(const Model& m, const RunVehicle& rv, io::ResultFile& f,
                        std::vector<OutputChannel>& outputs) {
  const auto& v = rv.vehicle;
  const std::string root = rv.prefix();
  const bool acc = m.spec.run.body_accelerations;
  std::string names;
  for (const auto& b : v.bodies) {
    names += (names.empty() ? "" : "\n") + b.name;
    const std::string body = root + "/bodies/" + b.name;
    f.attr(body, "kind", std::string(nameOf(b.kind)));
    addChannels(body + "/", kBodyCoordChannels, outputs);
    if (acc) addChannels(body + "/", kBodyAccelerationChannels, outputs);
  }
  f.attr(root + "/bodies", "names", names);
  if (acc)
    f.attr(root + "/bodies", "acceleration_frame",
           std::string("absolute acceleration of the centre of mass, components in the body's "
                       "track frame (x along the track, y lateral, z vertical)"));
  for (auto id : rv.output_elements) {
    const std::string base = root + "/elements/" + v.elementName(id) + "/";
    const bool bending = id.kind == vehicle::ElementKind::BendingSpring;
    outputs.push_back(
        {base + "deflection", bending ? "rad" : "m",
         "deflection of the element (" + std::string(vehicle::elementKindName(id.kind)) + ")", ""});
    outputs.push_back(
        {base + "force", bending ? "N m" : "N",
         "force of the element (" + std::string(vehicle::elementKindName(id.kind)) + ")", ""});
  }
  // Every external force is written: it is an input of the run, and its history is what its
  // result is read against.
  for (const auto& e : v.external_forces) {
    const std::string group = root + "/elements/" + e.name;
    const std::string frame(nameOf(e.frame));
    f.attr(group, "kind", std::string(vehicle::kExternalForceKind));
    f.attr(group, "body", v.bodies[static_cast<std::size_t>(e.body)].name);
    f.attr(group, "frame", frame);
    f.attr(group, "law", std::string(nameOf(e.law.kind)));
    outputs.push_back({group + "/force", "N",
                       "value F of the external force along its direction (external_force)", ""});
    for (const char* axis : {"x", "y", "z"})
      outputs.push_back({group + "/force_" + axis, "N",
                         std::string(axis) + " component of the external force in the " + frame +
                             " frame (external_force)",
                         ""});
  }
}

// Channels of the wheels, in the order sampleWheels fills them, and the /contact attributes.
void addContactChannels(const Model& m, const RunVehicle& rv, io::ResultFile& f,
                        std::vector<OutputChannel>& outputs) {
  const auto& v = rv.vehicle;
  const auto& cm = *rv.contact;
  const std::string contact = rv.prefix() + "/contact";
  const dynamics::ContactMethodInfo& info = dynamics::methodInfo(cm.method);
  for (std::size_t k = 0; k < cm.wheelsets.size(); ++k) {
    // The wheelset's wheels (its own: profiles.wheelsets) by file name, and their centred
    // rolling radii.
    const dynamics::ContactModel& own = cm.forWheelset(k);
    const std::string group = contact + "/" + v.bodies[cm.wheelsets[k]].name;
    const std::array<dynamics::WheelMeasures, 2> measures = dynamics::wheelMeasures(own);
    for (std::size_t side = 0; side < 2; ++side) {
      const char* name = side == 0 ? "left" : "right";
      f.attr(group, std::string("wheel_profile_") + name,
             std::filesystem::path(own.wheel_sources[side]).filename().string());
      f.attr(group, std::string("centred_radius_") + name, own.centred_radius[side]);
      // EN 15313 flange measures of the wheel, and a MiniProf file's own (docs/profiles.md).
      const dynamics::WheelMeasures& w = measures[side];
      const std::pair<const char*, double> values[] = {{"Sd", w.sd},
                                                       {"Sh", w.sh},
                                                       {"qR", w.qr},
                                                       {"header_Sd", w.header_sd},
                                                       {"header_Sh", w.header_sh},
                                                       {"header_qR", w.header_qr}};
      for (const auto& [key, value] : values)
        if (!std::isnan(value))
          f.attr(group, std::string("wheel_") + key + "_" + name + "_m", value);
    }
    if (const auto* e = own.elastic.get()) {
      // What follows from the wheelset's own wheels (the /contact attributes are the vehicle's).
      f.attr(group, "elastic_flange_height_m", e->flange_height);
      f.attr(group, "derailment_lift_m", e->derailment_lift);
      f.attr(group, "elastic_static_approach_m", e->static_approach);
    }
  }
  for (int w : cm.wheelsets)
    for (const char* side : {"left", "right"}) {
      const std::string base = contact + "/" + v.bodies[w].name + "/" + side + "/";
      addChannels(base, kWheelChannels, outputs);
      if (m.spec.run.output_patches)
        for (int p = 0; p < 2; ++p) {
          const std::string patch = base + "patch" + std::to_string(p);
          f.attr(patch, "role", std::string(info.patch_role[static_cast<std::size_t>(p)]));
          addChannels(patch + "/", kPatchChannels, outputs);
        }
      // A side with further rails (profiles.extra_rails): the wheel's contact per rail.
      const std::vector<std::string> rails = railNames(cm, side[0] == 'l' ? 0 : 1);
      if (cm.railSupport()) addChannels(base + "track/", kTrackChannels, outputs);
      for (const std::string& rail : rails)
        addChannels(base + "rails/" + rail + "/", kRailChannels, outputs);
    }
  writeContactConventions(f, contact, cm.method);
  f.attr(contact, "method", std::string(dynamics::ContactModel::methodName(cm.method)));
  f.attr(contact, "creep", std::string(dynamics::ContactModel::creepName(cm.creep)));
  if (cm.creep == dynamics::CreepModel::Fastsim) {
    // FASTSIM's result depends on its grid (docs/creep.md): recorded with the law.
    f.attr(contact, "fastsim_strips", static_cast<std::int64_t>(cm.fastsim.strips));
    f.attr(contact, "fastsim_elements", static_cast<std::int64_t>(cm.fastsim.elements));
    f.attr(contact, "fastsim_bound", std::string(nameOf(cm.fastsim.bound)));
  }
  f.attr(contact, "normal_forces", std::string(dynamics::ContactModel::couplingName(cm.coupling)));
  f.attr(contact, "min_normal_force", cm.min_normal_force);
  f.attr(contact, "mu", m.spec.contact.mu);
  // The flange angle of Nadal's limit (run.assessment.flange_angle, default S1002's): the contact
  // figures draw the same limit as the assessment.
  f.attr(contact, "flange_angle", m.spec.run.assessment.flange_angle);
  // Which interpolation the tables were read with (cubic/bicubic or the paper's linear, section
  // 5.5): results of the two are not interchangeable.
  f.attr(contact, "table_interpolation", std::string(nameOf(cm.geometry.interpolation)));
  const auto& ts = cm.tableStats();
  f.attr(contact, "table_build_time_s", ts.build_seconds);
  f.attr(contact, "table_bytes", static_cast<std::int64_t>(ts.bytes));
  if (const auto* e = cm.elastic.get()) {
    // The elastic method's assumptions and derived constants (docs/elastic_contact.md).
    f.attr(contact, "elastic_damping_ratio", e->damping_ratio);
    f.attr(contact, "elastic_damping_s_per_m", e->damping);
    f.attr(contact, "elastic_static_load_N", e->static_load);
    f.attr(contact, "elastic_static_approach_m", e->static_approach);
    f.attr(contact, "elastic_vertical_frequency_hz", e->vertical_frequency);
    f.attr(contact, "elastic_sample_step_m", e->search.front().spec().sample_step);
    f.attr(contact, "elastic_min_curvature_ratio", e->normal.min_ratio);
    f.attr(contact, "elastic_flange_height_m", e->flange_height);
    f.attr(contact, "derailment_lift_m", e->derailment_lift);
  }
}

// Per-patch values (kPatchChannels order); returns the next output slot.
double* samplePatch(const dynamics::PatchOutput& p, double* out) {
  for (const auto& c : kPatchChannels) *out++ = p.active ? c.get(p) : 0.0;
  return out;
}

// Per-wheel values (kWheelChannels order, then its patches, its track under the rail when the run
// has one, then its rails when its side has further rails); returns the next output slot.
double* sampleWheels(const std::vector<dynamics::WheelOutput>& wheels, double t, double* out,
                     CreepageMaximum& creepage, bool patches,
                     const std::array<std::size_t, 2>& rails, bool track) {
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    const dynamics::WheelOutput& w = wheels[i];
    // The dominant patch (largest normal force) gives creepages and contact position.
    const auto& p = std::abs(w.patch[1].normal) > std::abs(w.patch[0].normal) && w.patch[1].active
                        ? w.patch[1]
                        : w.patch[0];
    const WheelSample sample{w, p};
    for (const auto& c : kWheelChannels) *out++ = c.get(sample);
    if (patches)
      for (const auto& patch : w.patch) out = samplePatch(patch, out);
    if (track)
      for (const auto& c : kTrackChannels) *out++ = c.get(w);
    for (std::size_t r = 0; r < rails[i % 2]; ++r)
      for (const auto& c : kRailChannels) *out++ = c.get(w.rail[r]);
    creepage.update(w, t);
  }
  return out;
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

// The external forces at time t with the bodies at q (F, then its components in its frame).
void sampleExternalForces(const vehicle::VehicleModel& v, double t,
                          const std::vector<vehicle::Vector6d>& q, double*& out) {
  for (const auto& e : v.external_forces) {
    const double f =
        suspension::forceAt(e.law, t, q[static_cast<std::size_t>(e.body)][vehicle::kS]);
    *out++ = f;
    for (int k = 0; k < 3; ++k) *out++ = f * e.direction[k];
  }
}

}  // namespace

void CreepageMaximum::update(const dynamics::WheelOutput& w, double t_now) {
  for (const auto& pp : w.patch) {
    if (!pp.active) continue;
    const double c = std::max(std::abs(pp.sx), std::abs(pp.sy));
    if (c > value) {
      value = c;
      t = t_now;
    }
  }
}

VehicleOutputs::VehicleOutputs(const Model& m, const RunVehicle& v, vehicle::VehicleOde& ode)
    : m_(m),
      v_(v),
      ode_(ode),
      contact_(dynamic_cast<dynamics::ContactVehicleOde*>(&ode)),
      state_(ode, contact_),
      q_(v.vehicle.bodies.size()),
      a_(v.vehicle.bodies.size()),
      values_(v.output_elements.size()) {
  if (v.contact) {
    rails_ = {railNames(*v.contact, 0).size(), railNames(*v.contact, 1).size()};
    track_ = v.contact->railSupport();
    if (const auto* e = v.contact->elastic.get())
      for (std::size_t side = 0; side < 2; ++side)
        for (std::size_t r = 0; r < e->extra_check[side].size(); ++r)
          answers_.check[side][r + 1] = e->extra_check[side][r] != 0;
    if (dynamics::methodInfo(v.contact->method).band_monitor)
      band_.resize(2 * v.contact->wheelsets.size());
  }
}

void VehicleOutputs::declare(io::ResultFile& f, std::vector<OutputChannel>& outputs) const {
  addVehicleChannels(m_, v_, f, outputs);
  if (contact_ != nullptr) addContactChannels(m_, v_, f, outputs);
}

double* VehicleOutputs::sample(double t, const double* y, double* out) {
  const bool acc = m_.spec.run.body_accelerations;
  state_.at(t, y);
  ode_.bodyCoordinates(t, y, q_);
  if (acc) absoluteAccelerations(state_, a_);
  for (std::size_t b = 0; b < q_.size(); ++b) {
    const BodySample body{q_[b], a_[b]};
    for (const auto& c : kBodyCoordChannels) *out++ = c.get(body);
    if (acc)
      for (const auto& c : kBodyAccelerationChannels) *out++ = c.get(body);
  }
  if (contact_ == nullptr) {
    sampleElements(state_, v_.output_elements, values_, out);
    sampleExternalForces(v_.vehicle, t, q_, out);
    return out;
  }
  // The wheel outputs first: their evaluation also gives the element values.
  const bool wheels = state_.wheels();
  sampleElements(state_, v_.output_elements, values_, out);
  sampleExternalForces(v_.vehicle, t, q_, out);
  const bool patches = m_.spec.run.output_patches;
  if (!wheels) {
    const std::size_t n =
        state_.wheelOutputs().size() * (patches ? kWheelValues : kWheelChannelCount) +
        state_.wheelOutputs().size() / 2 * kRailChannelCount * (rails_[0] + rails_[1]) +
        (track_ ? state_.wheelOutputs().size() * kTrackChannelCount : 0);
    for (std::size_t k = 0; k < n; ++k) *out++ = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  if (rails_[0] + rails_[1] > 0) {
    ws_s_.clear();
    for (int b : contact_->contact().wheelsets)
      ws_s_.push_back(q_[static_cast<std::size_t>(b)][vehicle::kS]);
    answers_.update(state_.wheelOutputs(), ws_s_, rails_);
  }
  for (std::size_t i = 0; i < band_.size() && i < state_.wheelOutputs().size(); ++i) {
    const dynamics::WheelOutput& w = state_.wheelOutputs()[i];
    band_[i].add(t, w.force.Y, w.regime == 1);
  }
  return sampleWheels(state_.wheelOutputs(), t, out, creepage_, patches, rails_, track_);
}

void VehicleOutputs::writeRailAnswers(io::ResultFile& f, std::vector<std::string>& lines) const {
  if (contact_ == nullptr) return;
  const dynamics::ContactModel& cm = contact_->contact();
  for (const RailAnswers::Wheel& wh : answers_.wheels) {
    const std::vector<std::string> names = railNames(cm, wh.side);
    const std::string ws =
        v_.vehicle.bodies[static_cast<std::size_t>(cm.wheelsets[wh.wheelset])].name;
    const std::string side = wh.side == 0 ? "left" : "right";
    const std::string group = v_.prefix() + "/contact/" + ws + "/" + side + "/rails";
    std::string line = "  " + ws + " " + side + ":";
    for (std::size_t r = 0; r < names.size(); ++r) {
      line += (r > 0 ? "; " : " ") + names[r] + ":";
      const bool check = answers_.check[wh.side][r];
      if (r > 0) {
        if (std::isfinite(wh.transfer_s[r])) {
          f.attr(group, (check ? "first_contact_s_" : "transfer_s_") + names[r], wh.transfer_s[r]);
          line += (check ? " touched from s = " : " from s = ") +
                  formatNumber(wh.transfer_s[r], 5) + " m,";
        } else {
          line += check ? " never touched," : " never carried more than " + names[0] + ",";
        }
      }
      f.attr(group, "peak_normal_force_" + names[r], wh.peak[r]);
      line += " largest N " + formatNumber(wh.peak[r] * 1e-3, 4) + " kN";
      if (std::isfinite(wh.peak_s[r]) && wh.peak[r] > 0.0) {
        f.attr(group, "peak_normal_force_s_" + names[r], wh.peak_s[r]);
        line += " (s = " + formatNumber(wh.peak_s[r], 5) + " m)";
      }
    }
    lines.push_back(line);
  }
}

void VehicleOutputs::bandOscillationWarnings(std::vector<std::string>& warnings) const {
  if (contact_ == nullptr) return;
  const dynamics::ContactModel& cm = contact_->contact();
  for (std::size_t i = 0; i < band_.size(); ++i) {
    const BandOscillation& b = band_[i].result();
    if (!b.found) continue;
    const std::string ws = v_.vehicle.bodies[static_cast<std::size_t>(cm.wheelsets[i / 2])].name;
    warnings.push_back(
        bandOscillationWarning(ws + (i % 2 == 0 ? " left" : " right") + " wheel", b));
  }
}

void RailAnswers::update(const std::vector<dynamics::WheelOutput>& w, const std::vector<double>& s,
                         const std::array<std::size_t, 2>& rails) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (wheels.empty())
    for (std::size_t i = 0; i < w.size(); ++i)
      if (rails[i % 2] > 0) {
        Wheel wh;
        wh.wheelset = i / 2;
        wh.side = i % 2;
        wh.transfer_s.fill(nan);
        wh.peak_s.fill(nan);
        wh.last_diff.fill(nan);
        wheels.push_back(wh);
      }
  for (Wheel& wh : wheels) {
    const dynamics::WheelOutput& o = w[2 * wh.wheelset + wh.side];
    const double si = s[wh.wheelset];
    for (std::size_t r = 0; r < rails[wh.side]; ++r) {
      const double n = o.rail[r].normal;
      if (n > wh.peak[r]) {
        wh.peak[r] = n;
        wh.peak_s[r] = si;
      }
      if (r == 0) continue;
      if (check[wh.side][r]) {
        if (std::isnan(wh.transfer_s[r]) && n > 0.0) wh.transfer_s[r] = si;
        continue;
      }
      const double diff = o.rail[0].normal - n;
      // The first sample where the further rail carries more than the running rail.
      if (std::isnan(wh.transfer_s[r]) && wh.last_diff[r] >= 0.0 && diff < 0.0) {
        const double f = wh.last_diff[r] / (wh.last_diff[r] - diff);
        wh.transfer_s[r] = wh.last_s + f * (si - wh.last_s);
      }
      wh.last_diff[r] = diff;
    }
    wh.last_s = si;
  }
}

}  // namespace rb::run
