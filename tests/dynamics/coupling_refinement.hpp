#pragma once
// Step-halving refinement of one scenario under both normal-force couplings (docs/
// contact_dynamics.md section 4.1): the scenario is integrated with RK4 at each step of a halving
// sequence; the difference between consecutive steps (largest |dy| of any wheelset over all
// output times) estimates the error of the coarser one. Writes a CSV that plots/update_docs.py
// turns into the generated block of the docs.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "dyn_fixtures.hpp"

namespace rbtest {

struct RefinementRun {
  double step = 0.0;
  double diff_to_half = -1.0;  // [m] max |y(h) - y(h/2)| over wheelsets and outputs; < 0: none
  double cpu_s = 0.0;
  long rhs_evals = 0;
  double iterations_per_solve = 0.0;  // consistent: Phi evaluations per wheelset solve; lagged 0
};

struct Refinement {
  std::string coupling;
  std::vector<RefinementRun> runs;
};

// Integrates `file` (with `overrides`) to t_end with RK4 at each of `steps` for the coupling.
inline Refinement refine(const std::string& file, const std::vector<std::string>& overrides,
                         const std::string& coupling, const std::vector<double>& steps,
                         double t_end) {
  std::vector<std::string> ov = overrides;
  ov.push_back("contact.normal_forces=" + coupling);
  const Compiled c = compileScenario(file, ov);
  std::vector<std::size_t> ws;
  for (std::size_t b = 0; b < c.vehicle->bodies.size(); ++b)
    if (c.vehicle->bodies[b].kind == vehicle::BodyKind::Wheelset) ws.push_back(b);
  Refinement r;
  r.coupling = coupling;
  std::vector<Trace> traces;
  for (double h : steps) {
    dynamics::ContactVehicleOde ode(*c.vehicle, *c.contact, *c.track);
    traces.push_back(run(ode, solverSpec("rk4", h), t_end, 0.01));
    const Trace& tr = traces.back();
    EXPECT_TRUE(tr.result.ok) << file << " " << coupling << " h = " << h << ": "
                              << tr.result.message;
    RefinementRun rr;
    rr.step = h;
    rr.cpu_s = tr.result.stats.cpu_time_s;
    rr.rhs_evals = tr.result.stats.rhs_evals;
    const auto& st = ode.stats();
    if (c.contact->coupling == dynamics::NormalForceCoupling::Consistent &&
        st.consistent_solves > 0)
      rr.iterations_per_solve =
          static_cast<double>(st.consistent_iterations) / static_cast<double>(st.consistent_solves);
    r.runs.push_back(rr);
  }
  for (std::size_t k = 0; k + 1 < traces.size(); ++k) {
    const Trace& a = traces[k];
    const Trace& b = traces[k + 1];
    double d = 0.0;
    const std::size_t n = std::min(a.t.size(), b.t.size());
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t w : ws)
        d = std::max(d, std::abs(a.q[i][w][vehicle::kY] - b.q[i][w][vehicle::kY]));
    r.runs[k].diff_to_half = d;
  }
  for (const auto& rr : r.runs) {
    char diff[48] = "(finest step)";
    if (rr.diff_to_half >= 0) std::snprintf(diff, sizeof diff, "%.2e mm", rr.diff_to_half * 1e3);
    std::printf(
        "[ coupling ] %s %-10s RK4 h = %.5f ms: max |y(h) - y(h/2)| = %s, CPU %.2f s, %ld rhs, "
        "%.2f us/rhs, %.2f iterations per wheelset solve\n",
        file.c_str(), coupling.c_str(), rr.step * 1e3, diff, rr.cpu_s, rr.rhs_evals,
        1e6 * rr.cpu_s / static_cast<double>(std::max(1L, rr.rhs_evals)), rr.iterations_per_solve);
  }
  return r;
}

// One CSV per case under BUILD/dynamics/ (read by plots/update_docs.py, block
// coupling_convergence of docs/contact_dynamics.md).
inline void writeRefinementCsv(const std::string& name, const std::string& what,
                               const std::vector<Refinement>& rs) {
  const std::filesystem::path dir = std::filesystem::path(RB_BINARY_DIR) / "dynamics";
  std::filesystem::create_directories(dir);
  std::ofstream f(dir / (name + ".csv"));
  f << "# " << what << "\n";
  f << "coupling,step_ms,diff_to_half_step_mm,cpu_s,rhs_evals,us_per_rhs,iterations_per_solve\n";
  char buf[256];
  for (const auto& r : rs)
    for (const auto& rr : r.runs) {
      char diff[32] = "";
      if (rr.diff_to_half >= 0) std::snprintf(diff, sizeof diff, "%.4g", rr.diff_to_half * 1e3);
      std::snprintf(buf, sizeof buf, "%s,%.6g,%s,%.4g,%ld,%.4g,%.4g\n", r.coupling.c_str(),
                    rr.step * 1e3, diff, rr.cpu_s, rr.rhs_evals,
                    1e6 * rr.cpu_s / static_cast<double>(std::max(1L, rr.rhs_evals)),
                    rr.iterations_per_solve);
      f << buf;
    }
}

}  // namespace rbtest
