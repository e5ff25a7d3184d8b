// Polach creep forces (workbench/creep/polach.hpp), Kalker linear theory, creepages.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "workbench/creep/creepages.hpp"
#include "workbench/creep/polach.hpp"

namespace {

using namespace rb::creep;

constexpr double kPi = std::numbers::pi;
const Material kSteel{};

double rel(double x, double ref) {
  return std::fabs(x - ref) / std::fabs(ref);
}

// Typical tread contact: r = 0.46 m, concave S1002 tread R 0.32 m on the 60E1 crown R 0.3 m, 100
// kN.
ContactPatch treadPatch(double N = 1.0e5) {
  return makeContactPatch(kSteel, relativeCurvatures(1.0 / 0.46, -1.0 / 0.32, 0.0, 1.0 / 0.3), N);
}
// Patches with a/b from 0.2 to ~20 (flange-like).
std::vector<ContactPatch> patches() {
  std::vector<ContactPatch> v;
  v.push_back(treadPatch());
  v.push_back(makeContactPatch(kSteel, {1.0, 1.0}, 8.0e4));
  v.push_back(makeContactPatch(kSteel, {1.0, 5.0}, 6.0e4));
  v.push_back(makeContactPatch(kSteel, {std::cos(1.22) / 0.49 / 2, 38.46}, 5.0e4));  // flange
  v.push_back(makeContactPatch(kSteel, {3.0, 0.4}, 1.2e5));
  return v;
}

CreepParams params() {
  CreepParams p;
  p.G = shearModulus(kSteel);
  return p;  // mu = 0.2364 (paper)
}

TEST(Polach, PatchFromHertzAndKalker) {
  const ContactPatch p = treadPatch();
  EXPECT_GT(p.a, 0.0);
  EXPECT_GT(p.b, p.a);  // wide tread ellipse
  const auto c = kalkerCoefficients(p.a / p.b, 0.28);
  EXPECT_NEAR(p.c11, c.c11, 1e-12);
  EXPECT_NEAR(p.c22, c.c22, 1e-12);
  EXPECT_NEAR(p.c23, c.c23, 1e-12);
  EXPECT_EQ(p.Q, 1.0e5);
}

// makeContactPatch computes the semi-axes itself (without the Hertz stiffness): exactly hertz()'s,
// for rolling-major and lateral-major ellipses and without load.
TEST(Polach, PatchSemiAxesAreHertzBitForBit) {
  for (const RelativeCurvatures k : {RelativeCurvatures{1.09, 3.3}, RelativeCurvatures{4.0, 0.6},
                                     RelativeCurvatures{2.0, 2.0}}) {
    for (double N : {0.0, 3.7e4, 1.0e5}) {
      const HertzShape shape = hertzShape(k.A, k.B);
      const ContactPatch p = makeContactPatch(kSteel, k, shape, N);
      const HertzContact h = hertz(kSteel, k, shape, N);
      EXPECT_EQ(p.a, N > 0.0 ? h.a : 0.0);
      EXPECT_EQ(p.b, N > 0.0 ? h.b : 0.0);
      const auto c = kalkerCoefficients(shape.aOverB(), kSteel.nu);
      EXPECT_EQ(p.c11, c.c11);
      EXPECT_EQ(p.c23, c.c23);
    }
  }
}

TEST(Polach, SmallCreepageEqualsKalkerLinear) {
  const CreepParams cp = params();
  double worst = 0.0;
  for (const ContactPatch& p : patches()) {
    const double ab = p.a * p.b;
    for (double s : {1e-7, 1e-6, 1e-5}) {
      const CreepForce fx = polachForce(cp, p, {s, 0.0, 0.0, 20.0});
      const double kx = -cp.G * ab * p.c11 * s;
      EXPECT_LT(rel(fx.fx, kx), 0.01) << s;
      EXPECT_EQ(fx.fy, 0.0);
      const CreepForce fy = polachForce(cp, p, {0.0, s, 0.0, 20.0});
      const double ky = -cp.G * ab * p.c22 * s;
      EXPECT_LT(rel(fy.fy, ky), 0.01) << s;
      EXPECT_EQ(fy.fx, 0.0);
      if (s == 1e-6) worst = std::max({worst, rel(fx.fx, kx), rel(fy.fy, ky)});
      // Against the reference function.
      const LinearCreepForce lin = kalkerLinearForce(cp.G, p, {s, s, 0.0, 20.0});
      EXPECT_DOUBLE_EQ(lin.fx, kx);
      EXPECT_DOUBLE_EQ(lin.fy, ky);
    }
  }
  std::printf("Polach vs Kalker linear at creepage 1e-6: worst relative difference %.2e\n", worst);
}

TEST(Polach, SmallPureSpinEqualsKalkerLinear) {
  // Polach's s_yC definition makes the spin force of small pure spin Kalker's -G c^3 C23 phi.
  const CreepParams cp = params();
  for (const ContactPatch& p : patches()) {
    const double c3 = std::pow(p.a * p.b, 1.5);
    for (double phi : {1e-5, -1e-4}) {
      const CreepForce f = polachForce(cp, p, {0.0, 0.0, phi, 20.0});
      EXPECT_EQ(f.fx, 0.0);
      EXPECT_LT(rel(f.fy, -cp.G * c3 * p.c23 * phi), 1e-6) << phi;
      EXPECT_DOUBLE_EQ(kalkerLinearForce(cp.G, p, {0.0, 0.0, phi, 20.0}).fy,
                       -cp.G * c3 * p.c23 * phi);
    }
  }
}

TEST(Polach, PureSpinSignAndMagnitude) {
  const CreepParams cp = params();
  const ContactPatch p = treadPatch();
  const double muq = cp.mu * p.Q;
  double fmax = 0.0;
  for (double phi = 1e-3; phi < 1e4; phi *= 1.2) {
    const CreepForce f = polachForce(cp, p, {0.0, 0.0, phi, 20.0});
    EXPECT_LT(f.fy, 0.0) << phi;  // positive spin: negative lateral force, like positive s_y
    EXPECT_EQ(f.fx, 0.0);
    fmax = std::max(fmax, -f.fy);
    const CreepForce g = polachForce(cp, p, {0.0, 0.0, -phi, 20.0});
    EXPECT_EQ(g.fy, -f.fy);
  }
  // Maximum of the pure-spin force: (9/16) K_M max_eps g(eps) = 0.1218 K_M (docs/creep.md).
  const double km = 1.0 + 6.3 * (1.0 - std::exp(-p.a / p.b));
  EXPECT_NEAR(fmax / muq, 3.0 / 8.0 * km * (3.0 * std::sqrt(3.0) / 16.0), 2e-3);
  std::printf("pure spin, tread patch a/b = %.3f: max |F_y| = %.3f mu Q\n", p.a / p.b, fmax / muq);
}

TEST(Polach, SpinSimplifiedBracketIsPolachsExpression) {
  // (9/16)[e(-d^3/3 + d^2/2 - 1/6) + (1 - d^2)^1.5/3] == (3/8) e/(1 + e^2)^2, d = (e^2-1)/(e^2+1).
  for (double e = 1e-3; e < 1e3; e *= 1.1) {
    const double d = (e * e - 1.0) / (e * e + 1.0);
    const double orig =
        9.0 / 16.0 *
        (e * (-d * d * d / 3.0 + d * d / 2.0 - 1.0 / 6.0) + std::pow(1.0 - d * d, 1.5) / 3.0);
    const double simp = 3.0 / 8.0 * e / ((1.0 + e * e) * (1.0 + e * e));
    EXPECT_NEAR(orig, simp, 1e-12 + 1e-9 * simp) << e;  // orig loses digits by cancellation
  }
}

TEST(Polach, SpinCorrectionCondition) {
  const CreepParams cp = params();
  const ContactPatch p = treadPatch();
  // Linear range: s_y and phi of equal sign add up (s_yC = s_y + phi a), opposite signs subtract.
  {
    const double sy = 1e-6;
    const CreepForce none = polachForce(cp, p, {0.0, sy, 0.0, 20.0});
    const CreepForce same = polachForce(cp, p, {0.0, sy, 1e-3, 20.0});
    const CreepForce opp = polachForce(cp, p, {0.0, sy, -1e-4, 20.0});
    const double c3 = std::pow(p.a * p.b, 1.5);
    EXPECT_LT(same.fy, none.fy);  // more negative
    EXPECT_GT(opp.fy, none.fy);   // spin reduces the lateral force
    EXPECT_LT(rel(same.fy - none.fy, -cp.G * c3 * p.c23 * 1e-3), 1e-3);
    EXPECT_LT(rel(opp.fy - none.fy, cp.G * c3 * p.c23 * 1e-4), 1e-3);
  }
  // Opposite sign with |s_y + phi a| <= |s_y|: s_yC = s_y, so the creep part equals the spin-free
  // force and the difference is exactly the spin term F_yS evaluated at s_yC = s_y, times the
  // adhesion weight w = 1 / (1 + eps^2) (polach.hpp, "Saturation"; eps of s_y alone here).
  const double sy = 2e-3, phi = -0.5;
  ASSERT_LT(std::fabs(sy + phi * p.a), std::fabs(sy));
  const CreepForce none = polachForce(cp, p, {0.0, sy, 0.0, 20.0});
  const CreepForce opp = polachForce(cp, p, {0.0, sy, phi, 20.0});
  const double km = 1.0 + 6.3 * (1.0 - std::exp(-p.a / p.b));
  const double qmu = p.Q * cp.mu;
  const double es = 8.0 / 3.0 * cp.G * p.b * std::sqrt(p.a * p.b) * p.c23 * sy / (qmu * km);
  const double fys = 3.0 / 8.0 * p.a * qmu * km * es / ((1 + es * es) * (1 + es * es)) * phi / sy;
  const double eps = kPi * cp.G * p.a * p.b * p.c22 * sy / (4.0 * qmu);
  const double w = 1.0 / (1.0 + eps * eps);
  EXPECT_NEAR(opp.fy - none.fy, -w * fys, 1e-9 * std::fabs(fys));
}

// A patch that the creepage alone makes slide carries mu Q along (s_x, s_y) whatever the spin, as
// in Kalker's exact theory (test_creep_exact.cpp): Polach's divisor s_C gave s / s_C of it, here
// as little as 0.76 on a flank patch with spin of the sign of s_y (polach.hpp, "Saturation").
TEST(Polach, SlidingPatchWithSpinCarriesMuQ) {
  const CreepParams cp = params();
  const ContactPatch tread = treadPatch();
  const ContactPatch flank = patches()[3];
  for (const ContactPatch& p : {tread, flank}) {
    const double muq = cp.mu * p.Q;
    for (double phi : {0.5, 2.0, -0.5, -2.0}) {
      const double sx = 0.02, sy = 0.04;
      const CreepForce f = polachForce(cp, p, {sx, sy, phi, 20.0});
      SCOPED_TRACE("a/b = " + std::to_string(p.a / p.b) + ", phi = " + std::to_string(phi));
      EXPECT_NEAR(std::hypot(f.fx, f.fy) / muq, 1.0, 0.01);
      // Along -(s_x, s_y) within 3 degrees.
      const double angle = std::atan2(f.fy, f.fx) - std::atan2(-sy, -sx);
      EXPECT_LT(std::abs(angle), 3.0 * std::numbers::pi / 180.0);
    }
  }
}

TEST(Polach, SaturationForLargeCreepage) {
  const CreepParams cp = params();
  for (const ContactPatch& p : patches()) {
    const double muq = cp.mu * p.Q;
    for (double s : {0.5, 1.0, 1e3, 1e100, 1e300}) {
      const CreepForce f = polachForce(cp, p, {s, 0.0, 0.0, 20.0});
      EXPECT_NEAR(-f.fx / muq, 1.0, 1e-6) << s;
      const CreepForce g = polachForce(cp, p, {-0.6 * s, 0.8 * s, 0.0, 20.0});
      EXPECT_NEAR(std::hypot(g.fx, g.fy) / muq, 1.0, 1e-6) << s;
      EXPECT_NEAR(g.fx / g.fy, -0.75, 1e-12);  // force opposite to the creepage direction
    }
  }
}

TEST(Polach, NeverAboveFrictionLimitSweep) {
  std::vector<double> s = {0.0};
  for (double e = -7.0; e <= 0.0; e += 0.25) {
    s.push_back(std::pow(10.0, e));
    s.push_back(-std::pow(10.0, e));
  }
  std::vector<double> phis = {0.0};
  for (double e = -3.0; e <= 3.0; e += 0.25) {
    phis.push_back(std::pow(10.0, e));
    phis.push_back(-std::pow(10.0, e));
  }
  CreepParams dry = params();  // Polach 2005 dry set (UNVERIFIED values, reference note s.2)
  dry.mu = 0.55, dry.k_A = 1.0, dry.k_S = 0.4, dry.friction_A = 0.4, dry.friction_B = 0.6;
  long n = 0;
  double worst = 0.0;
  for (const CreepParams& cp : {params(), dry}) {
    for (const ContactPatch& p : patches()) {
      for (std::size_t i = 0; i < s.size(); i += 2)
        for (double sy : s)
          for (double phi : phis) {
            const CreepForce f = polachForce(cp, p, {s[i], sy, phi, 30.0});
            ASSERT_TRUE(std::isfinite(f.fx) && std::isfinite(f.fy));
            const double r = std::hypot(f.fx, f.fy) / (f.mu * p.Q);
            worst = std::max(worst, r);
            ASSERT_LE(r, 1.0 + 1e-12) << s[i] << " " << sy << " " << phi;
            ++n;
          }
    }
  }
  std::printf("|F| <= mu Q over %ld cases: max |F|/(mu Q) = %.15f\n", n, worst);
}

TEST(Polach, OddSymmetry) {
  const CreepParams cp = params();
  for (const ContactPatch& p : patches())
    for (double sx : {0.0, 1e-4, -3e-3, 0.2})
      for (double sy : {0.0, 2e-4, -5e-3, 0.1})
        for (double phi : {0.0, 0.3, -2.0, 40.0}) {
          const CreepForce f = polachForce(cp, p, {sx, sy, phi, 20.0});
          const CreepForce g = polachForce(cp, p, {-sx, -sy, -phi, 20.0});
          EXPECT_EQ(f.fx, -g.fx);
          EXPECT_EQ(f.fy, -g.fy);
          // Forces oppose the creepage (no spin: dissipative, F . s <= 0).
          if (phi == 0.0) {
            EXPECT_LE(f.fx * sx + f.fy * sy, 0.0);
          }
        }
}

TEST(Polach, ZeroCreepageAndZeroLoad) {
  const CreepParams cp = params();
  const ContactPatch p = treadPatch();
  CreepForce f = polachForce(cp, p, {0.0, 0.0, 0.0, 20.0});
  EXPECT_EQ(f.fx, 0.0);
  EXPECT_EQ(f.fy, 0.0);
  // Continuity at zero: tiny and denormal creepages give tiny forces, not NaN.
  for (double s : {1e-160, 1e-310}) {
    f = polachForce(cp, p, {s, s, s, 20.0});
    EXPECT_TRUE(std::isfinite(f.fx) && std::isfinite(f.fy));
    EXPECT_LT(std::fabs(f.fx) + std::fabs(f.fy), 1e-100);
  }
  // Zero / negative load, zero friction.
  for (double N : {0.0, -1.0e3}) {
    const ContactPatch z = makeContactPatch(kSteel, {1.0, 2.0}, N);
    EXPECT_EQ(z.Q, 0.0);
    EXPECT_GT(z.c11, 0.0);
    f = polachForce(cp, z, {1e-3, 1e-3, 1.0, 20.0});
    EXPECT_EQ(f.fx, 0.0);
    EXPECT_EQ(f.fy, 0.0);
  }
  ContactPatch q = p;
  q.Q = 1e-300;  // vanishing load with a finite patch: saturated, finite
  f = polachForce(cp, q, {1e-3, 0.0, 1.0, 20.0});
  EXPECT_TRUE(std::isfinite(f.fx) && std::isfinite(f.fy));
  CreepParams nofric = cp;
  nofric.mu = 0.0;
  f = polachForce(nofric, p, {1e-3, 1e-3, 1.0, 20.0});
  EXPECT_EQ(f.fx, 0.0);
  EXPECT_EQ(f.fy, 0.0);
  // Infinite / huge spin.
  f = polachForce(cp, p, {0.0, 1e-3, 1e300, 20.0});
  EXPECT_TRUE(std::isfinite(f.fx) && std::isfinite(f.fy));
}

TEST(Polach, Extension2005) {
  const ContactPatch p = treadPatch();
  CreepParams cp = params();
  cp.k_A = 0.3;
  cp.k_S = 0.1;
  EXPECT_TRUE(creepParamsProblem(cp).empty());
  // Initial slope reduced by (k_A + k_S)/2.
  const double s = 1e-7;
  const CreepForce f = polachForce(cp, p, {s, 0.0, 0.0, 20.0});
  EXPECT_LT(rel(f.fx, -0.5 * (cp.k_A + cp.k_S) * cp.G * p.a * p.b * p.c11 * s), 1e-3);
  // Falling friction: at large slip velocity mu -> mu_0 A.
  CreepParams dry = params();
  dry.mu = 0.55, dry.k_A = 1.0, dry.k_S = 0.4, dry.friction_A = 0.4, dry.friction_B = 0.6;
  const CreepForce big = polachForce(dry, p, {1.0, 0.0, 0.0, 50.0});  // w = 50 m/s
  EXPECT_NEAR(big.mu, 0.55 * (0.6 * std::exp(-30.0) + 0.4), 1e-15);
  EXPECT_NEAR(-big.fx, big.mu * p.Q, 1e-3 * p.Q);
  // The traction curve has a maximum and then falls.
  double peak = 0.0, last = 0.0;
  for (double sx = 1e-4; sx < 0.5; sx *= 1.1) {
    last = -polachForce(dry, p, {sx, 0.0, 0.0, 30.0}).fx;
    peak = std::max(peak, last);
  }
  EXPECT_LT(last, 0.8 * peak);
  // Constant friction reproduces the 1999 form exactly.
  CreepParams c99 = params();
  const Creepages cr{2e-3, -1e-3, 0.4, 20.0};
  CreepParams same = c99;
  same.friction_B = 5.0;  // ignored while friction_A = 1
  EXPECT_EQ(polachForce(c99, p, cr).fx, polachForce(same, p, cr).fx);
  // Parameter validation.
  CreepParams bad = params();
  bad.k_S = 0.5, bad.k_A = 0.3;
  EXPECT_FALSE(creepParamsProblem(bad).empty());
  bad = params();
  bad.friction_A = 1.5;
  EXPECT_FALSE(creepParamsProblem(bad).empty());
  EXPECT_TRUE(creepParamsProblem(params()).empty());
}

TEST(Creepages, FromKinematics) {
  const Creepages c = creepagesFromKinematics(0.02, -0.01, 0.5, 20.0);
  EXPECT_DOUBLE_EQ(c.sx, 1e-3);
  EXPECT_DOUBLE_EQ(c.sy, -5e-4);
  EXPECT_DOUBLE_EQ(c.phi, 0.025);
  EXPECT_EQ(c.v, 20.0);
  // Standstill: no division by zero, V_ref = v_min.
  const Creepages z = creepagesFromKinematics(0.01, 0.0, 0.1, 0.0);
  EXPECT_DOUBLE_EQ(z.sx, 0.01 / kMinReferenceSpeed);
  EXPECT_EQ(z.v, kMinReferenceSpeed);
  EXPECT_TRUE(std::isfinite(creepagesFromKinematics(1.0, 1.0, 1.0, 1e-300).sx));
  // Backwards: s_x, s_y keep the sign of the slip velocity, phi flips (leading edge at -a).
  const Creepages b = creepagesFromKinematics(0.02, -0.01, 0.5, -20.0);
  EXPECT_DOUBLE_EQ(b.sx, 1e-3);
  EXPECT_DOUBLE_EQ(b.sy, -5e-4);
  EXPECT_DOUBLE_EQ(b.phi, -0.025);
}

TEST(Creepages, BackwardRunningEqualsRotatedFrame) {
  // Running at V < 0 in frame (x, y, n) is running at |V| in the frame rotated by 180 deg about n:
  // (dv_x, dv_y, domega) -> (-dv_x, -dv_y, domega), forces rotate back with a sign change.
  const CreepParams cp = params();
  const ContactPatch p = treadPatch();
  const double dvx = 0.03, dvy = -0.05, dw = 0.8, V = -25.0;
  const CreepForce f = polachForce(cp, p, creepagesFromKinematics(dvx, dvy, dw, V));
  const CreepForce r = polachForce(cp, p, creepagesFromKinematics(-dvx, -dvy, dw, -V));
  EXPECT_EQ(f.fx, -r.fx);
  EXPECT_EQ(f.fy, -r.fy);
}

// patchConstants + makeContactPatch(pc, N) (the dynamics: constants once per patch geometry) give
// exactly makeContactPatch(mat, k, shape, N).
TEST(Polach, PatchConstantsGiveTheSamePatchBitForBit) {
  for (const RelativeCurvatures k : {RelativeCurvatures{1.09, 3.3}, RelativeCurvatures{4.0, 0.6},
                                     RelativeCurvatures{2.0, 2.0}}) {
    const HertzShape shape = hertzShape(k.A, k.B);
    const PatchConstants pc = patchConstants(kSteel, k, shape);
    for (double N : {-1.0, 0.0, 3.7e4, 1.0e5}) {
      const ContactPatch a = makeContactPatch(kSteel, k, shape, N);
      const ContactPatch b = makeContactPatch(pc, N);
      EXPECT_EQ(a.Q, b.Q);
      EXPECT_EQ(a.a, b.a);
      EXPECT_EQ(a.b, b.b);
      EXPECT_EQ(a.c11, b.c11);
      EXPECT_EQ(a.c22, b.c22);
      EXPECT_EQ(a.c23, b.c23);
      EXPECT_EQ(a.c33, b.c33);
    }
  }
}

}  // namespace

