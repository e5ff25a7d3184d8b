// Measured irregularities from CSV (header, units, plausibility, coverage of the track) and the
// work and memory bounds of the track: every problem is a file:line input error at check, never a
// failure while building or solving.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "track_test_util.hpp"
#include "workbench/track/irregularities.hpp"
#include "workbench/track/track.hpp"

namespace {

using namespace rb::track;

// Diagnostics of parsing `text` as "m.csv", one "file:line: message" per entry.
std::vector<std::string> csvErrors(const std::string& text, CsvUnit unit = CsvUnit::Metre,
                                   double max_rows = kDefaultMaxPoints) {
  rb::Diagnostics d;
  CsvReadOptions o;
  o.unit = unit;
  o.max_rows = max_rows;
  const auto t = parseMeasuredCsv(text, "m.csv", o, d);
  std::vector<std::string> out;
  for (const auto& x : d.items()) out.push_back(x.str());
  EXPECT_EQ(t.has_value(), out.empty());
  return out;
}

MeasuredTable csvOk(const std::string& text, CsvUnit unit = CsvUnit::Metre) {
  rb::Diagnostics d;
  CsvReadOptions o;
  o.unit = unit;
  auto t = parseMeasuredCsv(text, "m.csv", o, d);
  EXPECT_TRUE(d.empty()) << (d.empty() ? "" : d.items()[0].str());
  return t ? *t : MeasuredTable{};
}

std::vector<std::string> errorsOf(const TrackSpec& spec) {
  std::vector<std::string> out;
  try {
    (void)compileTrack(spec);
  } catch (const rb::InputError& e) {
    for (const auto& d : e.diagnostics()) out.push_back(d.str());
  }
  return out;
}

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TrackSpec straight(double length) {
  TrackSpec t;
  t.segments = {rbtest::tangent(length)};
  t.step = 0.5;
  t.loc = {"t.lua", 1};
  t.irregularities.loc = {"t.lua", 3};
  return t;
}

TrackSpec withCsv(double length, const std::string& path) {
  TrackSpec t = straight(length);
  t.irregularities.source = IrregularitySource::Csv;
  t.irregularities.csv_path = path;
  return t;
}

// ---- Header ------------------------------------------------------------------------------------

TEST(MeasuredCsv, HeaderNamesColumnsInAnyOrderAndSubset) {
  const MeasuredTable m = csvOk(
      "# exported by a track recording car\n"
      "Cross_Level; s; vertical\n"
      "1e-3; 0; -2e-3\n"
      "2e-3; 1; -3e-3\n");
  EXPECT_EQ(m.first_line, 3);
  EXPECT_EQ(m.last_line, 4);
  EXPECT_EQ(m.present, (std::array<bool, 4>{false, true, false, true}));
  EXPECT_EQ(m.table.s, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(m.table.channel[3], (std::vector<double>{1e-3, 2e-3}));
  EXPECT_EQ(m.table.channel[1], (std::vector<double>{-2e-3, -3e-3}));
  EXPECT_EQ(m.table.channel[0], (std::vector<double>{0.0, 0.0}));  // not named: zero
  EXPECT_EQ(m.table.channel[2], (std::vector<double>{0.0, 0.0}));
}

TEST(MeasuredCsv, HeaderIsRequired) {
  EXPECT_EQ(csvErrors("\n0,0,0,0,0\n1,0,0,0,0\n"),
            (std::vector<std::string>{
                "m.csv:2: irregularity csv: the first line must be a header naming the columns, "
                "e.g. 's, alignment, vertical, gauge, cross_level' (any order; a channel that is "
                "not named is zero)"}));
  EXPECT_EQ(csvErrors("# nothing\n"),
            (std::vector<std::string>{
                "m.csv: irregularity csv: the file is empty: it needs a header naming the columns "
                "(s, alignment, vertical, gauge, cross_level) and at least 2 rows"}));
}

TEST(MeasuredCsv, HeaderErrorsWithHints) {
  EXPECT_EQ(csvErrors("s, alignmnet, vertical, vertical, , crosslevel\n0,0,0,0,0,0\n"),
            (std::vector<std::string>{
                "m.csv:1: irregularity csv: unknown column 'alignmnet' (did you mean "
                "'alignment'?); columns: s, alignment, vertical, gauge, cross_level",
                "m.csv:1: irregularity csv: column 'vertical' is named twice",
                "m.csv:1: irregularity csv: column 5 has no name (columns: s, alignment, "
                "vertical, gauge, cross_level)",
                "m.csv:1: irregularity csv: unknown column 'crosslevel' (did you mean "
                "'cross_level'?); columns: s, alignment, vertical, gauge, cross_level"}));
  EXPECT_EQ(csvErrors("alignment, gauge\n0,0\n1,0\n"),
            (std::vector<std::string>{
                "m.csv:1: irregularity csv: the header names no column 's' (arc length [m])"}));
  EXPECT_EQ(csvErrors("s\n0\n1\n"),
            (std::vector<std::string>{"m.csv:1: irregularity csv: the header names no "
                                      "irregularity column (alignment, vertical, gauge, "
                                      "cross_level)"}));
}

// ---- Units -------------------------------------------------------------------------------------

TEST(MeasuredCsv, MillimetresDeclaredInTheBlockOrTheHeader) {
  const std::string mm = "s, alignment, gauge\n0, 1.5, -2\n0.5, 3, 4\n";
  const MeasuredTable m = csvOk(mm, CsvUnit::Millimetre);
  EXPECT_DOUBLE_EQ(m.table.channel[0][0], 1.5e-3);
  EXPECT_DOUBLE_EQ(m.table.channel[2][1], 4e-3);
  EXPECT_DOUBLE_EQ(m.table.s[1], 0.5);  // s stays in metres
  // A unit in the header must agree with the declared one (it documents the file).
  const MeasuredTable h =
      csvOk("s [m]\talignment [mm]\tgauge[mm]\n0 1.5 -2\n0.5 3 4\n", CsvUnit::Millimetre);
  EXPECT_EQ(h.table.channel[0], m.table.channel[0]);
  EXPECT_EQ(csvErrors("s, alignment [mm]\n0, 1\n1, 2\n"),
            (std::vector<std::string>{
                "m.csv:1: irregularity csv: column 'alignment' is in mm by its header, but the "
                "declared unit is m (measured { unit = \"mm\" } to read the file in mm)"}));
  EXPECT_EQ(csvErrors("s [mm], alignment [in], vertical [mm\n0,0,0\n"),
            (std::vector<std::string>{
                "m.csv:1: irregularity csv: column 's' is the arc length in metres, got unit 'mm'",
                "m.csv:1: irregularity csv: column 'alignment': unit 'in' is not m or mm",
                "m.csv:1: irregularity csv: column 3 'vertical [mm': write a unit as name "
                "[unit], e.g. 'alignment [mm]'"}));
}

// A file in millimetres read as metres: one clear error per column at check (it used to pass
// and fail later inside the KEC Newton solve).
TEST(MeasuredCsv, MillimetresReadAsMetresAreRefused) {
  std::string text = "s, alignment, vertical\n";
  for (int i = 0; i <= 10; ++i) {
    text += std::to_string(i) + ", " + std::to_string(0.05 * i) + ", " +
            std::to_string(2.0 + 0.1 * i) + "\n";
  }
  EXPECT_EQ(csvErrors(text),
            (std::vector<std::string>{
                "m.csv:5: irregularity csv: alignment = 0.15 m is larger than a track "
                "irregularity can be (0.1 m) here and on 7 more rows; is the file in "
                "millimetres? Declare it: measured { unit = \"mm\" }",
                "m.csv:2: irregularity csv: vertical = 2 m is larger than a track irregularity "
                "can be (0.1 m) here and on 10 more rows; is the file in millimetres? Declare "
                "it: measured { unit = \"mm\" }"}));
  EXPECT_TRUE(csvErrors(text, CsvUnit::Millimetre).empty());
  EXPECT_EQ(csvErrors("s, gauge\n0, 0\n1, 250\n", CsvUnit::Millimetre),
            (std::vector<std::string>{"m.csv:3: irregularity csv: gauge = 250 mm (0.25 m) is "
                                      "larger than a track irregularity can be (0.1 m)"}));
}

// ---- Rows --------------------------------------------------------------------------------------

TEST(MeasuredCsv, RowChecks) {
  EXPECT_EQ(csvErrors("s, alignment\n"
                      "0, 0\n"       // 2
                      "1, nan\n"     // 3
                      "2, inf\n"     // 4
                      "1e308, 0\n"   // 5
                      "-1, 0\n"      // 6
                      "3, 0, 0\n"    // 7
                      "3\n"          // 8
                      "-inf, 0\n"),  // 9
            (std::vector<std::string>{
                "m.csv:3: irregularity csv: column 2 (alignment) is not a finite number: 'nan'",
                "m.csv:4: irregularity csv: column 2 (alignment) is not a finite number: 'inf'",
                "m.csv:5: irregularity csv: s = 1e+308 m is beyond the longest track (1e+07 m)",
                "m.csv:6: irregularity csv: s = -1 m must be greater than the previous s = 0 m",
                "m.csv:7: irregularity csv: expected 2 columns (s, alignment), got 3",
                "m.csv:8: irregularity csv: expected 2 columns (s, alignment), got 1",
                "m.csv:9: irregularity csv: column 1 (s) is not a finite number: '-inf'"}));
  EXPECT_EQ(csvErrors("s, alignment\n0, 0\n"),
            (std::vector<std::string>{
                "m.csv:2: irregularity csv: at least 2 data rows are required, got 1"}));
  EXPECT_EQ(csvErrors("s, alignment\n0, 0\n1, 0\n2, 0\n", CsvUnit::Metre, 2.0),
            (std::vector<std::string>{"m.csv:4: irregularity csv: more than 2 data rows "
                                      "(track.max_points); raise track.max_points to read it"}));
}

// ---- Coverage of the track ---------------------------------------------------------------------

TEST(MeasuredCsv, FileShorterThanTheTrackIsAnErrorByDefault) {
  const std::string p = writeFile("rb_measured_short.csv", "s, vertical\n0, 0\n50, 1e-3\n100, 0\n");
  TrackSpec t = withCsv(300.0, p);
  EXPECT_EQ(errorsOf(t),
            (std::vector<std::string>{
                "t.lua:3: track.irregularities: the track is 300 m long but " + p +
                " ends at s = 100 m (line 4); give a file that covers the track, or beyond = "
                "\"zero\" for a perfect track beyond the file"}));
  const std::string late = writeFile("rb_measured_late.csv", "s, vertical\n5, 0\n400, 0\n");
  EXPECT_EQ(errorsOf(withCsv(300.0, late)),
            (std::vector<std::string>{
                "t.lua:3: track.irregularities: " + late +
                " starts at s = 5 m (line 2), after the track start s = 0 m; give rows from s = "
                "0, or beyond = \"zero\" for a perfect track where the file does not reach"}));
  // beyond = "zero": the run may go on, with a warning, and the track is perfect beyond.
  t.irregularities.beyond = Beyond::Zero;
  const TrackModel m = compileTrack(t);
  ASSERT_EQ(m.warnings().size(), 1u);
  EXPECT_EQ(m.warnings()[0].str(),
            "t.lua:3: track.irregularities: " + p +
                " covers s = 0 .. 100 m of the 300 m track; the track is perfect (zero "
                "irregularities) beyond it (beyond = \"zero\")");
  EXPECT_NEAR(m.irregularities()->at(50.0).xi[1], 1e-3, 1e-15);
  EXPECT_EQ(m.irregularities()->at(150.0).xi[1], 0.0);
  // A file that covers the track (here a little beyond both ends): no warning.
  const std::string full = writeFile("rb_measured_full.csv", "s, vertical\n-1, 0\n301, 0\n");
  EXPECT_TRUE(compileTrack(withCsv(300.0, full)).warnings().empty());
}

TEST(MeasuredCsv, UnusableFilesAreInputErrors) {
  TrackSpec t = withCsv(10.0, ::testing::TempDir());
  const auto e = errorsOf(t);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].rfind("t.lua:3: track.irregularities: csv file '", 0), 0u) << e[0];
  EXPECT_NE(e[0].find("not a regular file (a folder)"), std::string::npos) << e[0];
}

