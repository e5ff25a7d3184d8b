#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <string_view>

#include "workbench/core/strings.hpp"
#include "workbench/scenario/build.hpp"
#include "workbench/scenario/overrides.hpp"
#include "workbench/scenario/reader.hpp"
#include "workbench/vehicle/names.hpp"

namespace rb::scenario {
namespace {

vehicle::BodySpec buildBody(const Node& b, const std::string& path, Diagnostics& d) {
  Reader br(b, block("body"), path, d);
  vehicle::BodySpec body;
  body.loc = b.loc;
  body.name = br.string("name");
  body.kind = br.choiceOf<vehicle::BodyKind>("kind");
  body.mass = br.number("mass");
  if (br.vec3("inertia", body.inertia) && !(body.inertia.minCoeff() > 0))
    br.error(b, "inertia must be > 0 kg m^2 in every axis");
  body.x = br.number("x");
  body.height = br.number("height");
  return body;
}

// One suspension element (Appendix A); the keys its kind has in the schema are read.
vehicle::ElementSpec buildElement(const Node& e, const std::string& path, Diagnostics& d) {
  Reader er(e, block(e.kind), path, d);
  vehicle::ElementSpec el;
  el.loc = e.loc;
  el.kind = parse<vehicle::ElementKind>(e.kind).value_or(vehicle::ElementKind::SpringDamper);
  el.name = er.string("name");
  el.body1 = er.string("from");
  el.body2 = er.string("to");
  er.vec3("at_from", el.point1);
  er.vec3("at_to", el.point2);
  el.direction = er.choiceOf<vehicle::Direction>("direction");
  const BlockSpec& bs = block(e.kind);
  if (bs.key("stiffness")) el.stiffness = er.number("stiffness");
  if (bs.key("damping")) el.damping = er.number("damping");
  if (bs.key("series_stiffness")) el.series_stiffness = er.number("series_stiffness");
  if (bs.key("length0")) el.length0 = er.number("length0");
  if (bs.key("preload")) el.preload = er.number("preload");
  if (bs.key("table")) er.pairList("table", el.table_d, el.table_f);
  return el;
}

// Refuses each of `keys` that is given: it belongs to another law than the element's (a rate
// given to a constant force would otherwise be ignored in silence).
void refuseKeys(Reader& r, std::initializer_list<const char*> keys, suspension::ForceLawKind law,
                const char* belongs) {
  for (const char* k : keys)
    if (r.has(k))
      r.error(*r.value(k), std::string(k) + " applies to " + belongs + " (law is \"" +
                               std::string(nameOf(law)) + "\")");
}

// The law of an external force: its kind and the keys of that kind; the values are checked when
// the vehicle is compiled (suspension::checkForceLaw, with the table's line).
void buildForceLaw(Reader& r, const Node& e, vehicle::ExternalForceSpec& f) {
  using suspension::ForceLawKind;
  suspension::ForceLaw& law = f.law;
  law.kind = r.choiceOf<ForceLawKind>("law");
  // A misspelt law is reported by the reader; the keys of the law it falls back to would only
  // add errors about keys that are right for the law meant.
  if (const Node* given = r.value("law"); given != nullptr && !(given->type == Node::Type::String &&
                                                                parse<ForceLawKind>(given->string)))
    return;
  const std::string law_name(nameOf(law.kind));
  if (law.kind != ForceLawKind::Ramp)
    refuseKeys(r, {"initial", "start", "rate", "duration", "hold"}, law.kind,
               "law = \"ramp\" only");
  if (law.kind != ForceLawKind::Table)
    refuseKeys(r, {"over", "table"}, law.kind, "law = \"table\" only");
  if (law.kind == ForceLawKind::Table) {
    refuseKeys(r, {"value"}, law.kind, "law = \"constant\" or \"ramp\" (a table gives F)");
    law.over = r.choiceOf<suspension::ForceAbscissa>("over");
    if (!r.has("table")) {
      r.error(e,
              "law = \"table\" needs table = {{t, F}, ...} (or {{s, F}, ...} with over = "
              "\"distance\")");
      return;
    }
    f.table_loc = r.value("table")->loc;
    r.pairList("table", law.at, law.force);
    return;
  }
  if (!r.has("value")) r.error(e, "law = \"" + law_name + "\" needs value [N]");
  law.value = r.number("value");
  if (law.kind != ForceLawKind::Ramp) return;
  law.initial = r.number("initial");
  law.start = r.number("start");
  law.hold = r.has("hold") ? r.number("hold") : std::numeric_limits<double>::infinity();
  const bool rate = r.has("rate"), duration = r.has("duration");
  if (rate && duration)
    r.error(*r.value("duration"), "give rate or duration, not both");
  else if (!rate && !duration)
    r.error(e, "law = \"ramp\" needs rate [N/s] or duration [s]");
  if (duration) {
    law.duration = r.number("duration");
  } else if (rate) {
    const double per_second = r.number("rate");
    // A rate outside its range is reported; the duration then stays valid for the other checks.
    law.duration = per_second > 0.0 && std::isfinite(per_second)
                       ? std::abs(law.value - law.initial) / per_second
                       : 1.0;
  }
}

// external_force{}: a force on a body from outside the vehicle (vehicle::ExternalForceSpec).
vehicle::ExternalForceSpec buildExternalForce(const Node& e, const std::string& path,
                                              Diagnostics& d) {
  Reader r(e, block(vehicle::kExternalForceKind), path, d);
  vehicle::ExternalForceSpec f;
  f.loc = e.loc;
  f.name = r.string("name");
  f.body = r.string("body");
  r.vec3("at", f.point);
  f.frame = r.choiceOf<vehicle::ForceFrame>("frame");
  if (r.vec3("direction", f.direction) && !(f.direction.norm() > 0.0))
    r.error(*r.value("direction"), "direction must be a vector of length > 0, e.g. {0, 1, 0}");
  buildForceLaw(r, e, f);
  return f;
}

// Keys of vehicle.initial.<body>: the coordinate names from y (vehicle::kY = 1) to yaw, and their
// rates with "_dot" (vehicle::initialConditionKey).
constexpr std::string_view kRateSuffix = "_dot";
constexpr int kCoordY = 1;  // vehicle::kY (workbench/vehicle/kinematics.hpp)

// One body's table of vehicle.initial: a condition per key given (schema block
// "vehicle.initial.<body>": unknown keys, non-numbers and non-finite values are reported).
void buildBodyInitial(const std::string& body, const Node& t,
                      std::vector<vehicle::InitialCondition>& out, Diagnostics& d) {
  Reader r(t, block("vehicle.initial.<body>"), "vehicle.initial." + body, d);
  for (const bool rate : {false, true})
    for (int coord = kCoordY; coord < static_cast<int>(vehicle::kCoordNames.size()); ++coord) {
      const std::string key = std::string(vehicle::kCoordNames[static_cast<std::size_t>(coord)]) +
                              (rate ? std::string(kRateSuffix) : "");
      const Node* v = r.value(key);
      if (v == nullptr) continue;
      const double x = r.number(key);
      if (v->type != Node::Type::Number || !std::isfinite(x)) continue;
      vehicle::InitialCondition ic;
      ic.body = body;
      ic.coord = coord;
      ic.rate = rate;
      ic.value = x;
      ic.loc = v->loc;
      out.push_back(std::move(ic));
    }
}

// vehicle.initial = { BODY = { y = ..., yaw_dot = ... }, ... }: the body names are checked here
// against the vehicle's bodies; whether a coordinate is a state of the model is checked when the
// model is compiled (vehicle::checkInitialConditions).
void buildInitial(Reader& r, vehicle::VehicleSpec& v, Diagnostics& d) {
  const Node* n = r.value("initial");
  if (n == nullptr) return;
  if (n->type != Node::Type::Table || !n->items.empty()) {
    r.error(*n, "initial must be a table keyed by body name, e.g. { ws1 = { y = 3e-3 } }, got " +
                    n->describe());
    return;
  }
  std::vector<std::string> names;
  for (const auto& b : v.bodies) names.push_back(b.name);
  for (const auto& [body, t] : n->fields) {
    if (std::find(names.begin(), names.end(), body) == names.end()) {
      const std::string hint = closestMatch(body, names);
      r.error(t, "initial: no body named '" + body + "'" +
                     (hint.empty() ? " (bodies: " + join(names, ", ") + ")"
                                   : " (did you mean '" + hint + "'?)"));
      continue;
    }
    if (t.type != Node::Type::Table) {
      r.error(t, "initial." + body +
                     " must be a table of offsets, e.g. { y = 3e-3, yaw_dot = 0.01 }, got " +
                     t.describe());
      continue;
    }
    buildBodyInitial(body, t, v.initial, d);
  }
}

// The first line of `file` from line `from` on holding `needle` outside a comment (for a group
// name: followed by '='), 0 when none. Lua records no line for the fields of a plain table, so a
// group's own line is found in the text.
int lineOf(const std::string& file, const std::string& needle, bool assigned, int from = 1) {
  std::ifstream in(file);
  std::string line;
  for (int no = 1; std::getline(in, line); ++no) {
    if (no < from) continue;
    line = line.substr(0, line.find("--"));  // a Lua comment may mention a group
    for (auto p = line.find(needle); p != std::string::npos; p = line.find(needle, p + 1)) {
      if (!assigned) return no;
      const auto next = line.find_first_not_of(" \t\"']", p + needle.size());
      const bool word =
          p == 0 || !(std::isalnum(static_cast<unsigned char>(line[p - 1])) || line[p - 1] == '_');
      if (word && next != std::string::npos && line[next] == '=') return no;
    }
  }
  return 0;
}

// Where a group (or one of its entries) is written: the line of `GROUP =` in the vehicle file
// (the file of the vehicle's elements and bodies; a vehicle file returns a plain table, whose
// location would be the scenario's vehicle{} call) or the scenario, and the entry's line from
// there on; the vehicle{} call when the text does not show them (groups made in a loop).
SourceLoc groupLoc(const Node& vehicle, const std::string& group, const std::string& entry) {
  std::vector<std::string> files;
  for (const char* list : {"elements", "bodies"})
    if (const Node* l = vehicle.field(list))
      for (const Node& item : l->items)
        if (std::find(files.begin(), files.end(), item.loc.file) == files.end())
          files.push_back(item.loc.file);
  if (std::find(files.begin(), files.end(), vehicle.loc.file) == files.end())
    files.push_back(vehicle.loc.file);
  for (const auto& f : files) {
    const int line = lineOf(f, group, true);
    if (line == 0) continue;
    const int at = entry.empty() ? 0 : lineOf(f, "\"" + entry + "\"", false, line);
    return {f, at > 0 ? at : line};
  }
  return vehicle.loc;
}

// vehicle.groups = { GROUP = { "name", "glob*", ... }, ... }: every entry must select an element
// (overrides.cpp resolves them the same way when a --set names the group).
void buildGroups(Reader& r, const Node& vehicle) {
  const Node* g = r.value("groups");
  if (g == nullptr) return;
  if (g->type != Node::Type::Table || !g->items.empty()) {
    r.error(*g,
            "groups must be a table of named lists, e.g. { primary_longitudinal = { "
            "\"prim_x_*\" } }, got " +
                g->describe());
    return;
  }
  for (const auto& [name, members] : g->fields) {
    if (!isParameterName(name))
      r.errorAt(groupLoc(vehicle, name, ""),
                "groups: group name '" + name +
                    "' must be letters, digits and _ (not starting with a digit), so that --set "
                    "vehicle.groups.NAME.KEY can address it");
    const GroupMembers m = groupMembers(vehicle, members);
    for (const std::string& problem : m.problems) {
      // The entry a problem names (quoted), to find its line; else the group's line.
      std::string entry;
      for (const Node& item : members.items)
        if (item.type == Node::Type::String && !item.string.empty() &&
            problem.find("'" + item.string + "'") != std::string::npos) {
          entry = item.string;
          break;
        }
      r.errorAt(groupLoc(vehicle, name, entry), "groups." + name + ": " + problem);
    }
  }
}

}  // namespace

void buildVehicle(const Node& n, vehicle::VehicleSpec& v, Diagnostics& d) {
  Reader r(n, block("vehicle"), "vehicle", d);
  v.loc = n.loc;
  v.name = r.string("name");
  v.speed = r.number("speed");
  v.acceleration = r.number("acceleration");
  v.wheel_radius = r.number("wheel_radius");
  v.start = r.number("start");
  v.category = r.choiceOf<assessment::VehicleCategory>("category");
  auto bodies = r.blockList("bodies");
  for (std::size_t i = 0; i < bodies.size(); ++i)
    v.bodies.push_back(buildBody(*bodies[i], "vehicle.bodies[" + std::to_string(i + 1) + "]", d));
  buildInitial(r, v, d);
  buildGroups(r, n);
  if (!r.has("elements")) return;
  auto elements = r.blockList("elements");
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const std::string path = "vehicle.elements[" + std::to_string(i + 1) + "]";
    if (elements[i]->kind == vehicle::kExternalForceKind)
      v.external_forces.push_back(buildExternalForce(*elements[i], path, d));
    else
      v.elements.push_back(buildElement(*elements[i], path, d));
  }
}

}  // namespace rb::scenario
