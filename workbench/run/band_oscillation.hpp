#pragma once
// The KEC's regularised tread/flange band (paper Eq. 26) splits a flanging wheel's load between
// the band's two ends by the weight w of the indentation; in steady flanging that split can
// oscillate by itself at 25-40 Hz with a lateral force of several kN rms, which the LUT and the
// elastic method do not show on the same track (docs/three_way.md, section 2). A run on such a
// method watches each wheel's lateral force Y at its output samples: in windows of 0.5 s in which
// the wheel is in its band for at least 80 % of the samples, the part of Y above 15 Hz (Y minus its
// first-order low-pass at 15 Hz) whose rms exceeds 3 kN and whose zero crossings say 15 Hz or more
// is an oscillation of the band, and the run records a warning (the summary prints it). The
// thresholds: the elastic method's Y above 15 Hz is 0.08 kN rms on the trial curve with ORE B176
// high irregularities, the KEC's 8 kN on smooth track (docs/three_way.md); 3 kN lies between.
// Output intervals above 10 ms cannot resolve the band's frequencies: then nothing is watched and
// none is reported (the finding says so).
#include <string>

namespace rb::run {

struct BandOscillation {
  bool watched = false;    // the output interval resolved it (<= 10 ms) at least once
  bool found = false;      // some window met every condition
  double frequency = 0.0;  // [Hz] from the zero crossings of the strongest window
  double rms = 0.0;        // [N] the rms of Y above 15 Hz in the strongest window
  double t_first = 0.0;    // [s] start of the first window found
  double t_last = 0.0;     // [s] end of the last window found
  int windows = 0;         // windows found
};

class BandOscillationMonitor {
 public:
  static constexpr double kWindow = 0.5;         // [s]
  static constexpr double kCutoff = 15.0;        // [Hz]
  static constexpr double kRmsThreshold = 3e3;   // [N]
  static constexpr double kBandShare = 0.8;      // [-]
  static constexpr double kMaxInterval = 0.010;  // [s]

  // One output sample: time, the wheel's lateral force Y [N], whether it is in its band.
  void add(double t, double y_force, bool in_band);
  const BandOscillation& result() const { return result_; }

 private:
  void closeWindow(double t_end);

  BandOscillation result_;
  bool started_ = false;
  double t_prev_ = 0.0, low_ = 0.0, last_high_ = 0.0;
  double window_start_ = 0.0, sum_sq_ = 0.0;
  int samples_ = 0, in_band_ = 0, crossings_ = 0;
  bool resolved_ = true;
};

// "ws1 right wheel: ..." warning text of a finding.
std::string bandOscillationWarning(const std::string& wheel, const BandOscillation& b);

}  // namespace rb::run
