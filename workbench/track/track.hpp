#pragma once
// The compiled, immutable track model: validated spec -> geometry (Eq. 1-2 preprocessor) and,
// only if the scene asks for them, irregularities (Fig. 3). A scene without irregularities gets a
// model without them (no per-evaluation branch on a flag beyond the optional itself).
//
// Validation limits (each violation is reported with the SourceLoc of its block; all problems are
// collected and thrown together as one rb::InputError):
// - at least one segment; every length > 0 m.
// - Curve radius >= 10 m; a Transition ends straight (radius 0) or at radius >= 10 m. The
//   tightest curves of railways (tramways, industrial sidings) are about 15-20 m; below 10 m the
//   track-frame model of a wheelset running along the centreline is meaningless.
// - |cant| <= 0.2 m per 1.5 m of cant_base (0.2 m on the standard 1.5 m base, a cant angle of
//   7.7 deg). Service limits are 0.15-0.18 m (EN 13803: 0.16 m ballasted, 0.18 m slab track), a
//   few lines reach 0.2 m; more is no longer railway track.
// - |gradient| <= 0.1 (100 per mille; adhesion railways stay below about 0.09).
// - A tangent has radius 0 and cant 0. Cant and gradient change only inside transitions: a Tangent
//   or Curve must start with the end cant and gradient of the previous segment. A segment after a
//   Transition must continue its end curvature (radius and side). Curvature steps are otherwise
//   allowed (a curve directly after a tangent, compound curves). The first segment starts freely.
// - track.step in (0, shortest segment length]; cant_base, gauge, rail_lr > 0;
//   rail_inclination in [0, 0.1] rad (1:40 = 0.025, 1:20 = 0.05).
// - Irregularities (Psd): known spectrum; step > 0; 0 < wavelength_min < wavelength_max;
//   wavelength_min >= 2 step (Nyquist); 1 <= components <= 100000; scale >= 0; user tables with
//   matching lengths, >= 2 points, omega > 0 strictly increasing, values >= 0.
// - Irregularities (Psd): the synthesised RMS of every channel finite and <= 0.1 m
//   (kMaxIrregularity).
// - Irregularities (Csv): a regular file in the format of parseMeasuredCsv (header naming the
//   columns, declared unit, finite strictly increasing s, plausible values, >= 2 rows) covering
//   the track [0, length] unless beyond = "zero" (then a warning).
// - Work and memory: segment lengths and the track length <= 1e7 m; the centreline knots
//   (length / track.step), the irregularity knots (length / psd step, or CSV rows) <=
//   track.max_points, and the synthesis terms (knots x components x channels) <=
//   track.max_points x 8000. The default (1e6) is documented in spec.hpp; a scenario raises it
//   with track { max_points = ... }.
// Segments are named as in the Lua file, 1-based: "track.segments[3] (curve): ...".
#include <optional>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/track/geometry.hpp"
#include "workbench/track/irregularities.hpp"
#include "workbench/track/psd.hpp"
#include "workbench/track/spec.hpp"

namespace rb::track {

class TrackModel {
 public:
  TrackModel(TrackSpec spec, TrackGeometry geometry, std::optional<Irregularities> irregularities);

  const TrackSpec& spec() const { return spec_; }
  const TrackGeometry& geometry() const { return geometry_; }
  // Present only when the scene asked for irregularities (source Psd or Csv).
  const std::optional<Irregularities>& irregularities() const { return irregularities_; }
  // False when a PSD with an UNVERIFIED parameter table (FRA classes) was used: print a warning.
  bool psdVerified() const;
  // Problems that do not stop a run but must be shown (printed by check and run): e.g. a
  // measured CSV shorter than the track with beyond = "zero".
  const std::vector<Diagnostic>& warnings() const { return warnings_; }

 private:
  TrackSpec spec_;
  TrackGeometry geometry_;
  std::optional<Irregularities> irregularities_;
  std::vector<Diagnostic> warnings_;
  friend TrackModel compileTrack(const TrackSpec& spec);
};

// Adds every problem of `spec` to `diags` (reads the CSV file of a Csv source). Does not throw.
void validateTrack(const TrackSpec& spec, Diagnostics& diags);

// Validates (throws one rb::InputError listing all problems) and builds the model.
TrackModel compileTrack(const TrackSpec& spec);

}  // namespace rb::track
