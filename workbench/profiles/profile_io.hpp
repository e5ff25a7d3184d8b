#pragma once
// Reading wheel and rail profiles from point files into a smoothed, uniform-grid Profile.
//
// Formats:
// - SIMPACK .prw (wheel) / .prr (rail): `header.begin ... header.end` (type = 1 wheel, 0 rail) and
//   `spline.begin ... spline.end` with `key = value ! comment` lines and the points between
//   `point.begin` and `point.end`, one `y z [weight]` per line in the file's length unit
//   (units.len.f = l[user] / l[m], e.g. 1000 for mm; default 1 = metres). `!` starts a comment
//   (a commented-out point is skipped). Processing keys honoured: mirror.y / mirror.z (1 = negate
//   y / z). inversion only reverses the point order and is irrelevant here (points are sorted by
//   y); approx.smooth and point.dist.min are ignored (smoothing is ProfileReadOptions); non-zero
//   shift.y, shift.z, rotate and active bound.* are rejected as unsupported.
//   Conventions of the files (after mirror.y): y is the parameter s of the LEFT profile (s > 0
//   field side). Wheel: z is the radius increase over the tape circle, UP (the benchmark file
//   MBench_S1002_v3.prw has y = -S with mirror.y = 1, z = F), h = r0 + z. Rail: z is DOWNWARD
//   (SIMPACK rail convention), h = -z.
// - Plain text: two columns `y z` (a third column, if any, is a weight in 1e-6 .. 1e6), separated
// by blanks, tabs,
//   commas or semicolons, in mm or m (the `units` argument). Lines starting with #, !, % or // are
//   comments; non-numeric lines before the first data line are headers; a trailing # or ! comment
//   is allowed. Rail: z up, h = z. Wheel: h = r0 + z, or h = z (z is the radius) when r0 = 0.
//
// Processing (profileFromPoints): checks (below), then the longest run of consecutive points whose
// chord slopes |dz/dy| stay <= maxSlope is kept (the profile must be a function of s: near-vertical
// flanks and the flange back are cut; a rail whose points beyond a cut go down and rise again by
// more than 1 mm to within 40 mm of its top, a second head or a step, is refused), optional
// rotation/shift, then a Reinsch smoothing spline through the points (smoothing length, 0 = natural
// interpolating spline), resampled on a uniform grid of step ds aligned on multiples of ds inside
// the kept points.
//
// - MiniProf (Greenwood Engineering) .whl (wheel), .ban (rail), .mpt (sections; one profile per
//   file is read): keyword or free-text header lines, a ColumnDef naming the columns (X lateral,
//   Y vertical, further columns ignored), the data rows; `"`, `%` and `!` start a comment. X and Y
//   are in millimetres. A wheel's X runs from the back of the flange, its tape circle at X = 70 mm
//   (s = X - 70 mm), Y is the radius increase (h = r0 + Y). A rail's X grows toward the gauge
//   side: the left rail's s is -X. Which way Y points is read from the shape (flange tip, rail
//   head above both ends). Steps backwards in X are cut on steep flanks, refused elsewhere.
//   XYPoints, when given, must match the point lines (a truncated file is refused); the header's
//   Sd, Sh, qR (keywords, or an old file's "(Sd/Sh/qR)" line) are returned in ProfileFileInfo.
// - VAMPIRE .whe / .rai are refused with a message: no public example or description to verify.
//
// Errors: bad files throw rb::InputError whose diagnostic is "file:line: message", the line being
// the offending one: non-numeric data, fewer than 10 points, y not strictly monotone or two points
// closer than 1 nm, implausible units (a coordinate > 1 m, or all coordinates < 1 mm), a wheel
// radius outside 0.2 .. 0.7 m, kept points spanning fewer than 4 grid steps ds, a missing or
// unterminated point block, a wrong profile type, unsupported processing keys.
// A file that is not a regular file (a FIFO, a device, a folder) or larger than
// kMaxProfileFileBytes (32 MiB) is refused (rb::readRegularFile), and so are more than
// kMaxProfilePoints (200 000) points: measured profiles have a few thousand, and the bounds keep a
// runaway file from taking gigabytes. At most 20 problems are reported per file.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "workbench/profiles/profile.hpp"