// K_M of a patch made from its PatchConstants (a/b = m/n, once per patch) against Polach's
// K_M = 1 + 6.3 (1 - exp(-a/b)) from the patch's own semi-axes: equal to round-off, and the forces
// with it equal to those of a hand-made patch (km = 0: K_M from a and b) to round-off.
TEST(Polach, SpinFactorFromPatchConstants) {
  const CreepParams cp = params();
  for (const RelativeCurvatures k : {RelativeCurvatures{1.09, 3.3}, RelativeCurvatures{4.0, 0.6},
                                     RelativeCurvatures{2.0, 2.0}}) {
    const PatchConstants pc = patchConstants(kSteel, k, hertzShape(k.A, k.B));
    for (double N : {3.7e4, 1.0e5}) {
      const ContactPatch p = makeContactPatch(pc, N);
      const double km = 1.0 + 6.3 * (1.0 - std::exp(-p.a / p.b));
      EXPECT_EQ(p.km, pc.km);
      EXPECT_NEAR(p.km, km, 4e-16 * km);
      EXPECT_EQ(polachSpinFactor(p.a / p.b), km);
      ContactPatch hand = p;
      hand.km = 0.0;
      for (const Creepages s :
           {Creepages{1e-3, -2e-3, 0.5, 20.0}, Creepages{0.0, 1e-4, -2.0, 20.0}}) {
        const CreepForce f = polachForce(cp, p, s), g = polachForce(cp, hand, s);
        EXPECT_NEAR(f.fx, g.fx, 1e-12 * N);
        EXPECT_NEAR(f.fy, g.fy, 1e-12 * N);
      }
    }
  }
}
