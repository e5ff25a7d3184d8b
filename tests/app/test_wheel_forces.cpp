// The wheel/rail forces of contact runs in the track frame (EN 14363 X, Y, Q and the plain lateral
// component y_track), per wheel and per contact patch, checked against physics: static wheel
// loads on tangent track, the lateral balance of steady curving, the patches of a two-point
// contact adding up to their wheel, and the T gamma wear number from the written patch data.
// KEC and LUT alike, on short runs of shipped scenarios.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "h5read.hpp"
#include "scenario_run.hpp"
#include "workbench/app/run.hpp"

namespace {

// Manchester wagon 1 (scenarios/vehicles/manchester_wagon1.lua, paper Table 2): car 32000 kg,
// 2 bogie frames of 2615 kg, 4 wheelsets of 1813 kg; VehicleModel::gravity = 9.81 m/s^2.
constexpr double kWagonMass = 32000.0 + 2 * 2615.0 + 4 * 1813.0;  // [kg]
constexpr double kGravity = 9.81;                                 // [m/s^2]
constexpr const char* kWheelsets[] = {"ws1", "ws2", "ws3", "ws4"};
constexpr const char* kSides[] = {"left", "right"};
constexpr double kSigma[] = {1.0, -1.0};  // left +1, right -1

// Runs scenario (relative to the source tree) with overrides; returns the open result file.
hid_t run(const std::string& scenario, const std::string& name,
          const std::vector<std::string>& overrides) {
  return h5test::runAndOpen(
      h5test::quietRun(scenario, h5test::freshResult("rb_test_wheel_forces", name), overrides));
}

std::string wheel(const char* ws, const char* side) {
  return std::string("/contact/") + ws + "/" + side + "/";
}

// The datasets of one patch at one output time.
struct PatchSample {
  double active, normal, fx, fy, mz, sx, sy, spin, gamma_t, X, Y, Q, y_track, t_gamma, power;
};
struct PatchData {
  std::vector<double> active, normal, fx, fy, mz, sx, sy, spin, gamma_t, X, Y, Q, y_track, t_gamma,
      power;
  PatchData(hid_t f, const std::string& base) {
    const auto d = [&](const char* q) { return h5test::dataset(f, base + q); };
    active = d("active");
    normal = d("normal_force");
    fx = d("creep_force_x");
    fy = d("creep_force_y");
    mz = d("spin_moment");
    sx = d("creepage_x");
    sy = d("creepage_y");
    spin = d("spin");
    gamma_t = d("contact_angle_track");
    X = d("X");
    Y = d("Y");
    Q = d("Q");
    y_track = d("y_track");
    t_gamma = d("t_gamma");
    power = d("power");
  }
  PatchSample at(std::size_t k) const {
    return {active[k],  normal[k], fx[k], fy[k], mz[k],      sx[k],      sy[k],   spin[k],
            gamma_t[k], X[k],      Y[k],  Q[k],  y_track[k], t_gamma[k], power[k]};
  }
};

// Static wheel loads on straight level track: Q of every wheel is the eighth of the wagon's weight
// (the wagon is symmetric front/rear and left/right), the lateral forces of a wheelset's wheels
// cancel (they are the normal forces' inward components N sin(gamma), equal on both wheels), X ~ 0.
void staticLoads(const char* method) {
  const hid_t f =
      run("tests/app/data/wheel_forces/tangent.lua", std::string("tangent_") + method + ".h5",
          {std::string("contact.method=") + method});
  ASSERT_GE(f, 0) << method;
  const double q_static = kWagonMass * kGravity / 8.0;
  double worst_q = 0.0, worst_sum_y = 0.0, worst_y_sym = 0.0, worst_x = 0.0, y_wheel = 0.0;
  for (const char* ws : kWheelsets) {
    const std::string l = wheel(ws, "left"), r = wheel(ws, "right");
    const auto ql = h5test::dataset(f, l + "Q"), qr = h5test::dataset(f, r + "Q");
    const auto yl = h5test::dataset(f, l + "y_track"), yr = h5test::dataset(f, r + "y_track");
    const auto Yl = h5test::dataset(f, l + "Y"), Yr = h5test::dataset(f, r + "Y");
    const auto xl = h5test::dataset(f, l + "X"), xr = h5test::dataset(f, r + "X");
    ASSERT_FALSE(ql.empty()) << method << " " << ws;
    for (std::size_t k = 0; k < ql.size(); ++k) {
      for (const double q : {ql[k], qr[k]})
        worst_q = std::max(worst_q, std::abs(q - q_static) / q_static);
      worst_sum_y = std::max(worst_sum_y, std::abs(yl[k] + yr[k]) / q_static);
      worst_y_sym = std::max(worst_y_sym, std::abs(Yl[k] - Yr[k]) / q_static);
      worst_x = std::max({worst_x, std::abs(xl[k]) / q_static, std::abs(xr[k]) / q_static});
      y_wheel = Yl[k];
    }
  }
  // Contact positions: with the wheelset centred (no roll, no yaw) the contact point of a patch
  // lies at y = sigma Lw + s_w (Eq. 7, 10), the same Lw for every patch and both wheels.
  double lw = 0.0, worst_lw = 0.0;
  for (int s = 0; s < 2; ++s)
    for (const char* p : {"patch0/", "patch1/"}) {
      const std::string base = wheel("ws1", kSides[s]) + p;
      const auto active = h5test::dataset(f, base + "active");
      const auto y = h5test::dataset(f, base + "y"), sw = h5test::dataset(f, base + "wheel_s");
      for (std::size_t k = 0; k < y.size(); ++k) {
        if (active[k] < 0.5) continue;
        const double l = kSigma[s] * (y[k] - sw[k]);
        if (lw == 0.0) lw = l;
        worst_lw = std::max(worst_lw, std::abs(l - lw));
      }
    }
  std::printf(
      "[%s] static: contact positions y = sigma Lw + s_w with Lw = %.6f m (spread %.3e m)\n",
      method, lw, worst_lw);
  EXPECT_GT(lw, 0.7) << method;
  EXPECT_LT(lw, 0.8) << method;
  EXPECT_LT(worst_lw, 1e-12) << method;
  std::printf(
      "[%s] static: max |Q - W/8| / (W/8) = %.3e (W/8 = %.3f N), max |sum y_track| / (W/8) = "
      "%.3e, max |Y_l - Y_r| / (W/8) = %.3e, Y per wheel = %.3f N, max |X| / (W/8) = %.3e\n",
      method, worst_q, q_static, worst_sum_y, worst_y_sym, y_wheel, worst_x);
  EXPECT_LT(worst_q, 1e-6) << method;
  EXPECT_LT(worst_sum_y, 1e-9) << method;
  EXPECT_LT(worst_y_sym, 1e-9) << method;
  EXPECT_GT(y_wheel, 0.0) << method;  // the rail pushes each wheel toward the track centre
  EXPECT_LT(worst_x, 1e-6) << method;
  H5Fclose(f);
}

// Steady curving on case 2's R = 500 m (optionally with cant): the wheelsets' lateral track-frame
// forces together carry the vehicle's unbalanced lateral acceleration,
//   sum y_track = M (V^2/R cos(phi) - g sin(phi)),   sin(phi) = cant / cant_base,
// the lateral component (in the track plane) of centripetal acceleration and gravity. The run
// starts inside the curve (the car at s = 175 m, the curve begins at 150 m) and is averaged over
// its last 2 s (about two periods of the car's 0.9 Hz lower sway, which the centred start
// excites). At every sample the forces also balance the bodies' measured absolute accelerations
// (run.output.body_accelerations): sum y_track = sum_b m_b (ay_b - g sin(phi)); the car's ay is
// the centripetal V^2/R cos(phi).
void steadyCurving(const char* method, double cant, double tolerance) {
  const std::string c = std::to_string(cant);
  const hid_t f = run(std::string("scenarios/validation/case2_") + method + ".lua",
                      std::string("curving_") + method + "_" + c + ".h5",
                      {"vehicle.start=175", "run.duration=4", "run.output.body_accelerations=true",
                       "track.segments[2].cant=" + c, "track.segments[3].cant=" + c});
  ASSERT_GE(f, 0) << method;
  const auto t = h5test::dataset(f, "/time");
  const double V = 20.0, R = 500.0;
  const double sin_phi = cant / h5test::numAttr<double>(f, "/track", "cant_base");
  const double cos_phi = std::sqrt(1.0 - sin_phi * sin_phi);
  const double a_u = V * V / R * cos_phi - kGravity * sin_phi;
  const double expected = kWagonMass * a_u;
  std::vector<double> sum(t.size(), 0.0), inertia(t.size(), 0.0);
  for (const char* ws : kWheelsets)
    for (const char* side : kSides) {
      const auto y = h5test::dataset(f, wheel(ws, side) + "y_track");
      ASSERT_EQ(y.size(), t.size());
      for (std::size_t k = 0; k < t.size(); ++k) sum[k] += y[k];
    }
  const std::pair<const char*, double> bodies[] = {
      {"car", 32000.0}, {"bogie1", 2615.0}, {"bogie2", 2615.0}, {"ws1", 1813.0},
      {"ws2", 1813.0},  {"ws3", 1813.0},    {"ws4", 1813.0}};
  for (const auto& [body, mass] : bodies) {
    const auto ay = h5test::dataset(f, std::string("/bodies/") + body + "/ay");
    ASSERT_EQ(ay.size(), t.size()) << body;
    for (std::size_t k = 0; k < t.size(); ++k) inertia[k] += mass * (ay[k] - kGravity * sin_phi);
  }
  const auto ay = h5test::dataset(f, "/bodies/car/ay");
  double mean = 0.0, mean_ay = 0.0, dynamic = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] >= 0.5) dynamic = std::max(dynamic, std::abs(sum[k] - inertia[k]) / expected);
    if (t[k] < t.back() - 2.0) continue;
    mean += sum[k];
    mean_ay += ay[k];
    ++n;
  }
  mean /= n;
  mean_ay /= n;
  const double error = (mean - expected) / expected;
  const double approx = kWagonMass * (V * V / R - kGravity * sin_phi);
  std::printf(
      "[%s, cant %.3f m] curving: sum y_track = %.2f N, M a_u = %.2f N (a_u = %.5f m/s^2): "
      "error %.3f %% (against M (V^2/R - g cant/base) = %.2f N: %.3f %%); max |sum y_track - "
      "sum m (ay - g sin phi)| / (M a_u) = %.3f %%; car ay = %.5f m/s^2 against V^2/R cos(phi) "
      "= %.5f\n",
      method, cant, mean, expected, a_u, 100 * error, approx, 100 * (mean - approx) / approx,
      100 * dynamic, mean_ay, V * V / R * cos_phi);
  EXPECT_LT(std::abs(error), tolerance) << method;
  EXPECT_LT(dynamic, 0.015) << method;
  EXPECT_NEAR(mean_ay, V * V / R * cos_phi, 0.01 * V * V / R) << method;
  H5Fclose(f);
}