namespace rb::profiles {

enum class LengthUnit { Millimetre, Metre };

// Most points, and most bytes, a profile file may hold (see "Errors" above): 200 000 points take
// about 8 MiB of text.
inline constexpr std::size_t kMaxProfilePoints = 200'000;
inline constexpr std::size_t kMaxProfileFileBytes = std::size_t{32} << 20;

struct ProfileReadOptions {
  double r0 = 0.0;               // wheel: tape-circle radius [m] (h = r0 + z); 0 for text files
                                 // whose z is the radius itself. SIMPACK wheels need r0 > 0.
  double smoothingLength = 0.0;  // [m] Reinsch smoothing length l (0 = interpolation); the
                                 // half-amplitude wavelength is 2 pi l (see smoothing_spline.hpp)
  double ds = 2.0e-5;            // [m] grid step of the resulting Profile
  double maxSlope = 10.0;        // keep the longest run of points with |dz/dy| <= maxSlope
  bool mirrorY = false;          // negate y after reading (e.g. a file drawn for the right side)
  bool mirrorZ = false;          // plain text only: negate z as read (files with z down, as
                                 // CONTACT's canonical profiles); SIMPACK files say it themselves
  double rotate = 0.0;           // [rad] rotate the points about the file origin: y' = y cos a -
                                 // z sin a, z' = y sin a + z cos a (z up; -atan(1/40) undoes a
                                 // 1:40 cant of a rail drawn canted)
  double shiftS = 0.0;           // [m] then shift: s = y' + shiftS
  double shiftH = 0.0;           // [m]            h = z' + shiftH (+ r0 for wheels)
};

// Points as read, in SI and in the profile convention (y = s of the LEFT profile, z up; for wheels
// z excludes r0), with their file lines.
struct ProfilePoints {
  std::string file;
  ProfileKind kind = ProfileKind::Rail;
  std::vector<double> y, z, w;
  std::vector<int> line;
  int endLine = 0;        // line cited for errors about the point set as a whole
  int kindLine = 0;       // SIMPACK: line of the header type
  std::string unitsHint;  // how to fix the length unit, for the messages
};

// What a file says about itself beyond its points.
struct ProfileFileInfo {
  std::string format;  // "SIMPACK", "MiniProf", "text"
  // MiniProf wheels: the flange measures the instrument's software wrote into the header [m].
  bool hasHeaderDimensions = false;
  double headerSd = 0.0, headerSh = 0.0, headerQr = 0.0;
  int headerDimensionsLine = 0;
};

enum class ProfileFormat { Simpack, Miniprof, Vampire, Text };
// By the file's extension (case-insensitive).
ProfileFormat profileFormat(const std::string& path);

ProfilePoints readSimpackPoints(const std::string& path);
ProfilePoints readTextPoints(const std::string& path, ProfileKind kind, LengthUnit units);
// The same from the file's text already in memory; `path` names it in messages (and, for SIMPACK,
// its extension .prw / .prr gives the type when the header has none).
ProfilePoints parseSimpackPoints(std::string_view text, const std::string& path);
ProfilePoints parseTextPoints(std::string_view text, const std::string& path, ProfileKind kind,
                              LengthUnit units);
// MiniProf: the points of the file's one profile, oriented and in SI (see above); `info`, if given,
// receives the header's Sd, Sh, qR.
ProfilePoints readMiniprofPoints(const std::string& path, ProfileKind kind,
                                 ProfileFileInfo* info = nullptr);
ProfilePoints parseMiniprofPoints(std::string_view text, const std::string& path, ProfileKind kind,
                                  ProfileFileInfo* info = nullptr);

// Checks, trims, smooths and resamples (see above).
Profile profileFromPoints(const ProfilePoints& points, const ProfileReadOptions& options,
                          std::string name);

// The profile type is taken from the header (type = 1 wheel, 0 rail).
Profile readSimpackProfile(const std::string& path, const ProfileReadOptions& options = {});
Profile readTextProfile(const std::string& path, ProfileKind kind, LengthUnit units,
                        const ProfileReadOptions& options = {});
// By extension (profileFormat): .prw / .prr -> SIMPACK (its type must equal `kind`), .whl / .ban /
// .mpt -> MiniProf (.whl a wheel, .ban a rail), .whe / .rai refused, anything else -> text.
// `info`, if given, receives what the file says about itself.
Profile readProfileFile(const std::string& path, ProfileKind kind, LengthUnit units,
                        const ProfileReadOptions& options = {}, ProfileFileInfo* info = nullptr);

}  // namespace rb::profiles
