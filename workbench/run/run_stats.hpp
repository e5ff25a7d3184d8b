#pragma once
// What every vehicle run states about itself in /stats (docs/run_stats.md):
//   effects: the effects the compiled Model evaluates (derived from the Model, not from the
//     scenario text: a scenario may ask for what the vehicle cannot give), one per line,
//     "name" or "name: detail" with the names of kEffectNames;
//   stage_names, stage_share: the share of the integration's wall time per named rhs stage
//     (vehicle::StageClock, sampled 1 evaluation in stage_period and scaled to all), the
//     integrator's own work and the observer (outputs, assessment samples, progress);
//   stage_samples, stage_rejected, stage_period: how many rhs evaluations were timed and kept,
//     how many were left out (vehicle::StageClock::finish), and 1 in how many were timed.
// The summary of `workbench run` prints both as its second line.
#include <array>
#include <string>
#include <vector>

#include "workbench/core/names.hpp"
#include "workbench/integrators/integrator.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/vehicle/stage_clock.hpp"

namespace rb::run {

enum class Effect {
  GuidedWheelsets,
  WheelRailContact,
  CreepLaw,
  NormalForceCoupling,
  FlangeContact,
  WheelsetSpin,
  Irregularities,
  SpringDampers,
  SeriesDampers,
  ShearSprings,
  BendingSprings,
  BumpStops,
  PatchOutputs,
  ElementOutputs,
  BodyAccelerations,
  Assessment,
};

inline constexpr std::array<NameEntry<Effect>, 16> kEffectNames = {{
    {Effect::GuidedWheelsets, "guided_wheelsets",
     "wheelsets follow the track centre line (no wheel/rail contact)"},
    {Effect::WheelRailContact, "contact", "wheel/rail contact constraints: kec or lut"},
    {Effect::CreepLaw, "creep", "tangential creep forces: polach or kalker (absent with none)"},
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
    {Effect::PatchOutputs, "patch_outputs", "per-patch contact outputs (run.output.patches)"},
    {Effect::ElementOutputs, "element_outputs", "suspension element outputs (count)"},
    {Effect::BodyAccelerations, "body_accelerations", "body acceleration outputs"},
    {Effect::Assessment, "assessment", "assessment groups sampled during the run"},
}};
constexpr const auto& nameTable(Effect /*tag*/) {
  return kEffectNames;
}

// One effect of a run and what it is (a choice name, a count or a list; empty: none).
struct EffectUse {
  Effect effect;
  std::string detail;
  bool operator==(const EffectUse&) const = default;
};

// The effects the compiled vehicle model evaluates, in kEffectNames order.
std::vector<EffectUse> compiledEffects(const Model& m);
// "name" or "name: detail" (the lines of /stats/effects).
std::string effectLine(const EffectUse& e);
// "kec, polach, normal forces (consistent), ..." (the summary line).
std::string effectsSummary(const std::vector<EffectUse>& effects);

// The share of one part of the integration.
struct StageShare {
  std::string name;      // a vehicle::Stage name, "integrator" or "observer"
  double seconds = 0.0;  // [s] estimated wall time over the run
  double share = 0.0;    // [-] of the integration's wall time (the shares sum to 1)
};
struct StageCosts {
  std::vector<StageShare> parts;  // empty when no evaluation was timed
  long samples = 0;               // timed rhs evaluations kept
  long rejected = 0;              // timed evaluations left out (descheduled, failed)
  long evaluations = 0;           // rhs evaluations
  unsigned period = 0;            // 1 in period evaluations timed (0: timing off)
};

// Scales the sampled stage times to every rhs evaluation; the observer's share is the measured
// wall time of the observer and progress callbacks, the integrator's the rest of the
// integration's CPU time (at least 0; the shares are normalised to sum to 1).
StageCosts stageCosts(const vehicle::StageClock& clock, const integ::Stats& stats);
// "rhs cost: constraints 31 %, vehicle forces 28 %, ..." in decreasing share (parts below 0.5 %
// left out), or "rhs cost: not sampled".
std::string costSummary(const StageCosts& costs);

// /stats: effects, stage_period, stage_samples and (when sampled) stage_names, stage_share,
// stage_seconds.
void writeRunStats(io::ResultFile& f, const std::vector<EffectUse>& effects,
                   const StageCosts& costs);

}  // namespace rb::run
