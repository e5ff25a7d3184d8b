#pragma once
// What a run assesses (run.assessment of a scenario): which groups of quantities, the interval at
// which their signals are sampled and the parameters of their limits. Every default and its
// source is stated in the scenario reference (workbench help) and docs/assessment.md.
#include <array>
#include <vector>

#include "workbench/assessment/sections.hpp"
#include "workbench/core/error.hpp"
#include "workbench/core/names.hpp"

namespace rb::assessment {

// S1002 flange angle (EN 13715 profile: the flange flank is inclined at about 70 deg); used for
// Nadal's limit when the scenario gives none.
inline constexpr double kS1002FlangeAngle = 1.2217;  // [rad]
// Default sample interval of the assessment signals: 400 Hz, 20 times the 20 Hz low-pass of the
// wheel forces (EN 14363) and of the comfort bands (EN 12299 weightings end near 20 Hz).
inline constexpr double kDefaultSampleEvery = 2.5e-3;  // [s]

// What kind of vehicle is assessed: it sets the factor alpha of Prud'homme's track shift limit
// (EN 14363: 1.0 for locomotives, power units and passenger vehicles, 0.85 for freight wagons).
// vehicle.category of a scenario; unstated: alpha = 1.0 is assumed and the summary says so.
enum class VehicleCategory { Unstated, Passenger, Locomotive, Freight };
inline constexpr std::array<NameEntry<VehicleCategory>, 4> kVehicleCategoryNames = {{
    {VehicleCategory::Unstated, "unstated",
     "not given: the assessment assumes alpha = 1.0 and says so"},
    {VehicleCategory::Passenger, "passenger", "passenger vehicle (alpha = 1.0)"},
    {VehicleCategory::Locomotive, "locomotive", "locomotive or power unit (alpha = 1.0)"},
    {VehicleCategory::Freight, "freight", "freight wagon (alpha = 0.85)"},
}};
constexpr const auto& nameTable(VehicleCategory) {
  return kVehicleCategoryNames;
}

// alpha of Prud'homme's limit for a vehicle category (EN 14363; unstated: 1.0).
double trackShiftAlpha(VehicleCategory c);

// EN 12299 6.7.2 asks for 60 blocks of 5 s (5 minutes) for N_MV; fewer is a caveat of the result.
inline constexpr int kComfortBlocksRequired = 60;

struct AssessmentSpec {
  bool safety = false;     // Y/Q, sum Y, dQ/Q, quasi-static and maximum wheel forces (EN 14363)
  bool stability = false;  // bogie-frame lateral acceleration, simplified method (EN 14363)
  bool comfort = false;    // EN 12299 N_MV and continuous comfort, Sperling's Wz
  bool wear = false;       // T gamma and frictional power per wheel and patch
  double sample_every = kDefaultSampleEvery;  // [s]
  SourceLoc sample_every_loc;  // where sample_every was given; empty when it is the default
  // Floor points along the car body, x offsets from its centre of mass [m]; empty: over the two
  // bogie centres and mid-car (front, centre, rear).
  std::vector<double> floor_positions;
  // Track shift factor of Prud'homme's limit [-]; <= 0: from the vehicle category.
  double alpha = -1.0;
  VehicleCategory category = VehicleCategory::Unstated;  // vehicle.category (set by the run)
  // Sections of the assessment (run.assessment.sections); empty: the track's segments.
  std::vector<SectionSpec> sections;
  double flange_angle = kS1002FlangeAngle;  // [rad] for Nadal's limit
  double mu = -1.0;                         // [-] for Nadal's limit; < 0: contact.mu
  double yq_limit = 0.8;                    // (Y/Q) limit [-]
  double instability_frequency = 0.0;       // f0 [Hz]; 0: spectrum peak in 3..9 Hz
  double comfort_limit = 2.0;               // N_MV target [-]
  SourceLoc loc;                            // where run.assessment was given
  // run.assessment = true: every group that applies to the vehicle (the others are dropped
  // without an error).
  bool all = false;

  bool any() const { return safety || stability || comfort || wear; }
};

}  // namespace rb::assessment
