// Rails that change along the track (profiles.rail_slices, contact/sliced_rail.hpp) in runs of the
// Manchester wagon on elastic contact (tests/run/data/sliced_rails_*.lua): slices that are all the
// same rail are the prismatic rail bit for bit; rails lowered over a ramp carry the wheelsets down
// with them, both rails by the lowering, one rail by half of it with the roll of the cross level.
// docs/sliced_rails.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tests/run/run_files.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/run/channels.hpp"
#include "workbench/run/vehicle_run.hpp"

namespace {

constexpr double kBeta = 0.025;    // the scenes' rail inclination [rad]
constexpr double kLowered = 3e-3;  // rails/60e1_low3.txt: rails/60e1_a.txt with z - 3 mm

rb::test::RunFile run(const std::string& scene) {
  rb::test::RunFile f =
      rb::test::runInto(rb::test::compiled("tests/run/data/sliced_rails_" + scene + ".lua"),
                        "rb_test_sliced_rails", scene + ".h5");
  EXPECT_TRUE(f.result.result.ok) << f.result.result.message;
  return f;
}

TEST(SlicedRails, IdenticalSlicesAreThePrismaticRailBitForBit) {
  // Six slices alternating between two files of the same rail: each piece blends two different
  // profile objects, and its every result is the plain run's.
  const rb::test::RunFile plain = run("plain");
  const rb::test::RunFile sliced = run("identical");
  const rb::io::ResultReader a(plain.path), b(sliced.path);
  std::vector<std::string> names;
  rb::test::datasets(a, "/bodies", names);
  rb::test::datasets(a, "/contact", names);
  ASSERT_GT(names.size(), 40U);
  for (const std::string& n : names) {
    const auto x = a.dataset(n), y = b.dataset(n);
    ASSERT_TRUE(x && y) << n;
    EXPECT_EQ(*x, *y) << n;
  }
}

struct Wheelsets {
  std::vector<double> t;
  std::vector<std::vector<double>> s, z, roll, y;
};
Wheelsets read(const std::string& path) {
  const rb::io::ResultReader r(path);
  Wheelsets w;
  w.t = *r.dataset("/time");
  for (const char* ws : {"ws1", "ws2", "ws3", "ws4"}) {
    const std::string g = std::string("/bodies/") + ws + "/";
    w.s.push_back(*r.dataset(g + "s"));
    w.z.push_back(*r.dataset(g + "z"));
    w.roll.push_back(*r.dataset(g + "roll"));
    w.y.push_back(*r.dataset(g + "y"));
  }
  return w;
}

TEST(SlicedRails, LoweredRailsCarryTheWheelsetsDown) {
  // Both rails lowered by 3 mm over s = 60 .. 100 m. The slices are drawn in the inclined rail
  // frame: each rail moves 3 cos(beta) down and 3 sin(beta) outward (the gauge widens by
  // 0.15 mm, which lowers the wheelsets by a further fraction of a micrometre).
  const Wheelsets w = read(run("lowered").path);
  const double drop = kLowered * std::cos(kBeta);
  for (std::size_t k = 0; k < 4; ++k) {
    const double z0 = w.z[k].front();
    ASSERT_GT(w.s[k].back(), 105.0);
    EXPECT_NEAR(w.z[k].back() - z0, -drop, 1e-6) << "ws" << k + 1;
    // On the ramp (1:13333) the wheelset follows the blend of the two slices.
    for (std::size_t i = 0; i < w.t.size(); i += 10) {
      const double s = w.s[k][i];
      if (s < 62.0 || s > 98.0) continue;
      const double b = (s - 60.0) / 40.0;
      EXPECT_NEAR(w.z[k][i] - z0, -b * drop, 0.01 * drop) << "ws" << k + 1 << " at s = " << s;
    }
  }
}

TEST(SlicedRails, OneLoweredRailRollsTheWheelsets) {
  // The left rail alone lowered by 3 mm: a cross level of 3 cos(beta) over the distance of the two
  // contact points (about 1.5 m), half of it in the wheelset's height; the vehicle leans and moves
  // toward the lower rail (y > 0) under the gravity component of the cant.
  const Wheelsets w = read(run("lowered_left").path);
  const double drop = kLowered * std::cos(kBeta);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(w.z[k].back() - w.z[k].front(), -0.5 * drop, 0.03 * 0.5 * drop) << k + 1;
    EXPECT_NEAR(w.roll[k].back() - w.roll[k].front(), -drop / 1.5, 0.03 * drop / 1.5) << k + 1;
    EXPECT_GT(w.y[k].back(), 0.5e-3) << k + 1;
    EXPECT_LT(w.y[k].back(), 3e-3) << k + 1;
  }
}

// Rails of slices that stand lower than profiles.rail from the start (the centred height and roll
// the start begins from are profiles.rail's): the wheelsets start on them, lowered and rolled by
// their clearance, at the static equilibrium over them. Without that, the equilibrium began with
// the wheels 3 mm in the air, with no contact stiffness, and its Newton steps left the rails (the
// start was refused as a derailment).
TEST(SlicedRails, WheelsetsStartOnRailsLowerThanProfilesRail) {
  const Wheelsets plain = read(run("plain").path);
  const Wheelsets both = read(run("start_lowered").path);
  const Wheelsets left = read(run("start_lowered_left").path);
  const double drop = kLowered * std::cos(kBeta);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(both.z[k].front() - plain.z[k].front(), -drop, 1e-5) << "ws" << k + 1;
    EXPECT_NEAR(both.roll[k].front() - plain.roll[k].front(), 0.0, 1e-7) << "ws" << k + 1;
    EXPECT_NEAR(left.z[k].front() - plain.z[k].front(), -0.5 * drop, 0.03 * 0.5 * drop)
        << "ws" << k + 1;
    EXPECT_NEAR(left.roll[k].front() - plain.roll[k].front(), -drop / 1.5, 0.03 * drop / 1.5)
        << "ws" << k + 1;
  }
}

