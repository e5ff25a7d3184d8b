// The initial state of a vehicle on wheel/rail contact on an irregular track: every wheelset
// starts centred between its rails (y = xi_a, the rails' mid-line, Eq. 18) and parallel to them,
// not at the nominal centreline, which on a rough track can be several millimetres away.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/integrators/integrator.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/start_state.hpp"

namespace {

// The flange-curve study base (ORE B176 high irregularities, seed 42): the rails' mid-line is
// 5.7 mm to the right of the centreline under the leading wheelset at the start.
rb::run::Model compileFlangeCurve(const std::string& method) {
  rb::run::CompileOptions o;
  o.scenario = "scenarios/studies/bases/flange_curve.lua";
  o.root = RB_SOURCE_DIR;
  o.overrides = {"contact.method=" + method, "run.duration=0.2", "solver.step=2.5e-4",
                 "solver.stiff=explicit"};
  return rb::run::compile(o);
}

}  // namespace

TEST(InitialState, WheelsetsStartCentredBetweenTheirRails) {
  for (const std::string method : {"kec", "lut"}) {
    const rb::run::Model m = compileFlangeCurve(method);
    rb::dynamics::ContactVehicleOde ode(m.lead().vehicle, *m.lead().contact, *m.track);
    const Eigen::VectorXd y0 = ode.initialState(0.0);
    const auto& layout = ode.layout();
    const auto& irr = *m.track->irregularities();
    double largest_offset = 0.0;
    for (int w = 0; w < layout.n_ws; ++w) {
      const double s = m.lead().vehicle.bodyS(static_cast<int>(layout.wheelset(w)), 0.0);
      const auto rail = irr.at(s);
      const double mid = 0.5 * (rail.y_l + rail.y_r);
      largest_offset = std::max(largest_offset, std::abs(mid));
      EXPECT_NEAR(y0[layout.wsPosition(w, 0)], mid, 1e-12) << method << " wheelset " << w;
      EXPECT_NEAR(y0[layout.wsPosition(w, 2)], 0.5 * (rail.y_l_s + rail.y_r_s), 1e-12);
    }
    EXPECT_GT(largest_offset, 3e-3) << "the case must test an off-centre rail mid-line";
    // Both wheels of every wheelset carry load on the tread at the start (no flange contact
    // from the set-up): within 30 % of the wheelset's mean wheel load.
    std::vector<rb::dynamics::WheelOutput> wheels(2 * static_cast<std::size_t>(layout.n_ws));
    ASSERT_EQ(ode.wheelOutputs(0.0, y0.data(), wheels), 0);
    for (std::size_t w = 0; w + 1 < wheels.size(); w += 2) {
      const double mean = 0.5 * (wheels[w].normal + wheels[w + 1].normal);
      for (std::size_t side = 0; side < 2; ++side) {
        EXPECT_NEAR(wheels[w + side].normal, mean, 0.3 * mean) << method << " wheel " << w + side;
        EXPECT_EQ(wheels[w + side].regime, 0) << method << " wheel " << w + side;
      }
    }
  }
}

// Regression: started at the centreline, the KEC wagon on this track lifted its leading left
// wheel within 10 ms (flange contact from the set-up, then a violent transient).
TEST(InitialState, KecWagonOnTheRoughCurveRunsWithoutWheelLift) {
  const rb::run::Model m = compileFlangeCurve("kec");
  rb::dynamics::ContactVehicleOde ode(m.lead().vehicle, *m.lead().contact, *m.track);
  const Eigen::VectorXd y0 = ode.initialState(0.0);
  auto integ = rb::integ::makeIntegrator(m.solver);
  const auto res = rb::integ::integrate(ode, *integ, 0.0, y0, {0.1, 0.2},
                                        [](double, const Eigen::VectorXd&) { return true; });
  EXPECT_TRUE(res.ok) << res.message;
}

namespace {

rb::run::CompileOptions twoAxleTwist() {
  rb::run::CompileOptions o;
  o.scenario = "tests/run/data/two_axle_twist.lua";
  o.root = RB_SOURCE_DIR;
  return o;
}

}  // namespace

