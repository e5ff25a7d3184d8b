#include "workbench/critical_speed/runs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "workbench/core/strings.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/vehicle_run.hpp"
#include "workbench/vehicle/kinematics.hpp"

namespace fs = std::filesystem;

namespace rb::critical_speed {

namespace {

std::vector<std::string> runOverrides(const RunSetup& s, double v0, double a, double duration) {
  std::vector<std::string> o = s.overrides;
  o.push_back("vehicle.speed=" + formatNumberExact(v0));
  o.push_back("vehicle.acceleration=" + formatNumberExact(a));
  o.push_back("run.duration=" + formatNumberExact(duration));
  if (s.drop_irregularities) o.emplace_back("run.effects.irregularities=false");
  if (s.en14363) o.emplace_back("run.assessment.stability=true");
  return o;
}

std::vector<std::string> wheelsetNames(const run::Model& m) {
  std::vector<std::string> names;
  for (const auto& b : m.lead().vehicle.bodies)
    if (b.kind == vehicle::BodyKind::Wheelset) names.push_back(b.name);
  return names;
}

// Travelled time at which the vehicle has covered distance d: V0 t + a t^2 / 2 = d.
double timeAtDistance(double v0, double a, double d) {
  if (a == 0.0) return v0 > 0.0 ? d / v0 : 0.0;
  const double disc = v0 * v0 + 2.0 * a * d;
  return disc <= 0.0 ? -v0 / a : 2.0 * d / (v0 + std::sqrt(disc));
}

// The EN 14363 sliding rms of every bogie frame over every wheelset against its limit: the
// largest ratio at each window end, on the window grid of the first group (all share it).
void readStability(const io::ResultReader& r, const RunSetup& s, KickedRun& run) {
  const std::string A = "/assessment/stability";
  const auto dist = r.dataset("/assessment/distance");
  const double d0 = dist && !dist->empty() ? dist->front() : 0.0;
  std::vector<double> pos;
  for (const auto& bogie : r.members(A))
    for (const auto& ws : r.members(A + "/" + bogie)) {
      const std::string g = A + "/" + bogie + "/" + ws;
      const auto p = r.dataset(g + "/s");
      const auto rms = r.dataset(g + "/rms");
      const auto limit = r.number(g, "limit");
      if (!p || !rms || !limit || !(*limit > 0.0) || p->size() != rms->size()) continue;
      if (run.en_ratio.empty()) {
        pos = *p;
        run.en_ratio.assign(p->size(), 0.0);
      }
      for (std::size_t k = 0; k < std::min(pos.size(), rms->size()); ++k)
        run.en_ratio[k] = std::max(run.en_ratio[k], (*rms)[k] / *limit);
    }
  run.en_max_ratio = run.en_ratio.empty() ? std::numeric_limits<double>::quiet_NaN() : 0.0;
  for (std::size_t k = 0; k < pos.size(); ++k) {
    const double t = timeAtDistance(run.v0, run.acceleration, pos[k] - d0);
    run.en_speed.push_back(run.v0 + run.acceleration * t);
    if (t >= s.transient) run.en_max_ratio = std::max(run.en_max_ratio, run.en_ratio[k]);
  }
}

void readBack(const std::string& file, const std::vector<std::string>& wheelsets, const RunSetup& s,
              KickedRun& run) {
  const io::ResultReader r(file);
  if (!r.ok()) return;
  const auto t = r.dataset("/time");
  const auto v = r.dataset("/vehicle/speed");
  if (!t || !v || t->size() != v->size()) return;
  std::vector<std::vector<double>> y;
  for (const auto& w : wheelsets) {
    auto yw = r.dataset("/bodies/" + w + "/y");
    if (yw && yw->size() == t->size()) y.push_back(std::move(*yw));
  }
  if (y.empty()) return;
  run.windows = windowAmplitudes(*t, y, *v, s.window, s.transient);
  run.speed = *v;
  run.y_lead = y.front();
  run.verdict = judgeKickedRun(run.windows, s.threshold, s.decay);
  if (s.en14363) readStability(r, s, run);
}

}  // namespace

KickedRun runKicked(const RunSetup& s, const std::string& kind, const std::string& name, double v0,
                    double acceleration, double duration) {
  if (s.step_grid > 0.0) duration = std::ceil(duration / s.step_grid - 1e-9) * s.step_grid;
  KickedRun run;
  run.kind = kind;
  run.v0 = v0;
  run.acceleration = acceleration;
  run.duration = duration;
  run::CompileOptions co;
  co.scenario = s.scenario;
  co.overrides = runOverrides(s, v0, acceleration, duration);
  // The kick goes through the checks of the scenario's own initial conditions (a wheelset beyond
  // its flangeway is refused with the largest admissible offset) before it replaces them below.
  if (!s.first_wheelset.empty() && s.kick != 0.0)
    co.overrides.push_back("vehicle.initial." + s.first_wheelset +
                           ".y=" + formatNumberExact(s.kick));
  co.root = s.root;
  co.table_cache = s.table_cache;
  run::Model m = run::compile(co);
  const std::vector<std::string> wheelsets = wheelsetNames(m);
  if (!wheelsets.empty() && s.kick != 0.0) {
    // The kick replaces any initial condition of the scene: the command defines the start.
    vehicle::InitialCondition ic;
    ic.body = wheelsets.front();
    ic.coord = vehicle::kY;
    ic.value = s.kick;
    ic.loc = SourceLoc{"--kick", 0};
    m.spec.vehicle.initial = {ic};
  }
  std::error_code ec;
  fs::create_directories(s.run_dir, ec);
  run.file = (fs::path(s.run_dir) / (name + ".h5")).string();
  {
    io::ResultFile f(run.file);
    run::writeProvenance(m, f, "");
    const run::VehicleRunResult res = run::runVehicle(m, f, run::VehicleRunOptions{});
    f.finalize();
    run.ok = res.result.ok;
    run.message = res.result.message;
    run.t_reached = res.result.t_reached;
    run.cpu_s = res.result.stats.cpu_time_s;
    run.rhs_evals = res.result.stats.rhs_evals + res.result.stats.rhs_evals_jac;
    run.steps = res.result.stats.steps;
  }
  run.v_reached = v0 + acceleration * run.t_reached;
  readBack(run.file, wheelsets, s, run);
  return run;
}

bool runUnstable(const KickedRun& run, bool en14363) {
  if (en14363) return std::isfinite(run.en_max_ratio) ? run.en_max_ratio >= 1.0 : !run.ok;
  if (!run.verdict.valid) return !run.ok;
  return run.verdict.unstable;
}

}  // namespace rb::critical_speed
