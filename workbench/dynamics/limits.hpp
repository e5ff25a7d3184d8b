#pragma once
// Admissible ranges of the profiles{} and contact{} parameters (ProfilesSpec, ContactSpec): the
// scenario schema shows and checks them, compileContact guards its inputs with the same ones.
#include "workbench/core/range.hpp"

namespace rb::dynamics {

// Positioning (paper Table 1, EN 13715 / EN 13674-1 profiles).
inline constexpr Range kBackToBackRange{1.3, 1.5};   // [m] B
inline constexpr Range kGaugeRange{1.0, 2.0};        // [m] G, 14 mm below the rail top
inline constexpr Range kR0Range{0.2, 0.7};           // [m] nominal rolling radius
inline constexpr Range kInclinationRange{0.0, 0.1};  // [rad] beta (1:40 = 0.025)
inline constexpr Range kLwRange{0.0, 1.0};           // [m] explicit Lw, 0 = from back_to_back
inline constexpr Range kLrRange{0.0, 1.0};           // [m] explicit Lr, 0 = from gauge

// Contact (paper sections 2.4, 2.5, Table 3).
inline constexpr Range kKecTransitionRange{0.0, 0.01, true};    // [m] dhat, dbar
inline constexpr Range kFlangeStiffnessRange{0.0, 1e15, true};  // [N/m^1.5] K
inline constexpr Range kFlangeDampingRange{-1.0, 1e14};         // [N s/m^2] D, < 0: K/100
inline constexpr Range kMuRange{0.0, 1.0};                      // [-]
inline constexpr Range kYoungsModulusRange{1e9, 1e12};          // [Pa]
inline constexpr Range kPoissonRange{0.0, 0.5};                 // [-]
inline constexpr Range kMinNormalForceRange{0.0, 1e7};          // [N]

// Elastic contact (ElasticSpec).
inline constexpr Range kElasticDampingRatioRange{0.0, 2.0};     // [-] zeta
inline constexpr Range kElasticSampleStepRange{0.02e-3, 2e-3};  // [m] scan step
inline constexpr Range kDerailmentLiftRange{1e-3, 0.1};         // [m] (< 0: the default)
inline constexpr Range kElasticCurvatureRatioRange{0.01, 1.0};  // [-] B floor / A
// The track under the rail (contact.elastic.rail_support): a rail mass per wheel and its support.
inline constexpr Range kRailSupportMassRange{1.0, 1e4};        // [kg]
inline constexpr Range kRailSupportStiffnessRange{1e5, 1e11};  // [N/m]
inline constexpr Range kRailSupportDampingRange{0.0, 1e8};     // [N s/m]
inline constexpr std::size_t kMaxRailSupportPoints = 2000;

}  // namespace rb::dynamics
