// compileContact: profiles, positioning, the table of the chosen method only, cache, validation
// errors with their locations; the tabulated Hertz shape; the ODE's state layout and names.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "dyn_fixtures.hpp"
#include "workbench/creep/hertz.hpp"
#include "workbench/profiles/positioning.hpp"

namespace rbtest {
namespace {

std::string allMessages(const InputError& e) {
  std::string s;
  for (const auto& d : e.diagnostics()) s += d.str() + "\n";
  return s;
}

TEST(Compile, BuildsOnlyTheTableOfTheMethod) {
  dynamics::ContactSpec kec;
  dynamics::ContactSpec lut;
  lut.method = dynamics::ContactMethod::Lut;
  const Compiled a = compileSpecs(tangentTrack(100), freeWheelset(10), kec);
  const Compiled b = compileSpecs(tangentTrack(100), freeWheelset(10), lut);
  ASSERT_TRUE(a.contact->kec);
  EXPECT_FALSE(a.contact->lut);
  ASSERT_TRUE(b.contact->lut);
  EXPECT_FALSE(b.contact->kec);
  // Positioning from B = 1360 mm, G = 1435 mm (S1002 on 60E1 at 1:40).
  const auto pos = profiles::positionS1002On60E1(1.360, 1.435, 0.46, 1.0 / 40.0);
  EXPECT_NEAR(a.contact->geometry.wheel_lw, pos.Lw, 1e-12);
  EXPECT_NEAR(a.contact->geometry.rail_lr, pos.Lr, 1e-9);
  // Build statistics are kept for output; the centred wheelset is known.
  EXPECT_GT(a.contact->tableStats().bytes, 0u);
  EXPECT_GT(b.contact->tableStats().build_seconds, 0.0);
  EXPECT_NEAR(a.contact->centred_z - 0.46, -0.0883e-3, 0.001e-3);
  EXPECT_NEAR(a.contact->centredRadius(), 0.46 - 0.088e-3, 0.01e-3);
  EXPECT_EQ(a.contact->config_hash, contact::configHash(a.contact->geometry));
  EXPECT_DOUBLE_EQ(b.contact->flange_damping, b.contact->flange_stiffness / 100.0);
}

TEST(Compile, CacheReusesTablesByConfigHash) {
  dynamics::TableCache cache;
  dynamics::ContactSpec cs;
  const auto track = track::compileTrack(tangentTrack(100));
  const auto veh = vehicle::compileVehicle(freeWheelset(10), track);
  const auto m1 = dynamics::compileContact({}, cs, veh, track, &cache);
  const auto m2 = dynamics::compileContact({}, cs, veh, track, &cache);
  EXPECT_EQ(cache.builds(), 1);
  EXPECT_EQ(m1.kec.get(), m2.kec.get());
  dynamics::ProfilesSpec other;
  other.gauge = 1.437;
  const auto m3 = dynamics::compileContact(other, cs, veh, track, &cache);
  EXPECT_EQ(cache.builds(), 2);
  EXPECT_NE(m3.kec.get(), m1.kec.get());
}

TEST(Compile, VehicleWithoutWheelsetIsAnInputErrorAtTheContactBlock) {
  dynamics::ContactSpec cs;
  cs.loc = {"scene.lua", 12};
  vehicle::VehicleSpec v = loadedWheelset(10, 1000);
  v.bodies.erase(v.bodies.begin() + 1);  // drop the wheelset
  v.elements.clear();
  const auto track = track::compileTrack(tangentTrack(100));
  const auto veh = vehicle::compileVehicle(v, track);
  try {
    (void)dynamics::compileContact({}, cs, veh, track);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(allMessages(e).find("scene.lua:12: contact: vehicle 'loaded_wheelset' has no "
                                  "wheelset"),
              std::string::npos)
        << allMessages(e);
  }
}

TEST(Compile, BadParametersAreReportedTogether) {
  dynamics::ContactSpec cs;
  cs.loc = {"scene.lua", 20};
  cs.method = dynamics::ContactMethod::Lut;
  cs.mu = -0.1;
  cs.poisson = 0.6;
  cs.flange_stiffness = 0.0;
  const auto track = track::compileTrack(tangentTrack(100));
  const auto veh = vehicle::compileVehicle(freeWheelset(10), track);
  try {
    (void)dynamics::compileContact({}, cs, veh, track);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostics().size(), 3u) << allMessages(e);
    const std::string m = allMessages(e);
    EXPECT_NE(m.find("contact.mu"), std::string::npos);
    EXPECT_NE(m.find("contact.poisson"), std::string::npos);
    EXPECT_NE(m.find("contact.flange_stiffness"), std::string::npos);
  }
}

TEST(Compile, UnreadableProfileFileNamesTheProfilesBlock) {
  dynamics::ProfilesSpec ps;
  ps.loc = {"scene.lua", 5};
  ps.wheel = "/nonexistent/wheel.prw";
  const auto track = track::compileTrack(tangentTrack(100));
  const auto veh = vehicle::compileVehicle(freeWheelset(10), track);
  try {
    (void)dynamics::compileContact(ps, {}, veh, track);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(allMessages(e).find("scene.lua:5: profiles.wheel: cannot use"), std::string::npos)
        << allMessages(e);
  }
}

TEST(Compile, ProfilesThatDoNotTouchFailTheTableBuild) {
  dynamics::ProfilesSpec ps;
  ps.loc = {"scene.lua", 5};
  ps.lw = 0.60;  // wheels 150 mm inside the rails: no contact
  dynamics::ContactSpec cs;
  cs.loc = {"scene.lua", 9};
  const auto track = track::compileTrack(tangentTrack(100));
  const auto veh = vehicle::compileVehicle(freeWheelset(10), track);
  EXPECT_THROW((void)dynamics::compileContact(ps, cs, veh, track), InputError);
}

TEST(Compile, ScenarioFilesOfThePaperCasesCompile) {
  for (const char* f :
       {"scenarios/validation/case1_R300_kec.lua", "scenarios/validation/case1_R900_lut.lua",
        "scenarios/validation/case3_kec.lua"}) {
    const Compiled c = compileScenario(f);
    EXPECT_TRUE(c.contact->kec || c.contact->lut) << f;
    for (const auto& w : c.contact->warnings) std::printf("[ warning  ] %s\n", w.c_str());
  }
  const Compiled l = compileScenario("scenarios/validation/case1_R500_lut.lua");
  EXPECT_DOUBLE_EQ(l.contact->flange_stiffness, 1e10);
}

TEST(HertzShapeTable, MatchesTheSolver) {
  const auto table = dynamics::HertzShapeTable::shared();
  double worst = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    const double rho = std::pow(10.0, -6.0 + 6.0 * i / 1000.0);
    for (bool swap : {false, true}) {
      const double A = swap ? 1.0 : rho, B = swap ? rho : 1.0;
      const creep::HertzShape e = creep::hertzShape(A, B);
      const creep::HertzShape t = table->shape(A, B);
      EXPECT_EQ(e.rolling_major, t.rolling_major);
      for (auto [x, y] : {std::pair{e.g, t.g}, {e.m, t.m}, {e.n, t.n}, {e.K, t.K}, {e.E, t.E}})
        worst = std::max(worst, std::abs(x - y) / std::abs(x));
    }
  }
  EXPECT_LT(worst, 1e-8);
  // Beyond the table the solver is used.
  EXPECT_NEAR(table->shape(1e-8, 1.0).g, creep::hertzShape(1e-8, 1.0).g, 1e-15);
}

