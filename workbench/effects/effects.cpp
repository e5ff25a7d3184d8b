#include "workbench/effects/effects.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/effects/cases.hpp"
#include "workbench/study/option_checks.hpp"
#include "workbench/study/runner.hpp"

namespace fs = std::filesystem;

namespace rb::effects {
namespace {

const SourceLoc kCli{"<command line>", 0};

// The quantities the change in answer can be measured on (plots/railbench/study_data.py
// QUANTITY_TAGS): wheelset lateral displacement, yaw, wheel load, lateral creep force.
const std::vector<std::string> kQuantities = {"y", "yaw", "Q", "Fy"};

std::vector<std::string> commaList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');) out.push_back(item);
  return out;
}

// The user's options, before --quick changes any: all problems at once, each with its value. A
// length typed as 0 is no default, and an option --quick overrides is not silently dropped.
void checkOptions(const EffectsOptions& o) {
  Diagnostics d;
  const auto typed = [&](const char* option) { return o.given.contains(option); };
  if (typed("--duration") || o.duration != 0.0)
    if (const auto why = study::notPositive(o.duration, 1e9); !why.empty())
      study::badOption(d, "--duration", o.duration, why + " s");
  if (typed("--distance") || o.distance != 0.0)
    if (const auto why = study::notPositive(o.distance, 1e12); !why.empty())
      study::badOption(d, "--distance", o.distance, why + " m");
  if (o.duration > 0 && o.distance > 0) d.add(kCli, "give either --duration or --distance");
  if (const auto why = study::notPositive(o.cost_duration, 1e9); !why.empty())
    study::badOption(d, "--cost-duration", o.cost_duration, why + " s");
  if (o.repeats < 1 || o.repeats > 100)
    study::badOption(d, "--repeats", std::to_string(o.repeats), "must be in 1..100");
  else if (o.quick && typed("--repeats") && o.repeats != 1)
    study::badOption(d, "--repeats", std::to_string(o.repeats),
                     "--quick runs one repeat per case; give one of them");
  if (o.quick && typed("--cost-duration"))
    study::badOption(d, "--cost-duration", o.cost_duration,
                     "--quick runs no callgrind, so there is no cost run; give one of them");
  study::checkJobs(d, o.jobs, true);
  const auto quantities = commaList(o.quantities);
  if (quantities.empty())
    d.add(kCli, "--quantities: no quantity (one of: " + join(kQuantities, ", ") + ")");
  for (const auto& q : quantities) {
    bool known = false;
    for (const auto& k : kQuantities) known = known || k == q;
    if (!known)
      d.add(kCli,
            "--quantities: unknown quantity '" + q + "' (one of: " + join(kQuantities, ", ") + ")");
  }
  d.throwIfAny();
}

// How long every case runs, as an override of the key the scene itself uses (a scene that gives
// run.distance cannot also take run.duration): seconds are turned into metres at the vehicle's
// initial speed and back. Empty when neither is asked.
std::string lengthOverride(const scenario::ScenarioSpec& spec, double seconds, double metres) {
  if (!(seconds > 0) && !(metres > 0)) return {};
  const bool sceneDistance = spec.run.distance > 0;
  const bool sceneDuration = spec.run.duration > 0;
  const double v = spec.vehicle.speed;
  if (seconds > 0 && sceneDistance) {
    if (!(v > 0))
      throw InputError(kCli,
                       "--duration: the scene gives run.distance and the "
                       "vehicle has no speed to convert it; use --distance");
    return "run.distance=" + formatNumber(seconds * v);
  }
  if (metres > 0 && sceneDuration) {
    if (!(v > 0))
      throw InputError(kCli,
                       "--distance: the scene gives run.duration and the "
                       "vehicle has no speed to convert it; use --duration");
    return "run.duration=" + formatNumber(metres / v);
  }
  return seconds > 0 ? "run.duration=" + formatNumber(seconds)
                     : "run.distance=" + formatNumber(metres);
}

std::string effectHelp(scenario::Effect e) {
  const scenario::EffectSwitchEntry* s = scenario::effectSwitch(e);
  return s ? std::string(s->help) : std::string();
}

// effects_scene.csv: every effect of the scene, its state, the override that switches it off and
// what it is (read by plots/railbench/effects_cmd.py for the table's rows).
void writeSceneEffects(const fs::path& dir, const scenario::ScenarioSpec& spec) {
  std::ofstream f(dir / "effects_scene.csv");
  f << "effect,state,override,help\n";
  for (const auto& se : sceneEffects(spec))
    f << nameOf(se.effect) << "," << se.state << ","
      << (se.state == "measured" ? effectOffOverride(se.effect) : "") << ",\""
      << effectHelp(se.effect) << "\"\n";
  if (!f) throw InputError(kCli, "cannot write " + (dir / "effects_scene.csv").string());
}

}  // namespace

