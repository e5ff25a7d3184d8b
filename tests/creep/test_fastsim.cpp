// FASTSIM (workbench/creep/fastsim.hpp): linear limit against Kalker's linear theory, saturation,
// symmetry, extreme inputs, grid convergence, and comparison with CONTACT's exact theory and its
// own FASTSIM (tests/data/creep/contact_*.txt, Apache-2.0, see tests/data/README.md).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "tests/creep/fixtures.hpp"
#include "workbench/creep/fastsim.hpp"
#include "workbench/creep/polach.hpp"

namespace {

using namespace rb::creep;

constexpr double kPi = std::numbers::pi;

using rb::test::ellipse;

// Patches with a/b from 0.2 (tread) to 5 (flange-like), all in the Kalker table.
std::vector<ContactPatch> patches() {
  return {ellipse(3.4e-3, 15.8e-3, 1e5), ellipse(6e-3, 6e-3, 8e4), ellipse(8e-3, 4e-3, 6e4),
          ellipse(6.304e-3, 12.61e-3, 1.067e5), ellipse(10e-3, 2e-3, 5e4)};
}

CreepParams params(double mu = 0.3, double G = 8.2e10) {
  CreepParams p;
  p.mu = mu;
  p.G = G;
  return p;
}

FastsimGrid grid(int n, FastsimBound bound = FastsimBound::Parabolic) {
  FastsimGrid g;
  g.strips = g.elements = n;
  g.bound = bound;
  return g;
}

double rel(double x, double ref) {
  return std::fabs(x - ref) / std::fabs(ref);
}

// Kalker's flexibilities against those CONTACT prints for its examples (mm^3/N there; m^3/N =
// 1e9 mm^3/N). Our coefficients interpolate Kalker's table linearly in nu, CONTACT 1/C
// quadratically, hence up to ~1.7 % (docs/creep.md "Kalker coefficients").
TEST(Fastsim, FlexibilitiesMatchContact) {
  struct Case {
    double a, b, L1, L2, L3;  // [mm], CONTACT's FLX [mm^3/N]
  };
  const Case cases[] = {{6.304, 12.61, 0.5491e-4, 0.6773e-4, 0.4526e-4},  // tractcurv.ref_out
                        {8.0, 4.0, 0.4937e-4, 0.5152e-4, 0.4090e-4}};     // fastsim.ref_out
  for (const Case& c : cases) {
    const FastsimFlexibilities L = fastsimFlexibilities(8.2e10, ellipse(c.a * 1e-3, c.b * 1e-3, 1));
    std::printf("a/b = %.3f: L1 %.4e (CONTACT %.4e), L2 %.4e (%.4e), L3 %.4e (%.4e) mm^3/N\n",
                c.a / c.b, L.L1 * 1e9, c.L1, L.L2 * 1e9, c.L2, L.L3 * 1e9, c.L3);
    EXPECT_LT(rel(L.L1 * 1e9, c.L1), 0.02);
    EXPECT_LT(rel(L.L2 * 1e9, c.L2), 0.02);
    EXPECT_LT(rel(L.L3 * 1e9, c.L3), 0.02);
  }
}

// At vanishing creepage FASTSIM is the simplified theory in full adhesion, whose flexibilities are
// chosen to give Kalker's linear F_x, F_y(s_y) and F_y(phi). The moments are the simplified
// theory's own: M_z(s_y) = pi a^3 b s_y / (4 L2) and M_z(phi) = -8 a^2 b^3 phi / (15 L3), which
// differ from Kalker's linear G c^3 C23 s_y and -G c^4 C33 phi (printed; C33 is UNVERIFIED).
TEST(Fastsim, SmallCreepageEqualsKalkerLinear) {
  const CreepParams p = params();
  const double s = 1e-9;
  for (const ContactPatch& c : patches()) {
    const FastsimFlexibilities L = fastsimFlexibilities(p.G, c);
    const double phi = s / std::sqrt(c.a * c.b);
    const FastsimForce fx = fastsimForce(p, c, {s, 0, 0});
    const FastsimForce fy = fastsimForce(p, c, {0, s, 0});
    const FastsimForce fs = fastsimForce(p, c, {0, 0, phi});
    const LinearCreepForce kx = kalkerLinearForce(p.G, c, {s, 0, 0});
    const LinearCreepForce ky = kalkerLinearForce(p.G, c, {0, s, 0});
    const LinearCreepForce ks = kalkerLinearForce(p.G, c, {0, 0, phi});
    const double mz_sy = kPi * std::pow(c.a, 3) * c.b * s / (4.0 * L.L2);
    const double mz_phi = -8.0 * c.a * c.a * std::pow(c.b, 3) * phi / (15.0 * L.L3);
    std::printf(
        "a/b %5.2f: fx %.2e, fy(sy) %.2e, fy(phi) %.2e rel. to Kalker linear; mz(sy) %.2e, "
        "mz(phi) %.2e rel. to the simplified theory; Kalker/simplified mz(sy) %.3f, mz(phi) "
        "%.3f\n",
        c.a / c.b, rel(fx.fx, kx.fx), rel(fy.fy, ky.fy), rel(fs.fy, ks.fy), rel(fy.mz, mz_sy),
        rel(fs.mz, mz_phi), ky.mz / mz_sy, ks.mz / mz_phi);
    EXPECT_LT(rel(fx.fx, kx.fx), 0.01);
    EXPECT_LT(rel(fy.fy, ky.fy), 0.01);
    EXPECT_LT(rel(fs.fy, ks.fy), 0.01);
    EXPECT_LT(rel(fy.mz, mz_sy), 0.01);
    EXPECT_LT(rel(fs.mz, mz_phi), 0.02);  // 0.97 % at the default grid (y^2 across the strips)
    // Signs as kalkerLinearForce: forces oppose the creepage, M_z(s_y) > 0.
    EXPECT_LT(fx.fx, 0.0);
    EXPECT_LT(fy.fy, 0.0);
    EXPECT_LT(fs.fy, 0.0);
    EXPECT_GT(fy.mz, 0.0);
    EXPECT_LT(fs.mz, 0.0);
    // No cross terms in the linear range: pure s_x gives no F_y, M_z.
    EXPECT_EQ(fx.fy, 0.0);
    EXPECT_NEAR(fx.mz, 0.0, 1e-12 * std::fabs(fx.fx) * c.a);
  }
}

// The linear-range error against the grid: the trapezoidal rule along x is exact, the midpoint
// rule across y gives about +1/(2 strips^2) for F_x.
TEST(Fastsim, LinearRangeDiscretisationError) {
  const CreepParams p = params();
  const ContactPatch c = ellipse(6e-3, 6e-3, 8e4);
  const double phi = 1e-9 / c.a;
  for (int n : {6, 12, 24, 48}) {
    const double ex = rel(fastsimForce(p, c, {1e-9, 0, 0}, grid(n)).fx,
                          kalkerLinearForce(p.G, c, {1e-9, 0, 0}).fx);
    const double es =
        rel(fastsimForce(p, c, {0, 0, phi}, grid(n)).fy, kalkerLinearForce(p.G, c, {0, 0, phi}).fy);
    std::printf("grid %2d x %2d: linear F_x error %.2e (1/(2 n^2) = %.2e), F_y(phi) %.2e\n", n, n,
                ex, 0.5 / (n * n), es);
    EXPECT_LT(ex, 1.0 / (n * n));
    EXPECT_LT(es, 2.0 / (n * n));
  }
}

// Large creepage: full slip, |F| -> mu Q, never above (the bound is normalised to exactly mu Q).
TEST(Fastsim, SaturatesAtMuQ) {
  const CreepParams p = params();
  double worst = 0.0;
  for (const ContactPatch& c : patches()) {
    const double muQ = p.mu * c.Q;
    for (double s : {0.05, 1.0, 1e3, 1e300}) {
      EXPECT_NEAR(std::fabs(fastsimForce(p, c, {s, 0, 0}).fx), muQ, 1e-12 * muQ);
      EXPECT_NEAR(std::fabs(fastsimForce(p, c, {0, -s, 0}).fy), muQ, 1e-12 * muQ);
    }
    for (double sx : {-1.0, -1e-3, 0.0, 2e-3, 0.3})
      for (double sy : {-0.2, -1e-3, 0.0, 1e-3, 0.5})
        for (double phi : {-50.0, -1.0, 0.0, 0.5, 3.0, 1e3}) {
          const FastsimForce f = fastsimForce(p, c, {sx, sy, phi});
          worst = std::max(worst, std::hypot(f.fx, f.fy) / muQ);
        }
  }
  std::printf("largest |F| / (mu Q) over the sweep: %.15f\n", worst);
  EXPECT_LE(worst, 1.0 + 1e-12);
}

TEST(Fastsim, OddSymmetry) {
  const CreepParams p = params();
  for (const ContactPatch& c : patches())
    for (const Creepages s : {Creepages{1e-3, 0, 0}, Creepages{0, 2e-3, 0}, Creepages{0, 0, 0.7},
                              Creepages{1e-3, -2e-3, 1.3}, Creepages{-4e-3, 1e-4, -5.0}}) {
      const FastsimForce f = fastsimForce(p, c, s);
      const FastsimForce g = fastsimForce(p, c, {-s.sx, -s.sy, -s.phi});
      EXPECT_EQ(f.fx, -g.fx);
      EXPECT_EQ(f.fy, -g.fy);
      EXPECT_EQ(f.mz, -g.mz);
    }
}

TEST(Fastsim, ZeroAndExtremeInputs) {
  const CreepParams p = params();
  const ContactPatch c = ellipse(6e-3, 9e-3, 8e4);
  const FastsimForce zero = fastsimForce(p, c, {0, 0, 0});
  EXPECT_EQ(zero.fx, 0.0);
  EXPECT_EQ(zero.fy, 0.0);
  EXPECT_EQ(zero.mz, 0.0);
  // No force without load, friction, stiffness or size.
  for (double Q : {0.0, -1e4, std::numeric_limits<double>::infinity()}) {
    ContactPatch d = c;
    d.Q = Q;
    EXPECT_EQ(fastsimForce(p, d, {1e-3, 1e-3, 1}).fx, 0.0);
  }
  for (double mu : {0.0, -0.3}) EXPECT_EQ(fastsimForce(params(mu), c, {1e-3, 0, 0}).fx, 0.0);
  EXPECT_EQ(fastsimForce(params(0.3, 0.0), c, {1e-3, 0, 0}).fx, 0.0);
  ContactPatch flat = c;
  flat.a = 0.0;
  EXPECT_EQ(fastsimForce(p, flat, {1e-3, 0, 0}).fx, 0.0);
  // Huge, infinite, denormal and negative creepages, tiny and huge patches: finite and bounded.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double values[] = {0.0, 5e-324, -1e-300, 1e-3, -0.7, 1e150, -1e300, kInf, -kInf};
  std::vector<ContactPatch> odd = {c, ellipse(1e-9, 1e-2, 1e-300), ellipse(1e-2, 1e-9, 1e300)};
  for (const ContactPatch& d : odd)
    for (double sx : values)
      for (double sy : values)
        for (double phi : values) {
          const FastsimForce f = fastsimForce(p, d, {sx, sy, phi});
          ASSERT_TRUE(std::isfinite(f.fx) && std::isfinite(f.fy) && std::isfinite(f.mz))
              << sx << " " << sy << " " << phi << " a " << d.a;
          EXPECT_LE(std::hypot(f.fx, f.fy), p.mu * d.Q * (1 + 1e-12));
        }
  EXPECT_TRUE(std::isnan(fastsimForce(p, c, {std::nan(""), 0, 0}).fx));
}

// Refinement towards a 200 x 200 grid in the transition range: the difference falls with the
// grid (first order in 1/elements, from 12 x 12 on); the default grid is within 0.2 % of mu Q
// without spin and 1.5 % of mu Q at strong spin (phi a about three times the saturation creepage).
TEST(Fastsim, ConvergesWithGridRefinement) {
  const CreepParams p = params();
  const Creepages cases[] = {{1.5e-3, 0, 0}, {0, 1e-3, 0}, {0, 0, 1.0}, {6e-4, -8e-4, 0.6}};
  double worst_plain = 0.0, worst_spin = 0.0;
  for (const ContactPatch& c : {ellipse(6.304e-3, 12.61e-3, 1.067e5), ellipse(8e-3, 4e-3, 8.2e4)})
    for (const Creepages& s : cases) {
      const double muQ = p.mu * c.Q;
      const FastsimForce ref = fastsimForce(p, c, s, grid(200));
      double previous = std::numeric_limits<double>::infinity();
      for (int n : {6, 12, 24, 48, 96}) {
        const FastsimForce f = fastsimForce(p, c, s, grid(n));
        const double e = std::hypot(f.fx - ref.fx, f.fy - ref.fy) / muQ;
        std::printf("a/b %.2f s (%g, %g, %g) grid %3d: |F - F_200| / mu Q = %.2e\n", c.a / c.b,
                    s.sx, s.sy, s.phi, n, e);
        if (n > 12) {
          EXPECT_LT(e, previous);
        }
        previous = e;
      }
      const FastsimForce d = fastsimForce(p, c, s);
      const double e = std::hypot(d.fx - ref.fx, d.fy - ref.fy) / muQ;
      std::printf("  default grid: %.2e\n", e);
      double& worst = s.phi == 0.0 ? worst_plain : worst_spin;
      worst = std::max(worst, e);
    }
  std::printf("default grid: largest |F - F_200| / mu Q = %.2e without spin, %.2e with spin\n",
              worst_plain, worst_spin);
  EXPECT_LT(worst_plain, 2e-3);
  EXPECT_LT(worst_spin, 1.5e-2);
}

using rb::test::CurvePoint;

// The creep force curve of CONTACT's tractcurv example (a/b = 0.5, mu = 0.33, pure s_x): ours
// against CONTACT's own FASTSIM (same algorithm, its grid and coefficients: an implementation
// check) and against Kalker's exact theory (the method's known error in the transition range;
// measured, not tuned: docs/creep.md).
TEST(Fastsim, TractionCurveAgainstContact) {
  const std::vector<CurvePoint> curve = rb::test::tractcurv();
  ASSERT_EQ(curve.size(), 60u);
  const CreepParams p = params(0.33, 8.2e10);
  const ContactPatch c = ellipse(6.304e-3, 12.61e-3, 1.067e5);
  const double muQ = p.mu * c.Q;
  double worst_fastsim = 0.0, worst_exact = 0.0, worst_exact_fine = 0.0;
  for (const CurvePoint& pt : curve) {
    const double ours = fastsimForce(p, c, {pt.cksi, 0, 0}).fx;
    const double fine = fastsimForce(p, c, {pt.cksi, 0, 0}, grid(200)).fx;
    const double d = (ours - pt.fx) / muQ;
    const double dfine = (fine - pt.fx) / muQ;
    std::printf("%-7s cksi %.2e: CONTACT %.4f, ours %.4f (200x200 %.4f) mu Q: diff %+.4f\n",
                pt.series.c_str(), pt.cksi, pt.fx / muQ, ours / muQ, fine / muQ, d);
    if (pt.series == "fastsim") worst_fastsim = std::max(worst_fastsim, std::fabs(d));
    if (pt.series == "exact") {
      worst_exact = std::max(worst_exact, std::fabs(d));
      worst_exact_fine = std::max(worst_exact_fine, std::fabs(dfine));
    }
  }
  std::printf(
      "largest difference / mu Q: to CONTACT's FASTSIM %.4f, to the exact theory %.4f "
      "(200 x 200: %.4f)\n",
      worst_fastsim, worst_exact, worst_exact_fine);
  EXPECT_LT(worst_fastsim, 0.02);
  EXPECT_LT(worst_exact, 0.06);
}

// CONTACT's fastsim example (a = 8 mm, b = 4 mm, lateral creepage and spin, mu = 0.3): the
// lateral force and spin moment against CONTACT's FASTSIM on 220 x 220 and its exact solution.
// CONTACT's frame has z pointing down (user guide, "track coordinates"), ours n up, so y and the
// spin axis are reversed: its (CETA, CPHI) = (-6.25e-4, 6.25e-4 1/mm) is our (s_y, phi) =
// (6.25e-4, -0.625 1/m), with F_y, M_z = -FY, -MZ. (Same-sign s_y and phi would give
// F_y = -0.87 mu Q here, far from every CONTACT result, so the relative sign is not in doubt.)
TEST(Fastsim, SpinExampleAgainstContact) {
  const CreepParams p = params(0.3, 8.2e10);
  const ContactPatch c = ellipse(8e-3, 4e-3, 8.2e4);
  const double muQ = p.mu * c.Q;
  const Creepages s{0.0, 6.25e-4, -0.625};
  struct Ref {
    const char* what;
    double fy, mz;  // [N], [N m], in our frame
  };
  const Ref exact{"exact", 1.494e4, 48.21}, parabolic{"FASTSIM parabolic 220", 1.564e4, 37.98},
      elliptic{"FASTSIM elliptic 220", 1.465e4, 45.30};
  FastsimGrid elliptic_default;
  elliptic_default.bound = FastsimBound::Elliptic;
  const FastsimForce fp = fastsimForce(p, c, s);
  const FastsimForce fp_fine = fastsimForce(p, c, s, grid(200));
  const FastsimForce fe = fastsimForce(p, c, s, elliptic_default);
  const FastsimForce fe_fine = fastsimForce(p, c, s, grid(200, FastsimBound::Elliptic));
  const auto show = [&](const char* what, const FastsimForce& f, const Ref& r) {
    std::printf("%-28s F_y %.4f mu Q (%s %.4f: %+.1f %%), M_z %.2f N m (%+.1f %%)\n", what,
                f.fy / muQ, r.what, r.fy / muQ, 100 * (f.fy - r.fy) / r.fy, f.mz,
                100 * (f.mz - r.mz) / r.mz);
  };
  show("ours parabolic default", fp, parabolic);
  show("ours parabolic 200x200", fp_fine, parabolic);
  show("ours parabolic default", fp, exact);
  show("ours elliptic default", fe, elliptic);
  show("ours elliptic 200x200", fe_fine, elliptic);
  show("ours elliptic default", fe, exact);
  // CONTACT's FASTSIM runs on a rectangular grid over 1.1 times the ellipse and is itself not
  // converged: its 44 x 44 and 220 x 220 results differ by 3.8 % (F_y) and 2.6 % (M_z).
  EXPECT_LT(rel(fp_fine.fy, parabolic.fy), 0.03);
  EXPECT_LT(rel(fp_fine.mz, parabolic.mz), 0.03);
  EXPECT_LT(rel(fe_fine.fy, elliptic.fy), 0.03);
  EXPECT_LT(rel(fe_fine.mz, elliptic.mz), 0.03);
  // Against the exact theory: the known error of the simplified theory (measured, docs/creep.md).
  EXPECT_LT(rel(fp.fy, exact.fy), 0.08);
  EXPECT_LT(rel(fp.mz, exact.mz), 0.25);
}

// FASTSIM and Polach agree in the linear range (both reproduce Kalker) and at saturation; in
// between they differ by the shape of their curves (printed).
TEST(Fastsim, ComparedWithPolach) {
  const CreepParams p = params(0.3, 8.2e10);
  const ContactPatch c = ellipse(3.4e-3, 15.8e-3, 1e5);
  for (double s : {1e-6, 5e-4, 1e-3, 2e-3, 5e-3, 1e-2}) {
    const double f = fastsimForce(p, c, {s, 0, 0}).fx, q = polachForce(p, c, {s, 0, 0}).fx;
    std::printf("s_x %.0e: FASTSIM %.4f, Polach %.4f mu Q\n", s, f / (p.mu * c.Q),
                q / (p.mu * c.Q));
    if (s <= 1e-6) {
      EXPECT_LT(rel(f, q), 0.01);
    }
  }
}

}  // namespace
