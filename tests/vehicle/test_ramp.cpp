// Speed ramp (vehicle.acceleration): the imposed motion s = start + x + V0 t + a t^2 / 2 with its
// inertia -M_ps a in the free equations (docs/vehicle.md section 1).
#include <gtest/gtest.h>

#include <cmath>

#include "fixtures.hpp"
#include "workbench/vehicle/guided.hpp"
#include "workbench/vehicle/model.hpp"

namespace rbtest {
namespace {

using rb::vehicle::BodyKind;
using rb::vehicle::compileVehicle;
using rb::vehicle::GuidedVehicleOde;
using rb::vehicle::kPitch;
using rb::vehicle::kS;

// s(t) and V(t) of every body are the prescribed ones, wheelset spin travel / r0.
TEST(SpeedRamp, PrescribedArcLengthSpeedAndSpin) {
  const auto track = rb::track::compileTrack(tangentTrack(400.0));
  VehicleSpec spec = manchesterWagon(15.0, 20.0);
  spec.acceleration = 0.8;
  const auto model = compileVehicle(spec, track);
  GuidedVehicleOde ode(model);
  const Eigen::VectorXd y = ode.initialState(0.0);
  rb::vehicle::Workspace ws = rb::vehicle::makeWorkspace(model);
  const double t = 3.0;
  rb::vehicle::guidedCoordinates(model, ode.layout(), t, y.data(), ws);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    EXPECT_NEAR(ws.q[b][kS], 20.0 + model.bodies[b].x + 15.0 * t + 0.4 * t * t, 1e-12);
    EXPECT_NEAR(ws.qd[b][kS], 15.0 + 0.8 * t, 1e-14);
    if (model.bodies[b].kind == BodyKind::Wheelset) {
      EXPECT_NEAR(ws.q[b][kPitch], (15.0 * t + 0.4 * t * t) / model.wheel_radius, 1e-12);
      EXPECT_NEAR(ws.qd[b][kPitch], (15.0 + 0.8 * t) / model.wheel_radius, 1e-12);
    }
  }
}

// On tangent track every body's drive reaction acts at its own centre of mass (s is imposed on
// every body, docs/vehicle.md): the prescribed acceleration does not load the suspension, so the
// static state does not change (no pitch), the absolute acceleration of every body is a along the
// track, and the tractions add up to sum(m) a. Hand estimate for comparison: were the whole drive
// force applied at the wheelsets, the car would pitch by about m_c a (h_c - h_sec) / (4 Ksz 9.5^2),
// i.e. nose up; that physics needs a longitudinal degree of freedom the model does not have.
TEST(SpeedRamp, TangentTrackTractionBalancesInertiaWithoutPitch) {
  const auto track = rb::track::compileTrack(tangentTrack(400.0));
  VehicleSpec spec = manchesterWagon(20.0, 20.0);
  const auto m0 = compileVehicle(spec, track);
  spec.acceleration = 1.5;
  const auto m1 = compileVehicle(spec, track);
  GuidedVehicleOde ode0(m0), ode1(m1);
  const Eigen::VectorXd y0 = ode0.initialState(0.0);
  const Eigen::VectorXd y1 = ode1.initialState(0.0);
  EXPECT_LT((y1 - y0).lpNorm<Eigen::Infinity>(), 1e-12);
  double traction = 0.0, mass = 0.0;
  for (std::size_t b = 0; b < m1.bodies.size(); ++b) {
    if (m1.bodies[b].kind == BodyKind::Frame) continue;
    const auto o = ode1.bodyOutput(0.0, y1.data(), static_cast<int>(b));
    EXPECT_NEAR(o.acceleration.x(), 1.5, 1e-9) << m1.bodies[b].name;
    traction += o.traction;
    mass += m1.bodies[b].mass;
  }
  EXPECT_NEAR(traction, mass * 1.5, 1e-6 * mass * 1.5);
}

// On a curve of curvature kappa the track frames turn with kappa V: the speed ramp adds the
// angular acceleration kappa a of the frames (the M_ps a coupling), seen on a body at rest in its
// frame; the rhs with a != 0 differs from a = 0 exactly by -M_pp^-1 M_ps a.
TEST(SpeedRamp, CurveFrameAngularAccelerationKappaA) {
  const double R = 400.0, a = -1.2;
  const auto track = rb::track::compileTrack(curveTrack(rb::track::Side::Left, R, 0.0));
  VehicleSpec spec = manchesterWagon(20.0, 150.0);  // all bodies on the constant curve
  spec.acceleration = a;
  const auto model = compileVehicle(spec, track);
  GuidedVehicleOde ode(model);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(ode.size());
  const int car = model.findBody("car");
  // A guided wheelset (at rest in its frame at t = 0, spin angle 0): alpha = kappa a about the
  // vertical, a / r0 about the axle.
  const auto o = ode.bodyOutput(0.0, y.data(), model.findBody("ws1"));
  EXPECT_NEAR(o.angular_acceleration.z(), a / R, 1e-9);
  EXPECT_NEAR(o.angular_acceleration.y(), a / model.wheel_radius, 1e-9);
  // Against the same model at a = 0.
  VehicleSpec spec0 = spec;
  spec0.acceleration = 0.0;
  const auto model0 = compileVehicle(spec0, track);
  GuidedVehicleOde ode0(model0);
  Eigen::VectorXd yd(ode.size()), yd0(ode.size());
  ASSERT_EQ(ode.rhs(0.0, y.data(), yd.data()), 0);
  ASSERT_EQ(ode0.rhs(0.0, y.data(), yd0.data()), 0);
  const auto& ws = ode.workspace();
  const auto& l = ode.layout();
  for (int k = 0; k < l.n_free; ++k) {
    const auto b = static_cast<std::size_t>(l.free_bodies[static_cast<std::size_t>(k)]);
    const Eigen::Matrix<double, 5, 5> Mpp = ws.mass[b].block<5, 5>(1, 1);
    const Eigen::Matrix<double, 5, 1> expect = -Mpp.llt().solve(ws.mass[b].block<5, 1>(1, kS)) * a;
    for (int c = 0; c < 5; ++c)
      EXPECT_NEAR(yd[l.rate(k, c)] - yd0[l.rate(k, c)], expect[c], 1e-9) << k << " " << c;
  }
  // The yaw of the car: the frame's angular acceleration about Z needs I_zz kappa a.
  const int kc = l.slot[static_cast<std::size_t>(car)];
  EXPECT_NEAR(yd[l.rate(kc, 4)] - yd0[l.rate(kc, 4)], -a / R, 1e-9);
}

// a = 0 reproduces the constant-speed model exactly (the ramp terms add +0.0).
TEST(SpeedRamp, ZeroAccelerationIsBitIdentical) {
  const auto track = rb::track::compileTrack(curveTrack(rb::track::Side::Right, 300.0, 0.1));
  VehicleSpec spec = manchesterWagon(20.0, 30.0);
  const auto model = compileVehicle(spec, track);
  GuidedVehicleOde ode(model);
  Eigen::VectorXd y = ode.initialState(0.0);
  for (int i = 0; i < ode.size(); ++i) y[i] += 1e-4 * std::sin(1.0 + i);
  Eigen::VectorXd yd(ode.size());
  const double t = 2.345;
  ASSERT_EQ(ode.rhs(t, y.data(), yd.data()), 0);
  // The constant-speed expressions, evaluated independently.
  rb::vehicle::Workspace ws = rb::vehicle::makeWorkspace(model);
  rb::vehicle::guidedCoordinates(model, ode.layout(), t, y.data(), ws);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    EXPECT_EQ(ws.q[b][kS], model.start + model.bodies[b].x + model.speed * t);
    EXPECT_EQ(ws.qd[b][kS], model.speed);
  }
  rb::vehicle::evaluate(model, t, y.data() + ode.layout().series(0), ws);
  const auto& l = ode.layout();
  for (int k = 0; k < l.n_free; ++k) {
    const auto b = static_cast<std::size_t>(l.free_bodies[static_cast<std::size_t>(k)]);
    const Eigen::Matrix<double, 5, 5> Mpp = ws.mass[b].block<5, 5>(1, 1);
    const Eigen::Matrix<double, 5, 1> acc =
        Eigen::LLT<Eigen::Matrix<double, 5, 5>>(Mpp).solve(ws.force[b].segment<5>(1));
    for (int c = 0; c < 5; ++c) EXPECT_EQ(yd[l.rate(k, c)], acc[c]);
  }
}

}  // namespace
}  // namespace rbtest