// Largest deviations of a wheel from the sum of its patches and of each patch from the
// resolution of its contact-frame forces into the track frame.
struct PatchCheck {
  double wheel_sum = 0.0;  // max |wheel - sum of patches| / Q scale (X, Y, Q, y_track)
  double resolved = 0.0;   // max |patch track force - resolved| / Q scale
  double t_gamma = 0.0;    // max relative |t_gamma - (|fx sx| + |fy sy| + |mz spin|)|
  double power = 0.0;      // max relative |power - t_gamma V|
  int two_point = 0;       // wheel samples in tread + flange contact, both loaded
  double flange_q = 0.0;   // largest Q of a patch 1
  double max_t_gamma = 0.0;
  double max_spin_term = 0.0;  // largest |mz spin| of a patch
};

// Patch p of a wheel (side sigma, wheelset yaw psi): the normal n = (-sin psi nu, cos psi nu,
// cos g) with nu = -sigma sin g (g = contact_angle_track), rolling direction ex = (cos psi,
// sin psi, 0) and ey = n x ex give F = N n + fx ex + fy ey in the track frame.
void checkPatch(const PatchSample& p, double sigma, double psi, double speed, double scale,
                PatchCheck& c) {
  const double nu = -sigma * std::sin(p.gamma_t), nz = std::cos(p.gamma_t);
  const double cp = std::cos(psi), sp = std::sin(psi);
  const double Fx = -p.normal * sp * nu + p.fx * cp - p.fy * nz * sp;
  const double Fy = p.normal * cp * nu + p.fx * sp + p.fy * nz * cp;
  const double Fz = p.normal * nz - p.fy * nu;
  for (const double d : {p.X - Fx, p.y_track - Fy, p.Q - Fz, p.Y + sigma * Fy})
    c.resolved = std::max(c.resolved, std::abs(d) / scale);
  const double tg = std::abs(p.fx * p.sx) + std::abs(p.fy * p.sy) + std::abs(p.mz * p.spin);
  c.t_gamma = std::max(c.t_gamma, std::abs(p.t_gamma - tg) / std::max(1.0, tg));
  c.power = std::max(c.power, std::abs(p.power - tg * speed) / std::max(1.0, tg * speed));
  c.max_t_gamma = std::max(c.max_t_gamma, p.t_gamma);
  c.max_spin_term = std::max(c.max_spin_term, std::abs(p.mz * p.spin));
}