int runEffects(const EffectsOptions& options) {
  checkOptions(options);
  EffectsOptions o = options;
  if (o.quick) {
    if (!(o.duration > 0) && !(o.distance > 0)) o.duration = 0.2;
    o.repeats = 1;
    o.no_callgrind = true;
  }
  const scenario::ScenarioSpec scene = loadCommandScenario(o, o.overrides);
  if (!scene.has_vehicle)
    throw InputError({o.scenario, 0},
                     "the scenario has no vehicle{} block: nothing is simulated, "
                     "no effect to measure");
  // Q and Fy are wheel/rail forces: a guided vehicle has none, and every change would read as
  // nothing (the table's column empty, in unit "-").
  if (!scene.has_contact) {
    Diagnostics d;
    for (const auto& q : commaList(o.quantities))
      if (q == "Q" || q == "Fy")
        d.add(kCli, "--quantities: '" + q +
                        "' is a wheel/rail contact quantity, but the scenario's vehicle has no "
                        "contact (guided); use y or yaw");
    d.throwIfAny();
  }
  std::vector<std::string> common = o.overrides;
  std::vector<study::OptionOverride> lengths;
  if (auto len = lengthOverride(scene, o.duration, o.distance); !len.empty()) {
    common.push_back(len);
    // What the user typed (--quick's 0.2 s included, as --quick).
    if (options.duration > 0 || options.distance > 0)
      lengths.push_back({options.duration > 0 ? "--duration" : "--distance",
                         formatNumber(options.duration > 0 ? options.duration : options.distance),
                         len});
    else
      lengths.push_back({"--quick", "(0.2 s)", len});
  }
  // The cases' own run (with the length: the track's end, the output bound) is checked here, so
  // bad input runs nothing; a refusal names the option that set the length.
  (void)checkOptionOverrides(o, o.overrides, lengths);
  const scenario::ScenarioSpec spec = loadCommandScenario(o, common);
  if (!o.no_callgrind)
    (void)checkOptionOverrides(o, o.overrides,
                               {{"--cost-duration", formatNumber(o.cost_duration),
                                 lengthOverride(spec, o.cost_duration, 0)}});

  const study::StudyOptions so = commandStudyOptions(o, "effects");
  std::error_code ec;
  fs::create_directories(so.out, ec);
  if (ec) throw InputError(kCli, "--out: cannot create " + so.out + ": " + ec.message());
  writeSceneEffects(so.out, spec);

  const scenario::StudySpec st = effectsStudy(o.scenario, spec, common, o.repeats);
  const int study = study::runStudySpec(st, so, {});
  if (study == 2) return 2;
  std::vector<std::string> args = {"effects",      so.out,
                                   "--workbench",  o.program,
                                   "--root",       o.root,
                                   "--quantities", o.quantities,
                                   "--cost-set",   lengthOverride(spec, o.cost_duration, 0)};
  if (o.no_callgrind) args.emplace_back("--no-callgrind");
  const int plots = study::runPlots(so, args);
  return plots != 0 ? plots : study;
}

}  // namespace rb::effects
