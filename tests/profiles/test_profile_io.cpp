// Profile file readers (SIMPACK .prw/.prr, plain text), the smoothing spline, and the bad-file
// diagnostics ("file:line: message").
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

#include "test_util.hpp"
#include "workbench/core/error.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/profile_io.hpp"
#include "workbench/profiles/rail60e1.hpp"
#include "workbench/profiles/s1002.hpp"
#include "workbench/profiles/smoothing_spline.hpp"

namespace {

using namespace rb::profiles;
using rb::profiles::test::dataFile;
using rb::profiles::test::projectFile;
using rb::profiles::test::sharedFile;

constexpr double kR0 = 0.46;
const double kCant = std::atan(1.0 / 40.0);

// ---- Smoothing spline ---------------------------------------------------------------------------

TEST(SmoothingSpline, LambdaZeroInterpolates) {
  std::vector<double> x, y;
  for (int i = 0; i < 20; ++i) {
    x.push_back(0.1 * i + 0.01 * (i % 3));
    y.push_back(std::sin(3.0 * x.back()));
  }
  const SmoothingSpline s(x, y, {}, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(s.value(x[i]), y[i], 1e-14);
  EXPECT_NEAR(s.deriv2(x.front()), 0.0, 1e-12);  // natural end
}

TEST(SmoothingSpline, StraightLinesPassUnchanged) {
  std::vector<double> x, y, w;
  for (int i = 0; i < 30; ++i) {
    x.push_back(0.3 * i + 0.05 * (i % 4));
    y.push_back(2.0 - 0.7 * x.back());
    w.push_back(1.0 + 0.1 * (i % 5));
  }
  for (const double lambda : {1e-3, 1.0, 1e3}) {
    const SmoothingSpline s(x, y, w, lambda);
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(s.fitted()[i], y[i], 1e-10);
  }
}

TEST(SmoothingSpline, ActsAsTheDocumentedLowPassFilter) {
  // Evenly spaced samples of a sine of wavenumber omega; with lambda = l^4 / h the amplitude is
  // multiplied by 1 / (1 + (l omega)^4) away from the ends.
  const double h = 0.01, omega = 2.0 * std::numbers::pi / 1.0;
  std::vector<double> x, y;
  for (int i = 0; i <= 1000; ++i) {
    x.push_back(h * i);
    y.push_back(std::sin(omega * x.back()));
  }
  for (const double l : {0.05, 0.15, 0.3}) {
    const double lambda = SmoothingSpline::lambdaForLength(x, {}, l);
    EXPECT_NEAR(lambda, std::pow(l, 4) / h, 1e-12);
    const SmoothingSpline s(x, y, {}, lambda);
    double amp = 0.0;
    for (double t = 4.0; t < 6.0; t += 0.001) amp = std::max(amp, s.value(t));
    EXPECT_NEAR(amp, 1.0 / (1.0 + std::pow(l * omega, 4)), 0.01) << l;
  }
}

TEST(SmoothingSpline, ReducesNoise) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<double> x, y, truth;
  for (int i = 0; i <= 400; ++i) {
    x.push_back(0.01 * i);
    truth.push_back(std::cos(x.back()));
    y.push_back(truth.back() + noise(rng));
  }
  const SmoothingSpline s(x, y, {}, SmoothingSpline::lambdaForLength(x, {}, 0.1));
  double errRaw = 0.0, errFit = 0.0;
  for (std::size_t i = 20; i + 20 < x.size(); ++i) {
    errRaw += std::pow(y[i] - truth[i], 2);
    errFit += std::pow(s.fitted()[i] - truth[i], 2);
  }
  EXPECT_LT(errFit, 0.2 * errRaw);
}

// ---- Readers on the benchmark files -------------------------------------------------------------

TEST(ProfileFiles, SimpackWheelAgainstAnalyticS1002) {
  const Profile exact = s1002Wheel(kR0, WheelSide::Left);
  for (const double l : {0.0, 0.1e-3}) {
    ProfileReadOptions opt;
    opt.r0 = kR0;
    opt.smoothingLength = l;
    const Profile p = readSimpackProfile(projectFile("profiles/MBench_S1002_v3.prw"), opt);
    EXPECT_EQ(p.kind(), ProfileKind::Wheel);
    EXPECT_EQ(p.name(), "MBench_S1002_v3");
    EXPECT_NEAR(p.sMin(), -0.06960, 1e-12);  // first grid point inside the file (-69.6126 mm)
    EXPECT_NEAR(p.sMax(), 0.060, 1e-12);
    double maxAll = 0.0, maxInner = 0.0;
    for (double s = p.sMin(); s <= p.sMax(); s += 1e-5) {
      const double e = std::abs(p.at(s).h - exact.at(s).h);
      maxAll = std::max(maxAll, e);
      // Away from the first/last two file intervals (natural end conditions of the spline).
      if (s > -0.0688 && s < 0.0592) maxInner = std::max(maxInner, e);
    }
    EXPECT_LT(maxInner, l == 0.0 ? 2e-6 : 5e-6);
    std::printf(
        "prw reader, smoothing length %.2f mm: max |h - S1002| %.4f mm (%.4f mm inside "
        "the end intervals)\n",
        l * 1e3, maxAll * 1e3, maxInner * 1e3);
  }
}

TEST(ProfileFiles, SimpackRailAgainstInclined60E1) {
  const Profile exact = rail60E1(RailSide::Left);
  const TopPoint top = highestPoint(exact, kCant);
  // As drawn (canted, origin at the highest point): compare with the rotated analytic head.
  const Profile canted = readSimpackProfile(projectFile("profiles/MBench_UIC60_v3.prr"));
  EXPECT_EQ(canted.kind(), ProfileKind::Rail);
  double maxCanted = 0.0;
  for (double s = canted.sMin() + 1e-3; s <= canted.sMax() - 1e-3; s += 2e-5) {
    // Canted-file point -> rotated frame -> rail profile frame.
    const double Y = s + top.p.y, Z = canted.at(s).h + top.p.z;
    const double c = std::cos(kCant), sn = std::sin(kCant);
    const double sr = Y * c + Z * sn, hr = -Y * sn + Z * c;
    const ProfilePoint q = exact.at(sr);
    maxCanted = std::max(maxCanted, std::abs(hr - q.h) / std::sqrt(1.0 + q.dh * q.dh));
  }
  EXPECT_LT(maxCanted, 0.05e-3);
  // Un-canted by the reader: rotate by -beta about the file origin, which is the point s = top.s
  // of the uninclined head, then shift there.
  ProfileReadOptions opt;
  opt.rotate = -kCant;
  opt.shiftS = top.s;
  opt.shiftH = exact.at(top.s).h;
  const Profile p = readSimpackProfile(projectFile("profiles/MBench_UIC60_v3.prr"), opt);
  double maxUncanted = 0.0;
  for (double s = p.sMin() + 1e-3; s <= p.sMax() - 1e-3; s += 2e-5) {
    const ProfilePoint q = exact.at(s);
    maxUncanted = std::max(maxUncanted, std::abs(p.at(s).h - q.h) / std::sqrt(1.0 + q.dh * q.dh));
  }
  EXPECT_LT(maxUncanted, 0.05e-3);
  std::printf(
      "prr reader: kept s %.2f .. %.2f mm; max normal distance to 60E1 %.4f mm (canted), "
      "%.4f mm (un-canted)\n",
      canted.sMin() * 1e3, canted.sMax() * 1e3, maxCanted * 1e3, maxUncanted * 1e3);
}

TEST(ProfileFiles, TextWheelWithHeaderAndSteepEnd) {
  // Shared 0.1 mm samples of S1002 (comment header; S = -70 mm has a vertical tangent, so the
  // first interval is steeper than maxSlope and is cut).
  ProfileReadOptions opt;
  opt.r0 = kR0;
  const Profile p = readProfileFile(sharedFile("profiles/s1002_points_from_formula_0p1mm.txt"),
                                    ProfileKind::Wheel, LengthUnit::Millimetre, opt);
  EXPECT_NEAR(p.sMin(), -0.0699, 1e-12);
  const Profile exact = s1002Wheel(kR0, WheelSide::Left);
  double maxErr = 0.0;
  for (double s = -0.0689; s <= 0.0590; s += 1e-5) {
    maxErr = std::max(maxErr, std::abs(p.at(s).h - exact.at(s).h));
  }
  EXPECT_LT(maxErr, 1e-6);
  // mirrorY gives the right wheel.
  opt.mirrorY = true;
  const Profile r = readProfileFile(sharedFile("profiles/s1002_points_from_formula_0p1mm.txt"),
                                    ProfileKind::Wheel, LengthUnit::Millimetre, opt);
  EXPECT_NEAR(r.at(0.055).h, p.at(-0.055).h, 1e-9);
}

// ---- Bad files: exact "file:line: message" ------------------------------------------------------

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "<no error>";
}

