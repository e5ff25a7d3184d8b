#pragma once
// The effects of a scene, one enum and one name table (core/names.hpp) for both sides of a run:
//   - the switches a user sets in run.effects.<name> (kEffectSwitches: default on when the scene
//     has the effect; false leaves it out of the compiled model, so it costs nothing,
//     architecture.md "Effects are compiled in, not branched on"), read by the schema, the reader,
//     the builders and `workbench effects`;
//   - what a run records that its compiled model evaluates (run/run_stats.hpp: /stats/effects and
//     the summary line), a superset of the switches.
// It lives in scenario/ because that is the lowest folder both the reader of the switches and
// run/ (which links rb_scenario) depend on, so neither side includes upwards.
#include <array>
#include <cstddef>
#include <string_view>

#include "workbench/core/error.hpp"
#include "workbench/core/names.hpp"

namespace rb::scenario {

enum class Effect {
  GuidedWheelsets,      // wheelsets that follow the track centre line (no wheel/rail contact)
  WheelRailContact,     // the contact method's constraints
  CreepForces,          // tangential contact forces of a creep law (contact.creep = none: absent)
  NormalForceCoupling,  // how the creep forces see the normal forces
  FlangeContact,        // part of the contact model (KEC flange regime, LUT Hertz flange)
  WheelsetSpin,         // free or prescribed
  Irregularities,       // track irregularities (paper Fig. 3)
  SpringDampers,        // parallel spring-dampers
  SeriesDampers,        // series spring-dampers, a force state each
  ShearSprings,         // shear springs
  BendingSprings,       // bending springs, anti-roll bars
  BumpStops,            // bumpstop elements (Appendix A)
  Patches,              // run.output.patches: the per-patch contact datasets
  ElementOutputs,       // run.output.elements: deflection and force of suspension elements
  BodyAccelerations,    // run.output.body_accelerations
  Assessment,           // run.assessment: EN 14363 / EN 12299 / Sperling / wear sampling
  TrackSupport,         // contact.elastic.rail_support: a rail mass per wheel on its support
};

// The names are the keys of run.effects and the lines of /stats/effects; the help says what a
// recorded effect is and what its detail holds (run/run_stats.hpp).
inline constexpr std::array<NameEntry<Effect>, 17> kEffectNames = {{
    {Effect::GuidedWheelsets, "guided_wheelsets",
     "wheelsets follow the track centre line (no wheel/rail contact)"},
    {Effect::WheelRailContact, "contact", "wheel/rail contact constraints: kec or lut"},
    {Effect::CreepForces, "creep_forces",
     "tangential creep forces: polach or kalker (absent with none)"},
    {Effect::NormalForceCoupling, "normal_forces",
     "normal/tangential coupling of the creep forces: lagged or consistent"},
    {Effect::FlangeContact, "flange_contact",
     "kec_band: KEC regularised tread-flange band (Eq. 26); hertz: LUT Hertz flange (Eq. 20-21)"},
    {Effect::WheelsetSpin, "wheelset_spin", "wheelset spin: free (a state) or prescribed"},
    {Effect::Irregularities, "irregularities", "track irregularities: psd or measured"},
    {Effect::SpringDampers, "spring_dampers", "parallel spring-dampers (count)"},
    {Effect::SeriesDampers, "series_dampers", "Maxwell series dampers, a state each (count)"},
    {Effect::ShearSprings, "shear_springs", "shear springs (count)"},
    {Effect::BendingSprings, "bending_springs", "bending springs, anti-roll bars (count)"},
    {Effect::BumpStops, "bump_stops", "bump stops (count)"},
    {Effect::Patches, "patches", "per-patch contact outputs (run.output.patches)"},
    {Effect::ElementOutputs, "element_outputs", "suspension element outputs (count)"},
    {Effect::BodyAccelerations, "body_accelerations", "body acceleration outputs"},
    {Effect::Assessment, "assessment", "assessment groups sampled during the run"},
    {Effect::TrackSupport, "track_support",
     "the track under the rail: a rail mass per wheel on its support (moving_rail_masses)"},
}};
constexpr const auto& nameTable(Effect /*tag*/) {
  return kEffectNames;
}

inline constexpr std::size_t kEffectCount = kEffectNames.size();

// One switch of run.effects: the effect and what false does (the schema's help of the key and
// the table of `workbench effects`), in the order of the schema's keys.
struct EffectSwitchEntry {
  Effect effect;
  std::string_view help;
};

inline constexpr std::array<EffectSwitchEntry, 10> kEffectSwitches = {{
    {Effect::Irregularities,
     "track irregularities (false: the track is built without them, nothing of them is evaluated)"},
    {Effect::BumpStops, "bumpstop elements (false: dropped from the vehicle)"},
    {Effect::SeriesDampers,
     "series spring-dampers (false: each becomes a plain damper in parallel with its optional "
     "spring, one force state fewer per damper)"},
    {Effect::ElementOutputs,
     "the deflection and force of run.output.elements (false: none written)"},
    {Effect::CreepForces,
     "tangential creep forces (false: as contact.creep = none, normal contact only)"},
    {Effect::Patches, "the per-patch contact datasets (false: as run.output.patches = false)"},
    {Effect::BodyAccelerations,
     "body accelerations in the output (false: as run.output.body_accelerations = false)"},
    {Effect::Assessment,
     "the engineering assessment groups run.assessment asks for (false: none sampled or "
     "computed)"},
    {Effect::TrackSupport,
     "the track under the rail, contact.elastic.rail_support (false: rigid rails, eight states "
     "fewer per wheelset)"},
    {Effect::FlangeContact,
     "always on: flange contact is part of the contact model (KEC flange regime, LUT Hertz "
     "flange); it cannot be switched off without changing the physics (false is an error)"},
}};

// The switch of `e`; nullptr for an effect a user cannot name in run.effects.
constexpr const EffectSwitchEntry* effectSwitch(Effect e) {
  for (const auto& s : kEffectSwitches)
    if (s.effect == e) return &s;
  return nullptr;
}

// One effect of a scene: whether the scene has it (before the switches) and whether it is on in
// the compiled model; `given` and `loc` say where run.effects named it. Only the entries of
// kEffectSwitches are read or set.
struct EffectSwitch {
  bool present = false;
  bool on = true;
  bool given = false;
  SourceLoc loc;
};

using EffectSwitches = std::array<EffectSwitch, kEffectCount>;

constexpr std::size_t effectIndex(Effect e) {
  return static_cast<std::size_t>(e);
}

}  // namespace rb::scenario
