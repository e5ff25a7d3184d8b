// MiniProf profile files (.whl, .ban, .mpt) and the refusal of VAMPIRE files: the example files of
// the CONTACT test bank (tests/data/profiles_formats/, Apache-2.0, see its README) and malformed
// variants of them. The EN 15313 flange measures computed on a read wheel are compared with the
// values the measuring software wrote into the same file's header.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "test_util.hpp"
#include "workbench/core/error.hpp"
#include "workbench/profiles/dimensions.hpp"
#include "workbench/profiles/profile_io.hpp"

namespace {

using namespace rb::profiles;
using rb::profiles::test::projectFile;
using rb::profiles::test::referenceFile;

// [m] tape-circle radius: any plausible one; Sd, Sh and qR do not depend on it.
constexpr double kR0 = 0.46;

std::string formatFile(const std::string& name) {
  return referenceFile("profiles_formats/" + name);
}

// The first diagnostic of the input error `f` throws, as "file:line: message".
template <class F>
std::string firstError(F&& f) {
  try {
    f();
  } catch (const rb::InputError& e) {
    return e.diagnostics().front().str();
  }
  return "(no error)";
}

ProfilePoints parseWheel(const std::string& text) {
  return parseMiniprofPoints(text, "w.whl", ProfileKind::Wheel);
}

// A small keyword-format wheel: 20 points of a flanged profile (X from the flange back, Y up),
// with `extra` appended to the header.
std::string syntheticWheel(const std::string& extra = "", int points = 20) {
  std::string t =
      "ProgramName=test\nColumnDef=X,Y\nXYPoints=" + std::to_string(points) + "\n" + extra + "\n";
  for (int i = 0; i < points; ++i) {
    const double x = 5.0 + 6.0 * i;
    const double y = x < 30.0 ? 28.0 - 0.05 * (x - 15.0) * (x - 15.0) : -0.02 * (x - 70.0);
    t += std::to_string(x) + " " + std::to_string(y) + "\n";
  }
  return t;
}

// ---- Example files: the EN 15313 flange measures against the files' own headers --------------

struct WheelCase {
  const char* file;
  // The header's Sd, Sh, qR [mm] (as written in the file).
  double sd, sh, qr;
};

// Computed on the read profile (smoothing off, 0.02 mm grid) with the EN 15313 definitions of
// dimensions.hpp (Sd at 10 mm above the tape circle from the flange back at X = 0, Sh the flange
// tip above the tape circle, qR between the Sd point and the point 2 mm below the tip).
TEST(Miniprof, WheelHeaderMeasuresReproduced) {
  // left-wheel-v1-pre-dry.whl: measured by MiniProf for Windows 2.43.73 (its header); the
  // iteration file of a wear simulation writes the same keywords.
  for (const WheelCase& c : {WheelCase{"left-wheel-v1-pre-dry.whl", 36.1416, 27.8749, 9.0991},
                             WheelCase{"whl_left_iter288.whl", 36.4023, 28.3512, 5.4454}}) {
    SCOPED_TRACE(c.file);
    ProfileFileInfo info;
    ProfileReadOptions opt;
    opt.r0 = kR0;
    const Profile w =
        readProfileFile(formatFile(c.file), ProfileKind::Wheel, LengthUnit::Millimetre, opt, &info);
    EXPECT_EQ(info.format, "MiniProf");
    ASSERT_TRUE(info.hasHeaderDimensions);
    EXPECT_DOUBLE_EQ(info.headerSd, c.sd * 1e-3);
    EXPECT_DOUBLE_EQ(info.headerSh, c.sh * 1e-3);
    EXPECT_DOUBLE_EQ(info.headerQr, c.qr * 1e-3);
    const WheelDimensions d = wheelDimensions(w, 0.070, 0.0);
    std::printf("%s: Sd %.3f Sh %.3f qR %.3f mm (header %.3f %.3f %.3f)\n", c.file,
                d.flangeThickness * 1e3, d.flangeHeight * 1e3, d.qR * 1e3, c.sd, c.sh, c.qr);
    // The writing software measures on its own points (0.2 .. 0.4 mm apart) and interpolation;
    // ours agree with the headers to 0.04 mm (printed above).
    EXPECT_NEAR(d.flangeThickness * 1e3, c.sd, 0.05);
    EXPECT_NEAR(d.flangeHeight * 1e3, c.sh, 0.05);
    EXPECT_NEAR(d.qR * 1e3, c.qr, 0.05);
  }
}

TEST(Miniprof, OldLayoutsAndTheirHeaderLine) {
  // avg_wheel.whl: "MINIPROF 101 ..." first line, "32.58 37.11 14.71  (Sd/Sh/qR)" on line 7.
  // Car7422_0001r.whl: "#MINIWHEELPROF", the numbers on line 8 and "(Sd/Sh/qR)" on line 9.
  {
    const char* f = "avg_wheel.whl";
    ProfileFileInfo info;
    const ProfilePoints p = readMiniprofPoints(formatFile(f), ProfileKind::Wheel, &info);
    ASSERT_TRUE(info.hasHeaderDimensions);
    EXPECT_EQ(info.headerDimensionsLine, 7);
    EXPECT_DOUBLE_EQ(info.headerSd, 32.58e-3);
    EXPECT_DOUBLE_EQ(info.headerSh, 37.11e-3);
    EXPECT_DOUBLE_EQ(info.headerQr, 14.71e-3);
    ProfileReadOptions opt;
    opt.r0 = kR0;
    const WheelDimensions d = wheelDimensions(profileFromPoints(p, opt, f), 0.070, 0.0);
    std::printf("%s: Sd %.3f Sh %.3f qR %.3f mm (header 32.58 37.11 14.71)\n", f,
                d.flangeThickness * 1e3, d.flangeHeight * 1e3, d.qR * 1e3);
    // The points themselves put the flange tip 28 mm above the tape circle (avg_wheel: Y = 28.03
    // at X = 14.73 mm, Y = 0.00 at X = 70 mm), not the 37.11 mm of the header line, which these
    // files share word for word: the header line does not describe these points.
    EXPECT_GT(std::abs(d.flangeHeight * 1e3 - 37.11), 5.0);
    EXPECT_NEAR(d.flangeHeight * 1e3, 28.03, 0.05);
  }
  // Car7422_0001r.whl: its points fold back by 0.06 mm near the flange tip (X = 17.5295 then
  // 17.4664 mm, Y 27.1): refused at that point, the header line read before.
  const std::string car =
      firstError([&] { readMiniprofPoints(formatFile("Car7422_0001r.whl"), ProfileKind::Wheel); });
  EXPECT_NE(car.find("Car7422_0001r.whl:229: profile X values must advance: X = 17.4664 mm "
                     "follows X = 17.5295 mm"),
            std::string::npos)
      << car;
  // avg_wheel.whl's data begin after the empty line 8: the first point is line 9.
  const ProfilePoints p = readMiniprofPoints(formatFile("avg_wheel.whl"), ProfileKind::Wheel);
  EXPECT_EQ(p.line.front(), 9);
  EXPECT_NEAR(p.y.front(), (1.55 - 70.0) * 1e-3, 1e-15);
  EXPECT_NEAR(p.z.front(), 15.34e-3, 1e-15);
}

// MBench_UIC60_v3.ban is CONTACT's MiniProf copy of MBench_UIC60_v3.prr (both from the Manchester
// benchmark, drawn z down): the two readers must give the same rail, the .ban's Y detected as
// pointing down. Its 19 points marked `"` are the ones dropped as too close.
TEST(Miniprof, BenchmarkRailEqualsItsSimpackTwin) {
  const ProfilePoints ban =
      readMiniprofPoints(formatFile("MBench_UIC60_v3.ban"), ProfileKind::Rail);
  EXPECT_EQ(ban.y.size(), 495u - 19u);
  ProfileReadOptions opt;
  const Profile a = profileFromPoints(ban, opt, "ban");
  const Profile b = readSimpackProfile(projectFile("profiles/MBench_UIC60_v3.prr"), opt);
  const double s0 = std::max(a.sMin(), b.sMin()), s1 = std::min(a.sMax(), b.sMax());
  ASSERT_GT(s1 - s0, 0.05);
  double worst = 0.0;
  for (double s = s0; s <= s1; s += 1e-4) worst = std::max(worst, std::abs(a.at(s).h - b.at(s).h));
  // The .ban holds 8 significant digits (1e-6 mm at 40 mm).
  EXPECT_LT(worst, 1e-8);
}

TEST(Miniprof, MeasuredRailsAndSections) {
  // avg_HR.BAN (upper-case extension, quoted keyword lines): its head steps back by 0.01 mm at
  // line 136 (X = 29.27 then 29.26 mm at Y = -2.55 mm), on the running surface: refused there.
  const std::string hr =
      firstError([&] { readMiniprofPoints(formatFile("avg_HR.BAN"), ProfileKind::Rail); });
  EXPECT_NE(hr.find("avg_HR.BAN:136: profile X values must advance: X = 29.26 mm follows X = "
                    "29.27 mm"),
            std::string::npos)
      << hr;
  // The .mpt excerpt: one [Profile1Points] section, X,Y,A,C.
  const ProfilePoints m =
      readMiniprofPoints(formatFile("snx00500_profile2_head.mpt"), ProfileKind::Rail);
  EXPECT_EQ(m.y.size(), 429u);
  double top = -1.0;
  for (double z : m.z) top = std::max(top, z);
  EXPECT_NEAR(top, 0.0, 1e-12);
  EXPECT_NO_THROW(profileFromPoints(m, {}, "mpt"));
}

// ---- Malformed files: file:line and an InputError, never a crash -----------------------------

TEST(Miniprof, TruncatedFileRefused) {
  std::string t = syntheticWheel();
  t.resize(t.rfind('\n', t.size() - 2) + 1);  // the last point line cut off
  EXPECT_EQ(firstError([&] { parseWheel(t); }),
            "w.whl:23: XYPoints = 20 (line 3) but the file holds 19 point lines: the file is "
            "truncated or was edited");
  EXPECT_EQ(firstError([&] { parseWheel("ProgramName=x\nColumnDef=X,Y\nXYPo"); }),
            "w.whl:3: no profile points: the header is not followed by data (the file is cut "
            "short?)");
}

TEST(Miniprof, ColumnsChecked) {
  std::string t = syntheticWheel();
  t.replace(t.find("ColumnDef=X,Y"), 13, "ColumnDef=X,Y,A");
  EXPECT_EQ(firstError([&] { parseWheel(t); }),
            "w.whl:5: expected 3 values (ColumnDef, line 2), got 2");
  t = syntheticWheel();
  t.replace(t.find("ColumnDef=X,Y"), 13, "ColumnDef=X,Z");
  EXPECT_EQ(firstError([&] { parseWheel(t); }),
            "w.whl:2: ColumnDef names no X and Y column: the profile's coordinates are unknown");
}

TEST(Miniprof, BadValuesRefused) {
  std::string t = syntheticWheel();
  const std::size_t at = t.find("\n", t.find("\n\n") + 2) + 1;  // line 6
  std::string nan = t;
  nan.replace(at, nan.find(' ', at) - at, "nan");
  EXPECT_EQ(firstError([&] { parseWheel(nan); }).substr(0, 36),
            "w.whl:6: non-numeric profile data \"n");
  std::string nul = t;
  nul[at + 1] = '\0';
  EXPECT_EQ(firstError([&] { parseWheel(nul); }),
            "w.whl:6: NUL byte in the file: a MiniProf profile is text");
  EXPECT_EQ(firstError([&] { parseWheel(syntheticWheel("XYPoints=-3")); }),
            "w.whl:4: XYPoints must be a point count up to 200000, got \"-3\"");
  EXPECT_EQ(firstError([&] { parseWheel(syntheticWheel("WheelDiameterTaperline=65")); }),
            "w.whl:4: the tape line is 65 mm from the flange back; railbench reads wheels whose "
            "tape circle is 70 mm from it (EN 13715)");
}

TEST(Miniprof, ShapeAndUnitsChecked) {
  ProfileReadOptions opt;
  opt.r0 = kR0;
  // Two points swapped: not monotone.
  std::string t = syntheticWheel();
  const std::size_t a = t.find("11.0");
  const std::size_t b = t.find("17.0");
  std::swap(t[a], t[b]);
  std::swap(t[a + 1], t[b + 1]);
  EXPECT_EQ(firstError([&] { profileFromPoints(parseWheel(t), opt, "w"); }).substr(0, 53),
            "w.whl:7: profile X values must advance: X = 11 mm fol");
  // A wheel in metres: every coordinate below 1 mm.
  std::string m = "ColumnDef=X,Y\n\n";
  for (int i = 0; i < 20; ++i) {
    const double x = 0.005 + 0.006 * i;
    m += std::to_string(x) + " " +
         std::to_string(x < 0.03 ? 0.028 - 50 * (x - 0.015) * (x - 0.015) : -0.02 * (x - 0.070)) +
         "\n";
  }
  EXPECT_EQ(firstError([&] { profileFromPoints(parseWheel(m), opt, "w"); }).substr(0, 45),
            "w.whl:3: all coordinates are below 1 mm: the ");
  // Flat: no flange, no head.
  std::string flat = "ColumnDef=X,Y\n\n";
  for (int i = 0; i < 20; ++i) flat += std::to_string(5.0 * i) + " 0.1\n";
  EXPECT_EQ(firstError([&] { parseWheel(flat); }).substr(0, 42),
            "w.whl:3: cannot tell which way is up: no p");
  // A wheel drawn from its outer face: the flange beyond the tape circle.
  std::string mirrored = "ColumnDef=X,Y\n\n";
  for (int i = 0; i < 20; ++i) {
    const double x = 119.0 - 6.0 * i;  // the synthetic wheel with X reflected
    const double u = 124.0 - x;
    const double y = u < 30.0 ? 28.0 - 0.05 * (u - 15.0) * (u - 15.0) : -0.02 * (u - 70.0);
    mirrored += std::to_string(x) + " " + std::to_string(y) + "\n";
  }
  EXPECT_EQ(firstError([&] { parseWheel(mirrored); }).substr(0, 40),
            "w.whl:5: the flange tip lies at X = 107 ");
}

TEST(Miniprof, SecondProfileOfAnMptRefused) {
  const std::string t =
      "[FileInfo]\nProgramName=x\n[Profile1Info]\nColumnDef=X,Y\n[Profile1Points]\n0 0\n1 1\n"
      "[Profile2Info]\n[Profile2Points]\n0 0\n";
  EXPECT_EQ(firstError([&] { parseMiniprofPoints(t, "s.mpt", ProfileKind::Rail); }),
            "s.mpt:9: a second profile in the file ([Profile2Points]): railbench reads one "
            "profile per file; keep the one wanted");
}

TEST(ProfileFiles, FormatByExtension) {
  EXPECT_EQ(profileFormat("a/b.WHL"), ProfileFormat::Miniprof);
  EXPECT_EQ(profileFormat("b.ban"), ProfileFormat::Miniprof);
  EXPECT_EQ(profileFormat("b.mpt"), ProfileFormat::Miniprof);
  EXPECT_EQ(profileFormat("b.whe"), ProfileFormat::Vampire);
  EXPECT_EQ(profileFormat("b.RAI"), ProfileFormat::Vampire);
  EXPECT_EQ(profileFormat("b.prr"), ProfileFormat::Simpack);
  EXPECT_EQ(profileFormat("b.txt"), ProfileFormat::Text);
  ProfileReadOptions opt;
  opt.r0 = kR0;
  // VAMPIRE files are refused before they are opened; a .whl is no rail.
  EXPECT_EQ(firstError([&] {
              readProfileFile("w.whe", ProfileKind::Wheel, LengthUnit::Millimetre, opt);
            }).substr(0, 62),
            "w.whe:1: VAMPIRE profile files (.whe, .rai) are not read: no p");
  const std::string asRail = firstError([&] {
    readProfileFile(formatFile("avg_wheel.whl"), ProfileKind::Rail, LengthUnit::Millimetre, opt);
  });
  EXPECT_NE(asRail.find(":1: a MiniProf .whl file holds a wheel profile, a rail profile is "
                        "expected"),
            std::string::npos)
      << asRail;
}

TEST(Miniprof, HugeFileRefused) {
  // A sparse file beyond the 32 MiB limit: refused before it is read.
  const std::string path = testing::TempDir() + "huge_profile.whl";
  { std::ofstream f(path, std::ios::binary); }
  std::filesystem::resize_file(path, kMaxProfileFileBytes + 1);
  const std::string e = firstError([&] { readMiniprofPoints(path, ProfileKind::Wheel); });
  EXPECT_NE(e.find("cannot open profile file"), std::string::npos) << e;
  std::filesystem::remove(path);
}

}  // namespace
