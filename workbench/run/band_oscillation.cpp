#include "workbench/run/band_oscillation.hpp"

#include <cmath>
#include <numbers>

#include "workbench/core/strings.hpp"

namespace rb::run {

void BandOscillationMonitor::add(double t, double y_force, bool in_band) {
  if (!std::isfinite(t) || !std::isfinite(y_force)) return;
  if (!started_) {
    started_ = true;
    t_prev_ = t;
    low_ = y_force;
    window_start_ = t;
    return;
  }
  const double dt = t - t_prev_;
  if (!(dt > 0.0)) return;
  t_prev_ = t;
  if (dt > kMaxInterval) resolved_ = false;
  // First-order low-pass at kCutoff (exact discretisation for the sample interval); the rest of Y
  // is the part above it.
  const double alpha = 1.0 - std::exp(-2.0 * std::numbers::pi * kCutoff * dt);
  low_ += alpha * (y_force - low_);
  const double high = y_force - low_;
  ++samples_;
  if (in_band) ++in_band_;
  sum_sq_ += high * high;
  if (samples_ > 1 && ((high > 0.0) != (last_high_ > 0.0))) ++crossings_;
  last_high_ = high;
  if (t - window_start_ >= kWindow) closeWindow(t);
}

void BandOscillationMonitor::closeWindow(double t_end) {
  const double duration = t_end - window_start_;
  if (resolved_ && samples_ >= 20) {
    result_.watched = true;
    const double rms = std::sqrt(sum_sq_ / samples_);
    const double frequency = crossings_ / (2.0 * duration);
    const bool band = in_band_ >= kBandShare * samples_;
    if (band && rms > kRmsThreshold && frequency >= kCutoff) {
      if (!result_.found) result_.t_first = window_start_;
      result_.found = true;
      result_.t_last = t_end;
      ++result_.windows;
      if (rms > result_.rms) {
        result_.rms = rms;
        result_.frequency = frequency;
      }
    }
  }
  window_start_ = t_end;
  sum_sq_ = 0.0;
  samples_ = in_band_ = crossings_ = 0;
  resolved_ = true;
}

std::string bandOscillationWarning(const std::string& wheel, const BandOscillation& b) {
  return wheel + ": the KEC's tread/flange band oscillates by itself at about " +
         formatNumber(b.frequency, 3) + " Hz (lateral force " + formatNumber(b.rms * 1e-3, 3) +
         " kN rms above 15 Hz) in " + std::to_string(b.windows) +
         " windows of 0.5 s between t = " + formatNumber(b.t_first, 4) + " and " +
         formatNumber(b.t_last, 4) +
         " s; an artefact of the band's regularisation (Eq. 26) that the LUT and elastic methods "
         "do not show: compare its Y and Y/Q with contact.method = \"lut\" or \"elastic\" "
         "(docs/three_way.md)";
}

}  // namespace rb::run
