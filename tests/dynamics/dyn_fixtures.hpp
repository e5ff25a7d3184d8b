#pragma once
// Shared helpers of the contact-dynamics tests: load a scenario file (or build specs in code),
// compile track, vehicle and contact, integrate and sample the wheelset coordinates.
#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "workbench/dynamics/contact_model.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/integrators/integrator.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/model.hpp"

namespace rbtest {

using namespace rb;

// Tables are shared by all tests of one executable (built once per configuration).
inline dynamics::TableCache& tableCache() {
  static dynamics::TableCache cache;
  return cache;
}

struct Compiled {
  scenario::ScenarioSpec spec;
  std::unique_ptr<track::TrackModel> track;
  std::unique_ptr<vehicle::VehicleModel> vehicle;
  std::unique_ptr<dynamics::ContactModel> contact;
};

inline Compiled compileScenario(const std::string& file,
                                const std::vector<std::string>& overrides = {}) {
  scenario::LoadOptions lo;
  lo.root = RB_SOURCE_DIR;
  lo.overrides = overrides;
  Compiled c;
  c.spec = scenario::loadScenario(std::string(RB_SOURCE_DIR) + "/" + file, lo);
  c.track = std::make_unique<track::TrackModel>(track::compileTrack(c.spec.track));
  c.vehicle =
      std::make_unique<vehicle::VehicleModel>(vehicle::compileVehicle(c.spec.vehicle, *c.track));
  c.contact = std::make_unique<dynamics::ContactModel>(dynamics::compileContact(
      c.spec.profiles, c.spec.contact, *c.vehicle, *c.track, &tableCache()));
  return c;
}

// Specs built in code: a track, a vehicle, default profiles and a contact block.
inline Compiled compileSpecs(const track::TrackSpec& ts, const vehicle::VehicleSpec& vs,
                             const dynamics::ContactSpec& cs,
                             const dynamics::ProfilesSpec& ps = {}) {
  Compiled c;
  c.spec.track = ts;
  c.spec.vehicle = vs;
  c.spec.contact = cs;
  c.spec.profiles = ps;
  c.track = std::make_unique<track::TrackModel>(track::compileTrack(ts));
  c.vehicle = std::make_unique<vehicle::VehicleModel>(vehicle::compileVehicle(vs, *c.track));
  c.contact = std::make_unique<dynamics::ContactModel>(
      dynamics::compileContact(ps, cs, *c.vehicle, *c.track, &tableCache()));
  return c;
}

inline track::TrackSpec tangentTrack(double length) {
  track::TrackSpec t;
  track::SegmentSpec s;
  s.kind = track::SegmentKind::Tangent;
  s.length = length;
  t.segments = {s};
  t.step = 0.5;
  return t;
}

// Tangent, transition, curve (left), no cant.
inline track::TrackSpec curveTrack(double radius, double tangent, double transition, double curve) {
  track::TrackSpec t;
  track::SegmentSpec a, b, c;
  a.kind = track::SegmentKind::Tangent;
  a.length = tangent;
  b.kind = track::SegmentKind::Transition;
  b.length = transition;
  b.radius = radius;
  b.side = track::Side::Left;
  c.kind = track::SegmentKind::Curve;
  c.length = curve;
  c.radius = radius;
  c.side = track::Side::Left;
  t.segments = {a, b, c};
  t.step = 0.5;
  return t;
}

// A lone wheelset (Manchester wheelset, paper Table 2), no suspension: only its weight.
inline vehicle::VehicleSpec freeWheelset(double speed) {
  vehicle::VehicleSpec v;
  v.name = "free_wheelset";
  v.speed = speed;
  v.wheel_radius = 0.46;
  vehicle::BodySpec b;
  b.name = "ws";
  b.kind = vehicle::BodyKind::Wheelset;
  b.mass = 1813;
  b.inertia = Eigen::Vector3d(1120, 112, 1120);
  b.height = 0.46;
  v.bodies = {b};
  return v;
}

// A wheelset loaded by a kinematic frame through vertical-only constant loads (zero stiffness):
// free in y, psi, theta, carrying `axle_load` [N] in addition to its own weight.
inline vehicle::VehicleSpec loadedWheelset(double speed, double axle_load) {
  vehicle::VehicleSpec v = freeWheelset(speed);
  v.name = "loaded_wheelset";
  vehicle::BodySpec f;
  f.name = "frame";
  f.kind = vehicle::BodyKind::Frame;
  f.mass = 1;
  f.inertia = Eigen::Vector3d(1, 1, 1);
  f.height = 0.6;
  v.bodies.insert(v.bodies.begin(), f);
  for (double sy : {1.0, -1.0}) {
    vehicle::ElementSpec e;
    e.name = sy > 0 ? "load_l" : "load_r";
    e.kind = vehicle::ElementKind::SpringDamper;
    e.body1 = "frame";
    e.body2 = "ws";
    e.point1 = Eigen::Vector3d(0, sy, 0.46 - 0.6);
    e.point2 = Eigen::Vector3d(0, sy, 0);
    e.direction = vehicle::Direction::Z;
    e.preload = axle_load / 2;
    v.elements.push_back(e);
  }
  return v;
}

// A run sampled at the output times: the state and the full coordinates of every body.
struct Trace {
  integ::RunResult result;
  std::vector<double> t;
  std::vector<Eigen::VectorXd> y;
  std::vector<std::vector<vehicle::Vector6d>> q;  // [output][body]
};

inline Trace run(dynamics::ContactVehicleOde& ode, const integ::SolverSpec& solver, double t_end,
                 double every, const Eigen::VectorXd* y0 = nullptr) {
  Trace tr;
  auto integrator = integ::makeIntegrator(solver);
  const Eigen::VectorXd start = y0 ? *y0 : ode.initialState(0.0);
  std::vector<double> times;
  const long n = static_cast<long>(std::llround(t_end / every));
  for (long k = 1; k <= n; ++k) times.push_back(static_cast<double>(k) * every);
  const std::size_t nb = ode.model().bodies.size();
  tr.result = integ::integrate(ode, *integrator, 0.0, start, times,
                               [&](double t, const Eigen::VectorXd& y) {
                                 tr.t.push_back(t);
                                 tr.y.push_back(y);
                                 std::vector<vehicle::Vector6d> q(nb);
                                 ode.bodyCoordinates(t, y.data(), q);
                                 tr.q.push_back(q);
                                 return true;
                               });
  return tr;
}

inline integ::SolverSpec solverSpec(const std::string& method, double step) {
  integ::SolverSpec s;
  s.method = method;
  s.step = step;
  return s;
}

}  // namespace rbtest
