#pragma once
// The result of `workbench critical-speed` (docs/stability.md): <out>/critical_speed.h5.
//   /                 attributes: the options, the critical speed of each method, status
//   /runs/<name>      one group per kicked run (attributes: kind, file, v0, acceleration,
//                     duration, ok, message, t_reached, v_reached, cpu_s, rhs_evals, steps,
//                     unstable, state (hunting, sustained small-amplitude oscillation, stable),
//                     a_first, a_mid, a_last, trend, en14363_ratio); datasets window_t0,
//                     window_t1 [s], window_speed [m/s], window_amplitude [m] and, with the
//                     EN 14363 criterion, en14363_speed [m/s], en14363_ratio [-]
//   /ramp             speed [m/s] and y [m] (lateral displacement of the first wheelset) of the
//                     ramp-down run, window_speed and window_amplitude (the ramp's curve of the
//                     bifurcation diagram)
//   /bisection        speed [m/s], amplitude [m] (last window), unstable (0/1) and small_cycle
//                     (0/1: sustained below the threshold, not stable) of each constant-speed
//                     run, in the order run (points of the bifurcation diagram)
#include <string>
#include <utility>
#include <vector>

namespace rb::io {

struct CriticalSpeedRun {
  std::string name;
  std::string kind;
  std::string file;
  std::string message;
  double v0 = 0.0;
  double acceleration = 0.0;
  double duration = 0.0;
  double t_reached = 0.0;
  double v_reached = 0.0;
  double cpu_s = 0.0;
  long rhs_evals = 0;
  long steps = 0;
  bool ok = false;
  bool unstable = false;
  double a_first = 0.0;
  double a_mid = 0.0;
  double a_last = 0.0;
  double trend = 0.0;          // amplitude ratio per window over the second half
  std::string state;           // KickedVerdict::state()
  double en14363_ratio = 0.0;  // NaN-free: not written when the criterion is not en14363
  bool has_en14363 = false;
  std::vector<double> window_t0, window_t1, window_speed, window_amplitude;
  std::vector<double> en_speed, en_ratio;
};

struct CriticalSpeedResult {
  std::vector<std::pair<std::string, std::string>> text;  // root text attributes
  std::vector<std::pair<std::string, double>> numbers;    // root numeric attributes
  std::vector<CriticalSpeedRun> runs;
  std::vector<double> ramp_speed, ramp_y, ramp_window_speed, ramp_window_amplitude;
  std::vector<double> bisection_speed, bisection_amplitude, bisection_unstable;
  std::vector<double> bisection_small;  // 1: sustained small-amplitude oscillation (not stable)
};

// Writes `result` to `path` (replaced as a whole: written under a temporary name, then renamed).
// Throws WriteError when the file cannot be written.
void writeCriticalSpeedFile(const std::string& path, const CriticalSpeedResult& result);

}  // namespace rb::io
