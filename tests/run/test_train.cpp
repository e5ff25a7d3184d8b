// train{} (docs/trains.md): several vehicles of one scenario, each with its own vehicle file,
// place, profiles and contact model, without connections. A train of two wagons is each wagon's
// single run bit for bit (fixed step: every update is component-wise), a vehicle with its own
// contact model runs on it, and what a train cannot be is refused at its file:line before
// anything runs; the analyses of one vehicle refuse a train.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/run/run_files.hpp"
#include "workbench/core/error.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/vehicle_run.hpp"
#include "workbench/study/run_error.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kTrain = "tests/run/data/train_two_wagons.lua";

using rb::test::expectSameVehicle;

std::string run(const rb::run::Model& m, const std::string& name) {
  const rb::test::RunFile f = rb::test::runInto(m, "rb_test_train", name);
  EXPECT_TRUE(f.result.result.ok) << f.result.result.message;
  return f.path;
}

// The default scene's single wagon at `start` as the train's vehicles run (0.3 s, one element).
std::string single(double start, const std::string& name) {
  return run(rb::test::defaultSceneWagon(start), name);
}

TEST(Train, TwoWagonsAreEachTheirSingleRunBitForBit) {
  const rb::run::Model m = rb::test::compiled(kTrain);
  ASSERT_EQ(m.vehicles.size(), 2u);
  EXPECT_EQ(m.vehicles[0].name, "front");
  EXPECT_EQ(m.vehicles[1].name, "rear");
  EXPECT_EQ(m.vehicles[1].vehicle.start, 15.0);
  ASSERT_EQ(m.vehicles[1].output_elements.size(), 1u) << "run.output.elements per vehicle";
  const std::string train = run(m, "train.h5");
  EXPECT_GT(expectSameVehicle(single(40.0, "front.h5"), train, "/vehicles/front"), 500);
  EXPECT_GT(expectSameVehicle(single(15.0, "rear.h5"), train, "/vehicles/rear"), 500);
}

TEST(Train, AVehicleRunsOnItsOwnContactModel) {
  // The rear wagon on elastic contact, the front one on the scenario's KEC.
  // (ABM's 1.25 ms is beyond the stability limit of the elastic wagon's series dampers: the check
  // refuses it, 0.25 ms is inside.)
  const rb::run::Model m = rb::test::compiled(
      kTrain, {"train.vehicles[2].contact.method=elastic", "solver.step=2.5e-4"});
  ASSERT_EQ(m.vehicles.size(), 2u);
  ASSERT_TRUE(m.vehicles[0].contact && m.vehicles[1].contact);
  EXPECT_EQ(m.vehicles[0].contact->method, rb::dynamics::ContactMethod::Kec);
  EXPECT_EQ(m.vehicles[1].contact->method, rb::dynamics::ContactMethod::Elastic);
  const rb::io::ResultReader t(run(m, "mixed.h5"));
  EXPECT_EQ(t.text("/vehicles/front/contact", "method").value_or(""), "kec");
  EXPECT_EQ(t.text("/vehicles/rear/contact", "method").value_or(""), "elastic");
  // The run's record of its effects names both models (the summary's "effects" line).
  EXPECT_NE(t.text("/stats", "effects").value_or("").find("contact: kec+elastic"),
            std::string::npos);
  const std::string root = t.text("/", "effects").value_or("");
  EXPECT_NE(root.find("contact:kec"), std::string::npos);
  EXPECT_NE(root.find("contact:elastic"), std::string::npos);
  // The elastic contact writes its patch count per wheel; the wheels carry the wagon.
  const auto q = t.dataset("/vehicles/rear/contact/ws1/left/normal_force");
  ASSERT_TRUE(q && !q->empty());
  EXPECT_GT(q->back(), 40e3);
  EXPECT_LT(q->back(), 70e3);
}

// The problems of the train scenario with `replace` put in place of its train{} block, as one
// text.
std::string problems(const std::string& trainBlock, const std::vector<std::string>& sets = {}) {
  return rb::test::problemsWithReplaced(kTrain, "train {", "} }\n", trainBlock,
                                        "rb_test_train_bad.lua", sets);
}

TEST(Train, WhatATrainCannotBeIsRefusedAtItsLine) {
  const std::string w = "wagon { speed = 20, start = ";
  struct Case {
    std::string block, expect;
  };
  const std::vector<Case> cases = {
      {"train { vehicles = { { name = \"a\", vehicle = " + w + "40 } } } }", "2 to 100"},
      {"train { vehicles = { { name = \"a\", vehicle = " + w +
           "40 } }, { name = \"a\", vehicle = " + w + "10 } } } }",
       "name 'a' is given twice"},
      {"train { vehicles = { { name = \"a b\", vehicle = " + w +
           "40 } }, { name = \"c\", vehicle = " + w + "10 } } } }",
       "name 'a b' must be"},
      {"train { vehicles = { { name = \"a\", vehicle = " + w +
           "10 } }, { name = \"b\", vehicle = " + w + "40 } } } }",
       "must be behind the vehicles before it"},
      {"train { vehicles = { { name = \"a\", vehicle = " + w +
           "40 } }, { name = \"b\", vehicle = " + "wagon { speed = 25, start = 10 } } } }",
       "every vehicle of a train runs at the first one's"},
      {"train { vehicles = { { name = \"a\", vehicle = " + w +
           "40 } }, { name = \"b\", vehicle = " + w + "30 } } } }",
       "overlaps 'a'"},
      {"train { vehicles = { { name = \"a\", vehicle = " + w +
           "40 } }, { name = \"b\", vehicle = 3 "
           "} } }",
       "vehicle must be a vehicle table"},
      {"train { vehicles = { { name = \"a\", vehicle = " + w +
           "40 } }, { name = \"b\", vehicle = " + w + "10 }, colour = 1 } } }",
       "colour"},
      {"vehicle (" + w + "40 })\ntrain { vehicles = { { name = \"a\", vehicle = " + w +
           "40 } }, { name = \"b\", vehicle = " + w + "10 } } } }",
       "remove the vehicle{} block"},
  };
  for (const auto& c : cases) {
    const std::string p = problems(c.block);
    EXPECT_NE(p.find(c.expect), std::string::npos) << c.block << "\n-> " << p;
    EXPECT_NE(p.find("rb_test_train_bad.lua:"), std::string::npos) << p;
  }
}

