#include "workbench/io/critical_speed_file.hpp"

#include <cstdint>

#include "workbench/io/result_file.hpp"

namespace rb::io {

namespace {

void writeRun(ResultFile& f, const CriticalSpeedRun& r) {
  const std::string g = "/runs/" + r.name;
  f.attr(g, "kind", r.kind);
  f.attr(g, "file", r.file);
  f.attr(g, "message", r.message);
  f.attr(g, "v0", r.v0);
  f.attr(g, "acceleration", r.acceleration);
  f.attr(g, "duration", r.duration);
  f.attr(g, "t_reached", r.t_reached);
  f.attr(g, "v_reached", r.v_reached);
  f.attr(g, "cpu_s", r.cpu_s);
  f.attr(g, "rhs_evals", static_cast<std::int64_t>(r.rhs_evals));
  f.attr(g, "steps", static_cast<std::int64_t>(r.steps));
  f.attr(g, "ok", std::int64_t{r.ok ? 1 : 0});
  f.attr(g, "unstable", std::int64_t{r.unstable ? 1 : 0});
  f.attr(g, "a_first", r.a_first);
  f.attr(g, "a_mid", r.a_mid);
  f.attr(g, "a_last", r.a_last);
  f.attr(g, "trend", r.trend);
  f.attr(g, "state", r.state);
  f.dataset(g + "/window_t0", r.window_t0, "s");
  f.dataset(g + "/window_t1", r.window_t1, "s");
  f.dataset(g + "/window_speed", r.window_speed, "m/s");
  f.dataset(g + "/window_amplitude", r.window_amplitude, "m");
  if (r.has_en14363) {
    f.attr(g, "en14363_ratio", r.en14363_ratio);
    f.dataset(g + "/en14363_speed", r.en_speed, "m/s");
    f.dataset(g + "/en14363_ratio", r.en_ratio, "-");
  }
}

}  // namespace

void writeCriticalSpeedFile(const std::string& path, const CriticalSpeedResult& result) {
  ResultFile f(path);
  for (const auto& [name, value] : result.text) f.attr("/", name, value);
  for (const auto& [name, value] : result.numbers) f.attr("/", name, value);
  for (const auto& r : result.runs) writeRun(f, r);
  if (!result.ramp_speed.empty()) {
    f.dataset("/ramp/speed", result.ramp_speed, "m/s");
    f.dataset("/ramp/y", result.ramp_y, "m");
    f.dataset("/ramp/window_speed", result.ramp_window_speed, "m/s");
    f.dataset("/ramp/window_amplitude", result.ramp_window_amplitude, "m");
  }
  if (!result.bisection_speed.empty()) {
    f.dataset("/bisection/speed", result.bisection_speed, "m/s");
    f.dataset("/bisection/amplitude", result.bisection_amplitude, "m");
    f.dataset("/bisection/unstable", result.bisection_unstable, "-");
    f.dataset("/bisection/small_cycle", result.bisection_small, "-");
  }
  f.finalize();
}

}  // namespace rb::io
