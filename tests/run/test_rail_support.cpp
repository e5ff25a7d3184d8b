// The track under the rail (contact.elastic.rail_support, docs/track_support.md): per wheel a rail
// mass travelling with its wheelset on a spring and a damper to the ground. The Manchester wagon
// on a tangent (tests/run/data/rail_support_*.lua): each rail mass carries its wheel's load on its
// spring from the first instant (the start is an equilibrium); where the support changes slowly
// along the track the rail follows its static deflection; after an abrupt stiffening the wheel
// and rail masses ring at the frequency of the two-mass system wheel - Hertz spring - rail mass -
// support.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "tests/run/run_files.hpp"
#include "workbench/io/result_reader.hpp"

namespace {

rb::test::RunFile run(const std::string& scene) {
  rb::test::RunFile f =
      rb::test::runInto(rb::test::compiled("tests/run/data/rail_support_" + scene + ".lua"),
                        "rb_test_rail_support", scene + ".h5");
  EXPECT_TRUE(f.result.result.ok) << f.result.result.message;
  return f;
}

TEST(RailSupport, EachRailMassCarriesItsWheelLoad) {
  // Uniform support: k_z = 100 MN/m under every wheel.
  const rb::test::RunFile f = run("tangent");
  const rb::io::ResultReader r(f.path);
  for (const char* ws : {"ws1", "ws2", "ws3", "ws4"})
    for (const char* side : {"left", "right"}) {
      const std::string c = std::string("/contact/") + ws + "/" + side + "/";
      const auto Q = *r.dataset(c + "Q");
      const auto z = *r.dataset(c + "track/rail_z");
      const auto fz = *r.dataset(c + "track/support_force_z");
      ASSERT_FALSE(z.empty());
      for (std::size_t i = 0; i < z.size(); ++i) {
        // The static deflection under the wheel load, from the start on: the rail masses are
        // part of the initial equilibrium.
        EXPECT_NEAR(z[i], -Q[i] / 1e8, 1e-6 * Q[i] / 1e8) << c << " sample " << i;
        EXPECT_NEAR(fz[i], Q[i], 1e-6 * Q[i]) << c << " sample " << i;
      }
      EXPECT_NEAR(z.front(), z.back(), 1e-5 * std::abs(z.back())) << c;
    }
}

// The frequency [Hz] of the largest peak of x's Hann-windowed spectrum in [lo, hi] (0.05 Hz scan).
double peakFrequency(const std::vector<double>& x, double dt, double lo, double hi) {
  const std::size_t n = x.size();
  double best = 0.0, f_best = lo;
  for (double f = lo; f <= hi; f += 0.05) {
    double re = 0.0, im = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(i) /
                                            static_cast<double>(n - 1));
      const double a = 2.0 * std::numbers::pi * f * static_cast<double>(i) * dt;
      re += w * x[i] * std::cos(a);
      im += w * x[i] * std::sin(a);
    }
    if (re * re + im * im > best) {
      best = re * re + im * im;
      f_best = f;
    }
  }
  return f_best;
}

TEST(RailSupport, SupportThatVariesAlongTheTrack) {
  const rb::test::RunFile f = run("step");
  const rb::io::ResultReader r(f.path);
  const std::string c = "/contact/ws1/left/";
  const auto t = *r.dataset("/time");
  const auto s = *r.dataset("/bodies/ws1/s");
  const auto Q = *r.dataset(c + "Q");
  const auto z = *r.dataset(c + "track/rail_z");
  // The scene's vertical stiffness: 100 MN/m, doubled over s = 45 .. 55 m, 800 MN/m after 60.05 m.
  const auto kz = [](double x) {
    if (x <= 45.0) return 1e8;
    if (x <= 55.0) return 1e8 + (x - 45.0) / 10.0 * 1e8;
    if (x <= 60.0) return 2e8;
    if (x >= 60.05) return 8e8;
    return 2e8 + (x - 60.0) / 0.05 * 6e8;
  };
  // The ramp takes 0.5 s, far slower than the vertical modes (above 100 Hz): the rail follows its
  // static deflection, within 1 %.
  int ramp = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i] > 44.0 && s[i] < 59.5) {
      EXPECT_NEAR(z[i], -Q[i] / kz(s[i]), 0.01 * Q[i] / kz(s[i])) << "s = " << s[i];
      ++ramp;
    }
  EXPECT_GT(ramp, 500);
  // After the step: 0.25 s of the rail mass's motion about its final position.
  std::vector<double> x;
  double t0 = -1.0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i] >= 60.05) {
      if (t0 < 0.0) t0 = t[i];
      if (t[i] < t0 + 0.25) x.push_back(z[i]);
    }
  ASSERT_GT(x.size(), 400u);
  double mean = 0.0;
  for (std::size_t i = x.size() - 100; i < x.size(); ++i) mean += x[i] / 100.0;
  for (double& v : x) v -= mean;
  // The two-mass system: the wheel (half the wheelset, 1813 kg) on the linearised Hertz spring
  // 1.5 N0 / delta0 of the run's static wheel load and approach, on the rail mass (150 kg) on
  // 800 MN/m. Its lower mode is the one a stiffness step rings; the primary suspension (two
  // orders softer) and the contact damping (ratio 0.1) move it by about 1 %: within 3 %.
  const double n0 = *r.number("/contact", "elastic_static_load_N");
  const double d0 = *r.number("/contact", "elastic_static_approach_m");
  const double kh = 1.5 * n0 / d0, mw = 1813.0 / 2.0, mr = 150.0, ks = 8e8;
  Eigen::Matrix2d K, M;
  K << kh, -kh, -kh, kh + ks;
  M << mw, 0.0, 0.0, mr;
  const Eigen::Vector2d lambda = (M.inverse() * K).eigenvalues().real();
  const double f_low = std::sqrt(lambda.minCoeff()) / (2.0 * std::numbers::pi);
  const double dt = t[1] - t[0];
  EXPECT_NEAR(peakFrequency(x, dt, 50.0, 300.0), f_low, 0.03 * f_low);
}

}  // namespace
