#pragma once
// Track irregularities (paper section 2.1, Fig. 3 and the definitions before Eq. 4): synthesis of
// the four centreline channels from a PSD, measured tables from CSV, and their cubic splines.
//
// Left/right rail irregularities from the centreline channels (inverse of the paper definitions):
//   y_l = xi_a + xi_g / 2,  y_r = xi_a - xi_g / 2,  z_l = xi_v + xi_c / 2,  z_r = xi_v - xi_c / 2,
//   delta = (z_l - z_r) / (2 Lr)   (linearised irregularity angle of Eq. 5).
//
// Synthesis (sum of cosines, reference document section 4): per channel
//   xi(s) = sum_k A_k cos(Omega_k s + phi_k),  A_k = scale * sqrt(2 G(Omega_k) dOmega),
// G the one-sided PSD, the band [2 pi / wavelength_max, 2 pi / wavelength_min] split into
// `components` bands of width dOmega; Omega_k at the band centre or, with randomize_frequencies,
// uniform inside band k. Then Var[xi] = sum_k A_k^2 / 2 ~= scale^2 integral G dOmega.
//
// Reproducibility: channel c draws from its own std::mt19937_64 (whose output sequence the C++
// standard fixes) seeded with channelSeed(seed, c) (SplitMix64 mixing). Uniform doubles are made
// by uniform01(): the top 53 bits of one 64-bit draw times 2^-53, in [0, 1). For k = 0, 1, ...
// the draws are: phase phi_k = 2 pi u, then (if randomize_frequencies) the offset u inside the
// band. std::uniform_real_distribution is NOT used (its output is implementation-defined). Phases
// and frequencies are therefore bit-identical on every platform. The summation uses a fixed order
// and rb_track is built with -ffp-contract=off (no FMA contraction), so the realisation depends
// only on libm cos/sin: identical up to their last-ulp rounding across C libraries, and
// bit-identical for one build.
//
// The realisation is sampled every `step` metres from s = 0 (knots j * step; the same seed gives
// the same irregularity at a given s whatever the track length) up to the first knot >= the track
// length, and splined (not-a-knot). Outside the sampled (or, for CSV, tabulated) range every
// irregularity and derivative is zero.
#include <array>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/core/spline.hpp"
#include "workbench/track/spec.hpp"

namespace rb::track {

// Uniform double in [0, 1) from one draw: (g() >> 11) * 2^-53. Platform independent.
inline double uniform01(std::mt19937_64& g) {
  return static_cast<double>(g() >> 11) * 0x1.0p-53;
}
// Seed of channel c's generator: SplitMix64 finaliser of seed + (c + 1) * 0x9E3779B97F4A7C15.
std::uint64_t channelSeed(std::uint64_t seed, Channel c);

// The cosines of one channel.
struct CosineSeries {
  std::vector<double> omega;      // [rad/m]
  std::vector<double> amplitude;  // [m]
  std::vector<double> phase;      // [rad]
};
// Requires a valid Psd spec (internal check on the spectrum name). A disabled channel, or a user
// channel with an empty table, gives zero amplitudes.
CosineSeries makeCosineSeries(const IrregularitySpec& spec, Channel c);
// out[j] = sum_k A_k cos(Omega_k j h + phi_k), j = 0 .. out.size()-1 (rotation recurrence
// re-anchored with exact cos/sin every 256 samples).
void evaluateCosineSeries(const CosineSeries& series, double h, std::span<double> out);

// Sampled centreline irregularities [m] at increasing s [m].
struct IrregularityTable {
  std::vector<double> s;
  std::array<std::vector<double>, kChannels> channel;  // indexed by Channel
};

// Irregularities at one s, with s-derivatives (_s) and second derivatives of the channels (_ss).
struct IrregularityPoint {
  std::array<double, kChannels> xi{}, xi_s{}, xi_ss{};  // indexed by Channel [m], [-], [1/m]
  double y_l = 0.0, y_r = 0.0, z_l = 0.0, z_r = 0.0, delta = 0.0;            // [m], delta [rad]
  double y_l_s = 0.0, y_r_s = 0.0, z_l_s = 0.0, z_r_s = 0.0, delta_s = 0.0;  // [-], [rad/m]
};

class Irregularities {
 public:
  Irregularities() = default;
  // Splines `table` (>= 2 rows, strictly increasing s; internal check). rail_lr = Lr [m].
  Irregularities(IrregularityTable table, double rail_lr);

  // Allocation-free; zero outside [sBegin(), sEnd()].
  IrregularityPoint at(double s) const;
  double sBegin() const { return table_.s.front(); }
  double sEnd() const { return table_.s.back(); }
  const IrregularityTable& samples() const { return table_; }  // the spline knots
  double railLr() const { return rail_lr_; }

 private:
  IrregularityTable table_;
  double rail_lr_ = 0.0;
  CubicSplineSet spline_;  // channels in Channel order
};

// Multiplies every channel of `t` by the raised-cosine fade-in over [0, length] (spec.hpp,
// IrregularitySpec::fade_in): 0 for s <= 0, (1 - cos(pi s / length)) / 2 inside, 1 beyond.
// length <= 0 leaves the table unchanged.
void applyFadeIn(IrregularityTable& t, double length);

// Synthesises all four channels of a valid Psd spec over [0, track_length].
IrregularityTable synthesizeIrregularities(const IrregularitySpec& spec, double track_length);

// A measured-irregularity CSV. Format:
// - '#' starts a comment; blank lines are skipped; fields are separated by commas, or semicolons,
//   or white space.
// - The first content line is a header naming the columns: `s` (arc length [m]) and any subset of
//   alignment, vertical, gauge, cross_level, in any order (names case-insensitive). A channel that
//   is not named is zero. A name may carry its unit, `alignment [mm]`; it must then agree with
//   the declared unit (s only in m). Unknown or repeated names are errors (with a hint).
// - Then one row per s with as many numbers as the header has names: s finite, |s| <= 1e7 m,
//   strictly increasing; values finite and, converted to metres, |value| <= kMaxIrregularity
//   (a larger value is almost always a file in millimetres declared as metres); at least 2 rows,
//   at most max_rows.
// Every problem is added to `diags` as SourceLoc{file_name, line}; the table (in metres) is
// returned only when there were none.
struct CsvReadOptions {
  CsvUnit unit = CsvUnit::Metre;        // unit of the irregularity columns
  double max_rows = kDefaultMaxPoints;  // bound on data rows
};
struct MeasuredTable {
  IrregularityTable table;  // [m]
  int first_line = 0;       // file lines of the first and last data rows
  int last_line = 0;
  std::array<bool, kChannels> present{};  // which channels the header named
};
std::optional<MeasuredTable> parseMeasuredCsv(std::string_view text, const std::string& file_name,
                                              const CsvReadOptions& options, Diagnostics& diags);
// Reads `path` (a regular file of bounded size, core/files.hpp) and parses it; a file that cannot
// be used is reported at `loc` (the irregularities block).
std::optional<MeasuredTable> readMeasuredCsv(const std::string& path, const SourceLoc& loc,
                                             const CsvReadOptions& options, Diagnostics& diags);

// The same with the default options (metres), for callers that need only the table.
std::optional<IrregularityTable> parseIrregularityCsv(std::istream& in,
                                                      const std::string& file_name,
                                                      Diagnostics& diags);
std::optional<IrregularityTable> readIrregularityCsv(const std::string& path, const SourceLoc& loc,
                                                     Diagnostics& diags);

const char* channelName(Channel c);  // "alignment", "vertical", "gauge", "cross_level"

}  // namespace rb::track