std::string textError(const std::string& name, ProfileKind kind, LengthUnit u) {
  return errorOf([&] { readTextProfile(dataFile(name), kind, u); });
}

TEST(ProfileFiles, BadTextFiles) {
  const auto rail = ProfileKind::Rail;
  const auto mm = LengthUnit::Millimetre;
  EXPECT_EQ(textError("bad_nonnumeric.txt", rail, mm),
            dataFile("bad_nonnumeric.txt") + ":5: non-numeric profile data \"abc\"");
  EXPECT_EQ(textError("bad_too_few.txt", rail, mm),
            dataFile("bad_too_few.txt") + ":7: only 5 profile points; at least 10 are needed");
  EXPECT_EQ(textError("bad_nonmonotone.txt", rail, mm),
            dataFile("bad_nonmonotone.txt") +
                ":9: profile y values must be strictly monotone: y = -0.004 m follows y = 0 m");
  EXPECT_EQ(textError("bad_units_m.txt", rail, LengthUnit::Metre),
            dataFile("bad_units_m.txt") +
                ":2: coordinate -20 m is implausible for a profile (> 1 m): the data seem to be in "
                "millimetres (the units argument says m)");
  EXPECT_EQ(textError("bad_units_mm.txt", rail, mm),
            dataFile("bad_units_mm.txt") +
                ":2: all coordinates are below 1 mm: the data seem to be in metres (the units "
                "argument says mm)");
  EXPECT_EQ(textError("bad_radius.txt", ProfileKind::Wheel, mm),
            dataFile("bad_radius.txt") +
                ":3: wheel radius 0.0004605 m (r0 0 + z 0.0004605) is outside 0.2 .. 0.7 m: check "
                "r0 and the units");
  EXPECT_EQ(textError("missing.txt", rail, mm),
            dataFile("missing.txt") + ": cannot open profile file");
}

