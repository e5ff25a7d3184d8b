#pragma once
// Plain input structs for the track (built by workbench/scenario from Lua, consumed by
// compileTrack()). SI units throughout. Each carries the SourceLoc of the Lua block it came from so
// compile-time validation can report file:line.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "workbench/core/error.hpp"

namespace rb::track {

enum class SegmentKind { Tangent, Transition, Curve };
enum class Side { Left, Right };

// One track segment. Curvature, cant and gradient of a Transition change linearly in arc length
// from the end values of the previous segment to the values given here (a clothoid with linear
// cant ramp, paper section 5.2). A Tangent has zero curvature and zero cant. A Curve has constant
// curvature 1/radius to the given side and constant cant.
struct SegmentSpec {
  SegmentKind kind = SegmentKind::Tangent;
  double length = 0.0;     // [m] arc length along the centreline, > 0
  double radius = 0.0;     // [m] end radius (Curve: required; Transition: 0 means ends straight)
  Side side = Side::Left;  // direction of the curve (left = curvature centre on +Y side)
  double cant = 0.0;       // [m] superelevation height of the outer rail at the segment end
  double gradient = 0.0;   // [-] vertical gradient (rise/run, positive uphill) at the segment end
  SourceLoc loc;
};

enum class IrregularitySource { None, Psd, Csv };

// Unit of the irregularity columns of a measured CSV (s is always in metres).
enum class CsvUnit { Metre, Millimetre };
// What the track is where a measured CSV does not reach (before its first or after its last s).
// Error: check fails (default: a file shorter than the track is usually a mistake). Zero: perfect
// track there, with a warning.
enum class Beyond { Error, Zero };

// Bound on the knots of one spline (centreline, irregularities, measured CSV rows): about 0.4 kB
// of memory per centreline knot; a PSD synthesis may cost max_points x kSynthesisTermsPerPoint
// cosine terms (about 10 s at the default). 1e6 knots: 500 km of track at the paper's 0.5 m step,
// or 100 km of irregularities at 0.1 m. Raised per scenario with track { max_points = ... }.
inline constexpr double kDefaultMaxPoints = 1e6;
inline constexpr double kSynthesisTermsPerPoint = 2000.0 * 4.0;  // default components x channels
// [m] Longest track (and largest |s| of a measured CSV): longer than any railway line (the
// Trans-Siberian is 9 289 km), short enough that s keeps sub-micrometre resolution.
inline constexpr double kMaxTrackLength = 1e7;
// [m] Largest plausible irregularity (CSV value, synthesised RMS): track irregularities are
// millimetres to a few centimetres; 0.1 m is a unit mistake or a wrong PSD.
inline constexpr double kMaxIrregularity = 0.1;
// [m] Default length of the raised-cosine fade-in of synthesised irregularities from s = 0
// (IrregularitySpec::fade_in). Before s = 0 the track is perfect, so an unfaded synthesis starts
// with a step of the sum of its cosines (several mm for FRA class 4-6) that the first wheelsets hit
// at once. 20 m: the ramp is half a cosine period, so its own content lies at wavelengths of 2 L =
// 40 m and longer (0.5 Hz and below at 20 m/s), under the car-body bounce and sway modes (about
// 1 Hz) and far under the bogie modes, and it is longer than a bogie's wheelbase; yet short
// against a test section (EN 14363 evaluates sections of 100 m and more).
inline constexpr double kDefaultFadeIn = 20.0;

// The four centreline irregularities of paper Fig. 3 (Eq. before (4)).
enum class Channel { Alignment = 0, Vertical = 1, Gauge = 2, CrossLevel = 3 };
inline constexpr int kChannels = 4;

// A tabulated one-sided PSD G(Omega) [m^2/(rad/m)] for one channel (cross level in m^2/(rad/m) as
// a height difference), interpolated log-log. Used for user PSDs given as Lua functions or tables.
struct PsdTable {
  std::vector<double> omega;  // [rad/m], strictly increasing, > 0
  std::vector<double> value;  // [m^2/(rad/m)], >= 0
};

// Most cosines per channel a PSD synthesis may use (the track validator and the scenario schema
// both take this bound).
inline constexpr int kMaxPsdComponents = 100000;

// clang-tidy 14 names the implicit copy of an array member '__i0' (a false positive of
// bugprone-reserved-identifier on the compiler-generated copy constructor).
// NOLINTNEXTLINE(bugprone-reserved-identifier)
struct IrregularitySpec {
  IrregularitySource source = IrregularitySource::None;
  // Psd: named spectrum "ore_b176_low", "ore_b176_high", "fra_class_1" .. "fra_class_6", or "user".
  std::string spectrum;
  PsdTable user[kChannels];  // only for spectrum == "user"; an empty table disables the channel
  bool enabled[kChannels] = {true, true, true, true};
  double scale = 1.0;            // [-] amplitude factor applied to every channel
  std::uint64_t seed = 1;        // random phases; recorded in the output
  double wavelength_min = 3.0;   // [m] synthesis band (EN 13848 D1+D2: 3..70 m)
  double wavelength_max = 70.0;  // [m]
  int components = 2000;         // number of cosines per channel, 1..kMaxPsdComponents
  double step = 0.1;             // [m] spline sampling step (paper: 0.1 m)
  // [m] Raised-cosine fade-in of every channel from s = 0: the amplitudes are multiplied by
  // (1 - cos(pi s / fade_in)) / 2 over [0, fade_in] (continuous in value and slope at both ends),
  // so the vehicle meets no step where the irregularities begin; 0 = none. Synthesised
  // irregularities default to kDefaultFadeIn; a measured record is the track as measured (0).
  double fade_in = 0.0;
  // (Added by the track module.) Draw each cosine's frequency uniformly inside its band of width
  // dOmega (true), or put it at the band centre (false: the realisation then repeats every
  // 2 pi / dOmega metres).
  bool randomize_frequencies = true;
  // Csv: a header naming the columns (s and any of alignment, vertical, gauge, cross_level, in
  // any order; a missing channel is zero), then one row per s (irregularities.cpp).
  std::string csv_path;  // resolved absolute path
  CsvUnit csv_unit = CsvUnit::Metre;
  Beyond beyond = Beyond::Error;
  SourceLoc loc;
};

// [m] Nominal (standard) track gauge: the default of track.gauge and of profiles.gauge, which
// sets the rail positions of the contact geometry.
inline constexpr double kStandardGauge = 1.435;

struct TrackSpec {
  std::vector<SegmentSpec> segments;
  double step = 0.5;              // [m] centreline spline sampling step (paper: 0.5 m)
  double cant_base = 1.5;         // [m] lateral distance over which cant height is measured
  double gauge = kStandardGauge;  // [m] nominal track gauge (recorded; rail positions use Lr)
  double rail_lr = 0.7555;        // [m] Lr, rail profile frame lateral position (paper Table 1)
  double rail_inclination = 1.0 / 40.0;   // [rad] beta (paper Table 1)
  double max_points = kDefaultMaxPoints;  // work and memory bound (see kDefaultMaxPoints)
  IrregularitySpec irregularities;
  SourceLoc loc;
};

}  // namespace rb::track
