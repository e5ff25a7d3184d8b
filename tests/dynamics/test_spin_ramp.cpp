// contact.wheelset_spin = "prescribed" (theta_dot = V(t) / r_c, theta not a state) and the speed
// ramp (vehicle.acceleration) with wheel/rail contact (docs/contact_dynamics.md sections 1, 7).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dyn_fixtures.hpp"
#include "workbench/vehicle/modal.hpp"

namespace rbtest {
namespace {

using vehicle::kPitch;
using vehicle::kS;
using vehicle::kY;

// Case 2 (wagon, R = 500 m, 20 m/s) started with every wheelset on the constant curve.
const char* kCase2 = "scenarios/validation/case2_kec.lua";

TEST(PrescribedSpin, LayoutHasNoSpinStates) {
  const Compiled free = compileScenario(kCase2);
  const Compiled pres = compileScenario(kCase2, {"contact.wheelset_spin=prescribed"});
  ASSERT_EQ(pres.contact->spin, dynamics::WheelsetSpin::Prescribed);
  dynamics::ContactVehicleOde of(*free.vehicle, *free.contact, *free.track);
  dynamics::ContactVehicleOde op(*pres.vehicle, *pres.contact, *pres.track);
  const int nw = op.layout().n_ws;
  EXPECT_EQ(op.size(), of.size() - 2 * nw);
  EXPECT_GE(of.indexOf("ws1.theta"), 0);
  EXPECT_EQ(op.indexOf("ws1.theta"), -1);
  EXPECT_EQ(op.indexOf("ws1.theta_dot"), -1);
  const int ws1 = pres.vehicle->findBody("ws1");
  EXPECT_EQ(op.index(ws1, kPitch), -1);
  EXPECT_EQ(op.index(ws1, kPitch, true), -1);
  // Every name is unique and the wheelset y / psi are where the layout says.
  for (int w = 0; w < nw; ++w) {
    const std::string name =
        pres.vehicle
            ->bodies[static_cast<std::size_t>(op.layout().wheelsets[static_cast<std::size_t>(w)])]
            .name;
    EXPECT_EQ(op.componentName(op.layout().wsPosition(w, 0)), name + ".y");
    EXPECT_EQ(op.componentName(op.layout().wsPosition(w, 2)), name + ".psi");
    EXPECT_EQ(op.componentName(op.layout().wsRate(w, 2)), name + ".psi_dot");
    EXPECT_EQ(op.layout().wsPosition(w, 1), -1);
  }
  for (int i = 0; i < op.size(); ++i) EXPECT_EQ(op.indexOf(op.componentName(i)), i);
  EXPECT_EQ(op.componentName(op.layout().series(0)), "series[0].f");
}

// The spin angle is kinematic: theta = travel(t) / r_c.
TEST(PrescribedSpin, SpinAngleFollowsTheTravel) {
  const Compiled c =
      compileScenario(kCase2, {"contact.wheelset_spin=prescribed", "vehicle.acceleration=0.5"});
  dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
  const Eigen::VectorXd y = ode.initialState(0.0);
  std::vector<vehicle::Vector6d> q(c.vehicle->bodies.size());
  const double t = 1.7;
  ASSERT_EQ(ode.bodyCoordinates(t, y.data(), q), 0);
  const double rc = c.contact->centredRadius();
  for (int w : c.contact->wheelsets)
    EXPECT_NEAR(q[static_cast<std::size_t>(w)][kPitch], (20.0 * t + 0.25 * t * t) / rc, 1e-10);
}

// Linearised at t = 0 (tangent track, consistent normal forces so that the rhs is a function of
// the state): the free spin has the stiff creep mode near -2400 1/s (section 7), beyond ABM's
// 1 ms stability limit 1.28 / h; with the spin prescribed every eigenvalue lies inside it.
TEST(PrescribedSpin, RemovesTheStiffSpinCreepMode) {
  double most_negative[2] = {0.0, 0.0};
  int k = 0;
  for (const char* spin : {"free", "prescribed"}) {
    const Compiled c = compileScenario(
        kCase2, {std::string("contact.wheelset_spin=") + spin, "contact.normal_forces=consistent"});
    dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
    const Eigen::VectorXd y = ode.initialState(0.0);
    const Eigen::MatrixXd J = vehicle::finiteDifferenceJacobian(ode, 0.0, y);
    const Eigen::VectorXcd ev = J.eigenvalues();
    for (int i = 0; i < ev.size(); ++i) most_negative[k] = std::min(most_negative[k], ev[i].real());
    ++k;
  }
  EXPECT_LT(most_negative[0], -2000.0);
  EXPECT_GT(most_negative[1], -1280.0);  // h |lambda| < 1.28 at h = 1 ms (ABM4 PECE)
}

// ABM at the paper's 1 ms with a prescribed spin stays stable and agrees with the free-spin
// model integrated at a stable small step: steady curving, wagon on the R = 500 m curve.
TEST(PrescribedSpin, AbmOneMillisecondMatchesFreeSpinSteadyCurving) {
  const std::vector<std::string> common = {"vehicle.start=175"};
  auto over = [&](const char* spin) {
    std::vector<std::string> o = common;
    o.push_back(std::string("contact.wheelset_spin=") + spin);
    return o;
  };
  const Compiled cf = compileScenario(kCase2, over("free"));
  const Compiled cp = compileScenario(kCase2, over("prescribed"));
  dynamics::ContactVehicleOde of(*cf.vehicle, *cf.contact, *cf.track);
  dynamics::ContactVehicleOde op(*cp.vehicle, *cp.contact, *cp.track);
  const double t_end = 4.0;
  const Trace tf = run(of, solverSpec("abm", 2.5e-4), t_end, 0.1);
  const Trace tp = run(op, solverSpec("abm", 1e-3), t_end, 0.1);
  ASSERT_TRUE(tf.result.ok) << tf.result.message;
  ASSERT_TRUE(tp.result.ok) << tp.result.message;
  ASSERT_EQ(tf.q.size(), tp.q.size());
  double max_late = 0.0;
  for (int w : cp.contact->wheelsets) {
    const auto b = static_cast<std::size_t>(w);
    // Steady: the last second.
    for (std::size_t i = tp.q.size() - 10; i < tp.q.size(); ++i)
      max_late = std::max(max_late, std::abs(tp.q[i][b][kY] - tf.q[i][b][kY]));
    // Stable: no step-to-step oscillation in the last outputs.
    EXPECT_LT(std::abs(tp.q.back()[b][kY] - tp.q[tp.q.size() - 2][b][kY]), 2e-5);
  }
  EXPECT_LT(max_late, 0.2e-3);
}

// Speed ramp with contact: s(t) and V(t) as prescribed; with a free spin the creep forces spin
// the wheelsets up with the speed (theta_dot ~ V(t) / r), both methods run.
TEST(SpeedRamp, ContactRunsFollowTheRamp) {
  for (const char* f :
       {"scenarios/validation/case3_kec.lua", "scenarios/validation/case3_lut.lua"}) {
    for (const char* spin : {"free", "prescribed"}) {
      const Compiled c = compileScenario(
          f, {"vehicle.acceleration=1.0", std::string("contact.wheelset_spin=") + spin});
      dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
      const double step = std::string(spin) == "free" ? 2.5e-4 : 1e-3;
      const double t_end = 2.0;
      const Trace tr = run(ode, solverSpec("abm", step), t_end, 0.1);
      ASSERT_TRUE(tr.result.ok) << f << " " << spin << ": " << tr.result.message;
      const double t = tr.t.back();
      EXPECT_NEAR(t, t_end, 1e-12);
      const double travel = 20.0 * t + 0.5 * t * t;
      for (std::size_t b = 0; b < c.vehicle->bodies.size(); ++b)
        EXPECT_NEAR(tr.q.back()[b][kS], c.vehicle->start + c.vehicle->bodies[b].x + travel, 1e-9);
      const double V = 20.0 + t;
      if (std::string(spin) == "free") {
        const int i = ode.indexOf("ws1.theta_dot");
        ASSERT_GE(i, 0);
        EXPECT_NEAR(tr.y.back()[i] * c.contact->centredRadius() / V, 1.0, 2e-3) << f;
      }
      // Wheelsets stay on the rails (|y| of a few mm on the irregular track).
      for (int w : c.contact->wheelsets)
        EXPECT_LT(std::abs(tr.q.back()[static_cast<std::size_t>(w)][kY]), 8e-3);
    }
  }
}

}  // namespace
}  // namespace rbtest
