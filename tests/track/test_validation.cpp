// compileTrack() input validation: one test per rule, asserting the exact "file:line: message".
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "track_test_util.hpp"
#include "workbench/track/track.hpp"

namespace {

using namespace rb::track;
const rb::SourceLoc kLoc{"t.lua", 7};

std::vector<std::string> errorsOf(const TrackSpec& spec) {
  try {
    (void)compileTrack(spec);
  } catch (const rb::InputError& e) {
    std::vector<std::string> out;
    for (const auto& d : e.diagnostics()) out.push_back(d.str());
    return out;
  }
  return {};
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

void expectErrors(const TrackSpec& spec, const std::vector<std::string>& expected) {
  const auto got = errorsOf(spec);
  EXPECT_EQ(got, expected) << "got:\n" << joined(got);
}

TrackSpec base() {
  return rbtest::paperCase1(300.0, 0.1);
}

TEST(Validation, ValidSpecPassesAndValidateTrackCollects) {
  EXPECT_TRUE(errorsOf(base()).empty());
  rb::Diagnostics d;
  TrackSpec s = base();
  s.step = 0.0;
  validateTrack(s, d);
  EXPECT_EQ(d.size(), 1u);
}

TEST(Validation, AtLeastOneSegment) {
  TrackSpec s = base();
  s.segments.clear();
  s.loc = kLoc;
  expectErrors(s, {"t.lua:7: track.segments: at least one segment is required"});
}

TEST(Validation, LengthPositive) {
  TrackSpec s = base();
  s.segments[0].length = 0.0;
  s.segments[0].loc = kLoc;
  expectErrors(s, {"t.lua:7: track.segments[1] (tangent): length must be > 0 m, got 0"});
  s.segments[0].length = -2.5;
  expectErrors(s, {"t.lua:7: track.segments[1] (tangent): length must be > 0 m, got -2.5"});
}

TEST(Validation, CurveRadiusRequiredAndAtLeast10m) {
  TrackSpec s = base();
  s.segments[2].loc = kLoc;
  s.segments[2].radius = -500.0;
  expectErrors(s, {"t.lua:7: track.segments[3] (curve): radius must be > 0 m, got -500"});
  s.segments[2].radius = 0.0;  // missing
  expectErrors(s, {"t.lua:7: track.segments[3] (curve): radius must be > 0 m, got 0"});
  s.segments[2].radius = 5.0;
  expectErrors(s, {"t.lua:7: track.segments[3] (curve): radius must be >= 10 m (tighter curves "
                   "are not railway track), got 5"});
}

TEST(Validation, TransitionEndRadius) {
  TrackSpec s = base();
  s.segments[1].loc = kLoc;
  s.segments[1].radius = 8.0;
  expectErrors(s, {"t.lua:7: track.segments[2] (transition): radius must be 0 (ends straight) or "
                   ">= 10 m, got 8"});
  s.segments[1].radius = -3.0;
  expectErrors(s, {"t.lua:7: track.segments[2] (transition): radius must be 0 (ends straight) or "
                   ">= 10 m, got -3"});
}

TEST(Validation, TangentHasNoRadiusOrCant) {
  TrackSpec s = base();
  s.segments[0].loc = kLoc;
  s.segments[0].radius = 100.0;
  s.segments[0].cant = 0.05;
  expectErrors(s, {"t.lua:7: track.segments[1] (tangent): radius must be 0 on a tangent, got 100",
                   "t.lua:7: track.segments[1] (tangent): cant must be 0 on a tangent (ramp cant "
                   "in a transition), got 0.05"});
}

TEST(Validation, CantLimitScalesWithBase) {
  TrackSpec s = base();
  s.segments[1].cant = s.segments[2].cant = 0.25;
  s.segments[2].loc = kLoc;
  expectErrors(s, {"t.lua:11: track.segments[2] (transition): |cant| must be <= 0.2 m (0.2 m per "
                   "1.5 m of cant_base), got 0.25",
                   "t.lua:7: track.segments[3] (curve): |cant| must be <= 0.2 m (0.2 m per 1.5 m "
                   "of cant_base), got 0.25"});
  s.segments[1].cant = s.segments[2].cant = -0.195;
  s.cant_base = 1.435;
  expectErrors(s, {"t.lua:11: track.segments[2] (transition): |cant| must be <= 0.1913 m (0.2 m "
                   "per 1.5 m of cant_base), got -0.195",
                   "t.lua:7: track.segments[3] (curve): |cant| must be <= 0.1913 m (0.2 m per 1.5 "
                   "m of cant_base), got -0.195"});
}

TEST(Validation, GradientLimit) {
  TrackSpec s = base();
  s.segments[0].loc = kLoc;
  s.segments[0].gradient = 0.15;
  s.segments[1].gradient = 0.05;
  s.segments[2].gradient = 0.05;
  expectErrors(s, {"t.lua:7: track.segments[1] (tangent): |gradient| must be <= 0.1, got 0.15"});
}

TEST(Validation, TrackStep) {
  TrackSpec s = base();
  s.loc = kLoc;
  s.step = 0.0;
  expectErrors(s, {"t.lua:7: track.step must be > 0 m, got 0"});
  s.step = 45.0;
  expectErrors(s, {"t.lua:7: track.step must be <= the shortest segment length (30 m, "
                   "track.segments[1]), got 45"});
}

TEST(Validation, TrackLevelDimensions) {
  TrackSpec s = base();
  s.loc = kLoc;
  s.cant_base = 0.0;
  s.gauge = -1.0;
  s.rail_lr = 0.0;
  s.rail_inclination = 0.2;
  expectErrors(s, {"t.lua:7: track.cant_base must be > 0 m, got 0",
                   "t.lua:7: track.gauge must be > 0 m, got -1",
                   "t.lua:7: track.rail_lr must be > 0 m, got 0",
                   "t.lua:7: track.rail_inclination must be in [0, 0.1] rad, got 0.2"});
}

TEST(Validation, CantAndGradientChangeOnlyInTransitions) {
  TrackSpec s = base();
  s.segments[1].cant = 0.05;
  s.segments[2].loc = kLoc;
  expectErrors(s, {"t.lua:7: track.segments[3] (curve): cant jumps from 0.05 m to 0.1 m at the "
                   "segment start (signed, positive = banked left); change cant in a transition"});
  s = base();
  s.segments[2].gradient = 0.01;
  s.segments[2].loc = kLoc;
  expectErrors(s, {"t.lua:7: track.segments[3] (curve): gradient jumps from 0 to 0.01 at the "
                   "segment start; change gradient in a transition"});
  // A tangent after a canted curve.
  s = base();
  s.segments.push_back(rbtest::tangent(10.0, 7));
  s.segments.back().loc = kLoc;
  const auto got = errorsOf(s);
  ASSERT_FALSE(got.empty());
  EXPECT_EQ(got.back(),
            "t.lua:7: track.segments[4] (tangent): cant jumps from 0.1 m to 0 m at "
            "the segment start (signed, positive = banked left); change cant in a "
            "transition");
}

TEST(Validation, SegmentAfterTransitionContinuesItsCurvature) {
  TrackSpec s = base();
  s.segments[2].loc = kLoc;
  s.segments[2].radius = 500.0;
  expectErrors(s, {"t.lua:7: track.segments[3] (curve): curvature jumps from 0.003333 1/m to "
                   "0.002 1/m at the segment start (positive = left); the preceding transition "
                   "must end at this radius and side"});
  s = rbtest::paperCase1(300.0);
  s.segments[2].side = Side::Right;
  s.segments[2].loc = kLoc;
  expectErrors(s, {"t.lua:7: track.segments[3] (curve): curvature jumps from 0.003333 1/m to "
                   "-0.003333 1/m at the segment start (positive = left); the preceding "
                   "transition must end at this radius and side"});
  s = rbtest::paperCase1(300.0);
  s.segments[2] = rbtest::tangent(40.0, 7);
  expectErrors(s, {"t.lua:7: track.segments[3] (tangent): curvature jumps from 0.003333 1/m to 0 "
                   "1/m at the segment start (positive = left); the preceding transition must end "
                   "straight (radius 0)"});
  // A curve directly after a tangent is allowed (no transition).
  s = rbtest::paperCase1(300.0);
  s.segments.erase(s.segments.begin() + 1);
  EXPECT_TRUE(errorsOf(s).empty());
}

// ---- Irregularities -------------------------------------------------------------------------

TrackSpec withPsd() {
  TrackSpec s = base();
  s.irregularities.source = IrregularitySource::Psd;
  s.irregularities.spectrum = "ore_b176_low";
  s.irregularities.loc = kLoc;
  return s;
}

TEST(Validation, IrregularitySpectrumKnown) {
  TrackSpec s = withPsd();
  s.irregularities.spectrum = "ore_b176_medium";
  expectErrors(s, {"t.lua:7: track.irregularities: unknown spectrum 'ore_b176_medium' (valid: "
                   "ore_b176_low, ore_b176_high, fra_class_1, fra_class_2, fra_class_3, "
                   "fra_class_4, fra_class_5, fra_class_6, user)"});
}

TEST(Validation, IrregularityBand) {
  TrackSpec s = withPsd();
  s.irregularities.wavelength_min = 0.0;
  expectErrors(s, {"t.lua:7: track.irregularities: wavelength_min must be > 0 m, got 0"});
  s.irregularities.wavelength_min = 80.0;
  expectErrors(s, {"t.lua:7: track.irregularities: wavelength_min (80 m) must be < "
                   "wavelength_max (70 m)"});
}

TEST(Validation, IrregularityNyquist) {
  TrackSpec s = withPsd();
  s.irregularities.step = 2.0;
  expectErrors(s, {"t.lua:7: track.irregularities: wavelength_min (3 m) must be >= 2 * step (4 m) "
                   "to be resolved (Nyquist)"});
}

TEST(Validation, IrregularityStepComponentsScale) {
  TrackSpec s = withPsd();
  s.irregularities.step = 0.0;
  s.irregularities.components = 0;
  s.irregularities.scale = -1.0;
  expectErrors(s, {"t.lua:7: track.irregularities: step must be > 0 m, got 0",
                   "t.lua:7: track.irregularities: components must be in [1, 100000], got 0",
                   "t.lua:7: track.irregularities: scale must be >= 0, got -1"});
}

TEST(Validation, UserPsdTables) {
  TrackSpec s = withPsd();
  s.irregularities.spectrum = "user";
  auto& u = s.irregularities.user;
  u[0] = PsdTable{{0.1, 1.0, 2.0}, {1e-6, 1e-7}};
  u[1] = PsdTable{{0.1}, {1e-6}};
  u[2] = PsdTable{{0.0, 1.0}, {1e-6, 1e-7}};
  u[3] = PsdTable{{0.1, 1.0, 0.5}, {1e-6, 1e-7, 1e-8}};
  expectErrors(s, {"t.lua:7: track.irregularities: user.alignment: omega has 3 points but value "
                   "has 2",
                   "t.lua:7: track.irregularities: user.vertical: at least 2 points are "
                   "required, got 1",
                   "t.lua:7: track.irregularities: user.gauge: omega[1] must be > 0 rad/m, got 0",
                   "t.lua:7: track.irregularities: user.cross_level: omega must be strictly "
                   "increasing, omega[3] = 0.5 after 1"});
  u[0] = PsdTable{{0.1, 1.0}, {1e-6, -1e-6}};
  u[1] = u[2] = u[3] = PsdTable{};
  expectErrors(s, {"t.lua:7: track.irregularities: user.alignment: value[2] must be >= 0 "
                   "m^2/(rad/m), got -1e-06"});
  u[0] = PsdTable{{0.1, 1.0, 10.0}, {1e-6, 1e-7, 0.0}};
  EXPECT_TRUE(errorsOf(s).empty());
}

TEST(Validation, CsvPathRequiredAndReadable) {
  TrackSpec s = base();
  s.irregularities.source = IrregularitySource::Csv;
  s.irregularities.loc = kLoc;
  expectErrors(s, {"t.lua:7: track.irregularities: csv_path is required for a csv source"});
  s.irregularities.csv_path = "/nonexistent/dir/irr.csv";
  expectErrors(s, {"t.lua:7: track.irregularities: csv file '/nonexistent/dir/irr.csv': no such "
                   "file"});
}

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(Validation, CsvContents) {
  const std::string p = writeFile("rb_bad_irr.csv",
                                  "s,alignment,vertical,gauge,cross_level\n"  // 1 header: ok
                                  "0,0,0,0,0\n"                               // 2
                                  "1,0,0,0\n"                                 // 3
                                  "2,0,abc,0,0\n"                             // 4
                                  "\n"                                        // 5
                                  "0,0,0,0,0   # comment\n"                   // 6
                                  "x,y,z,w,v\n");                             // 7 no 2nd header
  TrackSpec s = base();
  s.irregularities.source = IrregularitySource::Csv;
  s.irregularities.csv_path = p;
  expectErrors(s, {p + ":3: irregularity csv: expected 5 columns (s, alignment, vertical, gauge, "
                       "cross_level), got 4",
                   p + ":4: irregularity csv: column 3 (vertical) is not a finite number: 'abc'",
                   p + ":6: irregularity csv: s = 0 m must be greater than the previous s = 0 m",
                   p + ":7: irregularity csv: column 1 (s) is not a finite number: 'x'"});
  const std::string q = writeFile("rb_short_irr.csv", "# one row\ns; alignment\n0; 0\n");
  s.irregularities.csv_path = q;
  expectErrors(s, {q + ":3: irregularity csv: at least 2 data rows are required, got 1"});
  // White-space separated, any order, a subset of the channels: valid (the track is 120 m).
  s.irregularities.csv_path = writeFile("rb_ws_irr.csv", "vertical s\n0 0\n1e-3 60\n0 120\n");
  EXPECT_TRUE(errorsOf(s).empty());
}

TEST(Validation, AllProblemsCollectedInOrder) {
  TrackSpec s = base();
  s.segments[0].length = -1.0;
  s.segments[2].radius = 3.0;
  s.irregularities.source = IrregularitySource::Psd;
  s.irregularities.spectrum = "ore";
  try {
    (void)compileTrack(s);
    FAIL() << "expected InputError";
  } catch (const rb::InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "t.lua:10: track.segments[1] (tangent): length must be > 0 m, got -1\n"
              "t.lua:12: track.segments[3] (curve): radius must be >= 10 m (tighter curves are "
              "not railway track), got 3\n"
              "t.lua:20: track.irregularities: unknown spectrum 'ore' (valid: ore_b176_low, "
              "ore_b176_high, fra_class_1, fra_class_2, fra_class_3, fra_class_4, fra_class_5, "
              "fra_class_6, user)");
  }
}

}  // namespace
