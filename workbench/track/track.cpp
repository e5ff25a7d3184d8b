#include "workbench/track/track.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "workbench/track/format.hpp"

namespace rb::track {

using detail::num;
using detail::num4;

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

// Checks everything; returns the CSV table of a Csv source when it could be read without errors.
std::optional<IrregularityTable> check(const TrackSpec& spec, Diagnostics& d) {
  const SourceLoc& tl = spec.loc;
  // Track-level fields.
  if (spec.segments.empty()) d.add(tl, "track.segments: at least one segment is required");
  if (!(spec.step > 0.0)) d.add(tl, "track.step must be > 0 m, got " + num(spec.step));
  const bool baseOk = spec.cant_base > 0.0 && std::isfinite(spec.cant_base);
  if (!baseOk) d.add(tl, "track.cant_base must be > 0 m, got " + num(spec.cant_base));
  if (!(spec.gauge > 0.0)) d.add(tl, "track.gauge must be > 0 m, got " + num(spec.gauge));
  if (!(spec.rail_lr > 0.0)) d.add(tl, "track.rail_lr must be > 0 m, got " + num(spec.rail_lr));
  if (!(spec.rail_inclination >= 0.0 && spec.rail_inclination <= kMaxInclination)) {
    d.add(tl, "track.rail_inclination must be in [0, " + num4(kMaxInclination) + "] rad, got " +
                  num(spec.rail_inclination));
  }

  // Segments.
  double shortest = std::numeric_limits<double>::infinity();
  std::size_t shortestIdx = 0;
  double kappa = 0.0, u = 0.0, grad = 0.0;  // end values of the previous segment
  bool prevOk = false;
  SegmentKind prevKind = SegmentKind::Tangent;
  for (std::size_t i = 0; i < spec.segments.size(); ++i) {
    const SegmentSpec& sg = spec.segments[i];
    const std::string where =
        "track.segments[" + std::to_string(i + 1) + "] (" + kindName(sg.kind) + "): ";
    const std::size_t before = d.size();
    auto err = [&](const std::string& msg) { d.add(sg.loc, where + msg); };

    if (!(sg.length > 0.0 && std::isfinite(sg.length))) {
      err("length must be > 0 m, got " + num(sg.length));
    } else if (sg.length < shortest) {
      shortest = sg.length;
      shortestIdx = i;
    }
    switch (sg.kind) {
      case SegmentKind::Curve:
        if (!(sg.radius > 0.0 && std::isfinite(sg.radius))) {
          err("radius must be > 0 m, got " + num(sg.radius));
        } else if (sg.radius < kMinRadius) {
          err("radius must be >= 10 m (tighter curves are not railway track), got " +
              num(sg.radius));
        }
        break;
      case SegmentKind::Transition:
        if (!(sg.radius == 0.0 || (sg.radius >= kMinRadius && std::isfinite(sg.radius)))) {
          err("radius must be 0 (ends straight) or >= 10 m, got " + num(sg.radius));
        }
        break;
      case SegmentKind::Tangent:
        if (sg.radius != 0.0) err("radius must be 0 on a tangent, got " + num(sg.radius));
        if (sg.cant != 0.0) {
          err("cant must be 0 on a tangent (ramp cant in a transition), got " + num(sg.cant));
        }
        break;
    }
    if (baseOk) {
      const double maxCant = kMaxCantPerBase * spec.cant_base;
      if (!(std::abs(sg.cant) <= maxCant)) {
        err("|cant| must be <= " + num4(maxCant) + " m (0.2 m per 1.5 m of cant_base), got " +
            num(sg.cant));
      }
    }
    if (!(std::abs(sg.gradient) <= kMaxGradient)) {
      err("|gradient| must be <= 0.1, got " + num(sg.gradient));
    }
    const bool ok = d.size() == before;

    // Continuity with the previous segment (only when both are otherwise valid).
    const double sgn = sideSign(sg.side);
    const double kEnd = sg.radius > 0.0 ? sgn / sg.radius : 0.0;
    const double uHere = sg.kind == SegmentKind::Tangent ? 0.0 : sgn * sg.cant;
    if (ok && prevOk && sg.kind != SegmentKind::Transition) {
      const double kStart = sg.kind == SegmentKind::Curve ? kEnd : 0.0;
      if (prevKind == SegmentKind::Transition && std::abs(kStart - kappa) > kJumpTol) {
        err("curvature jumps from " + num4(kappa) + " 1/m to " + num4(kStart) +
            " 1/m at the segment start (positive = left); the preceding transition must end " +
            (sg.kind == SegmentKind::Tangent ? std::string("straight (radius 0)")
                                             : std::string("at this radius and side")));
      }
      if (std::abs(uHere - u) > kJumpTol) {
        err("cant jumps from " + num4(u) + " m to " + num4(uHere) +
            " m at the segment start (signed, positive = banked left); change cant in a "
            "transition");
      }
      if (std::abs(sg.gradient - grad) > kJumpTol) {
        err("gradient jumps from " + num4(grad) + " to " + num4(sg.gradient) +
            " at the segment start; change gradient in a transition");
      }
    }
    kappa = sg.kind == SegmentKind::Tangent ? 0.0 : kEnd;
    u = uHere;
    grad = sg.gradient;
    prevOk = ok;
    prevKind = sg.kind;
  }
  if (spec.step > 0.0 && std::isfinite(shortest) && spec.step > shortest) {
    d.add(tl, "track.step must be <= the shortest segment length (" + num(shortest) +
                  " m, track.segments[" + std::to_string(shortestIdx + 1) + "]), got " +
                  num(spec.step));
  }

  // Irregularities.
  const IrregularitySpec& ir = spec.irregularities;
  auto ierr = [&](const std::string& msg) { d.add(ir.loc, "track.irregularities: " + msg); };
  if (ir.source == IrregularitySource::Psd) {
    const auto spectrum = parseSpectrum(ir.spectrum);
    if (!spectrum) {
      ierr("unknown spectrum '" + ir.spectrum + "' (valid: " + spectrumNames() + ")");
    }
    const bool stepOk = ir.step > 0.0 && std::isfinite(ir.step);
    if (!stepOk) ierr("step must be > 0 m, got " + num(ir.step));
    const bool wminOk = ir.wavelength_min > 0.0 && std::isfinite(ir.wavelength_min);
    if (!wminOk) {
      ierr("wavelength_min must be > 0 m, got " + num(ir.wavelength_min));
    } else if (!(ir.wavelength_max > ir.wavelength_min && std::isfinite(ir.wavelength_max))) {
      ierr("wavelength_min (" + num(ir.wavelength_min) + " m) must be < wavelength_max (" +
           num(ir.wavelength_max) + " m)");
    }
    if (wminOk && stepOk && ir.wavelength_min < 2.0 * ir.step) {
      ierr("wavelength_min (" + num(ir.wavelength_min) + " m) must be >= 2 * step (" +
           num(2.0 * ir.step) + " m) to be resolved (Nyquist)");
    }
    if (ir.components < 1 || ir.components > kMaxComponents) {
      ierr("components must be in [1, " + std::to_string(kMaxComponents) + "], got " +
           std::to_string(ir.components));
    }
    if (!(ir.scale >= 0.0 && std::isfinite(ir.scale))) {
      ierr("scale must be >= 0, got " + num(ir.scale));
    }
    if (spectrum == Spectrum::User) {
      for (int c = 0; c < kChannels; ++c) {
        const PsdTable& t = ir.user[c];
        const std::string tn = std::string("user.") + channelName(static_cast<Channel>(c)) + ": ";
        if (t.omega.empty() && t.value.empty()) continue;  // channel disabled
        if (t.omega.size() != t.value.size()) {
          ierr(tn + "omega has " + std::to_string(t.omega.size()) + " points but value has " +
               std::to_string(t.value.size()));
          continue;
        }
        if (t.omega.size() < 2) {
          ierr(tn + "at least 2 points are required, got " + std::to_string(t.omega.size()));
          continue;
        }
        for (std::size_t k = 0; k < t.omega.size(); ++k) {
          if (k == 0 && !(t.omega[0] > 0.0 && std::isfinite(t.omega[0]))) {
            ierr(tn + "omega[1] must be > 0 rad/m, got " + num(t.omega[0]));
            break;
          }
          if (k > 0 && !(t.omega[k] > t.omega[k - 1] && std::isfinite(t.omega[k]))) {
            ierr(tn + "omega must be strictly increasing, omega[" + std::to_string(k + 1) +
                 "] = " + num(t.omega[k]) + " after " + num(t.omega[k - 1]));
            break;
          }
        }
        for (std::size_t k = 0; k < t.value.size(); ++k) {
          if (!(t.value[k] >= 0.0 && std::isfinite(t.value[k]))) {
            ierr(tn + "value[" + std::to_string(k + 1) + "] must be >= 0 m^2/(rad/m), got " +
                 num(t.value[k]));
            break;
          }
        }
      }
    }
  } else if (ir.source == IrregularitySource::Csv) {
    if (ir.csv_path.empty()) {
      ierr("csv_path is required for a csv source");
    } else {
      return readIrregularityCsv(ir.csv_path, ir.loc, d);
    }
  }
  return std::nullopt;
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
  std::optional<IrregularityTable> csv = check(spec, d);
  d.throwIfAny();
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
      irr.emplace(std::move(*csv), spec.rail_lr);
      break;
  }
  return TrackModel(spec, std::move(geometry), std::move(irr));
}

}  // namespace rb::track
