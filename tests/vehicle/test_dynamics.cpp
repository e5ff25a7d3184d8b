// Acceptance tests of issue 5 with the wheelsets following the track kinematically
// (GuidedVehicleOde): static equilibrium, modal check (free decay vs eigenvalues), energy
// conservation, quasi-static curving, mirror symmetry, traction output.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include "fixtures.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/vehicle/guided.hpp"
#include "workbench/vehicle/modal.hpp"

namespace rb::vehicle {
namespace {

constexpr double g = 9.81;
constexpr double m_car = 32000.0, m_bogie = 2615.0;
constexpr double k_sz = 430e3, k_pz = 1220e3;

std::vector<double> grid(double dt, double t_end) {
  std::vector<double> out;
  const long n = std::lround(t_end / dt);
  for (long k = 1; k <= n; ++k) out.push_back(static_cast<double>(k) * dt);
  return out;
}

struct History {
  std::vector<double> t;
  std::vector<Eigen::VectorXd> y;
};

History simulate(integ::OdeSystem& ode, const Eigen::VectorXd& y0, const integ::SolverSpec& s,
                 double dt_out, double t_end) {
  auto integ = integ::makeIntegrator(s);
  History r;
  const auto res = integ::integrate(ode, *integ, 0.0, y0, grid(dt_out, t_end),
                                    [&](double t, const Eigen::VectorXd& y) {
                                      r.t.push_back(t);
                                      r.y.push_back(y);
                                      return true;
                                    });
  EXPECT_TRUE(res.ok) << res.message;
  return r;
}

integ::SolverSpec rk4(double step) {
  integ::SolverSpec s;
  s.method = "rk4";
  s.step = step;
  return s;
}

// Matrix pencil fit of x_k = sum a_i exp(s_i k dt): returns the complex exponent s_i of the
// component with the largest amplitude among the oscillating ones (Im s > 0).
std::complex<double> dominantPole(const std::vector<double>& x, double dt) {
  const int N = static_cast<int>(x.size());
  const int L = N / 3;
  Eigen::MatrixXd Y(N - L, L + 1);
  for (int i = 0; i < N - L; ++i)
    for (int j = 0; j <= L; ++j) Y(i, j) = x[static_cast<std::size_t>(i + j)];
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(Y, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  int M = 0;
  while (M < sv.size() && M < 16 && sv[M] > 1e-7 * sv[0]) ++M;
  const Eigen::MatrixXd V = svd.matrixV().leftCols(M);
  const Eigen::MatrixXd V1 = V.topRows(L), V2 = V.bottomRows(L);
  const Eigen::MatrixXd A = V1.completeOrthogonalDecomposition().solve(V2);
  const Eigen::VectorXcd z = A.transpose().eigenvalues();
  // Amplitudes by least squares.
  Eigen::MatrixXcd Z(N, M);
  for (int k = 0; k < N; ++k)
    for (int i = 0; i < M; ++i) Z(k, i) = std::pow(z[i], k);
  const Eigen::VectorXcd xc =
      Eigen::Map<const Eigen::VectorXd>(x.data(), N).cast<std::complex<double>>();
  const Eigen::VectorXcd a = Z.colPivHouseholderQr().solve(xc);
  int best = -1;
  for (int i = 0; i < M; ++i) {
    if (!(std::arg(z[i]) > 1e-6)) continue;
    if (best < 0 || std::abs(a[i]) > std::abs(a[best])) best = i;
  }
  EXPECT_GE(best, 0);
  return best < 0 ? 0.0 : std::log(z[best]) / dt;
}

class Manchester : public ::testing::Test {
 protected:
  static const track::TrackModel& straight() {
    static const track::TrackModel tm = track::compileTrack(rbtest::tangentTrack(400.0));
    return tm;
  }
};

TEST_F(Manchester, StaticEquilibriumDeflectionsFollowTheLoadPaths) {
  const VehicleModel m = compileVehicle(rbtest::manchesterFixture(20.0, 20.0), straight());
  GuidedVehicleOde ode(m);
  const Eigen::VectorXd y = ode.staticState(0.0);
  // At rest: all rates zero.
  Eigen::VectorXd yd(ode.size());
  ASSERT_EQ(ode.rhs(0.0, y.data(), yd.data()), 0);
  EXPECT_LT(yd.lpNorm<Eigen::Infinity>(), 1e-9);
  // Secondary: the car on 4 springs; primary: half the car and a bogie on 4 springs.
  const double d_sec = m_car * g / 4 / k_sz;
  const double d_prim = (m_car / 2 + m_bogie) * g / 4 / k_pz;
  int checked = 0;
  for (const ElementId& id : m.elements()) {
    if (id.kind != ElementKind::SeriesSpringDamper) continue;
    ElementValue v;
    ode.elementOutputs(0.0, y.data(), {&id, 1}, {&v, 1});
    const std::string& name = m.element(id).name;
    const double expected = name.starts_with("sec_") ? d_sec : d_prim;
    EXPECT_NEAR(v.d, expected, 1e-3 * expected) << name;  // acceptance: 0.1 %
    EXPECT_NEAR(v.d, expected, 1e-8 * expected) << name;  // achieved
    EXPECT_NEAR(v.force, (name.starts_with("sec_") ? k_sz : k_pz) * expected, 1e-6) << name;
    ++checked;
  }
  EXPECT_EQ(checked, 12);
  EXPECT_NEAR(y[ode.index(m.findBody("car"), kZ)], -(d_sec + d_prim), 1e-9);
  EXPECT_NEAR(y[ode.index(m.findBody("bogie2"), kZ)], -d_prim, 1e-9);
  for (Coord c : {kY, kRoll, kPitch, kYaw}) EXPECT_NEAR(y[ode.index(0, c)], 0.0, 1e-12);
  std::printf("static deflection: secondary %.6f m (m g / 4 k = %.6f), primary %.6f m\n",
              y[ode.index(0, kZ)] + d_prim, -d_sec, -d_prim);
}

TEST_F(Manchester, TractionBalancesTheGradient) {
  // Uphill gradient 2 % after a 40 m ramp; the wagon stands fully on the constant gradient.
  using K = track::SegmentKind;
  track::TrackSpec ts;
  ts.segments = {rbtest::segment(K::Tangent, 20),
                 rbtest::segment(K::Transition, 40, 0, track::Side::Left, 0, 0.02),
                 rbtest::segment(K::Tangent, 300, 0, track::Side::Left, 0, 0.02)};
  ts.loc = {"t.lua", 1};
  const track::TrackModel tm = track::compileTrack(ts);
  const VehicleModel m = compileVehicle(rbtest::manchesterFixture(20.0, 150.0), tm);
  GuidedVehicleOde ode(m);
  const Eigen::VectorXd y = ode.staticState(0.0);
  double traction = 0.0, mass = 0.0;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    traction += ode.bodyOutput(0.0, y.data(), static_cast<int>(b)).traction;
    mass += m.bodies[b].mass;
  }
  const double expected = mass * g * std::sin(std::atan(0.02));
  EXPECT_NEAR(traction, expected, 1e-6 * expected);
}

// Mode with the largest participation of `component` (and bogies in phase if asked).
const Mode& modeOf(const std::vector<Mode>& modes, int component, int in_phase_with = -1) {
  const Mode* best = nullptr;
  for (const Mode& md : modes) {
    if (in_phase_with >= 0 &&
        (md.shape[component] * std::conj(md.shape[in_phase_with])).real() <= 0.0)
      continue;
    if (!best || md.participation[component] > best->participation[component]) best = &md;
  }
  EXPECT_NE(best, nullptr);
  return *best;
}

TEST_F(Manchester, FreeDecayFrequenciesMatchEigenvalues) {
  const VehicleModel m = compileVehicle(rbtest::manchesterFixture(20.0, 20.0), straight());
  GuidedVehicleOde ode(m);
  const Eigen::VectorXd y0 = ode.staticState(0.0);
  const std::vector<Mode> modes = guidedModes(ode, 0.0, y0);
  const int car = m.findBody("car"), b1 = m.findBody("bogie1"), b2 = m.findBody("bogie2");
  struct Case {
    const char* name;
    const Mode* mode;
    std::vector<std::pair<int, double>> kick;  // state index, displacement
    int observe;
    double dt_out, t_end;
  };
  const Mode& bounce = modeOf(modes, ode.index(car, kZ));
  const Mode& roll = modeOf(modes, ode.index(car, kRoll));
  const Mode& bogie = modeOf(modes, ode.index(b1, kZ), ode.index(b2, kZ));
  const std::vector<Case> cases = {
      {"car bounce", &bounce, {{ode.index(car, kZ), 0.01}}, ode.index(car, kZ), 0.01, 8.0},
      {"car roll", &roll, {{ode.index(car, kRoll), 0.005}}, ode.index(car, kRoll), 0.01, 8.0},
      {"bogie bounce",
       &bogie,
       {{ode.index(b1, kZ), 0.002}, {ode.index(b2, kZ), 0.002}},
       ode.index(b1, kZ),
       0.002,
       1.5},
  };
  for (const Case& c : cases) {
    Eigen::VectorXd y = y0;
    for (const auto& [i, dx] : c.kick) y[i] += dx;
    const History r = simulate(ode, y, rk4(1e-3), c.dt_out, c.t_end);
    std::vector<double> x;
    for (const auto& s : r.y) x.push_back(s[c.observe] - y0[c.observe]);
    const std::complex<double> s = dominantPole(x, c.dt_out);
    const double f_fit = s.imag() / (2 * std::numbers::pi);
    std::printf(
        "%-13s free decay %.5f Hz (zeta %.4f)  eigenvalue %.5f Hz (zeta %.4f), "
        "participation %.3f\n",
        c.name, f_fit, -s.real() / std::abs(s), c.mode->frequency_hz, c.mode->damping_ratio,
        c.mode->participation[c.observe]);
    EXPECT_NEAR(f_fit, c.mode->frequency_hz, 0.02 * c.mode->frequency_hz) << c.name;  // acceptance
    EXPECT_NEAR(f_fit, c.mode->frequency_hz, 1e-3 * c.mode->frequency_hz) << c.name;  // achieved
    EXPECT_GT(c.mode->participation[c.observe], 0.3) << c.name;
  }
  // Plausibility against a hand estimate of the undamped vertical 2-DOF system (car on 4
  // secondary springs, each bogie on 4 primary springs): within 5 %.
  const double k2 = 4 * k_sz, k1 = 8 * k_pz, mc = m_car, mb = 2 * m_bogie;
  const double a = mc * mb, bq = -(mc * (k1 + k2) + mb * k2), cq = k1 * k2;
  const double w_lo = std::sqrt((-bq - std::sqrt(bq * bq - 4 * a * cq)) / (2 * a));
  const double w_hi = std::sqrt((-bq + std::sqrt(bq * bq - 4 * a * cq)) / (2 * a));
  EXPECT_NEAR(bounce.undamped_hz, w_lo / (2 * std::numbers::pi), 0.05 * bounce.undamped_hz);
  EXPECT_NEAR(bogie.undamped_hz, w_hi / (2 * std::numbers::pi), 0.05 * bogie.undamped_hz);
}

TEST_F(Manchester, ModeTableAndRhsCost) {
  // Prints the modes of the guided wagon (docs/vehicle.md) and the cost of one rhs evaluation.
  const VehicleModel m = compileVehicle(rbtest::manchesterFixture(20.0, 20.0), straight());
  GuidedVehicleOde ode(m);
  const Eigen::VectorXd y0 = ode.staticState(0.0);
  const std::vector<Mode> modes = guidedModes(ode, 0.0, y0);
  EXPECT_EQ(modes.size(), 15u);  // 3 free bodies x 5 coordinates, all oscillatory
  for (const Mode& md : modes)
    std::printf("mode %8.3f Hz  zeta %.3f  dominant %-12s (%.2f)\n", md.frequency_hz,
                md.damping_ratio, ode.componentName(md.dominant).c_str(),
                md.participation[md.dominant]);
  Eigen::VectorXd yd(ode.size());
  const int n = 20000;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < n; ++k) ode.rhs(1e-4 * k, y0.data(), yd.data());
  const double us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / n;
  std::printf("rhs: %.2f us per evaluation (7 bodies, 48 elements, %d states)\n", us, ode.size());
}

TEST_F(Manchester, EnergyIsConservedWithoutDampersAndDecaysWithThem) {
  for (const bool damped : {false, true}) {
    VehicleSpec spec = rbtest::manchesterFixture(20.0, 20.0);
    if (!damped) spec = rbtest::withoutDampers(spec);
    const VehicleModel m = compileVehicle(spec, straight());
    GuidedVehicleOde ode(m);
    const Eigen::VectorXd ys = ode.staticState(0.0);
    const double E_static = ode.energy(0.0, ys.data()).total();
    Eigen::VectorXd y0 = ys;
    const int car = m.findBody("car"), b1 = m.findBody("bogie1"), b2 = m.findBody("bogie2");
    y0[ode.index(car, kY)] += 0.01;
    y0[ode.index(car, kZ)] += 0.02;
    y0[ode.index(car, kRoll)] += 0.01;
    y0[ode.index(car, kYaw)] += 0.001;
    y0[ode.index(car, kPitch, true)] += 0.01;
    y0[ode.index(b1, kZ)] += 0.003;
    y0[ode.index(b1, kY)] -= 0.002;
    y0[ode.index(b2, kYaw)] += 0.001;
    y0[ode.index(b2, kRoll, true)] += 0.05;
    const double t_end = damped ? 3.0 : 1.0;
    const History r = simulate(ode, y0, rk4(1e-4), 0.01, t_end);
    const double E0 = ode.energy(0.0, y0.data()).total();
    const double scale = E0 - E_static;  // energy of the perturbation
    ASSERT_GT(scale, 100.0);
    double drift = 0.0, prev = E0, rise = 0.0;
    for (std::size_t k = 0; k < r.t.size(); ++k) {
      const double E = ode.energy(r.t[k], r.y[k].data()).total();
      drift = std::max(drift, std::abs(E - E0) / scale);
      rise = std::max(rise, (E - prev) / scale);
      prev = E;
    }
    const double E_end = ode.energy(r.t.back(), r.y.back().data()).total();
    if (!damped) {
      std::printf(
          "undamped: perturbation energy %.1f J, max relative drift %.2e over %.0f s (rk4 "
          "1e-4 s)\n",
          scale, drift, t_end);
      EXPECT_LT(drift, 1e-6);
    } else {
      std::printf("damped: energy above static %.1f J -> %.1f J after %.0f s, max rise %.1e\n",
                  scale, E_end - E_static, t_end, rise);
      EXPECT_LT(E_end - E_static, 0.2 * scale);
      EXPECT_LT(rise, 1e-9);  // dissipation D d_dot^2 + f^2 / D >= 0: never increases
    }
  }
}

TEST(Curving, QuasiStaticForceBalanceOfCantedCurve) {
  // Left curve R = 500 m, cant 100 mm on 1.5 m; V = 20 m/s (cant deficiency). Wagon fully in the
  // constant curve.
  const double R = 500.0, cant = 0.1, V = 20.0;
  const track::TrackModel tm =
      track::compileTrack(rbtest::curveTrack(track::Side::Left, R, cant, 40.0, 60.0, 400.0));
  const VehicleModel m = compileVehicle(rbtest::manchesterFixture(V, 250.0), tm);
  GuidedVehicleOde ode(m);
  const Eigen::VectorXd y = ode.staticState(0.0);
  const double phi = -std::asin(cant / 1.5);  // track cant angle: left curve, right rail raised
  for (const char* name : {"car", "bogie1", "bogie2"}) {
    const int b = m.findBody(name);
    const Body& body = m.bodies[static_cast<std::size_t>(b)];
    const double yb = y[ode.index(b, kY)], H = body.height + y[ode.index(b, kZ)];
    // Hand calculation: the CoM runs on a horizontal circle of radius R - l at angular speed V/R,
    // l = its horizontal offset towards the curve centre.
    const double l = yb * std::cos(phi) - H * std::sin(phi);
    const double a_h = (V / R) * (V / R) * (R - l);
    const double Fy = body.mass * (a_h * std::cos(phi) + g * std::sin(phi));
    const double Fz = body.mass * (-a_h * std::sin(phi) + g * std::cos(phi));
    const BodyOutput out = ode.bodyOutput(0.0, y.data(), b);
    std::printf(
        "%-7s lateral suspension force %10.3f N (hand %10.3f N), vertical %12.3f N (hand "
        "%12.3f N)\n",
        name, out.suspension_force.y(), Fy, out.suspension_force.z(), Fz);
    EXPECT_NEAR(out.suspension_force.y(), Fy, 1e-3 * std::abs(Fy)) << name;  // acceptance 0.1 %
    EXPECT_NEAR(out.suspension_force.y(), Fy, 1e-7 * body.mass * g) << name;
    EXPECT_NEAR(out.suspension_force.z(), Fz, 1e-7 * body.mass * g) << name;
    // The brief's form m (V^2/R cos|phi| - g sin|phi|) for the centreline radius: 0.1 % with the
    // CoM offset neglected.
    const double Fy_simple = body.mass * (V * V / R * std::cos(phi) + g * std::sin(phi));
    EXPECT_NEAR(out.suspension_force.y(), Fy_simple, 0.01 * std::abs(Fy_simple)) << name;
    // Felt (specific force) lateral acceleration equals the suspension force / mass, as the body
    // is at rest in its track frame.
    EXPECT_NEAR(out.specific_force.y(), Fy / body.mass, 1e-6) << name;
  }
  // The car centre sits inside the chord of its bogie pivots: y ~ 9.5^2 / (2 R) = 90 mm towards
  // the centre, less ~3 mm because the car rolls outwards (cant deficiency) about its low
  // suspension points.
  EXPECT_NEAR(y[ode.index(0, kY)], 9.5 * 9.5 / (2 * R), 5e-3);
  // Leaning outwards = positive roll in a left curve (the left, inner side rises).
  EXPECT_GT(y[ode.index(0, kRoll)], 0.0);
}

TEST(Curving, LeftAndRightCurvesGiveMirroredResponses) {
  History runs[2];
  VehicleModel models[2];
  for (int i = 0; i < 2; ++i) {
    const track::Side side = i == 0 ? track::Side::Left : track::Side::Right;
    const track::TrackModel tm =
        track::compileTrack(rbtest::curveTrack(side, 300.0, 0.1, 40.0, 60.0, 200.0));
    models[i] = compileVehicle(rbtest::manchesterFixture(20.0, 10.0), tm);
    GuidedVehicleOde ode(models[i]);
    const Eigen::VectorXd y0 = ode.staticState(0.0);
    runs[i] = simulate(ode, y0, rk4(1e-3), 0.05, 5.0);
  }
  const VehicleModel& m = models[0];
  GuidedVehicleOde ode(m);
  double max_y = 0.0, max_err = 0.0;
  for (std::size_t k = 0; k < runs[0].t.size(); ++k) {
    const Eigen::VectorXd& L = runs[0].y[k];
    const Eigen::VectorXd& Rr = runs[1].y[k];
    for (int b : ode.layout().free_bodies) {
      for (Coord c : {kY, kZ, kRoll, kPitch, kYaw}) {
        for (bool rate : {false, true}) {
          const int i = ode.index(b, c, rate);
          const double sign = (c == kY || c == kRoll || c == kYaw) ? -1.0 : 1.0;
          max_err = std::max(max_err, std::abs(L[i] - sign * Rr[i]));
          if (c == kY && !rate) max_y = std::max(max_y, std::abs(L[i]));
        }
      }
    }
    // Series damper forces: left element <-> right element.
    for (int e = 0; e < ode.layout().n_series; ++e) {
      std::string name = m.series_dampers[static_cast<std::size_t>(e)].g.name;
      name.back() = name.back() == 'l' ? 'r' : 'l';
      const auto mirror = m.findElement(name);
      ASSERT_TRUE(mirror.has_value()) << name;
      max_err = std::max(
          max_err, std::abs(L[ode.layout().series(e)] - Rr[ode.layout().series(mirror->index)]) *
                       1e-6);  // [N] -> scaled to metres for one tolerance
    }
  }
  std::printf("mirror: max |car y| %.4f m, max mirror error %.2e\n", max_y, max_err);
  EXPECT_GT(max_y, 1e-3);  // the response is not trivial
  EXPECT_LT(max_err, 1e-10);
  // Left curve: the car moves towards the curve centre (+y), yaws left in the curve.
  const Eigen::VectorXd& end = runs[0].y.back();
  EXPECT_GT(end[ode.index(0, kY)], 0.0);
}

TEST(Curving, BdfAgreesWithRk4OnCurveEntry) {
  const track::TrackModel tm =
      track::compileTrack(rbtest::curveTrack(track::Side::Left, 300.0, 0.1, 40.0, 60.0, 200.0));
  const VehicleModel m = compileVehicle(rbtest::manchesterFixture(20.0, 30.0), tm);
  GuidedVehicleOde ode(m);
  const Eigen::VectorXd y0 = ode.staticState(0.0);
  integ::SolverSpec bdf;
  bdf.method = "bdf";
  bdf.step = 0.0;
  bdf.rtol = 1e-7;
  bdf.atol = 1e-7;  // metres, radians, and newtons for the Maxwell forces
  bdf.max_steps = 100000;
  const History a = simulate(ode, y0, rk4(1e-3), 0.5, 3.0);
  const History b = simulate(ode, y0, bdf, 0.5, 3.0);
  ASSERT_EQ(a.y.size(), b.y.size());
  const int n = 10 * ode.layout().n_free;  // body states (metres, radians and rates)
  for (std::size_t k = 0; k < a.y.size(); ++k)
    EXPECT_LT((a.y[k].head(n) - b.y[k].head(n)).lpNorm<Eigen::Infinity>(), 1e-5) << a.t[k];
}

}  // namespace
}  // namespace rb::vehicle
