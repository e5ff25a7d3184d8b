// train{}: several vehicles on one track (schema "train", "train.vehicle").
#include <algorithm>
#include <cmath>

#include "workbench/assessment/sections.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/scenario/build.hpp"
#include "workbench/scenario/reader.hpp"

namespace rb::scenario {

namespace {

// The most vehicles one train may hold: each is a full vehicle model of its own.
constexpr std::size_t kMaxTrainVehicles = 100;

// One entry of train.vehicles, its profiles and contact defaulting to the scenario's.
void buildEntry(const Node& item, const std::string& what, LuaHost& host, const ScenarioSpec& spec,
                TrainVehicleSpec& e, Diagnostics& d) {
  Reader r(item, block("train.vehicle"), what, d);
  e.loc = item.loc;
  e.name = r.string("name");
  if (r.has("name") && !assessment::validSectionName(e.name))
    r.error(item, "name '" + e.name + "' must be 1-64 letters, digits, '_' or '-'");
  if (const Node* v = r.value("vehicle")) {
    if (v->type == Node::Type::Table && v->kind.empty())
      buildVehicle(*v, e.vehicle, d);
    else
      r.error(*v, "vehicle must be a vehicle table (require \"vehicles.NAME\" { ... }), got " +
                      v->describe());
  }
  e.has_profiles = spec.has_profiles;
  e.profiles = spec.profiles;
  if (const Node* p = r.blockValue("profiles")) {
    e.has_profiles = true;
    e.profiles = dynamics::ProfilesSpec{};
    buildProfiles(*p, host, e.profiles, d);
  }
  e.has_contact = spec.has_contact;
  e.guided = spec.guided;
  e.contact = spec.contact;
  if (const Node* c = r.blockValue("contact")) {
    e.own_contact = true;
    e.contact = dynamics::ContactSpec{};
    e.guided = buildContact(*c, e.contact, d);
    e.has_contact = !e.guided;
  }
  const auto traction = [&](const char* key, bool by_distance) {
    if (!r.has(key)) return;
    if (e.traction.given()) r.error(item, "give traction or traction_by_distance, not both");
    e.traction = train::TractionSpec{};
    e.traction.by_distance = by_distance;
    e.traction.loc = r.value(key)->loc;
    r.pairList(key, e.traction.at, e.traction.force);
  };
  traction("traction", false);
  traction("traction_by_distance", true);
  if (const Node* res = r.blockValue("resistance")) {
    Reader rr(*res, block("train.resistance"), what + ".resistance", d);
    e.resistance.loc = res->loc;
    e.resistance.a = rr.number("a");
    e.resistance.b = rr.number("b");
    e.resistance.c = rr.number("c");
  }
}

void buildBuffers(const Node& n, const std::string& what, train::BufferSpec& b, Diagnostics& d) {
  Reader r(n, block("train.buffers"), what + ".buffers", d);
  b.loc = n.loc;
  r.pairList("loading", b.load_stroke, b.load_force);
  r.pairList("unloading", b.unload_stroke, b.unload_force);
  b.spacing = r.number("spacing");
  b.height = r.number("height");
  b.friction = r.number("friction");
}

void buildDrawGear(const Node& n, const std::string& what, train::DrawGearSpec& g, Diagnostics& d) {
  Reader r(n, block("train.draw_gear"), what + ".draw_gear", d);
  g.loc = n.loc;
  g.stiffness = r.number("stiffness");
  g.slack = r.number("slack");
  g.friction = r.number("friction");
  g.height = r.number("height");
}

void buildCoupler(const Node& n, const std::string& what, train::CouplerSpec& g, Diagnostics& d) {
  Reader r(n, block("train.coupler"), what + ".coupler", d);
  g.loc = n.loc;
  g.stiffness = r.number("stiffness");
  g.slack = r.number("slack");
  g.friction = r.number("friction");
  g.height = r.number("height");
  g.pivot = r.number("pivot");
  g.compression = r.boolean("compression");
  g.angle_stop = r.number("angle_stop");
  g.stop_stiffness = r.number("stop_stiffness");
}

// train.connections: each joins a vehicle to the one right behind it, once.
void buildConnections(const Node& list, ScenarioSpec& spec, Diagnostics& d) {
  if (list.type != Node::Type::Table || !list.fields.empty()) {
    d.add(list.loc, "train.connections must be a list of { front = ..., rear = ..., ... }, got " +
                        list.describe());
    return;
  }
  for (std::size_t i = 0; i < list.items.size(); ++i) {
    const Node& item = list.items[i];
    const std::string what = "train.connections[" + std::to_string(i + 1) + "]";
    if (item.type != Node::Type::Table || !item.items.empty() || !item.kind.empty()) {
      d.add(item.loc, what + ": must be a plain table { front = ..., rear = ..., ... }, got " +
                          item.describe());
      continue;
    }
    Reader r(item, block("train.connection"), what, d);
    train::ConnectionSpec c;
    c.loc = item.loc;
    c.front = r.string("front");
    c.rear = r.string("rear");
    c.front_body = r.string("front_body");
    c.rear_body = r.string("rear_body");
    c.front_end = r.number("front_end");
    c.rear_end = r.number("rear_end");
    if (const Node* b = r.blockValue("buffers")) buildBuffers(*b, what, c.buffers.emplace(), d);
    if (const Node* g = r.blockValue("draw_gear"))
      buildDrawGear(*g, what, c.draw_gear.emplace(), d);
    if (const Node* g = r.blockValue("coupler")) buildCoupler(*g, what, c.coupler.emplace(), d);
    spec.train_connections.push_back(std::move(c));
  }
}

// The connections by name: neighbours front to rear, each pair once.
void checkConnections(const ScenarioSpec& spec, Diagnostics& d) {
  const auto place = [&](const std::string& name) {
    for (std::size_t k = 0; k < spec.train.size(); ++k)
      if (spec.train[k].name == name) return static_cast<int>(k);
    return -1;
  };
  std::vector<int> joined;
  for (const auto& c : spec.train_connections) {
    const int f = place(c.front), r = place(c.rear);
    const std::string what = "train.connections '" + c.front + "-" + c.rear + "'";
    if (f < 0 || r < 0) {
      d.add(c.loc, what + ": no vehicle named '" + (f < 0 ? c.front : c.rear) + "' in the train");
      continue;
    }
    if (r != f + 1) {
      d.add(c.loc, what + ": '" + c.rear + "' is not the vehicle right behind '" + c.front +
                       "' (connections join neighbours, front to rear)");
      continue;
    }
    if (std::find(joined.begin(), joined.end(), f) != joined.end())
      d.add(c.loc, what + ": the two vehicles are connected twice");
    joined.push_back(f);
  }
  // A train whose motion is a state needs every neighbour connected: a vehicle without a
  // connection would run away from the train or into it.
  if (spec.train_longitudinal.on)
    for (std::size_t k = 0; k + 1 < spec.train.size(); ++k)
      if (std::find(joined.begin(), joined.end(), static_cast<int>(k)) == joined.end())
        d.add(spec.train_longitudinal.loc,
              "train.longitudinal: '" + spec.train[k].name + "' and '" + spec.train[k + 1].name +
                  "' have no connection between them (give one in train.connections)");
}

}  // namespace

void buildTrain(const Node& n, LuaHost& host, ScenarioSpec& spec, Diagnostics& d) {
  Reader r(n, block("train"), "train", d);
  if (const Node* l = r.blockValue("longitudinal")) {
    Reader lr(*l, block("train.longitudinal"), "train.longitudinal", d);
    spec.train_longitudinal.on = true;
    spec.train_longitudinal.loc = l->loc;
    spec.train_longitudinal.min_speed = lr.number("min_speed");
    spec.train_longitudinal.traction_at = lr.choiceOf<train::TractionPath>("traction_at");
  }
  const Node* connections = r.value("connections");
  const Node* list = r.value("vehicles");
  if (list == nullptr) return;
  // Wheelsets with wheels of their own belong to one vehicle: the scenario's profiles{} is every
  // train vehicle's that has none of its own, and would give every wagon's ws1 those wheels.
  if (!spec.profiles.wheelsets.empty())
    d.add(spec.profiles.wheelsets.front().loc,
          "profiles.wheelsets with a train: give a vehicle's wheelsets their own wheels in that "
          "vehicle's own profiles{} (train.vehicles[k].profiles), not in the scenario's, which "
          "every vehicle without its own takes");
  if (list->type != Node::Type::Table || !list->fields.empty() || list->items.size() < 2 ||
      list->items.size() > kMaxTrainVehicles) {
    r.error(*list, "vehicles must be a list of 2 to " + std::to_string(kMaxTrainVehicles) +
                       " { name = \"...\", vehicle = ... }, got " + list->describe());
    return;
  }
  for (std::size_t i = 0; i < list->items.size(); ++i) {
    const Node& item = list->items[i];
    const std::string what = "train.vehicles[" + std::to_string(i + 1) + "]";
    if (item.type != Node::Type::Table || !item.items.empty() || !item.kind.empty()) {
      d.add(item.loc, what + ": must be a plain table { name = \"...\", vehicle = ... }, got " +
                          item.describe());
      continue;
    }
    TrainVehicleSpec e;
    buildEntry(item, what, host, spec, e, d);
    for (const auto& other : spec.train) {
      if (!e.name.empty() && other.name == e.name)
        d.add(item.loc, what + ": name '" + e.name + "' is given twice");
      // Front to rear: each vehicle's reference point behind the one before it (the bodies'
      // extent is checked on the compiled vehicles).
      if (!(e.vehicle.start < other.vehicle.start))
        d.add(item.loc, what + ": vehicle.start " + formatNumber(e.vehicle.start) +
                            " m must be behind the vehicles before it (front to rear; '" +
                            other.name + "' starts at " + formatNumber(other.vehicle.start) +
                            " m)");
    }
    // A train starts at one speed; without train.longitudinal it keeps the first vehicle's
    // prescribed motion, with it the motion is computed (no prescribed acceleration).
    if (spec.train_longitudinal.on && e.vehicle.acceleration != 0.0)
      d.add(item.loc, what +
                          ": vehicle.acceleration must be 0 with train.longitudinal (the "
                          "motion is computed from traction, braking and resistance)");
    if (!spec.train_longitudinal.on && (e.traction.given() || e.resistance.loc.line > 0))
      d.add(item.loc, what +
                          ": traction and resistance act through train.longitudinal{}, which "
                          "the train does not give (its speed is prescribed)");
    if (!spec.train.empty()) {
      const auto& lead = spec.train.front().vehicle;
      if (e.vehicle.speed != lead.speed || e.vehicle.acceleration != lead.acceleration)
        d.add(item.loc, what + ": speed " + formatNumber(e.vehicle.speed) + " m/s, acceleration " +
                            formatNumber(e.vehicle.acceleration) +
                            " m/s^2: every vehicle of a train runs at the first one's (" +
                            formatNumber(lead.speed) + " m/s, " + formatNumber(lead.acceleration) +
                            " m/s^2); a train starts at one speed");
    }
    spec.train.push_back(std::move(e));
  }
  if (connections != nullptr) buildConnections(*connections, spec, d);
  checkConnections(spec, d);
}

}  // namespace rb::scenario
