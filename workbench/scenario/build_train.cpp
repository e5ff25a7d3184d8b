// train{}: several vehicles on one track (schema "train", "train.vehicle").
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
    e.contact = dynamics::ContactSpec{};
    e.guided = buildContact(*c, e.contact, d);
    e.has_contact = !e.guided;
  }
}

}  // namespace

void buildTrain(const Node& n, LuaHost& host, ScenarioSpec& spec, Diagnostics& d) {
  Reader r(n, block("train"), "train", d);
  const Node* list = r.value("vehicles");
  if (list == nullptr) return;
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
    // The run's motion is prescribed: one speed for every vehicle until longitudinal motion and
    // the connections between vehicles are modelled.
    if (!spec.train.empty()) {
      const auto& lead = spec.train.front().vehicle;
      if (e.vehicle.speed != lead.speed || e.vehicle.acceleration != lead.acceleration)
        d.add(item.loc, what + ": speed " + formatNumber(e.vehicle.speed) + " m/s, acceleration " +
                            formatNumber(e.vehicle.acceleration) +
                            " m/s^2: every vehicle of a train runs at the first one's (" +
                            formatNumber(lead.speed) + " m/s, " + formatNumber(lead.acceleration) +
                            " m/s^2); the speed is prescribed");
    }
    spec.train.push_back(std::move(e));
  }
}

}  // namespace rb::scenario
