// Static wheel loads at the initial state, the constraint velocities and accelerations against
// finite differences (with irregularities), energy conservation without creep.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dyn_fixtures.hpp"
#include "workbench/vehicle/dynamics.hpp"

namespace rbtest {
namespace {

dynamics::ContactSpec method(dynamics::ContactMethod m) {
  dynamics::ContactSpec c;
  c.method = m;
  return c;
}

const dynamics::ContactMethod kMethods[2] = {dynamics::ContactMethod::Kec,
                                             dynamics::ContactMethod::Lut};

// Vertical contact forces (track frame) of all wheels at (t, y).
double verticalContactForce(dynamics::ContactVehicleOde& ode, double t, const Eigen::VectorXd& y,
                            std::vector<dynamics::WheelOutput>& wo) {
  wo.assign(2 * static_cast<std::size_t>(ode.layout().n_ws), {});
  EXPECT_EQ(ode.wheelOutputs(t, y.data(), wo), 0) << ode.lastError();
  double fz = 0.0;
  for (const auto& o : wo) fz += o.force_z;
  return fz;
}

TEST(Statics, FreeWheelsetNormalForcesCarryItsWeight) {
  for (auto m : kMethods) {
    const Compiled c = compileSpecs(tangentTrack(100), freeWheelset(10), method(m));
    dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
    const Eigen::VectorXd y0 = ode.initialState(0.0);
    std::vector<dynamics::WheelOutput> wo;
    const double W = 1813 * 9.81;
    const double fz = verticalContactForce(ode, 0.0, y0, wo);
    std::printf("[ statics  ] free wheelset: sum of vertical contact forces / weight - 1 = %.1e\n",
                fz / W - 1.0);
    EXPECT_NEAR(fz, W, 1e-3 * W);
    EXPECT_NEAR(wo[0].normal, wo[1].normal, 1e-6 * W);  // symmetric
    EXPECT_FALSE(wo[0].lift);
    EXPECT_EQ(wo[0].regime, 0);
    // The spin rate V / r_c leaves no longitudinal creep force to speak of.
    Eigen::VectorXd yd(ode.size());
    ASSERT_EQ(ode.rhs(0.0, y0.data(), yd.data()), 0);
    EXPECT_LT(std::abs(yd[ode.layout().wsRate(0, 0)]), 1e-9);
    EXPECT_LT(std::abs(yd[ode.layout().wsRate(0, 1)]), 1e-3);
  }
}

TEST(Statics, SingleWheelsetCarriesWeightAndAxleLoad) {
  for (const char* f :
       {"scenarios/validation/case1_R300_kec.lua", "scenarios/validation/case1_R300_lut.lua"}) {
    const Compiled c = compileScenario(f);
    dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
    const Eigen::VectorXd y0 = ode.initialState(0.0);
    std::vector<dynamics::WheelOutput> wo;
    const double fz = verticalContactForce(ode, 0.0, y0, wo);
    const int b = c.vehicle->findBody("ws");
    // Weight + axle-box loads - primary spring force (the wheelset sits 0.088 mm below its
    // nominal height) = the suspension resultant on the wheelset in the track frame.
    const double W = 1813 * 9.81 - ode.workspace().susp_force[static_cast<std::size_t>(b)].z();
    EXPECT_NEAR(fz, W, 1e-3 * W) << f;
    std::printf("[ statics  ] %s: vertical contact forces / load - 1 = %.1e\n", f, fz / W - 1.0);
    EXPECT_NEAR(W, 1813 * 9.81 + 91307.0, 300.0);
    EXPECT_NEAR(wo[0].normal, wo[1].normal, 1e-3 * W);
  }
}

TEST(Statics, WagonStartsInEquilibriumOnItsWheelLoads) {
  for (const char* f :
       {"scenarios/validation/case2_kec.lua", "scenarios/validation/case2_lut.lua"}) {
    const Compiled c = compileScenario(f);
    dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
    const Eigen::VectorXd y0 = ode.initialState(0.0);
    Eigen::VectorXd yd(ode.size());
    ASSERT_EQ(ode.rhs(0.0, y0.data(), yd.data()), 0);
    const auto& l = ode.layout();
    for (int k = 0; k < l.n_free; ++k)
      for (int cc = 0; cc < 5; ++cc) EXPECT_LT(std::abs(yd[l.rate(k, cc)]), 1e-8);
    for (int w = 0; w < l.n_ws; ++w) EXPECT_LT(std::abs(yd[l.wsRate(w, 0)]), 1e-6);
    std::vector<dynamics::WheelOutput> wo;
    const double W = (32000 + 2 * 2615 + 4 * 1813) * 9.81;
    const double fz = verticalContactForce(ode, 0.0, y0, wo);
    double spread = 0.0;
    for (const auto& o : wo) spread = std::max(spread, std::abs(o.force_z / (W / 8) - 1.0));
    std::printf(
        "[ statics  ] %s: vertical contact forces / weight - 1 = %.1e, wheel loads within "
        "%.1e of W/8\n",
        f, fz / W - 1.0, spread);
    EXPECT_NEAR(fz, W, 1e-3 * W) << f;
    for (const auto& o : wo) EXPECT_NEAR(o.force_z, W / 8, 5e-3 * W / 8) << f;
  }
}

// Velocities (coordinate partitioning) and accelerations of the dependent coordinates z, phi
// against central differences in time along the state trajectory, on the irregular track
// (consistent normal forces, so that the rhs is a function of (t, y) alone).
TEST(Kinematics, DependentRatesAndAccelerationsMatchFiniteDifferences) {
  for (const char* f :
       {"scenarios/validation/case3_kec.lua", "scenarios/validation/case3_lut.lua"}) {
    const Compiled c = compileScenario(f, {"contact.normal_forces=consistent"});
    dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
    Eigen::VectorXd y = ode.initialState(0.0);
    const auto& l = ode.layout();
    for (int w = 0; w < l.n_ws; ++w) {
      y[l.wsPosition(w, 0)] = (w % 2 ? -2.0 : 3.0) * 1e-3;
      y[l.wsRate(w, 0)] = 0.02;
      y[l.wsRate(w, 2)] = 0.003;
    }
    const double t = 7.0;  // s = 140..160 m, irregular rails
    Eigen::VectorXd yd(ode.size());
    ASSERT_EQ(ode.rhs(t, y.data(), yd.data()), 0) << ode.lastError();
    const std::size_t nb = c.vehicle->bodies.size();
    std::vector<vehicle::Vector6d> q0(nb), qp(nb), qm(nb), qdd(nb), vp(nb), vm(nb), v0(nb);
    ASSERT_EQ(ode.bodyAccelerations(t, y.data(), qdd), 0);
    ASSERT_EQ(ode.bodyCoordinates(t, y.data(), q0), 0);
    v0 = ode.workspace().qd;
    const double h = 1e-5;
    const Eigen::VectorXd yp = y + h * yd, ym = y - h * yd;
    ASSERT_EQ(ode.bodyCoordinates(t + h, yp.data(), qp), 0);
    vp = ode.workspace().qd;
    ASSERT_EQ(ode.bodyCoordinates(t - h, ym.data(), qm), 0);
    vm = ode.workspace().qd;
    for (int w = 0; w < l.n_ws; ++w) {
      const auto b = static_cast<std::size_t>(l.wheelsets[static_cast<std::size_t>(w)]);
      for (int cc : {vehicle::kZ, vehicle::kRoll}) {
        const double fd_v = (qp[b][cc] - qm[b][cc]) / (2 * h);
        const double fd_a = (vp[b][cc] - vm[b][cc]) / (2 * h);
        EXPECT_NEAR(v0[b][cc], fd_v, 1e-7 + 1e-5 * std::abs(fd_v)) << f << " ws" << w << " " << cc;
        EXPECT_NEAR(qdd[b][cc], fd_a, 2e-5 + 1e-4 * std::abs(fd_a)) << f << " ws" << w << " " << cc;
      }
    }
  }
}

// Without creep the normal forces do no work on motions the constraints allow: the mechanical
// energy of a free wheelset oscillating laterally (gravitational stiffness) is conserved. LUT:
// always (the reaction is -C_q^T lambda). KEC: outside the regularised bands; inside them the
// forces at A and B (Eq. 26) are not normal to the regularised constraint and the energy departs,
// to come back when the band is left (documented).
TEST(Energy, ConservedWithoutCreepOutsideRegularisedBands) {
  for (auto m : kMethods) {
    dynamics::ContactSpec cs = method(m);
    cs.creep = dynamics::CreepModel::None;
    const Compiled c = compileSpecs(tangentTrack(100), freeWheelset(10), cs);
    dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
    Eigen::VectorXd y0 = ode.initialState(0.0);
    y0[ode.layout().wsPosition(0, 0)] = 3e-3;
    std::vector<dynamics::WheelOutput> wo(2);
    const auto energy = [&](double t, const Eigen::VectorXd& y) {
      EXPECT_EQ(ode.wheelOutputs(t, y.data(), wo), 0);
      return vehicle::energy(*c.vehicle, nullptr, ode.workspace());
    };
    const vehicle::Energy e0 = energy(0.0, y0);
    const Trace tr = run(ode, solverSpec("rk4", 1e-4), 1.0, 0.01, &y0);
    ASSERT_TRUE(tr.result.ok) << tr.result.message;
    double exchanged = 0.0, worst = 0.0, worst_band = 0.0;
    for (std::size_t k = 0; k < tr.t.size(); ++k) {
      const vehicle::Energy e = energy(tr.t[k], tr.y[k]);
      exchanged = std::max(exchanged, std::abs(e.kinetic - e0.kinetic));
      const bool band = wo[0].weight > 0.0 || wo[1].weight > 0.0;
      (band ? worst_band : worst) =
          std::max(band ? worst_band : worst, std::abs(e.total() - e0.total()));
    }
    std::printf(
        "[ energy   ] %s: exchanged %.3f J, |E - E0| outside bands %.2e J, in bands %.2e J\n",
        m == dynamics::ContactMethod::Kec ? "KEC" : "LUT", exchanged, worst, worst_band);
    EXPECT_GT(exchanged, 1.0);
    EXPECT_LT(worst, 2e-3 * exchanged);
  }
}

}  // namespace
}  // namespace rbtest
