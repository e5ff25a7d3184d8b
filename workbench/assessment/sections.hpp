#pragma once
// Track sections of an EN 14363 assessment and their test zones (docs/assessment.md, "Track
// sections and test zones").
//
// EN 14363 (and UIC 518) evaluate the running safety and track loading quantities per track
// section, each with its own statistics, grouped by test zone: tangent track, large-radius
// curves, small-radius curves and very small-radius curves, transitions kept apart. A quantity
// over a whole run mixes tangent and curve samples, so that e.g. the quasi-static guiding force
// (the 50 % value) depends on how much tangent track was simulated. A section here is a stretch
// [from, to) of track arc length s [m]; a wheel's samples belong to a section when that wheel's
// own s lies in it.
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/core/names.hpp"

namespace rb::assessment {

// What a section is: one track segment's body (tangent, transition or constant-radius curve) or
// a stretch the scenario gave (run.assessment.sections).
enum class SectionKind { Tangent, Transition, Curve, Given };
inline constexpr std::array<NameEntry<SectionKind>, 4> kSectionKindNames = {{
    {SectionKind::Tangent, "tangent", "a tangent segment of the track"},
    {SectionKind::Transition, "transition", "a transition segment (radius and cant change)"},
    {SectionKind::Curve, "curve", "the constant-radius body of a curve"},
    {SectionKind::Given, "given", "a stretch given in run.assessment.sections"},
}};
constexpr const auto& nameTable(SectionKind) {
  return kSectionKindNames;
}

// Test zones of EN 14363 by curve radius R. Assumption (the normative text was not at hand; the
// bounds are those quoted for EN 14363:2005 / UIC 518 in the secondary sources of
// docs/assessment.md, and CEN/TS 17843:2022 for the zone below 250 m): zone 1 tangent track and
// very large radii, zone 2 large-radius curves, zone 3 small-radius curves 400 <= R < 600 m,
// zone 4 very small-radius curves 250 <= R < 400 m, and below 250 m the zone 5 of CEN/TS 17843
// (outside the acceptance of EN 14363). A transition is in no zone.
enum class TestZone { Zone1, Zone2, Zone3, Zone4, Zone5, None };
inline constexpr std::array<NameEntry<TestZone>, 6> kTestZoneNames = {{
    {TestZone::Zone1, "zone 1", "tangent track and very large radii (R >= 5000 m, assumption)"},
    {TestZone::Zone2, "zone 2", "large-radius curves (600 m <= R < 5000 m)"},
    {TestZone::Zone3, "zone 3", "small-radius curves (400 m <= R < 600 m)"},
    {TestZone::Zone4, "zone 4", "very small-radius curves (250 m <= R < 400 m)"},
    {TestZone::Zone5, "zone 5", "R < 250 m (CEN/TS 17843; outside EN 14363 acceptance)"},
    {TestZone::None, "none", "no zone (a transition, or a given section of mixed radii)"},
}};
constexpr const auto& nameTable(TestZone) {
  return kTestZoneNames;
}

inline constexpr double kZone1MinRadius = 5000.0;  // [m] assumption, see TestZone
inline constexpr double kZone2MinRadius = 600.0;   // [m]
inline constexpr double kZone3MinRadius = 400.0;   // [m]
inline constexpr double kZone4MinRadius = 250.0;   // [m]

// The test zone of a constant radius R [m] (infinite: tangent track).
TestZone testZone(double radius);

// One section as the assessment evaluates it.
struct TrackSection {
  std::string name;  // tangent1, transition2, curve3, ... or the given name
  SectionKind kind = SectionKind::Tangent;
  double from = 0.0, to = 0.0;  // [m] arc length range [from, to)
  // [m] constant radius of a curve body, infinity on a tangent, NaN where it varies
  // (transitions; a given section spanning several segments).
  double radius = std::numeric_limits<double>::infinity();
  double cant = 0.0;  // [m] cant of a curve body (0 on a tangent, NaN where it varies)
  TestZone zone = TestZone::Zone1;
};

// A section the scenario gives (run.assessment.sections).
struct SectionSpec {
  std::string name;
  double from = 0.0, to = 0.0;  // [m]
  SourceLoc loc;
};

// Most sections a scenario may give (a bound on the work and on the file's groups).
inline constexpr std::size_t kMaxSections = 10000;

// A section name is an HDF5 group name of /assessment/sections: 1-64 letters, digits, '_', '-'.
bool validSectionName(const std::string& name);

// The quasi-static values (50 % of the filtered signal) are those of a constant-radius curve
// (EN 14363: Y_qst and Q_qst per curve section); they are evaluated in curve and given sections
// only.
inline bool hasQuasiStatic(SectionKind k) {
  return k == SectionKind::Curve || k == SectionKind::Given;
}

}  // namespace rb::assessment