TEST(Layout, StateNamesAndIndicesOfTheWagon) {
  const Compiled c = compileScenario("scenarios/validation/case2_kec.lua");
  dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
  const auto& l = ode.layout();
  EXPECT_EQ(l.n_free, 3);
  EXPECT_EQ(l.n_ws, 4);
  EXPECT_EQ(l.n_series, static_cast<int>(c.vehicle->series_dampers.size()));
  EXPECT_EQ(ode.size(), 10 * 3 + 6 * 4 + l.n_series);
  EXPECT_EQ(ode.componentName(0), "car.y");
  EXPECT_EQ(ode.componentName(15), "ws1.y");
  EXPECT_EQ(ode.componentName(16), "ws1.theta");
  EXPECT_EQ(ode.componentName(26), "ws4.psi");
  EXPECT_EQ(ode.componentName(27), "car.y_dot");
  EXPECT_EQ(ode.componentName(43), "ws1.theta_dot");
  EXPECT_EQ(ode.componentName(54), "series[0].f");
  const int ws2 = c.vehicle->findBody("ws2");
  EXPECT_EQ(ode.index(ws2, vehicle::kYaw, true), ode.indexOf("ws2.psi_dot"));
  EXPECT_EQ(ode.index(ws2, vehicle::kZ), -1);  // dependent coordinate
  EXPECT_EQ(ode.index(c.vehicle->findBody("bogie1"), vehicle::kZ), ode.indexOf("bogie1.z"));
  for (int i = 0; i < ode.size(); ++i) EXPECT_EQ(ode.indexOf(ode.componentName(i)), i);
}

}  // namespace
}  // namespace rbtest
