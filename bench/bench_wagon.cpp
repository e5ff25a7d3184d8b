// Cost of ONE right-hand-side evaluation of the Manchester wagon with wheel/rail contact (paper
// case 3: irregular R = 500 m track, 20 m/s, scenarios/validation/case3_{kec,lut}.lua), and of its
// parts, for docs/performance.md. Run (Release build):
//   ./build/bench/bench_wagon --benchmark_min_time=0.5
// Every benchmark replays the same recorded trajectory: 2000 consecutive states of an ABM 1 ms
// run with a prescribed wheelset spin (t = 4..6 s: tangent and transition, irregular), each
// evaluated twice as ABM does (predictor and corrector at the same time), so warm starts and the
// per-time caches behave as in a run. Counter "per_eval" = CPU time per evaluation (SI prefix: u =
// microseconds).
//   Wagon/{kec,lut}[_free]   the whole rhs (ContactVehicleOde::rhs); _free: free spin (ABM 0.25 ms)
//   Vehicle                  vehicle::evaluate: 7 bodies (kinematics, mass matrices, inertia and
//                            gravity forces) and the 50 suspension elements
//   KecGeometry              the 4 wheelsets' contact constraints: solveKec (warm-started) +
//                            kecQuadraticTerm + KecTable::evalValues of both contact points
//   LutGeometry              the 4 wheelsets' LutTable::evalZPhi + evalValues
//   Creep                    8 patches: Hertz shape (table) + makeContactPatch + polachForce
//   AugmentedSolve           4 wheelsets: factor the augmented system + one solve
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"
#include "workbench/creep/polach.hpp"
#include "workbench/dynamics/augmented.hpp"
#include "workbench/dynamics/contact_model.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/dynamics.hpp"

