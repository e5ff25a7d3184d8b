#pragma once
// Names of the contact model's choices (scenario keywords of contact{}, HDF5 attributes of
// /contact, effect labels of studies), one table per enum of dynamics/spec.hpp (core/names.hpp).
#include <array>

#include "workbench/core/names.hpp"
#include "workbench/creep/fastsim.hpp"
#include "workbench/dynamics/contact_methods.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/dynamics/creep_laws.hpp"
#include "workbench/dynamics/spec.hpp"

namespace rb::dynamics {

// From the registry of contact methods (contact_methods.hpp): one entry per method.
inline constexpr auto kContactMethodNames = contactMethodNames(ContactMethods{});
constexpr const auto& nameTable(ContactMethod /*tag*/) {
  return kContactMethodNames;
}

// From the registry of creep laws (creep_laws.hpp): one entry per law.
inline constexpr auto kCreepModelNames = creepLawNames(CreepLaws{});
constexpr const auto& nameTable(CreepModel /*tag*/) {
  return kCreepModelNames;
}

inline constexpr std::array<NameEntry<ContactRegime>, 3> kContactRegimeNames = {{
    {ContactRegime::Tread, "tread", "tread contact only"},
    {ContactRegime::TwoPoint, "two_point", "a tread and a flange patch"},
    {ContactRegime::Flange, "flange", "flange contact only"},
}};
constexpr const auto& nameTable(ContactRegime /*tag*/) {
  return kContactRegimeNames;
}

inline constexpr std::array<NameEntry<ContactFailure>, 9> kContactFailureNames = {{
    {ContactFailure::None, "none", "no failure"},
    {ContactFailure::WheelLift, "wheel_lift", "a wheel's normal force fell below the minimum"},
    {ContactFailure::Derailment, "derailment", "a wheel rose beyond the derailment lift"},
    {ContactFailure::TableRange, "table_range", "the contact point left its table"},
    {ContactFailure::ConstraintSolve, "constraint_solve", "the KEC constraints were not solved"},
    {ContactFailure::Coupling, "coupling", "the normal/tangential coupling did not converge"},
    {ContactFailure::BodyRotation, "body_rotation", "a pitch angle reached the Euler-angle guard"},
    {ContactFailure::Singular, "singular", "a mass or constraint matrix could not be factored"},
    {ContactFailure::NonFinite, "non_finite", "a wheelset's solution is not finite"},
}};
constexpr const auto& nameTable(ContactFailure /*tag*/) {
  return kContactFailureNames;
}

inline constexpr std::array<NameEntry<NormalForceCoupling>, 2> kNormalForceCouplingNames = {{
    {NormalForceCoupling::Lagged, "lagged", "the previous evaluation's (the paper, section 2.5)"},
    {NormalForceCoupling::Consistent, "consistent",
     "solved together with the creep forces (converges under step refinement)"},
}};
constexpr const auto& nameTable(NormalForceCoupling /*tag*/) {
  return kNormalForceCouplingNames;
}

inline constexpr std::array<NameEntry<WheelsetSpin>, 2> kWheelsetSpinNames = {{
    {WheelsetSpin::Free, "free",
     "the wheelset spin is a degree of freedom driven by creep (a stiff mode, about -2400 1/s at "
     "20 m/s: solver.stiff = exponential integrates it; explicit ABM needs steps < 0.54 ms)"},
    {WheelsetSpin::Prescribed, "prescribed",
     "spin rate V(t)/r_c (constant rotational speed, the spin torque is a reaction), stable with "
     "ABM at 1 ms"},
}};
constexpr const auto& nameTable(WheelsetSpin /*tag*/) {
  return kWheelsetSpinNames;
}

}  // namespace rb::dynamics

namespace rb::creep {

// contact.fastsim.bound (found by argument-dependent lookup in rb::creep).
inline constexpr std::array<NameEntry<FastsimBound>, 2> kFastsimBoundNames = {{
    {FastsimBound::Parabolic, "parabolic",
     "Kalker's (1982) parabolic pressure of the simplified theory (the default)"},
    {FastsimBound::Elliptic, "elliptic", "Hertz's semi-ellipsoidal pressure"},
}};
constexpr const auto& nameTable(FastsimBound /*tag*/) {
  return kFastsimBoundNames;
}

}  // namespace rb::creep
