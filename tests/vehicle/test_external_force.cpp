// The external force element (vehicle::ExternalForceSpec) in the vehicle model: its generalised
// forces are those of a force at a point (virtual work against finite differences of the point's
// position, in both frames, on a car body and on a wheelset), and the guided Manchester wagon
// pushed sideways stands where the statics of its suspension put it (a hand calculation).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "fixtures.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/dynamics.hpp"
#include "workbench/vehicle/guided.hpp"

namespace rb::vehicle {
namespace {

ExternalForceSpec force(const std::string& name, const std::string& body, Eigen::Vector3d at,
                        ForceFrame frame, Eigen::Vector3d direction, double value) {
  ExternalForceSpec f;
  f.name = name;
  f.body = body;
  f.point = at;
  f.frame = frame;
  f.direction = direction;
  f.law.value = value;
  f.loc = {"test.lua", 1};
  return f;
}

// Global position of the point u of body b's attachment frame at coordinates q.
Eigen::Vector3d globalPoint(const VehicleModel& m, std::size_t b, const Vector6d& q,
                            const Eigen::Vector3d& u) {
  BodyKinematics k;
  bodyKinematics(m.geometry, m.bodies[b].rotation, m.bodies[b].height, q, Vector6d::Zero(), k);
  return k.tf.R + k.tf.A * (k.rbar + k.attach.A * u);
}

TEST(ExternalForce, GeneralisedForceIsTheVirtualWorkOfAForceAtItsPoint) {
  // On a canted curve, bodies displaced and rotated: the generalised force Q_i = F . dr_P/dq_i
  // (F in global components, r_P the global position of the point), with dr_P/dq_i by central
  // differences. Two forces on the car (track frame, body frame) and one on a wheelset (its
  // axle-box frame, which does not spin with the wheel), at points off the centre of mass.
  const track::TrackModel tm =
      track::compileTrack(rbtest::curveTrack(track::Side::Left, 300.0, 0.15));
  const VehicleSpec plain = rbtest::manchesterWagon(20.0, 120.0);
  VehicleSpec pushed = plain;
  pushed.external_forces = {
      force("wind", "car", {3.0, -0.8, 1.2}, ForceFrame::Track, {0.2, 1.0, -0.5}, 7e3),
      force("load", "car", {-4.0, 1.1, -0.4}, ForceFrame::Body, {0.0, 0.3, -1.0}, 11e3),
      force("rig", "ws1", {0.1, 0.75, -0.2}, ForceFrame::Body, {0.0, -1.0, 0.1}, 30e3)};
  const VehicleModel m0 = compileVehicle(plain, tm);
  const VehicleModel m1 = compileVehicle(pushed, tm);
  ASSERT_EQ(m1.external_forces.size(), 3u);
  Workspace w0 = makeWorkspace(m0), w1 = makeWorkspace(m1);
  const double t = 0.3;
  for (std::size_t b = 0; b < m0.bodies.size(); ++b) {
    Vector6d q, qd;
    const double k = static_cast<double>(b);
    q << m0.bodyS(static_cast<int>(b), t), 0.004 - 0.001 * k, -0.01 + 0.002 * k, 0.012 - 0.003 * k,
        -0.006 + 0.002 * k, 0.015 - 0.004 * k;
    qd << 20.0, 0.01, -0.02, 0.03, 0.01, -0.02;
    if (m0.bodies[b].kind == BodyKind::Wheelset) {
      q[kPitch] = 1.7 + k;
      qd[kPitch] = 43.0;
    }
    w0.q[b] = w1.q[b] = q;
    w0.qd[b] = w1.qd[b] = qd;
  }
  const std::vector<double> series_f(m0.series_dampers.size(), 250.0);
  evaluate(m0, t, series_f.data(), w0);
  evaluate(m1, t, series_f.data(), w1);
  std::vector<Vector6d> expected(m0.bodies.size(), Vector6d::Zero());
  for (const ExternalForce& e : m1.external_forces) {
    const auto b = static_cast<std::size_t>(e.body);
    const BodyKinematics& k = w1.kin[b];
    // F in global components: the direction in the body's track frame, or in its attachment
    // frame (the body's orientation relative to the track frame, then the track frame's).
    const Eigen::Vector3d dir_track =
        e.frame == ForceFrame::Track ? e.direction : Eigen::Vector3d(k.attach.A * e.direction);
    const Eigen::Vector3d F = k.tf.A * dir_track * e.law.value;
    for (int i = 0; i < 6; ++i) {
      const double h = 1e-6;
      Vector6d qp = w1.q[b], qm = w1.q[b];
      qp[i] += h;
      qm[i] -= h;
      const Eigen::Vector3d dr =
          (globalPoint(m1, b, qp, e.u) - globalPoint(m1, b, qm, e.u)) / (2 * h);
      expected[b][i] += F.dot(dr);
    }
  }
  for (std::size_t b = 0; b < m0.bodies.size(); ++b)
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(w1.force[b][i] - w0.force[b][i], expected[b][i], 1e-3)
          << m0.bodies[b].name << " coordinate " << i;
  // The moment of the point: the car's roll generalised force is not that of a force at the
  // centre of mass (whose roll term would vanish in a body-fixed direction at the CoM).
  EXPECT_GT(std::abs(w1.force[0][kRoll] - w0.force[0][kRoll]), 1e3);
}

// The guided wagon on a tangent at rest under a lateral push F to the left at height u_z above
// the car body's centre of mass (track frame).
struct Pushed {
  double car_y = 0.0, car_roll = 0.0, bogie_roll = 0.0;
  std::vector<double> shear_d, shear_f;
  BodyOutput car;
  Eigen::Vector3d au = Eigen::Vector3d::Zero();
};

Pushed pushedWagon(double F, double uz) {
  static const track::TrackModel tm = track::compileTrack(rbtest::tangentTrack(400.0));
  VehicleSpec v = rbtest::manchesterWagon(20.0, 50.0);
  v.external_forces = {force("push", "car", {0.0, 0.0, uz}, ForceFrame::Track, {0, 1, 0}, F)};
  const VehicleModel m = compileVehicle(v, tm);
  GuidedVehicleOde ode(m);
  const Eigen::VectorXd y = ode.initialState(0.0);
  Pushed p;
  p.car_y = y[ode.index(0, kY)];
  p.car_roll = y[ode.index(0, kRoll)];
  p.bogie_roll = y[ode.index(m.findBody("bogie1"), kRoll)];
  std::vector<ElementId> ids;
  for (const char* n : {"sec_shear_y_bogie1_l", "sec_shear_y_bogie1_r", "sec_shear_y_bogie2_l",
                        "sec_shear_y_bogie2_r"})
    ids.push_back(*m.findElement(n));
  std::vector<ElementValue> values(ids.size());
  ode.elementOutputs(0.0, y.data(), ids, values);
  for (const auto& e : values) {
    p.shear_d.push_back(e.d);
    p.shear_f.push_back(e.force);
  }
  p.car = ode.bodyOutput(0.0, y.data(), 0);
  p.au = ode.workspace().kin[0].attach.A * Eigen::Vector3d(0.0, 0.0, uz);
  return p;
}

TEST(ExternalForce, LateralPushOnTheCarStandsWhereTheSuspensionStaticsPutIt) {
  // F = 6.4 kN to the left. Only the four secondary shear springs (K = 160 kN/m each) carry the
  // car laterally at rest: the lateral dampers (Dsy with Ksy in series) carry no static force,
  // the bump stops stay inside their 25 mm clearance, every other element acts along x or z or
  // is a moment. Each shear spring therefore takes F/4 = 1.6 kN and deflects F/(4 K) = 10 mm
  // (d = bogie point - car point: -10 mm), whatever the height of the push.
  //
  // Roll, first order in the angles (docs/vehicle.md, External forces): with Kz = 430 kN/m
  // (secondary, 2 per bogie at +-1 m), Kr = 940 kN m/rad (anti-roll bar per bogie), Kpz =
  // 1220 kN/m (primary, 4 per bogie at +-1 m), the weights W_c = 32000 g, W_b = 2615 g carried
  // through the rolled attachment points, the secondary springs 0.9725 m below the car's centre
  // of mass and 0.2275 m above the bogie's, the primary 0.14 m below the bogie's, and the
  // wheelsets guided:
  //   car:   (4 Kz + 2 Kr)(phi_b - phi_c) + 0.9725 W_c phi_c - (0.9725 + u_z) F = 0
  //   bogie: -(2 Kz + Kr)(phi_b - phi_c) + (0.2275 W_c/2 + 0.14 (W_c/2 + W_b) - 4 Kpz) phi_b
  //          - (0.2275 + 0.14) F/2 = 0
  // and laterally y_b + 0.14 phi_b = (F/2)/(4 Kpy), y_c = y_b - 0.2275 phi_b + F/(4 K) -
  // 0.9725 phi_c. Solved for u_z = 0 (at the CoM), -0.9725 m (at the secondary springs) and
  // +1 m above the CoM:
  struct Case {
    double uz, phi_c, phi_b, y_c;  // [m], [rad], [rad], [m]
  };
  const double F = 6.4e3;
  for (const Case c : {Case{0.0, -2.96399e-3, -0.983753e-3, 13.44999e-3},
                       Case{-0.9725, -0.276222e-3, -0.252798e-3, 10.56750e-3},
                       Case{1.0, -5.72777e-3, -1.735377e-3, 16.41398e-3}}) {
    SCOPED_TRACE("u_z = " + std::to_string(c.uz));
    const Pushed p = pushedWagon(F, c.uz);
    // Together they carry F exactly; each a quarter of it up to a second-order split between
    // left and right: the rolled springs' points at y = +-1 m move by -+(phi_c^2 - phi_b^2)/2
    // (1.5e-5 m of the 10 mm with the push 1 m above the centre of mass, 0.15 %).
    double sum = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
      sum += p.shear_f[k];
      EXPECT_NEAR(p.shear_f[k], -F / 4.0, 2e-3 * F / 4.0) << k;
      EXPECT_NEAR(p.shear_d[k], -F / (4.0 * 160e3), 2e-3 * F / (4.0 * 160e3)) << k;
    }
    EXPECT_NEAR(sum, -F, 1e-6 * F);
    // The neglected terms are second order in angles of a few mrad: 1 % of the first-order
    // values, plus 2 urad / 0.02 mm for the near-zero roll of the push at the springs.
    EXPECT_NEAR(p.car_roll, c.phi_c, 0.01 * std::abs(c.phi_c) + 2e-6);
    EXPECT_NEAR(p.bogie_roll, c.phi_b, 0.01 * std::abs(c.phi_b) + 2e-6);
    EXPECT_NEAR(p.car_y, c.y_c, 0.01 * std::abs(c.y_c) + 2e-5);
    // Exactly, at rest: the suspension's resultant on the car balances the push and gravity, and
    // its moment about the centre of mass balances the push's moment au x F.
    const Eigen::Vector3d push(0.0, F, 0.0);
    EXPECT_NEAR(p.car.suspension_force.y(), -F, 1e-6 * F);
    EXPECT_NEAR(p.car.suspension_force.z(), 32000.0 * 9.81, 1e-6 * 32000.0 * 9.81);
    const Eigen::Vector3d moment = p.au.cross(push);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(p.car.suspension_moment[i], -moment[i], 1e-6 * F) << "moment component " << i;
  }
}

TEST(ExternalForce, CompileRefusesBadForcesWithTheirPlace) {
  const track::TrackModel tm = track::compileTrack(rbtest::tangentTrack(400.0));
  VehicleSpec v = rbtest::manchesterWagon(20.0, 50.0);
  v.external_forces = {
      force("push", "cra", {0, 0, 0}, ForceFrame::Track, {0, 1, 0}, 1e3),
      force("prim_x_ws1_l", "car", {0, 0, 200.0}, ForceFrame::Track, {0, 0, 0}, 1e3),
  };
  v.external_forces[1].law.kind = suspension::ForceLawKind::Table;
  v.external_forces[1].law.at = {0.0, 0.0};
  v.external_forces[1].law.force = {0.0, 1.0};
  v.external_forces[1].table_loc = {"test.lua", 7};
  try {
    (void)compileVehicle(v, tm);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("test.lua:1: element 'push' (external_force): unknown body 'cra' in "
                       "'body' (did you mean 'car'?)"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("element 'prim_x_ws1_l' (external_force): duplicate element name"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("the point 'at' must lie within 100 m"), std::string::npos) << msg;
    EXPECT_NE(msg.find("direction must be a vector of length > 0"), std::string::npos) << msg;
    EXPECT_NE(msg.find("test.lua:7: element 'prim_x_ws1_l' (external_force): table: t must be "
                       "strictly increasing"),
              std::string::npos)
        << msg;
  }
}

}  // namespace
}  // namespace rb::vehicle
