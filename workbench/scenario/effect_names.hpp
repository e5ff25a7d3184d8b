#pragma once
// The optional effects of a scene, each switched by run.effects.<name> (default on when the scene
// has it; false leaves it out of the compiled model, so it costs nothing, architecture.md
// "Effects are compiled in, not branched on"). One name table (core/names.hpp) feeds the schema
// of run.effects, the reader, `workbench effects` and its table.
#include <array>
#include <cstddef>

#include "workbench/core/error.hpp"
#include "workbench/core/names.hpp"

namespace rb::scenario {

enum class Effect {
  Irregularities,     // track irregularities (paper Fig. 3): the track built without them
  BumpStops,          // bumpstop elements (Appendix A) dropped from the vehicle
  SeriesDampers,      // series spring-dampers made plain dampers (one force state fewer each)
  ElementOutputs,     // run.output.elements: deflection and force of suspension elements
  CreepForces,        // tangential contact forces (contact.creep = none)
  Patches,            // run.output.patches: the per-patch contact datasets
  BodyAccelerations,  // run.output.body_accelerations
  Assessment,         // run.assessment: EN 14363 / EN 12299 / Sperling / wear sampling
  FlangeContact,      // part of the contact model (KEC flange regime, LUT Hertz flange): always on
};

inline constexpr std::array<NameEntry<Effect>, 9> kEffectNames = {{
    {Effect::Irregularities, "irregularities",
     "track irregularities (false: the track is built without them, nothing of them is evaluated)"},
    {Effect::BumpStops, "bump_stops", "bumpstop elements (false: dropped from the vehicle)"},
    {Effect::SeriesDampers, "series_dampers",
     "series spring-dampers (false: each becomes a plain damper in parallel with its optional "
     "spring, one force state fewer per damper)"},
    {Effect::ElementOutputs, "element_outputs",
     "the deflection and force of run.output.elements (false: none written)"},
    {Effect::CreepForces, "creep_forces",
     "tangential creep forces (false: as contact.creep = none, normal contact only)"},
    {Effect::Patches, "patches",
     "the per-patch contact datasets (false: as run.output.patches = false)"},
    {Effect::BodyAccelerations, "body_accelerations",
     "body accelerations in the output (false: as run.output.body_accelerations = false)"},
    {Effect::Assessment, "assessment",
     "the engineering assessment groups run.assessment asks for (false: none sampled or "
     "computed)"},
    {Effect::FlangeContact, "flange_contact",
     "always on: flange contact is part of the contact model (KEC flange regime, LUT Hertz "
     "flange); it cannot be switched off without changing the physics (false is an error)"},
}};
constexpr const auto& nameTable(Effect /*tag*/) {
  return kEffectNames;
}

inline constexpr std::size_t kEffectCount = kEffectNames.size();

// One effect of a scene: whether the scene has it (before the switches) and whether it is on in
// the compiled model; `given` and `loc` say where run.effects named it.
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
