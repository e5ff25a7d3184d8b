// Table evaluation and the online solvers must not allocate (they run inside the right-hand side):
// count global operator new calls. The replacement pairs malloc/free on purpose.
#include <gtest/gtest.h>

#include "tests/common/allocation_counter.hpp"

#include "contact_tables.hpp"
#include "workbench/contact/geometry.hpp"

using rbtest::g_allocations;

namespace {

using namespace rb::contact;

TEST(ContactAllocation, TableEvaluationAndOnlineSolversAllocateNothing) {
  const LutTable& lut = rbtest::s1002Lut();
  const KecTable& kec = rbtest::s1002Kec();
  const ContactSolver solver(rbtest::s1002On60E1());
  const TreadContact t0 = solver.solveTread(0.0, 0.0);
  KecSolution ks = solveKec(kec, KecInput{});
  double sink = 0.0;
  const long before = g_allocations.load();
  LutSample s;
  LutValue z, phi;
  KecPoint kp;
  TreadContact t = t0;
  for (int i = 0; i < 200; ++i) {
    const double y = -12e-3 + i * 0.12e-3, xi = -4e-3 + i * 0.04e-3;
    lut.eval(y, xi, s);
    lut.evalZPhi(y, xi, z, phi);
    sink += s.value[kLutZ] + z.dyy + phi.dxi + lut.evalChannel(kLutPhi, y, xi).dyxi;
    kec.eval(Side::Left, y, kp);
    double d1, d2;
    sink += kp.d2f + kec.f(Side::Right, y, &d1, &d2) + d1 + d2;
    ks = solveKec(kec, KecInput{0.5 * y, 0.1 * xi, -0.1 * xi, 1e-4, 0.0}, &ks);
    sink += ks.z + kecQuadraticTerm(ks, Eigen::Vector4d(0.1, 0.2, 0.3, 0.4)).sum();
    if (i < 50) {
      t = solver.solveTread(i * 0.1e-3, 0.0, &t);
      const FlangeContact f = solver.flange(Side::Left, WheelsetPose{t.y, t.z, t.phi}, 0.0);
      sink += t.z + f.delta;
    }
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
  // The counter works.
  const long b2 = g_allocations.load();
  auto* v = new std::vector<double>(10);
  delete v;
  EXPECT_GE(g_allocations.load() - b2, 2);
}

}  // namespace
