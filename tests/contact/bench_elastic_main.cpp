// Timing of the elastic contact search (elastic_search.hpp) and the Hertz normal problem per
// wheel (elastic_normal.hpp), S1002 on UIC60 1:40 (the Manchester benchmark profiles), for
// docs/elastic_contact.md ("Cost"). Not a test; run: ./build/tests/contact/bench_elastic
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "workbench/contact/elastic_normal.hpp"
#include "workbench/contact/elastic_search.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/profile_io.hpp"

namespace {

using namespace rb::contact;
using Clock = std::chrono::steady_clock;

// The fastest of 5 runs of n calls (the machine is shared: the minimum is the cost, the rest is
// other load).
template <class F>
double nsPerCall(F f, int n) {
  f(0);  // warm up
  double best = 1e300;
  for (int rep = 0; rep < 5; ++rep) {
    const auto t0 = Clock::now();
    for (int i = 0; i < n; ++i) f(i);
    best = std::min(best, std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / n);
  }
  return best;
}

volatile double g_sink = 0.0;

}  // namespace

int main() {
  const std::string src = RB_SOURCE_DIR;
  rb::profiles::ProfileReadOptions wo;
  wo.r0 = 0.46;
  auto wheel = std::make_shared<const rb::profiles::Profile>(
      rb::profiles::readSimpackProfile(src + "/profiles/MBench_S1002_v3.prw", wo));
  auto rail = std::make_shared<const rb::profiles::Profile>(
      rb::profiles::readSimpackProfile(src + "/profiles/MBench_UIC60_v3.prr"));
  WheelRailPair p;
  p.side = Side::Right;
  p.wheel = std::make_shared<const rb::profiles::Profile>(wheel->mirrored());
  p.rail = std::make_shared<const rb::profiles::Profile>(rail->mirrored());
  p.wheel_lw = 0.75;
  p.rail_lr =
      0.7175 + std::abs(rb::profiles::gaugePoint(*rail, rb::profiles::Side::Left, 0.0, 0.014).y);
  p.beta = 0.0;
  std::printf("elastic contact search, one wheel (S1002 on UIC60 1:40, benchmark profiles)\n");
  std::printf(
      "budget: case 3 at 30x real time = 8 wheels x 4000 evaluations per simulated "
      "second x 30 = 9.6e5 wheel evaluations per second: about 1000 ns per wheel\n");
  const ElasticNormalSpec nspec;
  for (double step : {0.25e-3, 0.5e-3, 1.0e-3}) {
    ElasticSearchSpec spec;
    spec.sample_step = step;
    const ElasticContactSearch s(p, spec);
    std::printf("sample step %.2f mm:\n", step * 1e3);
    for (double y : {0.0, 3e-3, 4.9e-3, 8e-3}) {
      ElasticPose pose{-y, 0.46, 0.0, -0.01};
      const WheelLoadSolution load = solveWheelLoad(s, pose, nspec, 1e4, WheelLoad::Vertical);
      pose.z = load.z;
      ElasticSearchWorkspace ws;
      ElasticWheelGeometry g;
      ElasticWheelContact c;
      const int n = 4000;
      // A small oscillation of y so that the calls are not identical.
      auto poseAt = [&](int i) {
        ElasticPose q = pose;
        q.y += 1e-6 * std::sin(0.01 * i);
        return q;
      };
      const double t_search = nsPerCall(
          [&](int i) {
            s.search(poseAt(i), g, ws);
            g_sink = g_sink + g.patch[0].gap_depth;
          },
          n);
      const double t_full = nsPerCall(
          [&](int i) {
            elasticWheelContact(s, poseAt(i), nspec, c, ws);
            g_sink = g_sink + c.force_z;
          },
          n);
      // As the dynamic method calls it: one workspace per wheel, successive poses a few nm (nrad)
      // apart (the steps between model evaluations of the case-2 run are 1e-12 to 4e-9 m), a
      // fresh workspace first.
      auto walkAt = [&](int i) {
        ElasticPose q = pose;
        q.y += 2e-9 * std::sin(0.37 * i);
        q.z += 1e-9 * std::cos(0.23 * i);
        q.phi += 1e-9 * std::sin(0.11 * i);
        q.psi += 1e-9 * std::cos(0.07 * i);
        return q;
      };
      ElasticSearchWorkspace ws_seq;
      const double t_seq = nsPerCall(
          [&](int i) {
            s.search(walkAt(i), g, ws_seq);
            g_sink = g_sink + g.patch[0].gap_depth;
          },
          n);
      std::printf(
          "  y = %4.1f mm (%d patch%s, %zu candidate minima, %d refinement iterations): "
          "search %6.0f ns, search + Hertz %6.0f ns, search in a walk of nm steps %6.0f ns\n",
          y * 1e3, c.geometry.count, c.geometry.count == 1 ? "" : "es", ws.minima.size(),
          c.geometry.newton_iterations, t_search, t_full, t_seq);
    }
  }
  // Parts, at the flange contact (y = 8 mm) and on the tread (y = 3 mm), default spec.
  const ElasticContactSearch s(p);
  for (double y : {3e-3, 8e-3}) {
    ElasticPose pose{-y, 0.46, 0.0, -0.01};
    pose.z = solveWheelLoad(s, pose, nspec, 1e4, WheelLoad::Vertical).z;
    const ElasticWheelGeometry g = s.search(pose);
    const double sw = g.patch[0].s_w, sr = g.patch[0].s_r;
    const int n = 20000;
    ElasticSearchSpec nospan;
    nospan.curvature_span = 0.0;
    const ElasticContactSearch s0(p, nospan);
    const double t_desc =
        nsPerCall([&](int) { g_sink = g_sink + s.describe(pose, sw, sr).B_span; }, n);
    const double t_desc0 =
        nsPerCall([&](int) { g_sink = g_sink + s0.describe(pose, sw, sr).B; }, n);
    const double t_ref = nsPerCall(
        [&](int i) {
          double a = sw + 1e-4 * std::sin(0.01 * i), b = sr;
          g_sink = g_sink + s.refine(pose, a, b);
        },
        n);
    const double t_hz =
        nsPerCall([&](int) { g_sink = g_sink + elasticNormal(g.patch[0], nspec).N; }, n);
    std::printf(
        "parts at y = %.0f mm: refine from 0.1 mm away %5.0f ns, describe (with B_span) "
        "%5.0f ns, describe (pointwise B) %5.0f ns, Hertz (shape solve) %5.0f ns\n",
        y * 1e3, t_ref, t_desc, t_desc0, t_hz);
  }
  return 0;
}