void checkWheel(hid_t f, const char* ws, int s, const std::vector<double>& speed, PatchCheck& c) {
  const std::string base = wheel(ws, kSides[s]);
  const PatchData p0(f, base + "patch0/"), p1(f, base + "patch1/");
  const auto X = h5test::dataset(f, base + "X"), Y = h5test::dataset(f, base + "Y");
  const auto Q = h5test::dataset(f, base + "Q"), yt = h5test::dataset(f, base + "y_track");
  const auto N = h5test::dataset(f, base + "normal_force");
  const auto regime = h5test::dataset(f, base + "regime");
  const auto yaw = h5test::dataset(f, std::string("/bodies/") + ws + "/yaw");
  ASSERT_EQ(p0.active.size(), Q.size());
  ASSERT_EQ(p1.active.size(), Q.size());
  for (std::size_t k = 0; k < Q.size(); ++k) {
    const PatchSample a = p0.at(k), b = p1.at(k);
    const double scale = std::max(1.0, std::abs(Q[k]));
    for (const double d : {X[k] - a.X - b.X, Y[k] - a.Y - b.Y, Q[k] - a.Q - b.Q,
                           yt[k] - a.y_track - b.y_track, N[k] - a.normal - b.normal})
      c.wheel_sum = std::max(c.wheel_sum, std::abs(d) / scale);
    for (const PatchSample& p : {a, b})
      if (p.active > 0.5) checkPatch(p, kSigma[s], yaw[k], speed[k], scale, c);
    // Tread and flange both carrying load (a KEC band inside the tread, which the centred
    // S1002/60E1 wheel sits in, is not a two-point contact in this sense).
    if (regime[k] == 1.0 && a.normal > 1e3 && b.normal > 1e3) {
      ++c.two_point;
      c.flange_q = std::max(c.flange_q, b.Q);
    }
  }
}

