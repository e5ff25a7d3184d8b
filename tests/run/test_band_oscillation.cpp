// The watch for the KEC band's own oscillation (run/band_oscillation.hpp): the monitor on
// synthetic lateral forces, and the trial curve on smooth track, where the KEC's flanging wheel
// oscillated by itself before the creep law saturated on sliding flange patches.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "run_files.hpp"
#include "workbench/run/band_oscillation.hpp"

namespace {

using rb::run::BandOscillation;
using rb::run::BandOscillationMonitor;

BandOscillation watch(double dt, double mean, double amplitude, double hz, bool in_band,
                      double t_end = 3.0) {
  BandOscillationMonitor m;
  for (double t = 0.0; t <= t_end + 1e-12; t += dt)
    m.add(t, mean + amplitude * std::sin(2.0 * std::numbers::pi * hz * t), in_band);
  return m.result();
}

TEST(BandOscillation, ASelfOscillationInTheBandIsFound) {
  const BandOscillation b = watch(0.002, 20e3, 8e3, 30.0, true);
  ASSERT_TRUE(b.watched);
  ASSERT_TRUE(b.found);
  EXPECT_NEAR(b.frequency, 30.0, 1.5);
  // A 30 Hz sine of 8 kN amplitude (rms 5.66 kN): its part above the 15 Hz first-order low-pass,
  // over windows that include the filter's start, is 0.75-0.9 of it.
  EXPECT_GT(b.rms, 0.75 * 8e3 / std::sqrt(2.0));
  EXPECT_LT(b.rms, 0.90 * 8e3 / std::sqrt(2.0));
  EXPECT_GE(b.windows, 5);
  EXPECT_GT(b.t_last, b.t_first);
  const std::string w = rb::run::bandOscillationWarning("ws1 right wheel", b);
  EXPECT_NE(w.find("ws1 right wheel: the KEC's tread/flange band oscillates"), std::string::npos)
      << w;
}

TEST(BandOscillation, OutsideTheBandSlowOrSmallIsNot) {
  EXPECT_FALSE(watch(0.002, 20e3, 8e3, 30.0, false).found);            // not in the band
  EXPECT_FALSE(watch(0.002, 20e3, 20e3, 3.0, true).found);             // the vehicle's own motion
  EXPECT_FALSE(watch(0.002, 20e3, 1.5e3, 30.0, true).found);           // below 3 kN rms
  const BandOscillation coarse = watch(0.020, 20e3, 8e3, 30.0, true);  // cannot be resolved
  EXPECT_FALSE(coarse.watched);
  EXPECT_FALSE(coarse.found);
  EXPECT_FALSE(watch(0.002, 20e3, 0.0, 30.0, true).found);  // constant
}

// The trial curve (R = 300 m, 100 mm cant, 20.9 m/s) on smooth track: the KEC's leading outer
// wheel runs in its band from about 4 s on. With Polach's own divisor s_C its Y oscillated there
// by itself (docs/three_way.md: about 30 Hz, 8 kN); with the creep law saturating on the sliding
// flange patch it does not: no warning, and Y above 15 Hz stays below 0.5 kN rms over the band.
TEST(BandOscillation, TheTrialCurveOnSmoothTrackIsQuietOnTheKec) {
  const char* scene = "scenarios/three_way/r300_cant100.lua";
  const rb::test::RunFile kec = rb::test::runInto(
      rb::test::compiled(scene, {"run.effects.irregularities=false", "run.duration=7"}),
      "rb_test_band", "kec.h5");
  ASSERT_TRUE(kec.result.result.ok) << kec.result.result.message;
  for (const auto& w : kec.result.warnings) EXPECT_EQ(w.find("band oscillates"), std::string::npos);
  const rb::io::ResultReader r(kec.path);
  const auto t = *r.dataset("/time");
  const auto y = *r.dataset("/contact/ws1/right/Y");
  const auto regime = *r.dataset("/contact/ws1/right/regime");
  BandOscillationMonitor m;
  double low = y.front(), sum = 0.0;
  int n = 0, in_band = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    m.add(t[i], y[i], regime[i] == 1.0);
    const double a = 1.0 - std::exp(-2.0 * std::numbers::pi * BandOscillationMonitor::kCutoff *
                                    (t[i] - t[i - 1]));
    low += a * (y[i] - low);
    if (t[i] < 5.0) continue;
    sum += (y[i] - low) * (y[i] - low);
    ++n;
    in_band += regime[i] == 1.0 ? 1 : 0;
  }
  ASSERT_GT(n, 100);
  const double rms = std::sqrt(sum / n);
  std::printf(
      "[ band     ] KEC ws1 right, t = 5..7 s: in the band %.0f %% of samples, Y above 15 Hz "
      "%.1f N rms\n",
      100.0 * in_band / n, rms);
  EXPECT_GT(in_band, 0.9 * n);
  EXPECT_LT(rms, 500.0);
  EXPECT_TRUE(m.result().watched);
  EXPECT_FALSE(m.result().found);
}

}  // namespace
