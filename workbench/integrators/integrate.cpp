#include <cmath>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/integrators/detail.hpp"
#include "workbench/integrators/integrator.hpp"

namespace rb::integ {
namespace {

// Time inside integrate(), callbacks included. The process CPU clock is a system call (~1.6 us
// on a VM), so it is read at the start and the end of a run and, for progress reports, at most
// every kCpuRefresh seconds of wall time; callbacks are timed with the (vDSO) wall clock only.
struct Timer {
  static constexpr double kCpuRefresh = 0.2;  // [s]
  double cpu0 = detail::cpuSeconds();
  double wall0 = detail::wallSeconds();
  double callback_wall = 0.0;
  double last_cpu_read = wall0;
  double last_cpu = 0.0;
  void fill(Stats& s, bool exact) {
    const double now = detail::wallSeconds();
    if (exact || now - last_cpu_read >= kCpuRefresh) {
      last_cpu = detail::cpuSeconds() - cpu0;
      last_cpu_read = now;
    }
    s.cpu_time_s = last_cpu;
    s.wall_time_s = now - wall0;
    s.callback_wall_time_s = callback_wall;
  }
  template <class F>
  auto timed(F&& f) {
    const double w = detail::wallSeconds();
    auto r = f();
    callback_wall += detail::wallSeconds() - w;
    return r;
  }
};

void checkArgs(long n, double t0, const Eigen::VectorXd& y0,
               const std::vector<double>& output_times) {
  RB_CHECK(y0.size() == n, "initial state has " + std::to_string(y0.size()) +
                               " entries, the system " + std::to_string(n));
  RB_CHECK(std::isfinite(t0), "t0 must be finite");
  double prev = t0;
  for (double t : output_times) {
    RB_CHECK(std::isfinite(t) && t > prev,
             "output times must be finite, strictly increasing and after t0");
    prev = t;
  }
}

// A non-finite initial state is reported like any other failure, before the method starts.
template <class Sys>
bool nonFiniteStart(const Sys& sys, const Integrator& integ, double t0, const Eigen::VectorXd& y,
                    const char* what, RunResult& res) {
  if (detail::allFinite(y.data(), y.size())) return false;
  res.ok = false;
  res.failure = FailureKind::NonFinite;
  res.t_reached = res.t_fail = t0;
  res.offending_components = detail::nonFiniteComponents(y.data(), y.size());
  res.message = std::string(integ.name()) + ": failed at t = " + formatNumber(t0, 10) +
                ": NaN/Inf in " + what + " " +
                detail::componentList(res.offending_components,
                                      [&sys](int i) { return sys.componentName(i); });
  return true;
}

// Runs `run(observer, progress)` with the callbacks wrapped so that their time is measured and
// the statistics carry the solver's own time (shared by the ODE and DAE entry points).
template <class Run>
RunResult timedRun(const Observer& observer, const Progress& progress, Run run) {
  Timer timer;
  const Observer obs = [&](double t, const Eigen::VectorXd& y) {
    return observer ? timer.timed([&] { return observer(t, y); }) : true;
  };
  Progress prog;
  if (progress) {
    prog = [&](double t, const Stats& s) {
      Stats copy = s;
      timer.fill(copy, false);
      timer.timed([&] {
        progress(t, copy);
        return 0;
      });
    };
  }
  RunResult res = run(obs, prog);
  timer.fill(res.stats, true);
  return res;
}

}  // namespace

RunResult Integrator::runDae(DaeSystem&, double, const Eigen::VectorXd&, const Eigen::VectorXd&,
                             const std::vector<double>&, const Observer&, const Progress&) {
  throw InputError(spec_.loc, "solver.method: '" + std::string(name()) +
                                  "' cannot integrate a DAE model; use 'ida'");
}

RunResult integrate(OdeSystem& sys, Integrator& integrator, double t0, const Eigen::VectorXd& y0,
                    const std::vector<double>& output_times, const Observer& observer,
                    const Progress& progress) {
  checkArgs(sys.size(), t0, y0, output_times);
  RunResult res;
  if (nonFiniteStart(sys, integrator, t0, y0, "the initial state", res)) return res;
  return timedRun(observer, progress, [&](const Observer& obs, const Progress& prog) {
    return integrator.runOde(sys, t0, y0, output_times, obs, prog);
  });
}

RunResult integrate(DaeSystem& sys, Integrator& integrator, double t0, const Eigen::VectorXd& y0,
                    const Eigen::VectorXd& yp0, const std::vector<double>& output_times,
                    const Observer& observer, const Progress& progress) {
  checkArgs(sys.size(), t0, y0, output_times);
  RB_CHECK(yp0.size() == sys.size(), "initial derivative has the wrong size");
  if (!integrator.supportsDae()) {
    throw InputError(integrator.spec().loc, "solver.method: '" + std::string(integrator.name()) +
                                                "' cannot integrate a DAE model; use 'ida'");
  }
  RunResult res;
  if (nonFiniteStart(sys, integrator, t0, y0, "the initial state", res)) return res;
  if (nonFiniteStart(sys, integrator, t0, yp0, "the initial derivative", res)) return res;
  return timedRun(observer, progress, [&](const Observer& obs, const Progress& prog) {
    return integrator.runDae(sys, t0, y0, yp0, output_times, obs, prog);
  });
}

}  // namespace rb::integ
