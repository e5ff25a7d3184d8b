#include "workbench/track/track.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "workbench/core/strings.hpp"
#include "workbench/track/format.hpp"

namespace rb::track {

namespace {

// Limits (documented in track.hpp).
constexpr double kMinRadius = 10.0;            // [m]
constexpr double kMaxCantPerBase = 0.2 / 1.5;  // [-] 0.2 m on a 1.5 m base
constexpr double kMaxGradient = 0.1;           // [-]
constexpr double kMaxInclination = 0.1;        // [rad]
constexpr int kMaxComponents = kMaxPsdComponents;
constexpr double kJumpTol = 1e-9;  // [m], [-], [1/m] tolerance of the continuity checks

const char* kindName(SegmentKind k) {
  switch (k) {
    case SegmentKind::Tangent:
      return "tangent";
    case SegmentKind::Transition:
      return "transition";
    case SegmentKind::Curve:
      return "curve";
  }
  return "?";
}

double sideSign(Side s) {
  return s == Side::Left ? 1.0 : -1.0;
}

struct Checked {
  std::optional<IrregularityTable> csv;  // the table of a Csv source read without errors
  std::vector<Diagnostic> warnings;
};

// Spline knots of a uniform grid of spacing `step` over [0, length] (as the builders make them),
// as a double so that an absurd request does not overflow.
double knotCount(double length, double step) {
  return std::max(1.0, std::ceil(length / step - 1e-9)) + 1.0;
}

std::string count(double n) {
  std::ostringstream os;
  os.precision(3);
  os << n;
  return os.str();
}

// A valid Psd source: the synthesis grid and its cost stay within track.max_points, and the
// synthesised irregularities are finite and of plausible size (a PSD off by orders of magnitude,
// or in the wrong units, is an input error here rather than a failure deep in the contact solve).
void checkSynthesis(const TrackSpec& spec, double length, Diagnostics& d) {
  const IrregularitySpec& ir = spec.irregularities;
  auto ierr = [&](const std::string& msg) { d.add(ir.loc, "track.irregularities: " + msg); };
  const double knots = knotCount(length, ir.step);
  if (knots > spec.max_points) {
    ierr(formatNumberExact(length) + " m at step " + formatNumberExact(ir.step) + " m needs " +
         count(knots) + " spline knots, more than track.max_points = " + count(spec.max_points) +
         "; use a coarser step, or raise track.max_points");
    return;
  }
  int active = 0;
  for (int c = 0; c < kChannels; ++c) active += ir.enabled[c] ? 1 : 0;
  const double terms = knots * static_cast<double>(ir.components) * active;
  const double maxTerms = spec.max_points * kSynthesisTermsPerPoint;
  if (terms > maxTerms) {
    ierr("the synthesis needs " + count(knots) + " knots x " + std::to_string(ir.components) +
         " components x " + std::to_string(active) + " channels = " + count(terms) +
         " cosine terms, more than track.max_points x " +
         std::to_string(static_cast<long long>(kSynthesisTermsPerPoint)) + " = " + count(maxTerms) +
         "; use fewer components or a coarser step, or raise track.max_points");
    return;
  }
  for (int c = 0; c < kChannels; ++c) {
    const CosineSeries series = makeCosineSeries(ir, static_cast<Channel>(c));
    double var = 0.0;
    for (const double a : series.amplitude) var += 0.5 * a * a;
    const double rms = std::sqrt(var);
    if (!(rms <= kMaxIrregularity)) {
      ierr(std::string(channelName(static_cast<Channel>(c))) + ": the synthesised irregularity " +
           "has an RMS of " + formatNumber(rms, 4) + " m, more than a track irregularity can be (" +
           formatNumberExact(kMaxIrregularity) +
           " m); check the PSD (one-sided, in m^2/(rad/m)) and scale");
    }
  }
}

// A measured table must cover the whole track [0, length] unless beyond = "zero" says that the
// track is perfect where the file does not reach.
void checkCoverage(const TrackSpec& spec, const MeasuredTable& m, double length, Diagnostics& d,
                   std::vector<Diagnostic>& warnings) {
  const IrregularitySpec& ir = spec.irregularities;
  const double tol = 1e-6;  // [m]
  const double s0 = m.table.s.front();
  const double s1 = m.table.s.back();
  const bool early = s0 > tol;
  const bool late = s1 < length - tol;
  if (!early && !late) return;
  const std::string file = detail::displayPath(ir.csv_path);
  if (ir.beyond == Beyond::Error) {
    if (early) {
      d.add(ir.loc, "track.irregularities: " + file + " starts at s = " + formatNumberExact(s0) +
                        " m (line " + std::to_string(m.first_line) +
                        "), after the track start s = 0 m; give rows from s = 0, or beyond = "
                        "\"zero\" for a perfect track where the file does not reach");
    }
    if (late) {
      d.add(ir.loc, "track.irregularities: the track is " + formatNumberExact(length) +
                        " m long but " + file + " ends at s = " + formatNumberExact(s1) +
                        " m (line " + std::to_string(m.last_line) +
                        "); give a file that covers the track, or beyond = \"zero\" for a "
                        "perfect track beyond the file");
    }
    return;
  }
  warnings.push_back({ir.loc, "track.irregularities: " + file +
                                  " covers s = " + formatNumberExact(s0) + " .. " +
                                  formatNumberExact(s1) + " m of the " + formatNumberExact(length) +
                                  " m track; the track is perfect (zero irregularities) beyond "
                                  "it (beyond = \"zero\")"});
}

// Track-level fields (segment list, steps, bounds, gauge, rail positions).
void checkTrackFields(const TrackSpec& spec, bool maxOk, bool baseOk, Diagnostics& d) {
  const SourceLoc& tl = spec.loc;
  if (spec.segments.empty()) d.add(tl, "track.segments: at least one segment is required");
  if (!(spec.step > 0.0))
    d.add(tl, "track.step must be > 0 m, got " + formatNumberExact(spec.step));
  if (!maxOk) d.add(tl, "track.max_points must be >= 2, got " + formatNumberExact(spec.max_points));
  if (!baseOk) d.add(tl, "track.cant_base must be > 0 m, got " + formatNumberExact(spec.cant_base));
  if (!(spec.gauge > 0.0))
    d.add(tl, "track.gauge must be > 0 m, got " + formatNumberExact(spec.gauge));
  if (!(spec.rail_lr > 0.0))
    d.add(tl, "track.rail_lr must be > 0 m, got " + formatNumberExact(spec.rail_lr));
  if (!(spec.rail_inclination >= 0.0 && spec.rail_inclination <= kMaxInclination)) {
    d.add(tl, "track.rail_inclination must be in [0, " + formatNumber(kMaxInclination, 4) +
                  "] rad, got " + formatNumberExact(spec.rail_inclination));
  }
}

// The fields of one segment on their own: radius by kind, cant (bounded by the cant base when that
// is valid), gradient. The length is checked by the caller.
void checkSegmentFields(const SegmentSpec& sg, const TrackSpec& spec, bool baseOk,
                        const std::function<void(const std::string&)>& err) {
  switch (sg.kind) {
    case SegmentKind::Curve:
      if (!(sg.radius > 0.0 && std::isfinite(sg.radius))) {
        err("radius must be > 0 m, got " + formatNumberExact(sg.radius));
      } else if (sg.radius < kMinRadius) {
        err("radius must be >= 10 m (tighter curves are not railway track), got " +
            formatNumberExact(sg.radius));
      }
      break;
    case SegmentKind::Transition:
      if (!(sg.radius == 0.0 || (sg.radius >= kMinRadius && std::isfinite(sg.radius)))) {
        err("radius must be 0 (ends straight) or >= 10 m, got " + formatNumberExact(sg.radius));
      }
      break;
    case SegmentKind::Tangent:
      if (sg.radius != 0.0)
        err("radius must be 0 on a tangent, got " + formatNumberExact(sg.radius));
      if (sg.cant != 0.0) {
        err("cant must be 0 on a tangent (ramp cant in a transition), got " +
            formatNumberExact(sg.cant));
      }
      break;
  }
  if (baseOk) {
    const double maxCant = kMaxCantPerBase * spec.cant_base;
    if (!(std::abs(sg.cant) <= maxCant)) {
      err("|cant| must be <= " + formatNumber(maxCant, 4) +
          " m (0.2 m per 1.5 m of cant_base), got " + formatNumberExact(sg.cant));
    }
  }
  if (!(std::abs(sg.gradient) <= kMaxGradient)) {
    err("|gradient| must be <= 0.1, got " + formatNumberExact(sg.gradient));
  }
}

// End state of the previous segment, for the continuity of curvature, cant and gradient.
struct SegmentEnd {
  double kappa = 0.0, u = 0.0, grad = 0.0;  // [1/m], [m] signed cant, [-]
  bool ok = false;                          // the previous segment passed its own checks
  SegmentKind kind = SegmentKind::Tangent;
};

// Continuity of a curve or tangent with the end of the previous segment (a transition ramps them,
// so it may start anywhere).
void checkContinuity(const SegmentSpec& sg, double kEnd, double uHere, const SegmentEnd& prev,
                     const std::function<void(const std::string&)>& err) {
  const double kStart = sg.kind == SegmentKind::Curve ? kEnd : 0.0;
  if (prev.kind == SegmentKind::Transition && std::abs(kStart - prev.kappa) > kJumpTol) {
    err("curvature jumps from " + formatNumber(prev.kappa, 4) + " 1/m to " +
        formatNumber(kStart, 4) +
        " 1/m at the segment start (positive = left); the preceding transition must end " +
        (sg.kind == SegmentKind::Tangent ? std::string("straight (radius 0)")
                                         : std::string("at this radius and side")));
  }
  if (std::abs(uHere - prev.u) > kJumpTol) {
    err("cant jumps from " + formatNumber(prev.u, 4) + " m to " + formatNumber(uHere, 4) +
        " m at the segment start (signed, positive = banked left); change cant in a "
        "transition");
  }
  if (std::abs(sg.gradient - prev.grad) > kJumpTol) {
    err("gradient jumps from " + formatNumber(prev.grad, 4) + " to " +
        formatNumber(sg.gradient, 4) + " at the segment start; change gradient in a transition");
  }
}

// Every segment (its fields, its continuity with the previous one), and the track step against
// the shortest segment.
void checkSegments(const TrackSpec& spec, bool baseOk, Diagnostics& d) {
  double shortest = std::numeric_limits<double>::infinity();
  std::size_t shortestIdx = 0;
  SegmentEnd prev;
  for (std::size_t i = 0; i < spec.segments.size(); ++i) {
    const SegmentSpec& sg = spec.segments[i];
    const std::string where =
        "track.segments[" + std::to_string(i + 1) + "] (" + kindName(sg.kind) + "): ";
    const std::size_t before = d.size();
    const std::function<void(const std::string&)> err = [&](const std::string& msg) {
      d.add(sg.loc, where + msg);
    };
    if (!(sg.length > 0.0 && std::isfinite(sg.length))) {
      err("length must be > 0 m, got " + formatNumberExact(sg.length));
    } else if (sg.length > kMaxTrackLength) {
      err("length must be <= " + formatNumberExact(kMaxTrackLength) +
          " m (longer than any railway line), got " + formatNumberExact(sg.length));
    } else if (sg.length < shortest) {
      shortest = sg.length;
      shortestIdx = i;
    }
    checkSegmentFields(sg, spec, baseOk, err);
    const bool ok = d.size() == before;
    // Continuity with the previous segment (only when both are otherwise valid).
    const double sgn = sideSign(sg.side);
    const double kEnd = sg.radius > 0.0 ? sgn / sg.radius : 0.0;
    const double uHere = sg.kind == SegmentKind::Tangent ? 0.0 : sgn * sg.cant;
    if (ok && prev.ok && sg.kind != SegmentKind::Transition)
      checkContinuity(sg, kEnd, uHere, prev, err);
    prev.kappa = sg.kind == SegmentKind::Tangent ? 0.0 : kEnd;
    prev.u = uHere;
    prev.grad = sg.gradient;
    prev.ok = ok;
    prev.kind = sg.kind;
  }
  if (spec.step > 0.0 && std::isfinite(shortest) && spec.step > shortest) {
    d.add(spec.loc, "track.step must be <= the shortest segment length (" +
                        formatNumberExact(shortest) + " m, track.segments[" +
                        std::to_string(shortestIdx + 1) + "]), got " +
                        formatNumberExact(spec.step));
  }
}

// Total length when every segment length is usable (0 otherwise: no length-based checks), and the
// spline knots it needs against track.max_points.
double checkedLength(const TrackSpec& spec, bool maxOk, Diagnostics& d) {
  const SourceLoc& tl = spec.loc;
  double length = 0.0;
  for (const SegmentSpec& sg : spec.segments) {
    length = sg.length > 0.0 && sg.length <= kMaxTrackLength && length >= 0.0 ? length + sg.length
                                                                              : -1.0;
  }
  if (length > kMaxTrackLength) {
    d.add(tl, "track: the segments add up to " + formatNumberExact(length) +
                  " m, more than the longest track (" + formatNumberExact(kMaxTrackLength) + " m)");
    length = 0.0;
  }
  length = std::max(length, 0.0);
  if (length > 0.0 && maxOk && spec.step > 0.0) {
    const double knots = knotCount(length, spec.step);
    if (knots > spec.max_points) {
      d.add(tl, "track: " + formatNumberExact(length) + " m at step " +
                    formatNumberExact(spec.step) + " m needs " + count(knots) +
                    " spline knots, more than track.max_points = " + count(spec.max_points) +
                    " (about 0.4 kB each); use a coarser step, or raise track.max_points");
    }
  }
  return length;
}

// One channel of a user PSD table: both columns of equal length >= 2, omega positive and strictly
// increasing, values >= 0 (an empty channel is disabled).
void checkUserPsdChannel(const PsdTable& t, int c,
                         const std::function<void(const std::string&)>& ierr) {
  const std::string tn = std::string("user.") + channelName(static_cast<Channel>(c)) + ": ";
  if (t.omega.empty() && t.value.empty()) return;  // channel disabled
  if (t.omega.size() != t.value.size()) {
    ierr(tn + "omega has " + std::to_string(t.omega.size()) + " points but value has " +
         std::to_string(t.value.size()));
    return;
  }
  if (t.omega.size() < 2) {
    ierr(tn + "at least 2 points are required, got " + std::to_string(t.omega.size()));
    return;
  }
  for (std::size_t k = 0; k < t.omega.size(); ++k) {
    if (k == 0 && !(t.omega[0] > 0.0 && std::isfinite(t.omega[0]))) {
      ierr(tn + "omega[1] must be > 0 rad/m, got " + formatNumberExact(t.omega[0]));
      break;
    }
    if (k > 0 && !(t.omega[k] > t.omega[k - 1] && std::isfinite(t.omega[k]))) {
      ierr(tn + "omega must be strictly increasing, omega[" + std::to_string(k + 1) +
           "] = " + formatNumberExact(t.omega[k]) + " after " + formatNumberExact(t.omega[k - 1]));
      break;
    }
  }
  for (std::size_t k = 0; k < t.value.size(); ++k) {
    if (!(t.value[k] >= 0.0 && std::isfinite(t.value[k]))) {
      ierr(tn + "value[" + std::to_string(k + 1) + "] must be >= 0 m^2/(rad/m), got " +
           formatNumberExact(t.value[k]));
      break;
    }
  }
}

// A PSD source: spectrum, synthesis band and step, components, scale, user tables; then the work
// of the synthesis when all of these are valid.
void checkPsdSource(const TrackSpec& spec, double length, bool maxOk, Diagnostics& d) {
  const IrregularitySpec& ir = spec.irregularities;
  const std::function<void(const std::string&)> ierr = [&](const std::string& msg) {
    d.add(ir.loc, "track.irregularities: " + msg);
  };
  const std::size_t psdBefore = d.size();
  const auto spectrum = parseSpectrum(ir.spectrum);
  if (!spectrum) {
    ierr("unknown spectrum '" + ir.spectrum + "' (valid: " + spectrumNames() + ")");
  }
  const bool stepOk = ir.step > 0.0 && std::isfinite(ir.step);
  if (!stepOk) ierr("step must be > 0 m, got " + formatNumberExact(ir.step));
  const bool wminOk = ir.wavelength_min > 0.0 && std::isfinite(ir.wavelength_min);
  if (!wminOk) {
    ierr("wavelength_min must be > 0 m, got " + formatNumberExact(ir.wavelength_min));
  } else if (!(ir.wavelength_max > ir.wavelength_min && std::isfinite(ir.wavelength_max))) {
    ierr("wavelength_min (" + formatNumberExact(ir.wavelength_min) +
         " m) must be < wavelength_max (" + formatNumberExact(ir.wavelength_max) + " m)");
  }
  if (wminOk && stepOk && ir.wavelength_min < 2.0 * ir.step) {
    ierr("wavelength_min (" + formatNumberExact(ir.wavelength_min) + " m) must be >= 2 * step (" +
         formatNumberExact(2.0 * ir.step) + " m) to be resolved (Nyquist)");
  }
  if (ir.components < 1 || ir.components > kMaxComponents) {
    ierr("components must be in [1, " + std::to_string(kMaxComponents) + "], got " +
         std::to_string(ir.components));
  }
  if (!(ir.scale >= 0.0 && std::isfinite(ir.scale))) {
    ierr("scale must be >= 0, got " + formatNumberExact(ir.scale));
  }
  if (spectrum == Spectrum::User) {
    for (int c = 0; c < kChannels; ++c) checkUserPsdChannel(ir.user[c], c, ierr);
  }
  if (d.size() == psdBefore && length > 0.0 && maxOk) checkSynthesis(spec, length, d);
}

// Checks everything, including the work and memory the track will need, so that nothing that
// passes here fails while building.
Checked check(const TrackSpec& spec, Diagnostics& d) {
  Checked out;
  const bool maxOk = spec.max_points >= 2.0 && std::isfinite(spec.max_points);
  const bool baseOk = spec.cant_base > 0.0 && std::isfinite(spec.cant_base);
  checkTrackFields(spec, maxOk, baseOk, d);
  checkSegments(spec, baseOk, d);
  const double length = checkedLength(spec, maxOk, d);

  // Irregularities.
  const IrregularitySpec& ir = spec.irregularities;
  if (ir.source == IrregularitySource::Psd) {
    checkPsdSource(spec, length, maxOk, d);
  } else if (ir.source == IrregularitySource::Csv) {
    if (ir.csv_path.empty()) {
      d.add(ir.loc, "track.irregularities: csv_path is required for a csv source");
    } else if (maxOk) {
      CsvReadOptions o;
      o.unit = ir.csv_unit;
      o.max_rows = spec.max_points;
      std::optional<MeasuredTable> m = readMeasuredCsv(ir.csv_path, ir.loc, o, d);
      if (m && length > 0.0) checkCoverage(spec, *m, length, d, out.warnings);
      if (m) out.csv = std::move(m->table);
    }
  }
  return out;
}

}  // namespace

TrackModel::TrackModel(TrackSpec spec, TrackGeometry geometry,
                       std::optional<Irregularities> irregularities)
    : spec_(std::move(spec)),
      geometry_(std::move(geometry)),
      irregularities_(std::move(irregularities)) {}

bool TrackModel::psdVerified() const {
  if (spec_.irregularities.source != IrregularitySource::Psd) return true;
  return track::psdVerified(spec_.irregularities.spectrum);
}

void validateTrack(const TrackSpec& spec, Diagnostics& diags) {
  (void)check(spec, diags);
}

TrackModel compileTrack(const TrackSpec& spec) {
  Diagnostics d;
  Checked checked = check(spec, d);
  d.throwIfAny();
  std::optional<IrregularityTable>& csv = checked.csv;
  TrackGeometry geometry(spec);
  std::optional<Irregularities> irr;
  switch (spec.irregularities.source) {
    case IrregularitySource::None:
      break;
    case IrregularitySource::Psd:
      irr.emplace(synthesizeIrregularities(spec.irregularities, geometry.length()), spec.rail_lr);
      break;
    case IrregularitySource::Csv:
      RB_CHECK(csv.has_value(), "csv table missing after validation");
      applyFadeIn(*csv, spec.irregularities.fade_in);
      irr.emplace(std::move(*csv), spec.rail_lr);
      break;
  }
  TrackModel model(spec, std::move(geometry), std::move(irr));
  model.warnings_ = std::move(checked.warnings);
  return model;
}

}  // namespace rb::track