PatchCheck checkPatches(hid_t f) {
  PatchCheck c;
  const auto speed = h5test::dataset(f, "/vehicle/speed");
  for (const char* ws : kWheelsets)
    for (int s = 0; s < 2; ++s) checkWheel(f, ws, s, speed, c);
  return c;
}

void report(const char* what, const PatchCheck& c) {
  std::printf(
      "[%s] max |wheel - sum of patches| / Q = %.3e, max |patch - resolved| / Q = %.3e, "
      "two-point samples %d (largest flange-patch Q %.1f N), T gamma rel. error %.3e (largest "
      "%.1f N, spin term %.3f N), power rel. error %.3e\n",
      what, c.wheel_sum, c.resolved, c.two_point, c.flange_q, c.t_gamma, c.max_t_gamma,
      c.max_spin_term, c.power);
}

// Two-point contact. KEC: the sharp curve (R = 150 m, 16 m/s, smooth track) puts the leading
// wheelset's outer wheel into tread + flange contact (both ends A and B of the tread-flange band
// loaded) from t ~ 0.5 s. LUT: on that curve the tread point at the flange root carries the
// curving force and the flange stays clear, so the wheel-climb case (R = 100 m, 5 m/s, mu = 0.5)
// is used, where the leading wheelset's outer wheel has tread and Hertz flange contact from
// t ~ 0.2 s (up to ~33 kN on the flange).
// resolved: tolerance of the patch forces against their resolution with a unit normal; the LUT's
// flange normal is interpolated from its table, unit only to about 1e-4 (the written forces are
// those the model applies, with that normal).
void twoPoint(const char* method, const char* scenario, double resolved) {
  const hid_t f = run(scenario, std::string("two_point_") + method + ".h5",
                      {std::string("contact.method=") + method, "run.duration=1"});
  ASSERT_GE(f, 0) << method;
  const PatchCheck c = checkPatches(f);
  report((std::string("two-point ") + method).c_str(), c);
  EXPECT_GT(c.two_point, 0) << method;
  EXPECT_GT(c.flange_q, 1e3) << method;
  EXPECT_LT(c.wheel_sum, 1e-12) << method;
  EXPECT_LT(c.resolved, resolved) << method;
  EXPECT_LT(c.t_gamma, 1e-12) << method;
  EXPECT_LT(c.power, 1e-12) << method;
  EXPECT_GT(c.max_t_gamma, 0.0) << method;
  H5Fclose(f);
}

}  // namespace