TEST(ProfileFiles, BadSimpackFiles) {
  auto simpack = [](const std::string& name) {
    return errorOf([&] { readSimpackProfile(dataFile(name)); });
  };
  EXPECT_EQ(
      simpack("bad_no_points.prw"),
      dataFile("bad_no_points.prw") + ":9: no point.begin ... point.end block with profile points");
  EXPECT_EQ(simpack("bad_unterminated.prr"),
            dataFile("bad_unterminated.prr") + ":7: point.begin without point.end");
  EXPECT_EQ(simpack("bad_nonnumeric.prr"),
            dataFile("bad_nonnumeric.prr") + ":14: non-numeric profile data \"x2.7E-02\"");
  EXPECT_EQ(simpack("bad_units.prr"),
            dataFile("bad_units.prr") +
                ":8: coordinate -20 m is implausible for a profile (> 1 m): the data seem to be in "
                "millimetres (set units.len.f (1000 for millimetres))");
  EXPECT_EQ(simpack("bad_shift.prr"),
            dataFile("bad_shift.prr") +
                ":7: shift.y = 1 is not supported (only 0); transform the points with "
                "ProfileReadOptions instead");
  EXPECT_EQ(
      errorOf([] {
        readProfileFile(dataFile("bad_type.prr"), ProfileKind::Wheel, LengthUnit::Metre, {});
      }),
      dataFile("bad_type.prr") + ":3: the file holds a rail profile, a wheel profile is expected");
  // A SIMPACK wheel needs r0.
  EXPECT_EQ(errorOf([] { readSimpackProfile(projectFile("profiles/MBench_S1002_v3.prw")); }),
            projectFile("profiles/MBench_S1002_v3.prw") +
                ":12: a SIMPACK wheel profile gives the radius increase: the tape-circle radius r0 "
                "is needed");
  // The good rail file of the same shape reads fine.
  EXPECT_NO_THROW(
      readProfileFile(dataFile("bad_type.prr"), ProfileKind::Rail, LengthUnit::Metre, {}));
}

// ---- Hostile files: bounded reading ---------------------------------------------------------

namespace bounded {

std::string textErrorAt(const std::string& path) {
  return errorOf([&] { readTextProfile(path, ProfileKind::Rail, LengthUnit::Millimetre); });
}

std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "rb_profile_io_" + name;
}

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = tempPath(name);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  EXPECT_NE(f, nullptr);
  std::fwrite(text.data(), 1, text.size(), f);
  std::fclose(f);
  return path;
}

// `n` points of a plausible rail head in mm, one per line from line 1.
std::string railPoints(std::size_t n) {
  std::string text;
  char line[64];
  for (std::size_t i = 0; i < n; ++i) {
    const double y = -30.0 + 60.0 * static_cast<double>(i) / static_cast<double>(n);
    std::snprintf(line, sizeof line, "%.9f %.6f\n", y, -y * y / 600.0);
    text += line;
  }
  return text;
}

