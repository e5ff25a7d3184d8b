#include "workbench/scenario/scenario.hpp"

#include <algorithm>

#include "workbench/dynamics/names.hpp"
#include "workbench/dynamics/rails_along_track.hpp"
#include "workbench/scenario/build.hpp"
#include "workbench/scenario/lua_host.hpp"
#include "workbench/scenario/overrides.hpp"
#include "workbench/vehicle/names.hpp"

namespace rb::scenario {
namespace {

// Wheelsets without a contact{} block would run guided (no wheel/rail forces) and write a
// plausible result: the wheel/rail model is never assumed, it is named, contact { method = "kec" }
// or "lut" for contact, "guided" for wheelsets that follow the track kinematically.
void checkWheelsetContact(const vehicle::VehicleSpec& v, bool has_contact, bool guided,
                          Diagnostics& d) {
  if (has_contact || guided) return;
  int wheelsets = 0;
  for (const auto& b : v.bodies)
    if (b.kind == vehicle::BodyKind::Wheelset) ++wheelsets;
  if (wheelsets == 0) return;
  d.add(v.loc,
        "vehicle: " + std::to_string(wheelsets) + (wheelsets == 1 ? " wheelset" : " wheelsets") +
            " and no contact{} block: give contact { method = \"kec\" } (or \"lut\") for "
            "wheel/rail contact, or contact { method = \"guided\" } for wheelsets that follow "
            "the track kinematically (no wheel/rail forces)");
}

// A guided wheelset follows the track kinematically: an external force on it would do nothing.
void checkGuidedForces(const vehicle::VehicleSpec& v, bool guided, Diagnostics& d) {
  if (!guided) return;
  for (const auto& f : v.external_forces)
    for (const auto& b : v.bodies)
      if (b.name == f.body && b.kind == vehicle::BodyKind::Wheelset)
        d.add(f.loc, "element '" + f.name + "' (" + vehicle::kExternalForceKind + "): wheelset '" +
                         f.body +
                         "' follows the track kinematically with contact { method = \"guided\" "
                         "}, so a force on it does nothing: choose a contact method, or apply "
                         "the force to the body its suspension hangs from");
}

// Rails that change along the track need the elastic method (the constraint methods' tables hold
// one rail profile). Checked when the scenario is read, so that every command, and every analysis
// that tries another contact method on the scene (precision --methods), is refused before a run;
// dynamics::compileContactModel says the same to callers without a scenario.
void checkRailsAlongTrack(const dynamics::ProfilesSpec& p, const dynamics::ContactSpec& c,
                          bool has_contact, Diagnostics& d) {
  if (!has_contact || c.method == dynamics::ContactMethod::Elastic || !dynamics::railsAlongTrack(p))
    return;
  d.add(p.loc,
        std::string("profiles.rail_slices / extra_rails: a rail that changes along the track "
                    "needs contact.method = \"elastic\" (the ") +
            std::string(nameOf(c.method)) +
            " method's tables hold one rail profile for the whole track)");
}

}  // namespace

ScenarioSpec loadScenario(const std::string& path, const LoadOptions& options) {
  ScenarioSpec spec;
  spec.file = path;
  spec.overrides = options.overrides;
  HostOptions ho;
  ho.root = options.root;
  ho.instruction_limit = options.instruction_limit;
  // A mistyped require must not hide the file's other problems: it is collected, and the blocks
  // made from the missing module are left out (they cannot be checked without it).
  ho.collect_missing_modules = true;
  LuaHost host(ho);
  Node root = host.runFile(path);
  spec.text = host.text();  // the bytes that ran, read once (never reopened: it may have changed)
  spec.modules = host.modules();
  Diagnostics d;
  for (const auto& m : host.missingModules()) d.add(m.loc, m.message);
  // A text with a NUL byte is refused before any block reads it: its builders would open the file
  // named by the text up to the NUL and report that file's problems instead.
  Diagnostics nul;
  reportNulBytes(root, "", nul);
  if (!nul.empty()) {
    for (const auto& m : nul.items()) d.add(m.loc, m.message);
    d.throwIfAny();
  }
  const auto& incomplete = host.incompleteBlocks();
  auto unchecked = [&](const char* kind) {
    return std::find(incomplete.begin(), incomplete.end(), kind) != incomplete.end();
  };
  for (std::size_t i = 0; i < options.overrides.size(); ++i)
    applyOverride(root, options.overrides[i],
                  i < options.override_locs.size() ? options.override_locs[i] : SourceLoc{}, d);

  if (const Node* t = root.field("track"))
    buildTrack(*t, host, spec.track, spec.track_rails_given, d);
  else if (!unchecked("track"))
    d.add({path, 0}, "scenario has no track { ... } block");
  if (const Node* p = root.field("profiles")) {
    spec.has_profiles = true;
    buildProfiles(*p, host, spec.profiles, d);
    if (spec.track_rails_given)
      d.add(p->loc,
            "profiles: rail position and inclination come from profiles{}; remove "
            "track.rail_lr / track.rail_inclination");
  }
  if (const Node* c = root.field("contact")) {
    spec.guided = buildContact(*c, spec.contact, d);
    spec.has_contact = !spec.guided;
    // The elastic method searches the profiles themselves: a table grid would be unused.
    if (const Node* p = root.field("profiles");
        p && !spec.guided && spec.contact.method == dynamics::ContactMethod::Elastic &&
        spec.profiles.refined_tables)
      if (const Node* rt = p->field("refined_tables"))
        d.add(rt->loc,
              "profiles.refined_tables has no effect with contact.method = \"elastic\" (the "
              "contact search works on the profiles, there are no tables)");
  }
  if (const Node* v = root.field("vehicle")) {
    spec.has_vehicle = true;
    buildVehicle(*v, spec.vehicle, d);
  }
  if (const Node* t = root.field("train")) {
    if (const Node* v = root.field("vehicle"))
      d.add(v->loc,
            "vehicle{}: a scenario with train{} gives its vehicles there (train.vehicles[k]."
            "vehicle); remove the vehicle{} block");
    buildTrain(*t, host, spec, d);
    // The first vehicle leads: it is the scenario's vehicle for everything that works on one.
    if (!spec.train.empty()) {
      const TrainVehicleSpec& lead = spec.train.front();
      spec.has_vehicle = true;
      spec.vehicle = lead.vehicle;
      spec.has_profiles = lead.has_profiles;
      spec.profiles = lead.profiles;
      spec.has_contact = lead.has_contact;
      spec.guided = lead.guided;
      spec.contact = lead.contact;
    }
  }
  // A block left unchecked still exists: no error about it being absent.
  spec.has_vehicle = spec.has_vehicle || unchecked("vehicle") || unchecked("train");
  spec.has_contact = spec.has_contact || unchecked("contact");
  if (spec.train.empty() && spec.has_vehicle) {
    checkWheelsetContact(spec.vehicle, spec.has_contact, spec.guided, d);
    checkGuidedForces(spec.vehicle, spec.guided, d);
  }
  for (const auto& e : spec.train) {
    checkWheelsetContact(e.vehicle, e.has_contact, e.guided, d);
    checkGuidedForces(e.vehicle, e.guided, d);
  }
  if (spec.train.empty()) checkRailsAlongTrack(spec.profiles, spec.contact, spec.has_contact, d);
  for (const auto& e : spec.train) checkRailsAlongTrack(e.profiles, e.contact, e.has_contact, d);
  if (spec.guided && spec.has_profiles)
    d.add(spec.profiles.loc,
          "profiles{} has no effect with contact { method = \"guided\" } (no wheel/rail "
          "contact); remove it or choose a contact method");
  if (const Node* s = root.field("solver")) {
    spec.has_solver = true;
    buildSolver(*s, spec.solver, d);
  }
  if (const Node* r = root.field("run")) buildRun(*r, spec.run, d);
  applyEffectSwitches(spec, d);
  // The leading vehicle's Specs after the switches are its train entry's.
  if (!spec.train.empty()) {
    spec.train.front().vehicle = spec.vehicle;
    spec.train.front().contact = spec.contact;
  }
  // Blocks that a scenario would otherwise silently ignore.
  if (const Node* st = root.field("study"))
    d.add(st->loc,
          "study{} belongs in a study file of its own, run with `workbench study FILE`; a "
          "scenario cannot hold one");
  if (const Node* s = root.field("solver"); s && !spec.has_vehicle)
    d.add(s->loc, "solver{} has no effect without a vehicle{} block (nothing is integrated)");
  d.throwIfAny();
  return spec;
}

void refuseTrain(const ScenarioSpec& spec, const std::string& command) {
  if (spec.train.empty()) return;
  throw InputError(spec.train.front().loc,
                   "train: `workbench " + command + "` works on a single vehicle; this scenario " +
                       "has a train of " + std::to_string(spec.train.size()) +
                       " vehicles (run it with `workbench run`, or give one vehicle{} block)");
}

}  // namespace rb::scenario
