// A run holds a list of vehicles (run::Model::vehicles): two wagons without connections between
// them move independently, so with a fixed-step method each is integrated exactly as it would be
// alone. Every output and assessment dataset of each vehicle of the run of two equals the same
// dataset of its single run bit for bit (under /vehicles/<name>), the run of one keeps the root
// groups, and what a run of several cannot be (unnamed vehicles, two of one name, a vehicle off
// the track, a connection) is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/run/run_files.hpp"
#include "workbench/core/error.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/vehicle_run.hpp"

namespace {

namespace fs = std::filesystem;

rb::run::Model compiled(double start) {
  return rb::test::defaultSceneWagon(start);
}

std::string runInto(const rb::run::Model& m, const std::string& name) {
  const rb::test::RunFile run = rb::test::runInto(m, "rb_test_run_of_vehicles", name);
  EXPECT_TRUE(run.result.result.ok) << run.result.result.message;
  return run.path;
}

using rb::test::expectSameVehicle;
using rb::test::sameBits;

TEST(RunOfVehicles, TwoUncoupledWagonsAreEachTheirSingleRunBitForBit) {
  const rb::run::Model front = compiled(40.0), rear = compiled(20.0);
  const std::string single_front = runInto(front, "front.h5");
  const std::string single_rear = runInto(rear, "rear.h5");

  rb::run::Model two = compiled(40.0);
  two.vehicles.front().name = "front";
  rb::run::RunVehicle second = rear.vehicles.front();
  second.name = "rear";
  rb::run::addVehicle(two, second);
  ASSERT_EQ(two.vehicles.size(), 2u);
  const std::string train = runInto(two, "two.h5");

  // Wheels, bodies, the element, the patches and the assessment of both wagons.
  EXPECT_GT(expectSameVehicle(single_front, train, "/vehicles/front"), 500);
  EXPECT_GT(expectSameVehicle(single_rear, train, "/vehicles/rear"), 500);
  const rb::io::ResultReader t(train), s(single_front), r(single_rear);
  EXPECT_FALSE(t.has("/bodies")) << "a run of several keeps no root vehicle groups";
  EXPECT_EQ(t.text("/vehicles", "names").value_or(""), "front\nrear");
  EXPECT_TRUE(sameBits(*t.dataset("/time"), *s.dataset("/time")));
  // Each wagon's contact model counts its own evaluations; the run's are their sum.
  EXPECT_EQ(t.number("/stats", "model_evaluations").value_or(-1),
            s.number("/stats", "model_evaluations").value_or(0) +
                r.number("/stats", "model_evaluations").value_or(0));
  EXPECT_TRUE(t.has("/vehicles/rear/assessment/summary"));

  const auto ode = rb::run::makeRunOde(two);
  EXPECT_EQ(ode->size(), 2 * rb::run::makeVehicleOde(front)->size());
  EXPECT_EQ(ode->componentName(0), "front." + rb::run::makeVehicleOde(front)->componentName(0));
  EXPECT_EQ(ode->componentName(ode->offset(1)),
            "rear." + rb::run::makeVehicleOde(rear)->componentName(0));
}

TEST(RunOfVehicles, TwoGuidedWagonsWithAnAdaptiveMethodRunAsTheirSingleRuns) {
  // Guided wheelsets (no contact), body accelerations, two elements and comfort and stability
  // assessments per wagon; dopri5 picks its steps for the pair, so each wagon is its single run
  // within the tolerance, not bit for bit.
  // Both cars run from the tangent into the transition to the R = 500 m curve (starts 90 and
  // 70 m, 3 s at 20 m/s), where the car bodies move out laterally.
  const std::vector<std::string> sets = {"run.duration=3", "solver.method=dopri5",
                                         "solver.rtol=1e-8", "solver.atol=1e-10"};
  auto at = [&](double start) {
    std::vector<std::string> s = sets;
    s.push_back("vehicle.start=" + std::to_string(start));
    return rb::test::compiled("scenarios/vehicle/manchester_guided_r500.lua", s);
  };
  const rb::run::Model front = at(90.0), rear = at(70.0);
  rb::run::Model two = at(90.0);
  two.vehicles.front().name = "front";
  rb::run::RunVehicle second = rear.vehicles.front();
  second.name = "rear";
  rb::run::addVehicle(two, second);
  const std::string single = runInto(rear, "guided_rear.h5");
  const std::string pair = runInto(two, "guided_two.h5");
  runInto(front, "guided_front.h5");
  const rb::io::ResultReader s(single), t(pair);
  ASSERT_TRUE(t.has("/vehicles/rear/assessment"));
  ASSERT_TRUE(t.has("/vehicles/front/elements/prim_z_ws1_l/force"));
  EXPECT_FALSE(t.has("/contact"));
  // The pair's output times are the single run's (fixed output interval); y of the rear car body
  // (millimetres in the transition) agrees within the integration tolerance.
  const auto ys = s.dataset("/bodies/car/y"), yt = t.dataset("/vehicles/rear/bodies/car/y");
  ASSERT_TRUE(ys && yt);
  ASSERT_EQ(ys->size(), yt->size());
  double worst = 0.0;
  for (std::size_t i = 0; i < ys->size(); ++i)
    worst = std::max(worst, std::abs((*ys)[i] - (*yt)[i]));
  EXPECT_LT(worst, 1e-7);  // [m]
}

TEST(RunOfVehicles, ARunOfOneKeepsItsRootGroupsAndComponentNames) {
  const rb::run::Model one = compiled(40.0);
  const auto ode = rb::run::makeRunOde(one);
  const auto alone = rb::run::makeVehicleOde(one);
  ASSERT_EQ(ode->size(), alone->size());
  for (int i = 0; i < ode->size(); ++i) EXPECT_EQ(ode->componentName(i), alone->componentName(i));
  EXPECT_EQ(ode->jacobianPattern().rows, alone->jacobianPattern().rows);
  EXPECT_EQ(ode->stiffComponents(), alone->stiffComponents());
  EXPECT_EQ(one.lead().prefix(), "");
}

TEST(RunOfVehicles, WhatARunOfSeveralCannotBeIsRefused) {
  const rb::run::Model rear = compiled(20.0);
  {
    rb::run::Model m = compiled(40.0);
    rb::run::RunVehicle v = rear.vehicles.front();
    v.name = "rear";
    EXPECT_THROW(rb::run::addVehicle(m, v), rb::InputError) << "the first vehicle has no name";
  }
  {
    rb::run::Model m = compiled(40.0);
    m.vehicles.front().name = "wagon";
    rb::run::RunVehicle v = rear.vehicles.front();
    v.name = "wagon";
    EXPECT_THROW(rb::run::addVehicle(m, v), rb::InputError) << "two vehicles named alike";
  }
  {
    rb::run::Model m = compiled(40.0);
    m.vehicles.front().name = "front";
    rb::run::RunVehicle v = rear.vehicles.front();
    v.name = "rear";
    v.vehicle.start = -30.0;  // its rear bodies before the track's start
    EXPECT_THROW(rb::run::addVehicle(m, v), rb::InputError);
  }
  {
    rb::run::Model m = compiled(40.0);
    m.vehicles.front().name = "front";
    rb::run::RunVehicle v = rear.vehicles.front();
    v.name = "rear";
    rb::run::addVehicle(m, v);
    rb::train::Connection c;  // rear to front: a connection joins a vehicle to the one behind it
    c.front = 1;
    c.rear = 0;
    m.connections.push_back(c);
    EXPECT_THROW((void)rb::run::makeRunOde(m), std::logic_error);
  }
}

}  // namespace
