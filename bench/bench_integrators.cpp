// Integrator overhead per step on a cheap ODE: a 40-state chain of 20 unit masses coupled by
// springs (k = 1e3) with light damping. The rhs costs ~40 flops, so the time per step is mostly
// the integrator's own work (vector updates, error control, Newton/LU for bdf).
//
// Counters per benchmark:
//   steps        accepted steps per run
//   rhs/step     rhs evaluations per step (bdf: including finite-difference Jacobian columns)
//   ns/step      wall time per step of a whole run
//   overhead_ns  ns/step minus (rhs/step x the measured cost of one rhs call)
#include <benchmark/benchmark.h>

#include <chrono>

#include "workbench/integrators/registry.hpp"

namespace {

using rb::integ::OdeSystem;

class Chain final : public OdeSystem {
 public:
  static constexpr int kMasses = 20;
  int size() const override { return 2 * kMasses; }
  int rhs(double, const double* y, double* yd) override {
    const double* x = y;
    const double* v = y + kMasses;
    for (int i = 0; i < kMasses; ++i) {
      const double left = i > 0 ? x[i - 1] : 0.0;
      const double right = i + 1 < kMasses ? x[i + 1] : 0.0;
      yd[i] = v[i];
      yd[kMasses + i] = -k_ * (2.0 * x[i] - left - right) - c_ * v[i];
    }
    return 0;
  }

 private:
  double k_ = 1e3;
  double c_ = 0.5;
};

Eigen::VectorXd initialState() {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(2 * Chain::kMasses);
  y(0) = 0.01;  // displace the first mass
  return y;
}

// Cost of one rhs call [ns], measured once.
double rhsNs() {
  static const double ns = [] {
    Chain c;
    Eigen::VectorXd y = initialState(), yd(y.size());
    constexpr int kCalls = 200000;
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < kCalls; ++i) {
      c.rhs(0.0, y.data(), yd.data());
      benchmark::DoNotOptimize(yd.data());
      y(1) += 1e-12;
    }
    const auto t1 = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::nano>(t1 - t0).count() / kCalls;
  }();
  return ns;
}

void runMethod(benchmark::State& state, const char* method) {
  rb::integ::SolverSpec spec;
  spec.method = method;
  const bool fixed = spec.method == "rk4" || spec.method == "abm";
  spec.step = fixed ? 1e-3 : 0.0;
  spec.rtol = 1e-6;
  spec.atol = 1e-9;
  auto integ = rb::integ::makeIntegrator(spec);
  std::vector<double> out;
  for (int k = 1; k <= 100; ++k) out.push_back(0.01 * k);  // 1 s, output every 10 ms
  Chain sys;
  const Eigen::VectorXd y0 = initialState();
  long steps = 0, evals = 0;
  double wall = 0.0;
  for (auto _ : state) {
    const auto r = rb::integ::integrate(sys, *integ, 0.0, y0, out,
                                        [](double, const Eigen::VectorXd&) { return true; });
    if (!r.ok) {
      state.SkipWithError(r.message.c_str());
      return;
    }
    steps += r.stats.steps;
    evals += r.stats.rhs_evals + r.stats.rhs_evals_jac;
    wall += r.stats.wall_time_s;
  }
  const double n = static_cast<double>(steps);
  state.SetItemsProcessed(steps);
  state.counters["steps"] = n / static_cast<double>(state.iterations());
  state.counters["rhs/step"] = static_cast<double>(evals) / n;
  state.counters["ns/step"] = 1e9 * wall / n;
  state.counters["overhead_ns"] = 1e9 * wall / n - rhsNs() * static_cast<double>(evals) / n;
}

void BM_rhs(benchmark::State& state) {
  Chain c;
  Eigen::VectorXd y = initialState(), yd(y.size());
  for (auto _ : state) {
    c.rhs(0.0, y.data(), yd.data());
    benchmark::DoNotOptimize(yd.data());
    benchmark::ClobberMemory();
  }
}

}  // namespace

BENCHMARK(BM_rhs);
BENCHMARK_CAPTURE(runMethod, rk4, "rk4")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(runMethod, abm, "abm")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(runMethod, dopri5, "dopri5")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(runMethod, bdf, "bdf")->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