namespace {

using namespace rb;

struct Setup {
  run::Model model;  // the library's compile(): the same Model a `workbench run` integrates
  std::unique_ptr<dynamics::ContactVehicleOde> ode;
  std::vector<double> t;
  std::vector<Eigen::VectorXd> y;
};

// Compiles the scenario and records the trajectory (once per configuration).
Setup& setup(const std::string& method, bool free_spin) {
  static std::map<std::string, std::unique_ptr<Setup>> all;
  const std::string key = method + (free_spin ? "_free" : "");
  auto& slot = all[key];
  if (slot) return *slot;
  slot = std::make_unique<Setup>();
  Setup& s = *slot;
  run::CompileOptions co;
  co.root = RB_SOURCE_DIR;
  co.scenario = std::string(RB_SOURCE_DIR) + "/scenarios/validation/case3_" + method + ".lua";
  if (!free_spin) co.overrides = {"contact.wheelset_spin=prescribed"};
  s.model = run::compile(co);
  s.ode = std::make_unique<dynamics::ContactVehicleOde>(s.model.lead().vehicle,
                                                        *s.model.lead().contact, *s.model.track);
  integ::SolverSpec solver;
  solver.method = "abm";
  solver.step = free_spin ? 2.5e-4 : 1e-3;
  auto integrator = integ::makeIntegrator(solver);
  std::vector<double> times;
  for (int k = 1; k <= 6000; ++k) times.push_back(1e-3 * k);
  integ::integrate(*s.ode, *integrator, 0.0, s.ode->initialState(0.0), times,
                   [&](double tt, const Eigen::VectorXd& yy) {
                     if (tt > 4.0 - 1e-9) {
                       s.t.push_back(tt);
                       s.y.push_back(yy);
                     }
                     return true;
                   });
  return s;
}

void wagonRhs(benchmark::State& st, const std::string& method, bool free_spin) {
  Setup& s = setup(method, free_spin);
  Eigen::VectorXd yd(s.ode->size());
  std::size_t k = 0;
  long n = 0;
  for (auto _ : st) {
    // Predictor and corrector: two evaluations at one time.
    s.ode->rhs(s.t[k], s.y[k].data(), yd.data());
    s.ode->rhs(s.t[k], s.y[k].data(), yd.data());
    benchmark::DoNotOptimize(yd.data());
    k = (k + 1) % s.t.size();
    n += 2;
  }
  st.counters["us_per_eval"] = benchmark::Counter(
      static_cast<double>(n) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_Wagon_kec(benchmark::State& st) {
  wagonRhs(st, "kec", false);
}
void BM_Wagon_lut(benchmark::State& st) {
  wagonRhs(st, "lut", false);
}
void BM_Wagon_kec_free(benchmark::State& st) {
  wagonRhs(st, "kec", true);
}
void BM_Wagon_lut_free(benchmark::State& st) {
  wagonRhs(st, "lut", true);
}

// The recorded full coordinates of every body (after an rhs at each state).
struct BodyStates {
  std::vector<std::vector<vehicle::Vector6d>> q, qd;
  std::vector<Eigen::VectorXd> series;
};
const BodyStates& bodyStates() {
  static const BodyStates b = [] {
    Setup& s = setup("kec", false);
    BodyStates r;
    Eigen::VectorXd yd(s.ode->size());
    const auto& l = s.ode->layout();
    for (std::size_t k = 0; k < s.t.size(); ++k) {
      s.ode->rhs(s.t[k], s.y[k].data(), yd.data());
      r.q.push_back(s.ode->workspace().q);
      r.qd.push_back(s.ode->workspace().qd);
      r.series.push_back(s.y[k].segment(l.series(0), l.n_series));
    }
    return r;
  }();
  return b;
}

void BM_Vehicle(benchmark::State& st) {
  Setup& s = setup("kec", false);
  const BodyStates& b = bodyStates();
  vehicle::Workspace ws = vehicle::makeWorkspace(s.model.lead().vehicle);
  std::size_t k = 0;
  long n = 0;
  for (auto _ : st) {
    ws.q = b.q[k];
    ws.qd = b.qd[k];
    for (int r = 0; r < 2; ++r)
      vehicle::evaluate(s.model.lead().vehicle, 0.0, b.series[k].data(), ws);
    benchmark::DoNotOptimize(ws.force.data());
    k = (k + 1) % b.q.size();
    n += 2;
  }
  st.counters["us_per_eval"] = benchmark::Counter(
      static_cast<double>(n) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_KecGeometry(benchmark::State& st) {
  Setup& s = setup("kec", false);
  const BodyStates& b = bodyStates();
  const contact::KecTable& tab = *s.model.lead().contact->kec;
  const track::Irregularities* irr =
      s.model.track->irregularities() ? &*s.model.track->irregularities() : nullptr;
  std::vector<contact::KecSolution> warm(s.model.lead().contact->wheelsets.size());
  std::vector<bool> has(warm.size(), false);
  std::size_t k = 0;
  long n = 0;
  contact::KecPoint kp;
  double sink = 0.0;
  for (auto _ : st) {
    for (int r = 0; r < 2; ++r) {
      for (std::size_t w = 0; w < warm.size(); ++w) {
        const auto& q = b.q[k][static_cast<std::size_t>(s.model.lead().contact->wheelsets[w])];
        const auto& qd = b.qd[k][static_cast<std::size_t>(s.model.lead().contact->wheelsets[w])];
        track::IrregularityPoint ip;
        if (irr) ip = irr->at(q[vehicle::kS]);
        const contact::KecInput in{q[vehicle::kY], ip.y_l, ip.y_r, ip.z_l, ip.z_r};
        const contact::KecSolution sol = contact::solveKec(tab, in, has[w] ? &warm[w] : nullptr);
        warm[w] = sol;
        has[w] = true;
        Eigen::Matrix<double, 5, 1> pd;
        pd << qd[vehicle::kY], 20 * ip.y_l_s, 20 * ip.y_r_s, 20 * ip.z_l_s, 20 * ip.z_r_s;
        const Eigen::Vector4d xd = sol.dx_dp * pd;
        sink += contact::kecQuadraticTerm(sol, xd)(0);
        tab.evalValues(contact::Side::Left, sol.s_lk, kp);
        sink += kp.value[1];  // Sw (evalValues leaves F)
        tab.evalValues(contact::Side::Right, sol.s_rk, kp);
        sink += kp.value[1];  // Sw (evalValues leaves F)
      }
    }
    benchmark::DoNotOptimize(sink);
    k = (k + 1) % b.q.size();
    n += 2;
  }
  st.counters["us_per_eval"] = benchmark::Counter(
      static_cast<double>(n) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_LutGeometry(benchmark::State& st) {
  Setup& s = setup("lut", false);
  const BodyStates& b = bodyStates();
  const contact::LutTable& lut = *s.model.lead().contact->lut;
  const track::Irregularities* irr =
      s.model.track->irregularities() ? &*s.model.track->irregularities() : nullptr;
  std::size_t k = 0;
  long n = 0;
  contact::LutSample ls;
  contact::LutValue zv, pv;
  double sink = 0.0;
  for (auto _ : st) {
    for (int r = 0; r < 2; ++r) {
      for (int w : s.model.lead().contact->wheelsets) {
        const auto& q = b.q[k][static_cast<std::size_t>(w)];
        track::IrregularityPoint ip;
        if (irr) ip = irr->at(q[vehicle::kS]);
        const double ybar = q[vehicle::kY] - ip.xi[0];
        lut.evalZPhi(ybar, ip.xi[2], zv, pv);
        lut.evalValues(ybar, ip.xi[2], ls);
        sink += zv.v + ls.value[0];
      }
    }
    benchmark::DoNotOptimize(sink);
    k = (k + 1) % b.q.size();
    n += 2;
  }
  st.counters["us_per_eval"] = benchmark::Counter(
      static_cast<double>(n) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// 8 tread patches with the wheel outputs of the recorded states (creepages, normal forces) and
// tread curvatures (wheel rolling radius 0.46 m, transverse wheel/rail curvatures of the S1002 /
// 60E1 tread: A = 1.09, B = 3.3 1/m).
void BM_Creep(benchmark::State& st) {
  Setup& s = setup("kec", false);
  const dynamics::ContactModel& c = *s.model.lead().contact;
  std::vector<dynamics::WheelOutput> wo(2 * c.wheelsets.size());
  std::vector<std::vector<dynamics::WheelOutput>> rec;
  for (std::size_t k = 0; k < s.t.size(); k += 7) {
    s.ode->wheelOutputs(s.t[k], s.y[k].data(), wo);
    rec.push_back(wo);
  }
  std::size_t k = 0;
  long n = 0;
  double sink = 0.0;
  for (auto _ : st) {
    for (int r = 0; r < 2; ++r) {
      for (const auto& w : rec[k]) {
        const auto& p = w.patch[0];
        const creep::RelativeCurvatures kc{1.09, 3.3};
        const creep::HertzShape shape = c.hertz_shapes->shape(kc.A, kc.B);
        const creep::ContactPatch cp = creep::makeContactPatch(c.material, kc, shape, p.normal);
        const creep::CreepForce f =
            creep::polachForce(c.creep_params, cp, {p.sx, p.sy, p.spin, 20.0});
        sink += f.fx + f.fy;
      }
    }
    benchmark::DoNotOptimize(sink);
    k = (k + 1) % rec.size();
    n += 2;
  }
  st.counters["us_per_eval"] = benchmark::Counter(
      static_cast<double>(n) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_AugmentedSolve(benchmark::State& st) {
  Setup& s = setup("kec", false);
  const auto& ws = s.ode->workspace();
  Eigen::VectorXd yd(s.ode->size());
  s.ode->rhs(s.t[0], s.y[0].data(), yd.data());
  std::vector<Eigen::Matrix<double, 5, 5>> M;
  for (int w : s.model.lead().contact->wheelsets)
    M.push_back(ws.mass[static_cast<std::size_t>(w)].block<5, 5>(1, 1));
  Eigen::Matrix<double, 5, 2> N = Eigen::Matrix<double, 5, 2>::Zero();
  N << 0.05, -0.05, 0.99, 0.99, -0.75, 0.75, 0.0, 0.0, 0.001, -0.001;
  Eigen::Matrix<double, 2, 5> G = Eigen::Matrix<double, 2, 5>::Zero();
  G << -0.05, 1, 0, 0, 0, -0.07, 0, 1, 0, 0;
  Eigen::Matrix<double, 7, 1> r = Eigen::Matrix<double, 7, 1>::Constant(1.0);
  dynamics::AugmentedSolver solver;
  long n = 0;
  double sink = 0.0;
  for (auto _ : st) {
    for (const auto& m : M) {
      solver.factor(m, N, G, true, 0.0);
      sink += solver.solve(r)(0);
    }
    benchmark::DoNotOptimize(sink);
    ++n;
  }
  st.counters["us_per_eval"] = benchmark::Counter(
      static_cast<double>(n) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(BM_Wagon_kec);
BENCHMARK(BM_Wagon_lut);
BENCHMARK(BM_Wagon_kec_free);
BENCHMARK(BM_Wagon_lut_free);
BENCHMARK(BM_Vehicle);
BENCHMARK(BM_KecGeometry);
BENCHMARK(BM_LutGeometry);
BENCHMARK(BM_Creep);
BENCHMARK(BM_AugmentedSolve);

}  // namespace

BENCHMARK_MAIN();
