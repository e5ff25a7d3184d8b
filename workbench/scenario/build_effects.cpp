// run.effects: reading the switches and removing every switched-off effect from the Specs, so the
// compiled model does not contain it (architecture.md, "Effects are compiled in, not branched
// on"): no irregularity spline, no bumpstop element, no series-damper force state, no output
// channel and no assessment sampling is left for the right-hand side or the output to skip.
#include <algorithm>
#include <string>

#include "workbench/scenario/build.hpp"
#include "workbench/scenario/reader.hpp"

namespace rb::scenario {
namespace {

bool hasElement(const vehicle::VehicleSpec& v, vehicle::ElementKind kind) {
  return std::any_of(v.elements.begin(), v.elements.end(),
                     [kind](const vehicle::ElementSpec& e) { return e.kind == kind; });
}

bool assessmentAsked(const assessment::AssessmentSpec& a) {
  return a.safety || a.stability || a.comfort || a.wear;
}

// Whether the loaded scene has effect `e` (before its switch is applied). Wheel/rail effects
// need both a vehicle and a contact block (a guided vehicle has neither creep nor flange).
bool present(const ScenarioSpec& s, Effect e) {
  const bool wheelRail = s.has_vehicle && s.has_contact;
  switch (e) {
    case Effect::Irregularities:
      return s.track.irregularities.source != track::IrregularitySource::None;
    case Effect::BumpStops:
      return s.has_vehicle && hasElement(s.vehicle, vehicle::ElementKind::Bumpstop);
    case Effect::SeriesDampers:
      return s.has_vehicle && hasElement(s.vehicle, vehicle::ElementKind::SeriesSpringDamper);
    case Effect::ElementOutputs:
      return s.has_vehicle && !s.run.output_elements.empty();
    case Effect::CreepForces:
      return wheelRail && s.contact.creep != dynamics::CreepModel::None;
    case Effect::Patches:
      return wheelRail && s.run.output_patches;
    case Effect::BodyAccelerations:
      return s.has_vehicle && s.run.body_accelerations;
    case Effect::Assessment:
      return s.has_vehicle && assessmentAsked(s.run.assessment);
    case Effect::FlangeContact:
      return wheelRail;
    case Effect::TrackSupport:
      return wheelRail && !s.contact.elastic.rail_support.empty();
    default:
      break;  // recorded by a run, not a switch: applyEffectSwitches never asks
  }
  return false;
}

// Bump stops leave the vehicle, and with them any output asked of them (an element that is not
// there cannot be written).
void dropBumpStops(ScenarioSpec& s) {
  std::vector<std::string> dropped;
  auto& els = s.vehicle.elements;
  for (const auto& e : els)
    if (e.kind == vehicle::ElementKind::Bumpstop) dropped.push_back(e.name);
  els.erase(std::remove_if(els.begin(), els.end(),
                           [](const vehicle::ElementSpec& e) {
                             return e.kind == vehicle::ElementKind::Bumpstop;
                           }),
            els.end());
  auto& out = s.run.output_elements;
  out.erase(std::remove_if(out.begin(), out.end(),
                           [&](const std::string& n) {
                             return std::find(dropped.begin(), dropped.end(), n) != dropped.end();
                           }),
            out.end());
}

// A series damper (Appendix A: f_dot + (K_series / D) f = K_series d_dot, total force preload +
// K d + f) as the plain damper it tends to for K_series -> infinity: preload + K d + D d_dot, with
// the same parallel spring K and damping D and no force state.
void plainDampers(ScenarioSpec& s) {
  for (auto& e : s.vehicle.elements) {
    if (e.kind != vehicle::ElementKind::SeriesSpringDamper) continue;
    e.kind = vehicle::ElementKind::SpringDamper;
    e.series_stiffness = 0.0;
  }
}

// Why a scene lacks effect `e` (the message of a switch it cannot use).
const char* absentReason(Effect e) {
  switch (e) {
    case Effect::Irregularities:
      return "the track has no irregularities";
    case Effect::BumpStops:
      return "the vehicle has no bumpstop element";
    case Effect::SeriesDampers:
      return "the vehicle has no series_damper element";
    case Effect::ElementOutputs:
      return "run.output.elements names no element";
    case Effect::CreepForces:
      return "no wheel/rail contact with a creep law (contact.creep = none, or no contact or "
             "vehicle block)";
    case Effect::Patches:
      return "no wheel/rail contact patches are written";
    case Effect::BodyAccelerations:
      return "run.output.body_accelerations is not on";
    case Effect::Assessment:
      return "run.assessment asks for no group";
    case Effect::FlangeContact:
      return "no wheel/rail contact";
    case Effect::TrackSupport:
      return "contact.elastic.rail_support is not given (the rails are rigid)";
    default:
      break;  // not a switch
  }
  return "";
}

void switchOff(ScenarioSpec& s, Effect e) {
  switch (e) {
    case Effect::Irregularities:
      s.track.irregularities = track::IrregularitySpec{};
      break;
    case Effect::BumpStops:
      dropBumpStops(s);
      break;
    case Effect::SeriesDampers:
      plainDampers(s);
      break;
    case Effect::ElementOutputs:
      s.run.output_elements.clear();
      break;
    case Effect::CreepForces:
      s.contact.creep = dynamics::CreepModel::None;
      break;
    case Effect::Patches:
      s.run.output_patches = false;
      break;
    case Effect::BodyAccelerations:
      s.run.body_accelerations = false;
      break;
    case Effect::Assessment:
      s.run.assessment.safety = s.run.assessment.stability = false;
      s.run.assessment.comfort = s.run.assessment.wear = false;
      s.run.assessment.all = false;
      break;
    case Effect::TrackSupport:
      s.contact.elastic.rail_support.clear();
      break;
    default:
      break;  // flange contact is refused in applyEffectSwitches, the others are no switches
  }
}

}  // namespace

void buildEffects(const Node& n, EffectSwitches& effects, Diagnostics& d) {
  Reader r(n, block("run.effects"), "run.effects", d);
  for (const auto& entry : kEffectSwitches) {
    const std::string name(nameOf(entry.effect));
    const Node* v = r.value(name);
    if (!v) continue;
    EffectSwitch& sw = effects[effectIndex(entry.effect)];
    sw.given = true;
    sw.loc = v->loc;
    sw.on = r.boolean(name);
  }
}

void applyEffectSwitches(ScenarioSpec& spec, Diagnostics& d) {
  // The train's vehicles behind the first as scenes of their own (their vehicle and contact
  // model): an effect is present when any vehicle has it, and a switch acts on every vehicle.
  std::vector<ScenarioSpec> others;
  for (std::size_t k = 1; k < spec.train.size(); ++k) {
    ScenarioSpec v;
    v.track = spec.track;
    v.run = spec.run;
    v.has_vehicle = true;
    v.vehicle = spec.train[k].vehicle;
    v.has_contact = spec.train[k].has_contact;
    v.contact = spec.train[k].contact;
    others.push_back(std::move(v));
  }
  for (const auto& entry : kEffectSwitches) {
    const Effect e = entry.effect;
    EffectSwitch& sw = spec.run.effects[effectIndex(e)];
    sw.present =
        present(spec, e) || std::any_of(others.begin(), others.end(),
                                        [&](const ScenarioSpec& v) { return present(v, e); });
    if (sw.on) {
      sw.on = sw.present;
      continue;
    }
    const std::string key = "run.effects." + std::string(nameOf(e));
    if (e == Effect::FlangeContact)
      d.add(sw.loc, key +
                        ": flange contact is part of the contact model (the KEC flange regime, "
                        "the LUT Hertz flange) and cannot be switched off without changing the "
                        "physics; remove the switch");
    else if (!sw.present)
      d.add(sw.loc,
            key + " = false: nothing to switch off, " + absentReason(e) + "; remove the switch");
    else {
      switchOff(spec, e);
      for (auto& v : others) switchOff(v, e);
    }
  }
  for (std::size_t k = 1; k < spec.train.size(); ++k) {
    spec.train[k].vehicle = std::move(others[k - 1].vehicle);
    spec.train[k].contact = std::move(others[k - 1].contact);
  }
}

}  // namespace rb::scenario
