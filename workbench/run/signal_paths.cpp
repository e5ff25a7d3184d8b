// Which dataset paths a vehicle run writes, before any run (vehicle_run.hpp: signalProblem).
#include <algorithm>
#include <string>
#include <vector>

#include "workbench/core/strings.hpp"
#include "workbench/run/channels.hpp"
#include "workbench/run/vehicle_run.hpp"

namespace rb::run {
namespace {

// "'x' is not one of a, b (did you mean 'a'?)" for a name that is not among `names`.
std::string notAmong(const std::string& what, const std::string& x,
                     const std::vector<std::string>& names) {
  const std::string hint = closestMatch(x, names);
  return "no " + what + " '" + x + "'" +
         (hint.empty() ? " (there are: " + join(names, ", ") + ")"
                       : " (did you mean '" + hint + "'?)");
}

}  // namespace

std::string signalProblem(const scenario::ScenarioSpec& spec, const std::string& path);

namespace {

std::vector<std::string> trainNames(const scenario::ScenarioSpec& spec) {
  std::vector<std::string> names;
  for (const auto& e : spec.train) names.push_back(e.name);
  return names;
}

// /vehicles/<name>/<group>/...: the path of that vehicle's group as its own run would write it.
std::string trainSignalProblem(const scenario::ScenarioSpec& spec,
                               const std::vector<std::string>& p) {
  if (spec.train.empty()) return "only a scenario with train{} writes /vehicles";
  if (p.size() < 3) return "a train vehicle's signal is /vehicles/<name>/<group>/...";
  const auto names = trainNames(spec);
  const auto it = std::find(names.begin(), names.end(), p[1]);
  if (it == names.end()) return notAmong("vehicle", p[1], names);
  const scenario::TrainVehicleSpec& e = spec.train[static_cast<std::size_t>(it - names.begin())];
  scenario::ScenarioSpec one = spec;
  one.train.clear();
  one.vehicle = e.vehicle;
  one.has_contact = e.has_contact;
  one.guided = e.guided;
  one.contact = e.contact;
  const std::vector<std::string> rest(p.begin() + 2, p.end());
  return signalProblem(one, "/" + join(rest, "/"));
}

bool among(const std::string& x, const std::vector<std::string>& names) {
  return std::find(names.begin(), names.end(), x) != names.end();
}

std::string bodySignalProblem(const scenario::ScenarioSpec& spec,
                              const std::vector<std::string>& p) {
  if (p.size() != 3) return "a body's signal is /bodies/<body>/<coordinate>";
  std::vector<std::string> bodies;
  for (const auto& b : spec.vehicle.bodies) bodies.push_back(b.name);
  if (!among(p[1], bodies)) return notAmong("body", p[1], bodies);
  std::vector<std::string> q;
  for (const auto& c : kBodyCoordChannels) q.emplace_back(c.name);
  const bool acc = spec.run.body_accelerations;
  if (acc)
    for (const auto& c : kBodyAccelerationChannels) q.emplace_back(c.name);
  if (among(p[2], q)) return {};
  const bool asks_acc =
      std::any_of(std::begin(kBodyAccelerationChannels), std::end(kBodyAccelerationChannels),
                  [&](const auto& c) { return p[2] == c.name; });
  return notAmong("body signal", p[2], q) +
         (acc || !asks_acc ? "" : "; ax, ay, az need run.output.body_accelerations = true");
}

std::string elementSignalProblem(const scenario::ScenarioSpec& spec,
                                 const std::vector<std::string>& p) {
  const auto& out = spec.run.output_elements;
  if (p.size() != 3) return "an element's signal is /elements/<name>/deflection or force";
  // An external force is written whether named or not, with its value and components.
  const auto& forces = spec.vehicle.external_forces;
  if (std::any_of(forces.begin(), forces.end(), [&](const auto& e) { return e.name == p[1]; })) {
    const std::vector<std::string> q = {"force", "force_x", "force_y", "force_z"};
    return among(p[2], q) ? std::string() : notAmong("external force signal", p[2], q);
  }
  if (!among(p[1], out))
    return "element '" + p[1] + "' is not written: name it in run.output.elements" +
           (out.empty() ? "" : " (written: " + join(out, ", ") + ")");
  if (p[2] != "deflection" && p[2] != "force")
    return notAmong("element signal", p[2], {"deflection", "force"});
  return {};
}

std::string contactSignalProblem(const scenario::ScenarioSpec& spec,
                                 const std::vector<std::string>& p) {
  if (!spec.has_contact)
    return "the scenario has no wheel/rail contact model, so its result has no /contact";
  if (p.size() < 4) return "a wheel's signal is /contact/<wheelset>/<left|right>/<quantity>";
  std::vector<std::string> wheelsets;
  for (const auto& b : spec.vehicle.bodies)
    if (b.kind == vehicle::BodyKind::Wheelset) wheelsets.push_back(b.name);
  if (!among(p[1], wheelsets)) return notAmong("wheelset", p[1], wheelsets);
  if (p[2] != "left" && p[2] != "right") return notAmong("side", p[2], {"left", "right"});
  std::vector<std::string> q;
  if (p.size() == 4) {
    for (const auto& c : kWheelChannels) q.emplace_back(c.name);
    return among(p[3], q) ? std::string() : notAmong("wheel signal", p[3], q);
  }
  if (p.size() == 6 && p[3] == "rails") {
    // Written for a side with further rails (elastic contact): "rail" and their names.
    const auto& extra = spec.profiles.extra_rails[p[2] == "left" ? 0 : 1];
    if (extra.empty())
      return "the " + p[2] + " side has no further rails (profiles.extra_rails), so no /rails";
    std::vector<std::string> rails = {"rail"};
    for (const auto& r : extra) rails.push_back(r.name);
    if (!among(p[4], rails)) return notAmong("rail", p[4], rails);
    for (const auto& c : kRailChannels) q.emplace_back(c.name);
    return among(p[5], q) ? std::string() : notAmong("rail signal", p[5], q);
  }
  if (p.size() != 5 || (p[3] != "patch0" && p[3] != "patch1"))
    return "a patch's signal is /contact/<wheelset>/<side>/patch0|patch1/<quantity> (or, on a "
           "side with further rails, /contact/<wheelset>/<side>/rails/<rail>/<quantity>)";
  for (const auto& c : kPatchChannels) q.emplace_back(c.name);
  return among(p[4], q) ? std::string() : notAmong("patch signal", p[4], q);
}

}  // namespace

std::string signalProblem(const scenario::ScenarioSpec& spec, const std::string& path) {
  if (path.size() < 2 || path[0] != '/') return {};
  const std::vector<std::string> p = pathParts(path);
  const std::string& group = p[0];
  if (group == "vehicles") return trainSignalProblem(spec, p);
  if (group != "vehicle" && group != "bodies" && group != "elements" && group != "contact")
    return {};
  if (!spec.has_vehicle) return "the scenario has no vehicle, so its result has no /" + group;
  if (!spec.train.empty() && group != "vehicle")
    return "a train writes each vehicle's /" + group + " under /vehicles/<name>/" + group +
           " (vehicles: " + join(trainNames(spec), ", ") + ")";
  if (group == "vehicle")
    return p.size() == 2 && p[1] == "speed" ? std::string()
                                            : "the vehicle group holds /vehicle/speed only";
  if (group == "bodies") return bodySignalProblem(spec, p);
  if (group == "elements") return elementSignalProblem(spec, p);
  return contactSignalProblem(spec, p);
}

}  // namespace rb::run
