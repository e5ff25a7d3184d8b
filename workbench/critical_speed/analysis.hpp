#pragma once
// The signal processing of `workbench critical-speed` (docs/stability.md), free of any run: the
// limit-cycle amplitude of the wheelsets' lateral motion in moving windows, the decay/growth
// criterion of a kicked constant-speed run, and the speed at which the limit cycle of a
// ramp-down run dies.
//
// Amplitude of a window: the largest over the wheelsets of half the peak-to-peak lateral
// displacement y of the wheelset (track frame) inside the window. For a harmonic limit cycle this
// is its amplitude; for a decaying motion it is the amplitude at the window's start.
#include <span>
#include <string>
#include <vector>

namespace rb::critical_speed {

struct Window {
  double t0 = 0.0;         // [s] window start
  double t1 = 0.0;         // [s] window end
  double speed = 0.0;      // [m/s] vehicle speed at the window centre
  double amplitude = 0.0;  // [m] max over wheelsets of (max y - min y) / 2 in the window
  int wheelset = -1;       // index of the wheelset with that amplitude
};

// Non-overlapping windows of length `window` [s] over [t_start, t.back()] (a last window shorter
// than half a window is dropped). `y[k]` is wheelset k's lateral displacement at the times t;
// `speed` the vehicle speed at the times t. Windows without a sample are skipped.
std::vector<Window> windowAmplitudes(std::span<const double> t,
                                     const std::vector<std::vector<double>>& y,
                                     std::span<const double> speed, double window, double t_start);

// Growth or decay of the kicked motion of a constant-speed run (criterion "amplitude"):
// a_first = amplitude of the first window after the kick transient, a_mid of the window at the
// middle of the remaining run, a_last of the last window. The run hunts (is unstable) when the
// motion is sustained at the end: a_last >= threshold and a_last >= decay * a_mid (it has not
// decayed by the factor `decay` over the second half of the run). The second half, not the
// first window, is the reference so that a kick larger than the limit cycle, which shrinks onto
// the cycle during the first half, still counts as hunting.
// Below the threshold the amplitude alone proves nothing: a motion that has not decayed over the
// second half (a_last >= decay * a_mid, and the last window not smaller than the one before by the
// factor decay either) is a sustained small-amplitude oscillation, a small limit cycle or a mode at
// the edge of its damping, not a stable run. It is kept apart (small_cycle) with its amplitude,
// and only called "at rest" (stable) when it has died out to below kRestFraction of the threshold
// (there the numerical noise of the run, not the vehicle, sets the amplitude).
inline constexpr double kRestFraction = 0.01;
struct KickedVerdict {
  bool valid = false;        // enough windows (at least 3) to judge
  bool unstable = false;     // limit cycle at or above the threshold (hunting) or growth
  bool small_cycle = false;  // sustained below the threshold: neither hunting nor stable
  double a_first = 0.0;      // [m]
  double a_mid = 0.0;        // [m]
  double a_last = 0.0;       // [m]
  double a_prev = 0.0;       // [m] the window before the last
  double threshold = 0.0;    // [m] the threshold it was judged against
  // Amplitude ratio per window over the second half, (a_last / a_mid)^(1 / windows): < 1 decays,
  // 1 sustained, > 1 grows.
  double trend = 0.0;
  std::string why;            // one line: the numbers behind the verdict
  std::string state() const;  // "hunting", "sustained small-amplitude oscillation", "stable", ...
};
KickedVerdict judgeKickedRun(const std::vector<Window>& windows, double threshold, double decay);

// The ramp-down critical speed: the limit cycle dies at the speed where the window amplitude
// falls below `threshold` for the last time (after the last window at or above it, every window
// is below). Interpolated linearly in speed between the last window at or above the threshold
// and the next one. found = false when no window reaches the threshold (no hunting at the start)
// or the last window still does (the limit cycle lives down to the end speed).
struct RampVerdict {
  bool found = false;
  bool hunting_at_start = false;  // the first window at or above the threshold
  bool hunting_at_end = false;    // the last window at or above the threshold
  double critical_speed = 0.0;    // [m/s]
  double start_amplitude = 0.0;   // [m] largest amplitude of the ramp
};
RampVerdict rampCriticalSpeed(const std::vector<Window>& windows, double threshold);

// The same with a generic exceedance series (e.g. the EN 14363 sliding rms over its limit):
// value[k] >= 1 exceeds at speed[k]; the critical speed is where it falls below 1 for the last
// time.
RampVerdict lastExceedance(std::span<const double> speed, std::span<const double> ratio);

}  // namespace rb::critical_speed