TEST(SlicedRails, TheLoadMovesToTheHigherOfTwoRails) {
  // A second rail of the same profile on the right (profiles.extra_rails) rises from 2 mm below
  // while the running rail drops by 2 mm, over s = 60 .. 100 m: the two are level at s = 80 m,
  // where each carries half the wheel load (the two surfaces are the same there); before it the
  // running rail carries the wheel, after it the second rail, at the same lateral position, and
  // the wheel load moves across without a jump.
  const rb::test::RunFile f = run("transfer");
  const rb::io::ResultReader r(f.path);
  for (const char* ws : {"ws1", "ws2", "ws3", "ws4"}) {
    const std::string c = std::string("/contact/") + ws + "/right/";
    const auto s = *r.dataset(std::string("/bodies/") + ws + "/s");
    const auto a = *r.dataset(c + "rails/rail/normal_force");
    const auto b = *r.dataset(c + "rails/nose/normal_force");
    const auto ya = *r.dataset(c + "rails/rail/y");
    const auto yb = *r.dataset(c + "rails/nose/y");
    const auto n = *r.dataset(c + "normal_force");
    const auto xa = *r.dataset(c + "rails/rail/x");
    const auto xb = *r.dataset(c + "rails/nose/x");
    double cross = 0.0, y_before = 0.0, y_after = 0.0, lo = 1e9, hi = 0.0;
    int both = 0;
    for (std::size_t i = 1; i < s.size(); ++i) {
      EXPECT_NEAR(a[i] + b[i], n[i], 1e-6 * n[i]) << ws;
      // The rails' forces add up to the wheel's.
      for (const char* q : {"X", "Y", "Q"}) {
        const double sum =
            (*r.dataset(c + "rails/rail/" + q))[i] + (*r.dataset(c + "rails/nose/" + q))[i];
        EXPECT_NEAR(sum, (*r.dataset(c + q))[i], 1e-6 * n[i]) << ws << " " << q;
      }
      // Where both rails carry the wheel (the same profile at the same height, the same wheel
      // point) the contacts differ only by the rails' slopes (2 mm / 40 m, up and down): the one
      // on the rising rail lies r sin(atan p) ahead of the axle, the other as far behind it.
      if (a[i] > 0.0 && b[i] > 0.0) {
        const double lead = 0.46 * 0.002 / 40.0;
        EXPECT_NEAR(xb[i] - xa[i], 2.0 * lead, 0.05 * lead) << ws << " at s = " << s[i];
        ++both;
      }
      if (a[i - 1] >= b[i - 1] && a[i] < b[i])
        cross = s[i - 1] +
                (s[i] - s[i - 1]) * (a[i - 1] - b[i - 1]) / ((a[i - 1] - b[i - 1]) - (a[i] - b[i]));
      if (s[i] > 70.0 && s[i] < 75.0) y_before = ya[i];
      if (s[i] > 85.0 && s[i] < 90.0) y_after = yb[i];
      if (s[i] > 75.0 && s[i] < 85.0) {
        lo = std::min(lo, n[i]);
        hi = std::max(hi, n[i]);
      }
      if (s[i] < 78.0) {
        EXPECT_EQ(b[i], 0.0) << ws << " at s = " << s[i];
      }
      if (s[i] > 82.0) {
        EXPECT_EQ(a[i], 0.0) << ws << " at s = " << s[i];
      }
    }
    EXPECT_NEAR(cross, 80.0, 0.1) << ws;
    // The run's own answer (VehicleOutputs::writeRailAnswers): the same transfer, and the largest
    // force on each rail.
    const std::string g = c + "rails";
    EXPECT_NEAR(*r.number(g, "transfer_s_nose"), cross, 1e-9) << ws;
    EXPECT_EQ(*r.number(g, "peak_normal_force_nose"), *std::max_element(b.begin(), b.end())) << ws;
    EXPECT_EQ(*r.number(g, "peak_normal_force_rail"), *std::max_element(a.begin(), a.end())) << ws;
    EXPECT_GT(both, 0) << ws;
    EXPECT_NEAR(y_after, y_before, 0.2e-3) << ws;
    // The wheel load through the transfer: within 2 % of its mean (the wagon's own dynamics
    // move it by about 1 %).
    EXPECT_LT(hi - lo, 0.02 * 0.5 * (hi + lo)) << ws;
  }
}

// A study's metric may read a rail's channels (signalProblem): the rails of a side with further
// rails and every channel the run writes for them, nothing else.
TEST(SlicedRails, RailSignalsAreKnownToTheMetrics) {
  const rb::run::Model m = rb::test::compiled("tests/run/data/sliced_rails_transfer.lua");
  for (const auto& c : rb::run::kRailChannels)
    EXPECT_EQ(
        rb::run::signalProblem(m.spec, "/contact/ws2/right/rails/nose/" + std::string(c.name)), "")
        << c.name;
  EXPECT_EQ(rb::run::signalProblem(m.spec, "/contact/ws1/right/rails/rail/y_over_q"), "");
  EXPECT_NE(rb::run::signalProblem(m.spec, "/contact/ws1/right/rails/noze/x").find("'nose'"),
            std::string::npos);
  EXPECT_NE(rb::run::signalProblem(m.spec, "/contact/ws1/right/rails/nose/yq").find("rail signal"),
            std::string::npos);
  EXPECT_NE(rb::run::signalProblem(m.spec, "/contact/ws1/left/rails/rail/x").find("no further"),
            std::string::npos);
}

}  // namespace
