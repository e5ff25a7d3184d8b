#pragma once
// The command lines of the analyses that run variants of one scenario (effects, critical-speed,
// modes, precision, stress; their options and drivers in their own libraries): the scenario and the
// common options (study/command.hpp) declared once, in scenario_command.cpp.
#include <string>

#include "workbench/critical_speed/critical_speed.hpp"
#include "workbench/effects/effects.hpp"
#include "workbench/modes/modes.hpp"
#include "workbench/precision/precision.hpp"
#include "workbench/stress/stress.hpp"
#include "workbench/study/command.hpp"

namespace CLI {
class App;
}

namespace rb::app {

using study::ScenarioCommandOptions;

// Declares the subcommand `name` on `app` with the scenario and the common options.
CLI::App* addScenarioCommand(CLI::App& app, const std::string& name, const std::string& description,
                             ScenarioCommandOptions& options);

// Declares the subcommand and its options on `app` (filled into `options` when parsed).
CLI::App* addPrecisionCommand(CLI::App& app, precision::PrecisionOptions& options);

// Declares the subcommand and its options on `app` (filled into `options` when parsed).
CLI::App* addStressCommand(CLI::App& app, stress::StressOptions& options);

// Declares the subcommand and its options on `app` (filled into `options` when parsed).
CLI::App* addEffectsCommand(CLI::App& app, effects::EffectsOptions& options);

// Declares the subcommand and its options on `app` (filled into `options` when parsed).
CLI::App* addModesCommand(CLI::App& app, modes::ModesOptions& options);

// Declares the subcommand and its options on `app` (filled into `options` when parsed).
CLI::App* addCriticalSpeedCommand(CLI::App& app, critical_speed::CriticalSpeedOptions& options);

}  // namespace rb::app
