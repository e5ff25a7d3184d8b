// Normal-force coupling of the creep forces (docs/contact_dynamics.md section 4.1): the default is
// the consistent coupling, the one that converges under step refinement; the paper's lagged
// coupling (section 2.5: creep forces from the previous evaluation's normal forces) stays an
// option, and the study bases keep it explicitly.
#include <gtest/gtest.h>

#include <cstdio>

#include "coupling_refinement.hpp"
#include "dyn_fixtures.hpp"

namespace rbtest {
namespace {

using dynamics::NormalForceCoupling;

TEST(Coupling, DefaultIsConsistentAndLaggedIsAnOption) {
  EXPECT_EQ(dynamics::ContactSpec{}.normal_forces, NormalForceCoupling::Consistent);
  // The default scenario of `wb run` states no coupling: it gets the default.
  const Compiled d = compileScenario("scenarios/validation/case3_kec.lua");
  EXPECT_EQ(d.spec.contact.normal_forces, NormalForceCoupling::Consistent);
  EXPECT_EQ(d.contact->coupling, NormalForceCoupling::Consistent);
  const Compiled l =
      compileScenario("scenarios/validation/case3_kec.lua", {"contact.normal_forces=lagged"});
  EXPECT_EQ(l.contact->coupling, NormalForceCoupling::Lagged);
}

// The studies reproduce the paper's method comparison (Tables 7-18) with its lagged coupling;
// their generated tables in docs/studies.md were made with it.
TEST(Coupling, StudyBasesKeepThePapersLaggedCoupling) {
  for (const char* f :
       {"scenarios/studies/case3_base.lua", "scenarios/studies/bases/flange_curve.lua",
        "scenarios/studies/bases/minimal.lua"}) {
    const Compiled c = compileScenario(f);
    EXPECT_EQ(c.spec.contact.normal_forces, NormalForceCoupling::Lagged) << f;
  }
}

// RK4 with halved steps on the paper's case 3 (KEC, 20 m/s, R = 500 m, ORE B176 low), the first
// 9 s: the tangent, the transition and the start of the curve, where the leading wheelset enters
// two-point tread-flange contact (t ~ 7.5-8 s) and the lagged coupling stops converging.
// d(h) = max over wheelsets and output times of |y(h) - y(h/2)|, an estimate of the error at step
// h (the generated block of docs/contact_dynamics.md gives the numbers). A shorter case would be
// cheaper, but the flange-curve study base on ORE B176 high lifts ws1's inner wheel within 10 ms
// of its start from centred wheelsets (the run stops there), and on ORE B176 low the two
// couplings differ by less than their common 0.0025 mm there.
TEST(Coupling, StepHalvingConvergesWithTheDefaultCoupling) {
  const std::string f = "scenarios/validation/case3_kec.lua";
  const std::vector<double> steps = {2.5e-4, 1.25e-4, 6.25e-5};
  const double t_end = 9.0;
  const Refinement con = refine(f, {}, "consistent", steps, t_end);
  const Refinement lag = refine(f, {}, "lagged", steps, t_end);
  writeRefinementCsv("coupling_case3",
                     "RK4 step halving, " + f + ", t = 0 .. 9 s, max |dy| of ws1..ws4 (" +
                         "test_dynamics Coupling.StepHalvingConvergesWithTheDefaultCoupling)",
                     {con, lag});
  const double c1 = con.runs[0].diff_to_half, c2 = con.runs[1].diff_to_half;
  const double l2 = lag.runs[1].diff_to_half;
  // Consistent: the difference shrinks per halving and is below 0.01 mm at 0.125 ms. Measured
  // with the creep law saturating on sliding patches (docs/creep.md): 2.57e-4 -> 1.48e-4 mm (0.58
  // per halving; with Polach's own divisor s_C it halved, while the lagged coupling stalled and
  // was several times larger, why the default changed). Now the lagged coupling converges at the
  // same rate here (2.76e-4 -> 1.49e-4 mm): printed, not asserted. What limits the order is not
  // measured yet (the kink of Polach's s_yC switch is a candidate).
  EXPECT_LT(c2, 0.65 * c1);
  EXPECT_LT(c2, 1e-5);
  std::printf("[ coupling ] lagged against consistent at h = 0.125 ms: %.3g / %.3g mm\n", l2 * 1e3,
              c2 * 1e3);
  // The consistent coupling iterates (Phi evaluations per wheelset solve, its cost).
  EXPECT_GT(con.runs[1].iterations_per_solve, 1.0);
}

// The consistent coupling's quasi-Newton iteration (contact_coupling.hpp): from the remembered
// normal forces and Jacobian of Phi it needs about 3 Phi evaluations per wheelset solve on case 3
// at RK4 2 ms (the plain fixed-point iteration needs 4.7), and its result is the plain
// iteration's within the coupling tolerance: the maximum iteration count stays small too.
TEST(Coupling, ConsistentQuasiNewtonNeedsFewPhiEvaluations) {
  const Compiled c = compileScenario("scenarios/studies/case3_base.lua",
                                     {"contact.method=kec", "contact.normal_forces=consistent"});
  dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
  const Trace tr = run(ode, solverSpec("rk4", 2e-3), 0.5, 0.01);
  ASSERT_TRUE(tr.result.ok) << tr.result.message;
  const dynamics::ContactStats& st = ode.stats();
  ASSERT_GT(st.consistent_solves, 0);
  const double per_solve =
      static_cast<double>(st.consistent_iterations) / static_cast<double>(st.consistent_solves);
  EXPECT_LT(per_solve, 3.5);
  EXPECT_LE(st.consistent_max_iterations, 8);
}

}  // namespace
}  // namespace rbtest
