#pragma once
// Builders of the typed Specs, one per top-level block: each reads its block through a Reader
// (reader.hpp) and adds every problem to the Diagnostics. loadScenario (scenario.cpp) calls them.
#include "workbench/core/error.hpp"
#include "workbench/scenario/lua_host.hpp"
#include "workbench/scenario/node.hpp"
#include "workbench/scenario/scenario.hpp"

namespace rb::scenario {

// track{} with its segments and irregularities; railsGiven: rail_lr or rail_inclination set.
void buildTrack(const Node& n, LuaHost& host, track::TrackSpec& t, bool& railsGiven,
                Diagnostics& d);
void buildProfiles(const Node& n, LuaHost& host, dynamics::ProfilesSpec& p, Diagnostics& d);
// contact{}; returns true for method = "guided" (no contact model: c is left at its defaults).
bool buildContact(const Node& n, dynamics::ContactSpec& c, Diagnostics& d);
void buildVehicle(const Node& n, vehicle::VehicleSpec& v, Diagnostics& d);
// train{} into spec.train; profiles{} and contact{} of `spec` (built before) are the entries'
// defaults.
void buildTrain(const Node& n, LuaHost& host, ScenarioSpec& spec, Diagnostics& d);
void buildSolver(const Node& n, integ::SolverSpec& s, Diagnostics& d);
void buildRun(const Node& n, RunSpec& run, Diagnostics& d);
// run.effects = { name = true|false, ... } (effect_names.hpp) into run.effects[].given / .on.
void buildEffects(const Node& n, EffectSwitches& effects, Diagnostics& d);
// Marks the effects the scene has, then removes every one switched off from the Specs; a switch
// the scene cannot use (false for an effect it does not have, flange_contact = false) is an
// error at the switch.
void applyEffectSwitches(ScenarioSpec& spec, Diagnostics& d);

}  // namespace rb::scenario