// ---- Work and memory bounds --------------------------------------------------------------------

// Each of these used to run for minutes, exhaust memory (bad_alloc, exit 3) or fail an internal
// spline check; now check refuses them at once with the limit and how to raise it.
TEST(TrackLimits, TooFineCentrelineStepIsRefusedAtCheck) {
  TrackSpec t = straight(500.0);
  t.step = 1e-7;
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(errorsOf(t), (std::vector<std::string>{
                             "t.lua:1: track: 500 m at step 1e-07 m needs 5e+09 spline knots, "
                             "more than track.max_points = 1e+06 (about 0.4 kB each); use a "
                             "coarser step, or raise track.max_points"}));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
  t.step = 1e-3;  // 5e5 knots: within the default
  t.max_points = 1e5;
  EXPECT_EQ(errorsOf(t).size(), 1u);
  rb::Diagnostics d;
  t.max_points = 1e6;
  validateTrack(t, d);
  EXPECT_TRUE(d.empty());
}

TEST(TrackLimits, TooFinePsdStepOrTooManyTermsIsRefusedAtCheck) {
  TrackSpec t = straight(500.0);
  IrregularitySpec& ir = t.irregularities;
  ir.source = IrregularitySource::Psd;
  ir.spectrum = "ore_b176_low";
  ir.step = 1e-6;
  ir.wavelength_min = 3.0;
  EXPECT_EQ(errorsOf(t), (std::vector<std::string>{
                             "t.lua:3: track.irregularities: 500 m at step 1e-06 m needs 5e+08 "
                             "spline knots, more than track.max_points = 1e+06; use a coarser "
                             "step, or raise track.max_points"}));
  ir.step = 1e-3;  // 5e5 knots, 5e5 x 100000 x 4 = 2e11 terms
  ir.components = 100000;
  EXPECT_EQ(errorsOf(t), (std::vector<std::string>{
                             "t.lua:3: track.irregularities: the synthesis needs 5e+05 knots x "
                             "100000 components x 4 channels = 2e+11 cosine terms, more than "
                             "track.max_points x 8000 = 8e+09; use fewer components or a coarser "
                             "step, or raise track.max_points"}));
  // Raising the limit is the documented way out (validated only here: building would take long).
  t.max_points = 1e8;
  rb::Diagnostics d;
  validateTrack(t, d);
  EXPECT_TRUE(d.empty()) << (d.empty() ? "" : d.items()[0].str());
}

