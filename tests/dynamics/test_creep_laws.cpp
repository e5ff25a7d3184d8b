// The creep-law registry (workbench/dynamics/creep_laws.hpp) in the dynamics: every law runs with
// both contact methods, FASTSIM gives the spin moment, and FASTSIM's steady curving on the paper's
// case 1 (R = 500 m) is close to Polach's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dyn_fixtures.hpp"
#include "workbench/dynamics/names.hpp"

namespace rbtest {
namespace {

// Every law of the registry, with KEC and LUT: the model compiles, starts and evaluates; the
// laws with tangential forces give them, FASTSIM and Kalker with a spin moment.
TEST(CreepLaws, EveryLawRunsWithEveryMethod) {
  for (const auto& law : dynamics::kCreepModelNames)
    for (auto m : {dynamics::ContactMethod::Kec, dynamics::ContactMethod::Lut}) {
      dynamics::ContactSpec cs;
      cs.method = m;
      cs.creep = law.value;
      const Compiled c = compileSpecs(tangentTrack(100), freeWheelset(10), cs);
      dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
      Eigen::VectorXd y = ode.initialState(0.0);
      // A small lateral offset and motion: every law, Kalker's unbounded linear one too, keeps
      // both wheels loaded.
      y[ode.layout().wsPosition(0, 0)] = 1e-3;
      y[ode.layout().wsRate(0, 0)] = 0.01;
      y[ode.layout().wsRate(0, 2)] = 0.005;
      std::vector<dynamics::WheelOutput> wo(2);
      ASSERT_EQ(ode.wheelOutputs(0.0, y.data(), wo), 0) << law.name;
      Eigen::VectorXd yd(ode.size());
      ASSERT_EQ(ode.rhs(0.0, y.data(), yd.data()), 0) << law.name;
      const dynamics::PatchOutput& p = wo[0].patch[0];
      std::printf("[ law      ] %-8s %s: left tread fx %9.1f N, fy %9.1f N, mz %8.3f N m\n",
                  std::string(law.name).c_str(), m == dynamics::ContactMethod::Kec ? "kec" : "lut",
                  p.fx, p.fy, p.mz);
      const bool creep = law.value != dynamics::CreepModel::None;
      EXPECT_EQ(p.fy != 0.0, creep) << law.name;
      const bool moment = law.value == dynamics::CreepModel::Kalker ||
                          law.value == dynamics::CreepModel::Fastsim ||
                          law.value == dynamics::CreepModel::ShenHedrickElkins;
      EXPECT_EQ(p.mz != 0.0, moment) << law.name;
    }
}

struct Steady {
  double y = 0.0, yaw = 0.0;                              // [mm], [mrad]
  double fx[2] = {0, 0}, fy[2] = {0, 0}, mz[2] = {0, 0};  // tread patches, left and right
  double cpu = 0.0;
};

Steady steadyCase1(const std::vector<std::string>& overrides) {
  const Compiled c = compileScenario("scenarios/validation/case1_R500_lut.lua", overrides);
  dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
  const double t_end = 12.0;  // the 40 m curve ends at s = 120 m (10 m/s)
  const Trace tr = run(ode, c.spec.solver, t_end, 0.01);
  EXPECT_TRUE(tr.result.ok) << tr.result.message;
  Steady s;
  if (!tr.result.ok) return s;
  // Steady curving: the last 10 m of the curve (t = 11 .. 12 s), as tests/dynamics/test_long.cpp.
  int n = 0;
  std::vector<dynamics::WheelOutput> wo(2);
  for (std::size_t k = 0; k < tr.t.size(); ++k) {
    if (tr.t[k] < 11.0 - 1e-9) continue;
    s.y += tr.q[k][1][vehicle::kY];
    s.yaw += tr.q[k][1][vehicle::kYaw];
    EXPECT_EQ(ode.wheelOutputs(tr.t[k], tr.y[k].data(), wo), 0);
    for (int w = 0; w < 2; ++w) {
      s.fx[w] += wo[w].patch[0].fx;
      s.fy[w] += wo[w].patch[0].fy;
      s.mz[w] += wo[w].patch[0].mz;
    }
    ++n;
  }
  s.y *= 1e3 / n;
  s.yaw *= 1e3 / n;
  for (int w = 0; w < 2; ++w) {
    s.fx[w] /= n;
    s.fy[w] /= n;
    s.mz[w] /= n;
  }
  s.cpu = tr.result.stats.cpu_time_s;
  return s;
}

// Paper case 1 (single wheelset, R = 500 m, LUT, 10 m/s): FASTSIM (default grid) against Polach.
// Steady curving is quasi-static, so the two laws differ only where their creep curves differ:
// both reproduce Kalker's linear theory at small creepage, FASTSIM's curve lies a few per cent
// of mu Q below Polach's in the transition range (tests/creep/test_fastsim.cpp,
// Fastsim.ComparedWithPolach). Measured (docs/creep.md "In the dynamics"): y -4.10 against
// -3.91 mm (4.7 %), yaw -2.404 against -2.405 mrad, tread forces within 11 % of their resultant
// (FASTSIM's larger lateral force on the right wheel, where its spin term differs most).
TEST(CreepLaws, FastsimSteadyCurvingCloseToPolach) {
  const Steady polach = steadyCase1({});
  const Steady fastsim = steadyCase1({"contact.creep=fastsim"});
  std::printf("[ case 1   ] R = 500 m LUT steady curving     %10s %10s\n", "polach", "fastsim");
  std::printf("[ case 1   ] y [mm]                           %10.4f %10.4f\n", polach.y, fastsim.y);
  std::printf("[ case 1   ] yaw [mrad]                       %10.4f %10.4f\n", polach.yaw,
              fastsim.yaw);
  for (int w = 0; w < 2; ++w)
    std::printf("[ case 1   ] %-5s tread fx / fy [N], mz [N m] %10.1f %10.1f / %8.1f %8.1f, %.2f\n",
                w == 0 ? "left" : "right", polach.fx[w], fastsim.fx[w], polach.fy[w], fastsim.fy[w],
                fastsim.mz[w]);
  std::printf("[ case 1   ] CPU [s]                          %10.2f %10.2f\n", polach.cpu,
              fastsim.cpu);
  EXPECT_NEAR(fastsim.y, polach.y, 0.08 * std::fabs(polach.y));
  EXPECT_NEAR(fastsim.yaw, polach.yaw, 0.10 * std::fabs(polach.yaw) + 0.05);
  for (int w = 0; w < 2; ++w) {
    const double scale = std::hypot(polach.fx[w], polach.fy[w]);
    EXPECT_NEAR(fastsim.fx[w], polach.fx[w], 0.15 * scale);
    EXPECT_NEAR(fastsim.fy[w], polach.fy[w], 0.15 * scale);
  }
}

// The same steady curving with the Shen-Hedrick-Elkins law against Polach: both saturate
// Kalker's linear forces, by different curves (tests/creep/test_shen_hedrick_elkins.cpp).
// Measured: y -4.11 against -3.91 mm (5.0 %; FASTSIM -4.10), yaw -2.403 against -2.405 mrad,
// tread forces within 10 % of their resultant.
TEST(CreepLaws, ShenHedrickElkinsSteadyCurvingCloseToPolach) {
  const Steady polach = steadyCase1({});
  const Steady she = steadyCase1({"contact.creep=shen_hedrick_elkins"});
  std::printf("[ case 1   ] R = 500 m LUT steady curving     %10s %10s\n", "polach", "she");
  std::printf("[ case 1   ] y [mm]                           %10.4f %10.4f\n", polach.y, she.y);
  std::printf("[ case 1   ] yaw [mrad]                       %10.4f %10.4f\n", polach.yaw, she.yaw);
  for (int w = 0; w < 2; ++w)
    std::printf("[ case 1   ] %-5s tread fx / fy [N], mz [N m] %10.1f %10.1f / %8.1f %8.1f, %.2f\n",
                w == 0 ? "left" : "right", polach.fx[w], she.fx[w], polach.fy[w], she.fy[w],
                she.mz[w]);
  EXPECT_NEAR(she.y, polach.y, 0.08 * std::fabs(polach.y));
  EXPECT_NEAR(she.yaw, polach.yaw, 0.10 * std::fabs(polach.yaw) + 0.05);
  for (int w = 0; w < 2; ++w) {
    const double scale = std::hypot(polach.fx[w], polach.fy[w]);
    EXPECT_NEAR(she.fx[w], polach.fx[w], 0.15 * scale);
    EXPECT_NEAR(she.fy[w], polach.fy[w], 0.15 * scale);
  }
}

}  // namespace
}  // namespace rbtest
