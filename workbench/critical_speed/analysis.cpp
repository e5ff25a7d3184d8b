#include "workbench/critical_speed/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace rb::critical_speed {

namespace {

// Half the peak-to-peak of samples [i0, i1) of y (0 when empty).
double halfPeakToPeak(const std::vector<double>& y, std::size_t i0, std::size_t i1) {
  if (i1 <= i0 || i1 > y.size()) return 0.0;
  const auto [lo, hi] = std::minmax_element(y.begin() + static_cast<std::ptrdiff_t>(i0),
                                            y.begin() + static_cast<std::ptrdiff_t>(i1));
  return 0.5 * (*hi - *lo);
}

Window windowAt(std::span<const double> t, const std::vector<std::vector<double>>& y,
                std::span<const double> speed, std::size_t i0, std::size_t i1) {
  Window w;
  w.t0 = t[i0];
  w.t1 = t[i1 - 1];
  const std::size_t mid = (i0 + i1 - 1) / 2;
  w.speed = mid < speed.size() ? speed[mid] : 0.0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    const double a = halfPeakToPeak(y[k], i0, i1);
    if (a > w.amplitude || w.wheelset < 0) {
      w.amplitude = a;
      w.wheelset = static_cast<int>(k);
    }
  }
  return w;
}

}  // namespace

std::vector<Window> windowAmplitudes(std::span<const double> t,
                                     const std::vector<std::vector<double>>& y,
                                     std::span<const double> speed, double window, double t_start) {
  std::vector<Window> out;
  if (t.empty() || !(window > 0.0)) return out;
  const double t_end = t.back();
  std::size_t i =
      static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), t_start) - t.begin());
  for (double a = t_start; a + 0.5 * window <= t_end + 1e-12; a += window) {
    const double b = a + window;
    std::size_t j = i;
    while (j < t.size() && t[j] < b - 1e-12) ++j;
    if (j > i + 1) out.push_back(windowAt(t, y, speed, i, j));
    i = j;
  }
  return out;
}

KickedVerdict judgeKickedRun(const std::vector<Window>& all, double threshold, double decay) {
  KickedVerdict v;
  // Full windows only: a last window cut short by the end of the run may hold half a hunting
  // period, whose half peak-to-peak can be half the amplitude (a sustained cycle would read as
  // decaying).
  double longest = 0.0;
  for (const Window& w : all) longest = std::max(longest, w.t1 - w.t0);
  std::vector<Window> windows;
  for (const Window& w : all)
    if (w.t1 - w.t0 >= 0.75 * longest) windows.push_back(w);
  if (windows.size() < 3) {
    v.why = "too few windows to judge (" + std::to_string(windows.size()) + ")";
    return v;
  }
  v.valid = true;
  v.threshold = threshold;
  const std::size_t mid = windows.size() / 2;
  v.a_first = windows.front().amplitude;
  v.a_mid = windows[mid].amplitude;
  v.a_last = windows.back().amplitude;
  v.a_prev = windows[windows.size() - 2].amplitude;
  const double span = static_cast<double>(windows.size() - 1 - mid);
  v.trend = v.a_mid > 0.0 && span > 0.0 ? std::pow(v.a_last / v.a_mid, 1.0 / span) : 0.0;
  const bool sustained = v.a_last >= decay * v.a_mid;
  // The last cycles: a motion that still shrinks from the window before the last by the decay
  // factor is decaying even when the middle window happened to be low.
  const bool still_decaying = v.a_last < decay * v.a_prev;
  const bool at_rest = v.a_last < kRestFraction * threshold;
  v.unstable = v.a_last >= threshold && sustained;
  v.small_cycle = !v.unstable && !at_rest && v.a_last < threshold && sustained && !still_decaying;
  std::ostringstream s;
  s << "amplitude first " << v.a_first * 1e3 << " mm, middle " << v.a_mid * 1e3 << " mm, last "
    << v.a_last * 1e3 << " mm, ratio per window " << v.trend << ", threshold " << threshold * 1e3
    << " mm: ";
  if (v.unstable)
    s << "sustained (hunting)";
  else if (v.small_cycle)
    s << "sustained small-amplitude oscillation of " << std::setprecision(3) << v.a_last * 1e3
      << " mm (not decayed by the decay factor over the second half, not died out; below the "
         "threshold: not stable, not counted as hunting)";
  else if (at_rest)
    s << "died out (stable)";
  else
    s << "decaying (stable)";
  v.why = s.str();
  return v;
}

std::string KickedVerdict::state() const {
  if (!valid) return "not judged";
  if (unstable) return "hunting";
  if (small_cycle) return "sustained small-amplitude oscillation";
  return "stable";
}

RampVerdict lastExceedance(std::span<const double> speed, std::span<const double> ratio) {
  RampVerdict r;
  const std::size_t n = std::min(speed.size(), ratio.size());
  if (n == 0) return r;
  r.hunting_at_start = ratio[0] >= 1.0;
  r.hunting_at_end = ratio[n - 1] >= 1.0;
  std::size_t last = n;
  for (std::size_t k = n; k-- > 0;)
    if (ratio[k] >= 1.0) {
      last = k;
      break;
    }
  if (last == n || last == n - 1) return r;
  // Linear interpolation of the ratio between the last exceeding window and the next one.
  const double r0 = ratio[last];
  const double r1 = ratio[last + 1];
  const double f = r0 > r1 ? (r0 - 1.0) / (r0 - r1) : 0.0;
  r.critical_speed = speed[last] + f * (speed[last + 1] - speed[last]);
  r.found = true;
  return r;
}

RampVerdict rampCriticalSpeed(const std::vector<Window>& windows, double threshold) {
  std::vector<double> speed;
  std::vector<double> ratio;
  double largest = 0.0;
  for (const auto& w : windows) {
    speed.push_back(w.speed);
    ratio.push_back(threshold > 0.0 ? w.amplitude / threshold
                                    : std::numeric_limits<double>::infinity());
    largest = std::max(largest, w.amplitude);
  }
  RampVerdict r = lastExceedance(speed, ratio);
  r.start_amplitude = largest;
  return r;
}

}  // namespace rb::critical_speed