TEST(WheelForces, StaticWheelLoadsOnTangentKec) {
  staticLoads("kec");
}
TEST(WheelForces, StaticWheelLoadsOnTangentLut) {
  staticLoads("lut");
}

// Case 2 as shipped (no cant): within 1 % (measured +0.21 % KEC, -0.19 % LUT).
TEST(WheelForces, SteadyCurvingBalancesUnbalancedAccelerationKec) {
  steadyCurving("kec", 0.0, 0.01);
}
TEST(WheelForces, SteadyCurvingBalancesUnbalancedAccelerationLut) {
  steadyCurving("lut", 0.0, 0.01);
}
// With 50 mm cant the unbalanced acceleration is 0.47 m/s^2 (59 % of V^2/R), so the same force
// error is a larger fraction of it (measured +0.93 % KEC, +0.01 % LUT): 1.5 %.
TEST(WheelForces, SteadyCurvingWithCantKec) {
  steadyCurving("kec", 0.05, 0.015);
}
TEST(WheelForces, SteadyCurvingWithCantLut) {
  steadyCurving("lut", 0.05, 0.015);
}

TEST(WheelForces, TwoPointPatchesAddUpToTheWheelKec) {
  twoPoint("kec", "scenarios/hard/sharp_curve.lua", 1e-12);
}
TEST(WheelForces, TwoPointPatchesAddUpToTheWheelLut) {
  twoPoint("lut", "scenarios/hard/wheel_climb.lua", 1e-3);
}

// T gamma with the spin term: the Kalker linear law gives the spin moment mz.
TEST(WheelForces, TGammaIncludesTheSpinMomentWithKalker) {
  const hid_t f = run("tests/app/data/wheel_forces/tangent.lua", "tgamma_kalker.h5",
                      {"contact.creep=kalker", "run.duration=0.05"});
  ASSERT_GE(f, 0);
  const PatchCheck c = checkPatches(f);
  report("kalker tangent", c);
  EXPECT_GT(c.max_spin_term, 0.0);
  EXPECT_LT(c.t_gamma, 1e-12);
  EXPECT_LT(c.power, 1e-12);
  EXPECT_LT(c.wheel_sum, 1e-12);
  EXPECT_LT(c.resolved, 1e-12);
  H5Fclose(f);
}
