#pragma once
// Signal processing shared by the assessment quantities (docs/assessment.md, "Processing"):
// second-order filter sections designed from continuous transfer functions by the bilinear
// transform, Butterworth low/high/band-pass filters, sliding means and sliding rms values over a
// track length (distance based, as EN 14363 prescribes for the 2 m and 100 m windows), rms values
// over consecutive time blocks (EN 12299's 5 s values) and percentiles.
//
// Inputs are time series sampled at a fixed interval dt [s] (the run's output interval), with the
// travelled distance s [m] of each sample where a quantity is defined over track length. Outputs
// that are series are returned as std::vector (one allocation per call, none per sample); the
// per-sample loops do not allocate.
#include <array>
#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace rb::assessment {

// A quantity checked against its limit. margin = limit - value, in the quantity's unit: the limit
// is kept when margin >= 0 (every limit here is an upper bound of a non-negative quantity).
struct Check {
  double value = 0.0;   // assessed value [unit of the quantity]
  double limit = 0.0;   // limit value [same unit]
  double margin = 0.0;  // limit - value [same unit]
  bool ok() const { return margin >= 0.0; }
};

inline Check check(double value, double limit) {
  return {value, limit, limit - value};
}

// Continuous second-order section H(s) = (B0 + B1 s + B2 s^2) / (A0 + A1 s + A2 s^2), s in rad/s.
struct AnalogSection {
  double B0 = 1.0, B1 = 0.0, B2 = 0.0;
  double A0 = 1.0, A1 = 0.0, A2 = 0.0;
};

// H(j 2 pi f) of a continuous section.
std::complex<double> analogResponse(const AnalogSection& h, double f_hz);

// Digital second-order section y = b0 x + b1 x[-1] + b2 x[-2] - a1 y[-1] - a2 y[-2].
struct Section {
  double b0 = 1.0, b1 = 0.0, b2 = 0.0;
  double a1 = 0.0, a2 = 0.0;
};

// Bilinear transform s = k (1 - z^-1) / (1 + z^-1) with k = w_p / tan(w_p dt / 2), w_p = 2 pi
// prewarp_hz, so the digital response equals the continuous one exactly at prewarp_hz; with
// prewarp_hz <= 0, k = 2 / dt. prewarp_hz must lie below the Nyquist frequency 1 / (2 dt).
Section bilinear(const AnalogSection& h, double dt, double prewarp_hz);

// A cascade of at most kMaxSections digital sections (the EN 12299 weightings need four).
struct Cascade {
  static constexpr std::size_t kMaxSections = 4;
  std::array<Section, kMaxSections> sections{};
  std::size_t size = 0;
  void push(const Section& s);
};

// H(e^{j 2 pi f dt}) of a cascade.
std::complex<double> digitalResponse(const Cascade& c, double f_hz, double dt);

// y = cascade applied to x (y.size() == x.size(); y may alias x). Each section starts in the
// steady state of a constant input equal to x[0], so a signal with a static part (a wheel load)
// has no start transient through a low-pass filter; a high-pass section starts at rest.
void applyCascade(const Cascade& c, std::span<const double> x, std::span<double> y);

// Butterworth filters as cascades of second-order sections, each prewarped at its corner
// frequency (so the -3 dB point is exact at any sampling rate). Corner frequencies must lie below
// the Nyquist frequency.
Cascade butterworthLowPass4(double fc_hz, double dt);   // 4th order (2 sections)
Cascade butterworthHighPass2(double fc_hz, double dt);  // 2nd order (1 section)
// Band-pass f_low..f_high: a 2nd-order Butterworth high-pass at f_low followed by a 2nd-order
// Butterworth low-pass at f_high.
Cascade butterworthBandPass(double f_low_hz, double f_high_hz, double dt);

// Second-order band-pass (one resonator section) H = (w0 / Q) s / (s^2 + w0 s / Q + w0^2) with
// unit gain at the centre f_centre and the -3 dB bandwidth `bandwidth` (Q = f_centre / bandwidth),
// prewarped at the centre.
Cascade resonatorBandPass(double f_centre_hz, double bandwidth_hz, double dt);

// Values of a sliding window over track length, evaluated at the window ends
// p_k = s[0] + window + k step (k = 0, 1, ... while p_k <= s.back()); the window ending at p
// holds the samples with p - window < s_j <= p. s must be non-decreasing.
struct DistanceSeries {
  std::vector<double> position;  // window end p_k [m]
  std::vector<double> value;     // windowed value [unit of the signal]
};

// Arithmetic mean of the samples in each window (EN 14363's 2 m sliding mean).
DistanceSeries slidingMean(std::span<const double> x, std::span<const double> s, double window,
                           double step);
// Root mean square of the samples in each window (EN 14363's 100 m sliding rms).
DistanceSeries slidingRms(std::span<const double> x, std::span<const double> s, double window,
                          double step);

// Rms of consecutive, non-overlapping blocks of block_s seconds (EN 12299's 5 s rms values); a
// last incomplete block is dropped. Empty when the signal is shorter than one block.
std::vector<double> blockRms(std::span<const double> x, double dt, double block_s);

// Rms of the trailing block_s seconds at every sample (the continuous comfort of EN 12299); the
// first samples, before a whole block is available, use the samples so far.
std::vector<double> trailingRms(std::span<const double> x, double dt, double block_s);

// Percentile p (0..100) of x: the empirical distribution with linear interpolation between order
// statistics, x_(h) with h = (n - 1) p / 100 (Hyndman & Fan's definition 7, the default of
// numpy and R). x must not be empty.
double percentile(std::span<const double> x, double p);

// Largest |x| of a non-empty series.
double maxAbs(std::span<const double> x);

}  // namespace rb::assessment