// Regression: the equilibrium iteration's trial states unloaded a wheel of the rear wagon (the
// start's first iterate has the suspension unloaded), and a constraint-method evaluation refused
// that as a wheel lift at t = 0 (-1.03 kN) although the equilibrium loads every wheel with about
// 100 kN: a twist of 1 mm per metre changes a wheel load of a wagon on 1.2 MN/m axleboxes by a few
// kilonewtons (k g / 4 for a twist g of the four wheels), not by 100.
TEST(InitialState, LoadedWagonsOnTwistedRailsStartInTheirEquilibrium) {
  const rb::run::Model m = rb::run::compile(twoAxleTwist());
  ASSERT_EQ(m.vehicles.size(), 2u);
  for (const rb::run::RunVehicle& v : m.vehicles) {
    rb::dynamics::ContactVehicleOde ode(v.vehicle, *v.contact, *m.track);
    const Eigen::VectorXd y0 = ode.initialState(0.0);
    const auto& layout = ode.layout();
    std::vector<rb::dynamics::WheelOutput> wheels(2 * static_cast<std::size_t>(layout.n_ws));
    ASSERT_EQ(ode.wheelOutputs(0.0, y0.data(), wheels), 0);
    // Static wheel load (38 t + 2 x 1.4 t) g / 4 = 100.1 kN; the twist moves it by < 15 %.
    double total = 0.0;
    for (std::size_t i = 0; i < wheels.size(); ++i) {
      EXPECT_NEAR(wheels[i].normal, 100.1e3, 15e3) << v.name << " wheel " << i;
      total += wheels[i].force_z;
    }
    // The wheels carry the whole weight (the start is an equilibrium, not a fall).
    EXPECT_NEAR(std::abs(total), (38000.0 + 2 * 1400.0) * 9.81, 0.01 * 40800.0 * 9.81) << v.name;
  }
}

// A lift that the equilibrium itself has (a rigid suspension on the same twist) is refused at the
// train entry that places the vehicle, with the rails' irregularities under its wheelsets.
TEST(InitialState, ALiftInTheEquilibriumNamesTheEntryAndTheRails) {
  rb::run::CompileOptions o = twoAxleTwist();
  for (const int element : {1, 4, 7, 10})  // prim_z of the rear wagon
    o.overrides.push_back("train.vehicles[2].vehicle.elements[" + std::to_string(element) +
                          "].stiffness=1.2e9");
  try {
    (void)rb::run::compile(o);
    FAIL() << "a rigid wagon on these rails lifts a wheel in its equilibrium";
  } catch (const rb::InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.diagnostics().size(), 1u) << what;
    EXPECT_NE(what.find("two_axle_twist.lua:21: train.vehicles[2] 'rear'"), std::string::npos)
        << what;
    EXPECT_NE(what.find("wheel lift in the static equilibrium"), std::string::npos) << what;
    EXPECT_NE(what.find("ws1 at s = 108.5 m: -1.30211 / -0.541376 mm"), std::string::npos) << what;
  }
}

// Regression: a lateral offset of vehicle.initial was added to the elastic-contact equilibrium
// with the wheelset's height and roll of the centred position: ws1 moved by -3 mm started with
// 318 kN on its right wheel and its left wheel in the air (static 54.5 kN). The offset is now
// held and the rest of the equilibrium settles around it (run::startWithInitialConditions).
TEST(InitialState, ElasticWheelsetKickedSidewaysStartsOnBothTreads) {
  rb::run::CompileOptions o;
  o.scenario = "scenarios/validation/case3_elastic.lua";
  o.root = RB_SOURCE_DIR;
  o.overrides = {"run.duration=0.05", "vehicle.initial.ws1.y=-0.004"};
  const rb::run::Model m = rb::run::compile(o);
  rb::dynamics::ContactVehicleOde ode(m.lead().vehicle, *m.lead().contact, *m.track);
  const Eigen::VectorXd equilibrium = ode.initialState(0.0);
  Eigen::VectorXd y0 = equilibrium;
  rb::run::startWithInitialConditions(ode, m.lead().initial, y0);
  const auto& layout = ode.layout();
  EXPECT_DOUBLE_EQ(y0[layout.wsPosition(0, 0)], equilibrium[layout.wsPosition(0, 0)] - 0.004);
  std::vector<rb::dynamics::WheelOutput> wheels(2 * static_cast<std::size_t>(layout.n_ws));
  double largest = 0.0, smallest = 1e9;
  const auto record = [&](double t, const Eigen::VectorXd& y) {
    if (ode.wheelOutputs(t, y.data(), wheels) != 0) return false;
    for (const auto& w : wheels) {
      largest = std::max(largest, w.normal);
      smallest = std::min(smallest, w.normal);
    }
    return true;
  };
  ASSERT_TRUE(record(0.0, y0));
  // Measured: 52.2 and 57.1 kN on ws1 at t = 0, 48.3 to 57.1 kN over the first 0.1 s.
  EXPECT_GT(smallest, 40e3);
  EXPECT_LT(largest, 70e3);
  auto integ = rb::integ::makeIntegrator(m.solver);
  const auto res =
      rb::integ::integrate(ode, *integ, 0.0, y0, {0.01, 0.02, 0.03, 0.04, 0.05}, record);
  ASSERT_TRUE(res.ok) << res.message;
  EXPECT_GT(smallest, 40e3);
  EXPECT_LT(largest, 70e3);
}