TEST(ProfileFiles, RefusesMoreThanTheMaximumNumberOfPoints) {
  const std::string path = writeTemp("too_many.txt", railPoints(kMaxProfilePoints + 5));
  const std::string line = std::to_string(kMaxProfilePoints + 1);
  EXPECT_EQ(textErrorAt(path), path + ":" + line + ": more than " +
                                   std::to_string(kMaxProfilePoints) +
                                   " profile points (a measured profile has a few thousand): thin "
                                   "the data");
  // The same bound in a SIMPACK point block (line 1 is point.begin).
  const std::string simpack = "point.begin\n" + railPoints(kMaxProfilePoints + 1) + "point.end\n";
  EXPECT_EQ(errorOf([&] { parseSimpackPoints(simpack, "many.prr"); }),
            "many.prr:" + std::to_string(kMaxProfilePoints + 2) + ": more than " +
                std::to_string(kMaxProfilePoints) +
                " profile points (a measured profile has a few thousand): thin the data");
  // Exactly the maximum is accepted.
  EXPECT_EQ(parseTextPoints(railPoints(kMaxProfilePoints), "max.txt", ProfileKind::Rail,
                            LengthUnit::Millimetre)
                .y.size(),
            kMaxProfilePoints);
}

TEST(ProfileFiles, RefusesFilesAboveTheSizeBound) {
  const std::string path = tempPath("huge.txt");
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  // A sparse file: the size is checked before anything is read.
  ASSERT_EQ(std::fseek(f, static_cast<long>(kMaxProfileFileBytes), SEEK_SET), 0);
  std::fputc('\n', f);
  std::fclose(f);
  EXPECT_EQ(textErrorAt(path), path + ": cannot open profile file: larger than 32 MiB (32 MiB)");
  std::remove(path.c_str());
}

TEST(ProfileFiles, RefusesFifosAndFolders) {
  const std::string fifo = tempPath("fifo.txt");
  std::remove(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Opening a FIFO for reading would block until a writer comes: it must be refused before.
  EXPECT_EQ(textErrorAt(fifo), fifo + ": cannot open profile file: not a regular file (a FIFO)");
  std::remove(fifo.c_str());
  const std::string dir = ::testing::TempDir();
  EXPECT_EQ(errorOf([&] { readSimpackProfile(dir); }),
            dir + ": cannot open profile file: not a regular file (a folder)");
}

TEST(ProfileFiles, ReportsAtMostTwentyProblemsPerFile) {
  std::string text;
  for (int i = 0; i < 1000; ++i) text += "1 x\n";
  try {
    parseTextPoints("0 0\n" + text, "garbage.txt", ProfileKind::Rail, LengthUnit::Millimetre);
    ADD_FAILURE() << "no error";
  } catch (const rb::InputError& e) {
    ASSERT_EQ(e.diagnostics().size(), 21u);
    EXPECT_EQ(e.diagnostics()[0].str(), "garbage.txt:2: non-numeric profile data \"x\"");
    EXPECT_EQ(e.diagnostics()[20].str(),
              "garbage.txt:21: too many problems; the rest of the file was not checked");
  }
}

TEST(ProfileFiles, ParsingFromMemoryEqualsReadingTheFile) {
  const std::string text = railPoints(50);
  const std::string path = writeTemp("same.txt", text);
  const ProfilePoints a = readTextPoints(path, ProfileKind::Rail, LengthUnit::Millimetre);
  const ProfilePoints b = parseTextPoints(text, path, ProfileKind::Rail, LengthUnit::Millimetre);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
  EXPECT_EQ(a.line, b.line);
  // A last line without '\n' and CRLF line ends are read too.
  const ProfilePoints c =
      parseTextPoints("1 0\r\n2 0.5\r\n3 1", "crlf.txt", ProfileKind::Rail, LengthUnit::Millimetre);
  EXPECT_EQ(c.y.size(), 3u);
  EXPECT_EQ(c.line.back(), 3);
}

TEST(ProfileFiles, RefusesPointSetsTheSplineCannotTake) {
  // Found by fuzzing: each of these stopped at an internal check (exit 3) before.
  auto rail = [](const std::string& text) {
    return errorOf([&] {
      profileFromPoints(parseTextPoints(text, "p.txt", ProfileKind::Rail, LengthUnit::Millimetre),
                        {}, "p");
    });
  };
  std::string tiny, close, weights;
  for (int i = 0; i < 10; ++i) {
    tiny += std::to_string(0.001 * i) + " 2\n";  // 9 um wide
    close += (i < 9 ? std::to_string(i) + "e-300" : std::string("30")) + " 2\n";
    weights += std::to_string(3 * i) + " 0 " + (i == 3 ? "1e-300" : "1") + "\n";
  }
  EXPECT_EQ(rail(tiny),
            "p.txt:10: the kept points span only 0.009 mm along y; the profile grid needs at least "
            "4 steps of 0.02 mm inside them");
  EXPECT_EQ(rail(close),
            "p.txt:2: y = 1e-303 m is closer than 1 nm to the previous point (y = 0 m): merge or "
            "drop duplicate points");
  EXPECT_EQ(rail(weights),
            "p.txt:4: point weight 1e-300 is outside 1e-06 .. 1e+06 (weights are relative: scale "
            "them)");
}

}  // namespace bounded

}  // namespace