TEST(TrackLimits, AstronomicalSegmentsAreInputErrors) {
  TrackSpec t = straight(1e308);
  t.segments.push_back(rbtest::tangent(9e6, 11));
  t.segments.push_back(rbtest::tangent(9e6, 12));
  EXPECT_EQ(errorsOf(t),
            (std::vector<std::string>{
                "t.lua:10: track.segments[1] (tangent): length must be <= 1e+07 m (longer than "
                "any railway line), got 1e+308"}));
  t.segments.erase(t.segments.begin());
  EXPECT_EQ(errorsOf(t), (std::vector<std::string>{
                             "t.lua:1: track: the segments add up to 1.8e+07 m, more than the "
                             "longest track (1e+07 m)"}));
}

// A user PSD off by hundreds of orders of magnitude gave 4.6e150 m irregularities and an "ok"
// run; now the synthesised RMS is bounded at check.
TEST(TrackLimits, AbsurdPsdAmplitudesAreInputErrors) {
  TrackSpec t = straight(200.0);
  IrregularitySpec& ir = t.irregularities;
  ir.source = IrregularitySource::Psd;
  ir.spectrum = "user";
  ir.user[0] = PsdTable{{0.01, 10.0}, {1e300, 1e300}};
  ir.user[3] = PsdTable{{0.01, 10.0}, {1.7e308, 1.7e308}};
  const auto e = errorsOf(t);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].rfind("t.lua:3: track.irregularities: alignment: the synthesised irregularity "
                       "has an RMS of 1.",
                       0),
            0u)
      << e[0];
  EXPECT_NE(e[0].find("e+150 m, more than a track irregularity can be (0.1 m); check the PSD "
                      "(one-sided, in m^2/(rad/m)) and scale"),
            std::string::npos)
      << e[0];
  EXPECT_EQ(e[1],
            "t.lua:3: track.irregularities: cross_level: the synthesised irregularity has "
            "an RMS of inf m, more than a track irregularity can be (0.1 m); check the PSD "
            "(one-sided, in m^2/(rad/m)) and scale");
  // Every named spectrum at its defaults (and ORE high scaled up 3x) is plausible.
  for (const char* name : {"ore_b176_low", "ore_b176_high", "fra_class_1", "fra_class_2",
                           "fra_class_3", "fra_class_4", "fra_class_5", "fra_class_6"}) {
    IrregularitySpec named;
    named.source = IrregularitySource::Psd;
    named.spectrum = name;
    named.loc = ir.loc;
    named.scale = std::string(name) == "ore_b176_high" ? 3.0 : 1.0;
    t.irregularities = named;
    rb::Diagnostics d;
    validateTrack(t, d);
    EXPECT_TRUE(d.empty()) << name << ": " << (d.empty() ? "" : d.items()[0].str());
  }
}

}  // namespace
