// Timing of the contact tables: build times and sizes (default and refined grids, Tables 9-10) and
// the cost of one evaluation (ns). Not a test; run: ./build/tests/contact/bench_contact
#include <chrono>
#include <cmath>
#include <cstdio>

#include "contact_test_util.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"

namespace {

using namespace rb::contact;
using Clock = std::chrono::steady_clock;

template <class F>
double nsPerCall(F f, int n) {
  f(0);  // warm up
  const auto t0 = Clock::now();
  for (int i = 0; i < n; ++i) f(i);
  return std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / n;
}

volatile double g_sink = 0.0;

void run(const char* label, const ContactGeometryConfig& cfg) {
  const LutTable lut = buildLut(cfg);
  const KecTable kec = buildKec(cfg);
  std::printf("%s\n", label);
  std::printf("  LUT %zu x %zu: build %.3f s, %.2f MB, %ld Newton iterations, %zu restarts\n",
              lut.ny(), lut.ng(), lut.stats().build_seconds,
              static_cast<double>(lut.stats().bytes) / 1e6, lut.stats().newton_iterations,
              lut.stats().restarts);
  std::printf("  KEC %zu points: build %.3f s, %.3f MB, %zu branch samples\n", kec.grid().count(),
              kec.stats().build_seconds, static_cast<double>(kec.stats().bytes) / 1e6,
              kec.stats().nodes);
  const int n = 200000;
  auto yof = [](int i) { return 12e-3 * std::sin(0.001 * i); };
  auto xof = [](int i) { return 4e-3 * std::cos(0.0007 * i); };
  LutSample s;
  std::printf("  LUT eval, all %zu channels + first derivatives: %7.1f ns\n", kLutChannels,
              nsPerCall(
                  [&](int i) {
                    lut.eval(yof(i), xof(i), s);
                    g_sink = g_sink + s.value[0];
                  },
                  n));
  LutValue z, phi;
  std::printf("  LUT z, phi with 1st and 2nd derivatives:        %7.1f ns\n",
              nsPerCall(
                  [&](int i) {
                    lut.evalZPhi(yof(i), xof(i), z, phi);
                    g_sink = g_sink + z.v;
                  },
                  n));
  double d1, d2;
  std::printf("  KEC f, f', f'' (one side):                      %7.1f ns\n",
              nsPerCall([&](int i) { g_sink = g_sink + kec.f(Side::Left, yof(i), &d1, &d2); }, n));
  KecPoint kp;
  std::printf("  KEC all quantities + derivatives (one side):    %7.1f ns\n",
              nsPerCall(
                  [&](int i) {
                    kec.eval(Side::Left, yof(i), kp);
                    g_sink = g_sink + kp.d2f;
                  },
                  n));
  KecSolution ks = solveKec(kec, KecInput{});
  std::printf(
      "  KEC online solve (Eq. 22), warm, + Jacobian:    %7.1f ns\n",
      nsPerCall(
          [&](int i) {
            ks = solveKec(kec, KecInput{0.5 * yof(i), 0.1 * xof(i), -0.1 * xof(i), 0, 0}, &ks);
            g_sink = g_sink + ks.z;
          },
          n));
}

}  // namespace

int main() {
  run("S1002 / 60E1 1:40, default grids (Table 9, Table 10 before refinement)",
      rbtest::s1002On60E1());
  ContactGeometryConfig refined = rbtest::s1002On60E1();
  refined.useRefinedGrids();
  run("S1002 / 60E1 1:40, refined grids (Table 9, Table 10 after refinement)", refined);
  return 0;
}