TEST(Train, SignalPathsNameTheVehicle) {
  // What a study's metrics may read of a train: each vehicle's groups under /vehicles/<name>.
  const rb::run::Model m = rb::test::compiled(kTrain);
  EXPECT_EQ(rb::run::signalProblem(m.spec, "/vehicles/rear/bodies/ws1/y"), "");
  EXPECT_EQ(rb::run::signalProblem(m.spec, "/vehicles/front/contact/ws2/left/normal_force"), "");
  EXPECT_EQ(rb::run::signalProblem(m.spec, "/vehicle/speed"), "");
  EXPECT_NE(rb::run::signalProblem(m.spec, "/bodies/ws1/y").find("/vehicles/<name>/bodies"),
            std::string::npos);
  EXPECT_NE(rb::run::signalProblem(m.spec, "/vehicles/back/bodies/ws1/y").find("no vehicle"),
            std::string::npos);
  EXPECT_NE(rb::run::signalProblem(m.spec, "/vehicles/rear/bodies/ws9/y").find("no body"),
            std::string::npos);
}

TEST(Train, NamedParametersReachOneVehicle) {
  // A group of the second wagon's own table (its anti-roll bars), its bodies by name: the first
  // wagon keeps its values.
  const rb::run::Model m =
      rb::test::compiled(kTrain, {"train.vehicles[2].vehicle.groups.anti_roll.stiffness=12345",
                                  "train.vehicles[2].vehicle.bodies.car.mass=40000"});
  auto stiffness = [&](std::size_t k) {
    for (const auto& e : m.spec.train[k].vehicle.elements)
      if (e.name == "anti_roll_bogie1") return e.stiffness;
    return -1.0;
  };
  auto carMass = [&](std::size_t k) {
    for (const auto& b : m.spec.train[k].vehicle.bodies)
      if (b.name == "car") return b.mass;
    return -1.0;
  };
  EXPECT_EQ(stiffness(1), 12345.0);
  EXPECT_NE(stiffness(0), 12345.0);
  EXPECT_GT(stiffness(0), 0.0);
  EXPECT_EQ(carMass(1), 40000.0);
  EXPECT_EQ(carMass(0), 32000.0);
  // A group the vehicle does not have, and an entry the train does not have, are refused.
  EXPECT_THROW(
      (void)rb::test::compiled(kTrain, {"train.vehicles[2].vehicle.groups.anti_rol.stiffness=1"}),
      rb::InputError);
  EXPECT_THROW(
      (void)rb::test::compiled(kTrain, {"train.vehicles[3].vehicle.groups.anti_roll.stiffness=1"}),
      rb::InputError);
}

// The error of a run against a reference (precision, stress, the studies' summaries) covers
// every vehicle of a train: a train against itself has zero error, against a looser run of the
// same train a positive one, and a single vehicle's file shares no series with a train's.
TEST(Train, RunErrorsCoverEveryVehicle) {
  const rb::test::RunFile a = rb::test::runInto(rb::test::compiled(kTrain, {"run.duration=0.1"}),
                                                "rb_test_train_errors", "a.h5");
  const rb::test::RunFile b =
      rb::test::runInto(rb::test::compiled(kTrain, {"run.duration=0.1", "solver.method=dopri5",
                                                    "solver.rtol=1e-3", "solver.atol=1e-4"}),
                        "rb_test_train_errors", "b.h5");
  ASSERT_TRUE(a.result.result.ok && b.result.result.ok);
  const auto y = rb::study::parseQuantities({"y"}, {}, true).front();
  const rb::study::Error self = rb::study::fileError(a.path, a.path, y);
  ASSERT_TRUE(self.have);
  EXPECT_EQ(self.max, 0.0);
  const rb::study::Error loose = rb::study::fileError(b.path, a.path, y);
  ASSERT_TRUE(loose.have);
  EXPECT_GT(loose.max, 0.0);
  EXPECT_TRUE(std::isfinite(loose.max));
  // A body quantity covers the body of that name in every vehicle.
  const auto car = rb::study::parseQuantities({"car.y"}, {"car"}, true).front();
  EXPECT_TRUE(rb::study::fileError(b.path, a.path, car).have);
  const rb::test::RunFile single = rb::test::runInto(
      rb::test::compiled("scenarios/default/case3_kec_fast.lua", {"run.duration=0.1"}),
      "rb_test_train_errors", "single.h5");
  ASSERT_TRUE(single.result.result.ok);
  EXPECT_FALSE(rb::study::fileError(single.path, a.path, y).have);
}

TEST(Train, TheLinearisationOfOneVehicleRefusesATrain) {
  const rb::run::Model m = rb::test::compiled(kTrain);
  for (const char* command : {"modes / critical-speed"}) {
    try {
      rb::scenario::refuseTrain(m.spec, command);
      FAIL() << command << " accepted a train";
    } catch (const rb::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("`workbench ") + command + "`"),
                std::string::npos);
      EXPECT_NE(std::string(e.what()).find("train_two_wagons.lua:"), std::string::npos);
    }
  }
}

}  // namespace
