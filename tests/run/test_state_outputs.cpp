// The model's outputs at one observed state (run/state_outputs.hpp): each kind is evaluated at
// most once per state, the element values come with either evaluation, and what the samplers get
// is bit for bit what the model's own on-demand calls give, for a vehicle on wheel/rail contact
// (KEC and LUT) and a guided one.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/state_outputs.hpp"

namespace {

using rb::vehicle::ElementId;
using rb::vehicle::ElementValue;
using rb::vehicle::Vector6d;

rb::run::Model compileScene(const std::string& scenario, std::vector<std::string> sets = {}) {
  rb::run::CompileOptions o;
  o.scenario = scenario;
  o.root = RB_SOURCE_DIR;
  sets.emplace_back("run.duration=0.1");
  o.overrides = sets;
  return rb::run::compile(o);
}

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expectSame(const Vector6d& a, const Vector6d& b, const std::string& what) {
  for (int k = 0; k < 6; ++k) EXPECT_TRUE(sameBits(a[k], b[k])) << what << " component " << k;
}

void expectSame(const rb::dynamics::WheelOutput& a, const rb::dynamics::WheelOutput& b,
                const std::string& what) {
  EXPECT_TRUE(sameBits(a.normal, b.normal)) << what;
  EXPECT_TRUE(sameBits(a.force.Y, b.force.Y)) << what;
  EXPECT_TRUE(sameBits(a.force.Q, b.force.Q)) << what;
  EXPECT_TRUE(sameBits(a.y_over_q, b.y_over_q)) << what;
  for (int p = 0; p < 2; ++p) {
    EXPECT_EQ(a.patch[p].active, b.patch[p].active) << what;
    EXPECT_TRUE(sameBits(a.patch[p].fx, b.patch[p].fx)) << what << " patch " << p;
    EXPECT_TRUE(sameBits(a.patch[p].fy, b.patch[p].fy)) << what << " patch " << p;
    EXPECT_TRUE(sameBits(a.patch[p].sx, b.patch[p].sx)) << what << " patch " << p;
    EXPECT_TRUE(sameBits(a.patch[p].t_gamma, b.patch[p].t_gamma)) << what << " patch " << p;
  }
}

// Every element of the vehicle (the wagon has one of each kind at least).
std::vector<ElementId> allElements(const rb::vehicle::VehicleModel& v) {
  return v.elements();
}

// A state off equilibrium: the leading wheelset 2 mm to the left with some yaw rate, so the
// contact forces, creepages and accelerations are not those of the symmetric rest state.
Eigen::VectorXd offState(rb::vehicle::VehicleOde& ode) {
  Eigen::VectorXd y = ode.initialState(0.0);
  const auto& l = ode.layout();
  y[l.wsPosition(0, 0)] += 2e-3;
  y[l.wsRate(0, 2)] += 0.05;
  return y;
}

}  // namespace

