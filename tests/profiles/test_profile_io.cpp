// Profile file readers (SIMPACK .prw/.prr, plain text), the smoothing spline, and the bad-file
// diagnostics ("file:line: message").
#include <gtest/gtest.h>

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
using rb::profiles::test::referenceFile;

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
  // Reference 0.1 mm samples of S1002 (comment header; S = -70 mm has a vertical tangent, so the
  // first interval is steeper than maxSlope and is cut).
  ProfileReadOptions opt;
  opt.r0 = kR0;
  const Profile p = readProfileFile(referenceFile("profiles/s1002_points_from_formula_0p1mm.txt"),
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
  const Profile r = readProfileFile(referenceFile("profiles/s1002_points_from_formula_0p1mm.txt"),
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

}  // namespace
