#pragma once
// What every vehicle run states about itself in /stats (docs/run_stats.md):
//   effects: the effects the compiled Model evaluates (derived from the Model, not from the
//     scenario text: a scenario may ask for what the vehicle cannot give), one per line,
//     "name" or "name: detail" with the names of scenario::kEffectNames;
//   stage_names, stage_share: the share of the integration's wall time per named rhs stage
//     (vehicle::StageClock, sampled 1 evaluation in stage_period and scaled to all), the
//     integrator's own work and the observer (outputs, assessment samples, progress);
//   stage_samples, stage_rejected, stage_period: how many rhs evaluations were timed and kept,
//     how many were left out (vehicle::StageClock::finish), and 1 in how many were timed.
// The summary of `workbench run` prints both as its second line.
#include <string>
#include <vector>

#include "workbench/integrators/integrator.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/scenario/effect_names.hpp"
#include "workbench/vehicle/stage_clock.hpp"

namespace rb::run {

// The effects are the one table of scenario/effect_names.hpp: the switches of run.effects are a
// part of what a run records.
using scenario::Effect;

// One effect of a run and what it is (a choice name, a count or a list; empty: none).
struct EffectUse {
  Effect effect;
  std::string detail;
  bool operator==(const EffectUse&) const = default;
};

// The effects the compiled vehicle model evaluates, in scenario::kEffectNames order.
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