TEST(StateOutputs, ContactOutputsAreTheModelsOwnFromOneEvaluation) {
  for (const std::string method : {"kec", "lut"}) {
    SCOPED_TRACE(method);
    const rb::run::Model m = compileScene("scenarios/validation/case3_" + method + ".lua");
    // Two models of the same vehicle from the same start: one asked by the model's own calls,
    // one through StateOutputs.
    rb::dynamics::ContactVehicleOde direct(m.lead().vehicle, *m.lead().contact, *m.track);
    rb::dynamics::ContactVehicleOde shared(m.lead().vehicle, *m.lead().contact, *m.track);
    const Eigen::VectorXd y = offState(direct);
    ASSERT_EQ(offState(shared), y);
    const double t = 0.0;
    const std::size_t nb = m.lead().vehicle.bodies.size();
    const std::vector<ElementId> ids = allElements(m.lead().vehicle);

    std::vector<rb::dynamics::WheelOutput> wheels(2 * m.lead().contact->wheelsets.size());
    std::vector<Vector6d> qdd(nb);
    std::vector<ElementValue> values(ids.size());
    ASSERT_EQ(direct.wheelOutputs(t, y.data(), wheels), 0);
    ASSERT_EQ(direct.bodyAccelerations(t, y.data(), qdd), 0);
    ASSERT_EQ(direct.elementOutputs(t, y.data(), ids, values), 0);

    rb::run::StateOutputs state(shared, &shared);
    const long before = shared.stats().evaluations;
    state.at(t, y.data());
    ASSERT_TRUE(state.wheels());
    ASSERT_TRUE(state.accelerations());
    std::vector<ElementValue> got(ids.size());
    state.elements(ids, got);
    // The same state sampled again (the assessment and the outputs at one step end): nothing new.
    state.at(t, y.data());
    ASSERT_TRUE(state.wheels());
    ASSERT_TRUE(state.accelerations());
    state.elements(ids, got);
    // On contact the wheels and the accelerations come from one evaluation.
    EXPECT_EQ(state.evaluations(), 1);
    EXPECT_EQ(shared.stats().evaluations - before, 1);

    for (std::size_t w = 0; w < wheels.size(); ++w)
      expectSame(state.wheelOutputs()[w], wheels[w], "wheel " + std::to_string(w));
    for (std::size_t b = 0; b < nb; ++b)
      expectSame(state.qdd()[b], qdd[b], "body " + std::to_string(b));
    for (std::size_t i = 0; i < ids.size(); ++i) {
      EXPECT_TRUE(sameBits(got[i].d, values[i].d)) << "element " << i;
      EXPECT_TRUE(sameBits(got[i].force, values[i].force)) << "element " << i;
    }

    // Another state is evaluated anew.
    Eigen::VectorXd y2 = y;
    y2[shared.layout().wsPosition(0, 0)] += 1e-4;
    state.at(t, y2.data());
    ASSERT_TRUE(state.wheels());
    EXPECT_EQ(state.evaluations(), 2);
    ASSERT_EQ(direct.wheelOutputs(t, y2.data(), wheels), 0);
    expectSame(state.wheelOutputs()[0], wheels[0], "wheel 0 at the second state");
  }
}

TEST(StateOutputs, ElementsAloneCostOneEvaluation) {
  const rb::run::Model m = compileScene("scenarios/validation/case3_kec.lua");
  rb::dynamics::ContactVehicleOde ode(m.lead().vehicle, *m.lead().contact, *m.track);
  const Eigen::VectorXd y = offState(ode);
  const std::vector<ElementId> ids = allElements(m.lead().vehicle);
  std::vector<ElementValue> direct(ids.size()), got(ids.size());
  ASSERT_EQ(ode.elementOutputs(0.0, y.data(), ids, direct), 0);
  rb::run::StateOutputs state(ode, &ode);
  state.at(0.0, y.data());
  state.elements(ids, got);
  EXPECT_EQ(state.evaluations(), 1);
  for (std::size_t i = 0; i < ids.size(); ++i)
    EXPECT_TRUE(sameBits(got[i].force, direct[i].force)) << "element " << i;
}

TEST(StateOutputs, GuidedVehicleHasNoWheelsAndSharesTheAccelerationsEvaluation) {
  const rb::run::Model m = compileScene("scenarios/vehicle/manchester_guided_r500.lua");
  auto direct = rb::run::makeVehicleOde(m);
  auto shared = rb::run::makeVehicleOde(m);
  Eigen::VectorXd y = direct->initialState(0.0);
  ASSERT_EQ(shared->initialState(0.0), y);
  y[direct->layout().position(0, 0)] += 1e-3;  // the car body 1 mm to the left
  const std::vector<ElementId> ids = allElements(m.lead().vehicle);
  std::vector<Vector6d> qdd(m.lead().vehicle.bodies.size());
  std::vector<ElementValue> values(ids.size()), got(ids.size());
  ASSERT_EQ(direct->bodyAccelerations(0.5, y.data(), qdd), 0);
  ASSERT_EQ(direct->elementOutputs(0.5, y.data(), ids, values), 0);

  rb::run::StateOutputs state(*shared, nullptr);
  state.at(0.5, y.data());
  EXPECT_FALSE(state.wheels());
  EXPECT_TRUE(state.wheelOutputs().empty());
  ASSERT_TRUE(state.accelerations());
  state.elements(ids, got);
  EXPECT_EQ(state.evaluations(), 1);
  for (std::size_t b = 0; b < qdd.size(); ++b)
    expectSame(state.qdd()[b], qdd[b], "body " + std::to_string(b));
  for (std::size_t i = 0; i < ids.size(); ++i) {
    EXPECT_TRUE(sameBits(got[i].d, values[i].d)) << "element " << i;
    EXPECT_TRUE(sameBits(got[i].force, values[i].force)) << "element " << i;
  }
}
