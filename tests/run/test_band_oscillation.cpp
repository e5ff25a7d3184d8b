// The watch for the KEC band's own oscillation (run/band_oscillation.hpp): the monitor on
// synthetic lateral forces, and the trial curve on smooth track, where the KEC's flanging wheel
// oscillates by itself at about 30 Hz and the LUT's does not (docs/three_way.md).
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
  // A 30 Hz sine of 8 kN amplitude: its part above the 15 Hz low-pass is 0.89 of it (|1 - H| with
  // H = 1 / (1 + 2i)), rms 5.1 kN.
  EXPECT_NEAR(b.rms, 8e3 * 0.894 / std::sqrt(2.0), 0.05 * 8e3);
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
// wheel is in its band and its Y oscillates by itself (docs/three_way.md: 29.6 Hz, 8 kN); the run
// says so in its warnings. The LUT on the same track is quiet.
TEST(BandOscillation, TheTrialCurveOnSmoothTrackWarnsForTheKecOnly) {
  const char* scene = "scenarios/three_way/r300_cant100.lua";
  const std::vector<std::string> sets = {"run.effects.irregularities=false", "run.duration=7"};
  const rb::test::RunFile kec =
      rb::test::runInto(rb::test::compiled(scene, sets), "rb_test_band", "kec.h5");
  ASSERT_TRUE(kec.result.result.ok) << kec.result.result.message;
  std::string found;
  for (const auto& w : kec.result.warnings)
    if (w.find("band oscillates") != std::string::npos) found += w + "\n";
  std::printf("%s", found.c_str());
  EXPECT_NE(found.find("ws1 right wheel"), std::string::npos) << found;
  std::vector<std::string> lut_sets = sets;
  lut_sets.push_back("contact.method=lut");
  const rb::test::RunFile lut =
      rb::test::runInto(rb::test::compiled(scene, lut_sets), "rb_test_band", "lut.h5");
  ASSERT_TRUE(lut.result.result.ok) << lut.result.result.message;
  for (const auto& w : lut.result.warnings) EXPECT_EQ(w.find("band oscillates"), std::string::npos);
}

}  // namespace
