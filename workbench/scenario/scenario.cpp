#include "workbench/scenario/scenario.hpp"

#include "workbench/scenario/build.hpp"
#include "workbench/scenario/lua_host.hpp"
#include "workbench/scenario/overrides.hpp"

namespace rb::scenario {

ScenarioSpec loadScenario(const std::string& path, const LoadOptions& options) {
  ScenarioSpec spec;
  spec.file = path;
  spec.overrides = options.overrides;
  HostOptions ho;
  ho.root = options.root;
  ho.instruction_limit = options.instruction_limit;
  LuaHost host(ho);
  Node root = host.runFile(path);
  spec.text = host.text();  // the bytes that ran, read once (never reopened: it may have changed)
  spec.modules = host.modules();
  Diagnostics d;
  for (const auto& o : options.overrides) applyOverride(root, o, d);

  if (const Node* t = root.field("track"))
    buildTrack(*t, host, spec.track, spec.track_rails_given, d);
  else
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
    spec.has_contact = true;
    buildContact(*c, spec.contact, d);
  }
  if (const Node* v = root.field("vehicle")) {
    spec.has_vehicle = true;
    buildVehicle(*v, spec.vehicle, d);
  }
  if (const Node* s = root.field("solver")) {
    spec.has_solver = true;
    buildSolver(*s, spec.solver, d);
  }
  if (const Node* r = root.field("run")) buildRun(*r, spec.run, d);
  applyEffectSwitches(spec, d);
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

}  // namespace rb::scenario
