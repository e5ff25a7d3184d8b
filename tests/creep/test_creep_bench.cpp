// Speed of the tangential-contact chain (prints ns per call; asserts nothing about time).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "workbench/creep/fastsim.hpp"
#include "workbench/creep/polach.hpp"

namespace {

using namespace rb::creep;
using Clock = std::chrono::steady_clock;

template <class F>
double nsPerCall(int n, F&& f) {
  const auto t0 = Clock::now();
  for (int i = 0; i < n; ++i) f(i);
  const auto t1 = Clock::now();
  return std::chrono::duration<double, std::nano>(t1 - t0).count() / n;
}

TEST(CreepBench, NanosecondsPerCall) {
  const Material mat{};
  CreepParams cp;
  cp.G = shearModulus(mat);
  const RelativeCurvatures tread = relativeCurvatures(1.0 / 0.46, -1.0 / 0.32, 0.0, 1.0 / 0.3);
  const int n = 200000;
  volatile double sink = 0.0;
  // Vary the inputs a little so nothing is hoisted out of the loop.
  const double t_hertz = nsPerCall(n, [&](int i) {
    const HertzContact h = hertz(mat, {tread.A * (1.0 + 1e-6 * (i & 255)), tread.B}, 1.0e5);
    sink = sink + h.a;
  });
  const double t_kalker = nsPerCall(
      n, [&](int i) { sink = sink + kalkerCoefficients(0.2 + 1e-4 * (i & 1023), 0.28).c11; });
  const ContactPatch patch = makeContactPatch(mat, tread, 1.0e5);
  const double t_polach = nsPerCall(n, [&](int i) {
    const double s = 1e-4 * (i & 63);
    const CreepForce f = polachForce(cp, patch, {s, -0.5 * s, 0.3, 20.0});
    sink = sink + f.fx + f.fy;
  });
  const double t_chain = nsPerCall(n, [&](int i) {
    const double s = 1e-4 * (i & 63);
    const ContactPatch p =
        makeContactPatch(mat, {tread.A * (1.0 + 1e-6 * (i & 255)), tread.B}, 1.0e5);
    const CreepForce f =
        polachForce(cp, p, creepagesFromKinematics(20.0 * s, -10.0 * s, 6.0, 20.0));
    sink = sink + f.fx + f.fy;
  });
  const HertzShape shape = hertzShape(tread.A, tread.B);
  const double t_chain_shape = nsPerCall(n, [&](int i) {
    const double s = 1e-4 * (i & 63);
    const ContactPatch p = makeContactPatch(mat, tread, shape, 1.0e5 + (i & 255));
    const CreepForce f =
        polachForce(cp, p, creepagesFromKinematics(20.0 * s, -10.0 * s, 6.0, 20.0));
    sink = sink + f.fx + f.fy;
  });
  std::printf(
      "hertz %.1f ns (%d shape evaluations), kalker lookup %.1f ns, polachForce %.1f ns\n"
      "hertz + kalker + creepages + polach: %.1f ns per call; with a precomputed Hertz "
      "shape: %.1f ns\n",
      t_hertz, shape.iterations, t_kalker, t_polach, t_chain, t_chain_shape);
  EXPECT_TRUE(std::isfinite(sink));
}

// FASTSIM per patch (tread patch, 100 kN) against its grid and the creep regime: small creepage
// (adhesion almost everywhere), the transition and full slip (a square root and a division per
// element); Polach on the same inputs for comparison. docs/creep.md quotes these.
TEST(CreepBench, FastsimNanosecondsPerPatch) {
  const Material mat{};
  CreepParams cp;
  cp.G = shearModulus(mat);
  const ContactPatch patch =
      makeContactPatch(mat, relativeCurvatures(1.0 / 0.46, -1.0 / 0.32, 0.0, 1.0 / 0.3), 1.0e5);
  volatile double sink = 0.0;
  const int n = 20000;
  for (const double s : {1e-5, 1e-3, 2e-2}) {
    std::printf("s_x = %.0e, s_y = -s_x / 2, phi = 0.3 1/m: polach %.0f ns;", s,
                nsPerCall(n, [&](int i) {
                  const double k = 1.0 + 1e-3 * (i & 63);
                  sink = sink + polachForce(cp, patch, {k * s, -0.5 * s, 0.3, 20.0}).fx;
                }));
    for (const int m : {8, 16, 32}) {
      FastsimGrid g;
      g.strips = m;
      g.elements = 2 * m;
      std::printf(" fastsim %dx%d %.0f ns;", g.strips, g.elements, nsPerCall(n / m, [&](int i) {
                    const double k = 1.0 + 1e-3 * (i & 63);
                    sink = sink + fastsimForce(cp, patch, {k * s, -0.5 * s, 0.3}, g).fx;
                  }));
    }
    std::printf("\n");
  }
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
