#include <cmath>

#include "workbench/core/strings.hpp"
#include "workbench/scenario/build.hpp"
#include "workbench/scenario/reader.hpp"

namespace rb::scenario {
namespace {

// A built-in profile name, or the resolved path of a profile file below the scenario.
std::string profileSource(Reader& r, const Node& n, const std::string& key,
                          const std::string& builtin, LuaHost& host) {
  std::string v = r.string(key);
  if (v.empty() || v == builtin) return builtin;
  try {
    return host.resolveDataFile(v, n.loc);
  } catch (const InputError& e) {
    // A near miss of the built-in name ("60E1", "S1002") is the likely intent, not a file.
    const std::string hint = closestMatch(v, {builtin});
    const Node* at = r.value(key);
    r.error(at != nullptr ? *at : n,
            key + ": " + e.diagnostics().front().message +
                (hint.empty() ? "" : " (did you mean the built-in profile '" + hint + "'?)"));
    return builtin;
  }
}

// profiles.rail_slices = { left = { { s = 0, rail = "60e1" }, ... }, right = { ... } }.
constexpr std::size_t kMaxRailSlices = 2000;  // per side: a turnout needs tens

void railSlices(Reader& r, LuaHost& host, dynamics::ProfilesSpec& p) {
  const Node* v = r.value("rail_slices");
  if (!v) return;
  const std::string form =
      "rail_slices must be a table { left = { { s = s0, rail = \"file\" }, ... }, right = "
      "{ ... } } (s the track arc length [m], strictly increasing)";
  if (v->type != Node::Type::Table || !v->items.empty() || v->fields.empty()) {
    r.error(*v, form + ", got " + v->describe());
    return;
  }
  for (const auto& [name, list] : v->fields) {
    if (name != "left" && name != "right") {
      r.error(list, "rail_slices: unknown side '" + name + "' (left or right)");
      continue;
    }
    const std::size_t side = name == "left" ? 0 : 1;
    const std::string what = "rail_slices." + name;
    if (list.type != Node::Type::Table || !list.fields.empty() || list.items.empty()) {
      r.error(list, what + " must be a non-empty list { { s = s0, rail = \"file\" }, ... }, got " +
                        list.describe());
      continue;
    }
    if (list.items.size() > kMaxRailSlices) {
      r.error(list, what + ": at most " + std::to_string(kMaxRailSlices) + " slices, got " +
                        std::to_string(list.items.size()));
      continue;
    }
    std::vector<dynamics::RailSliceSpec> out;
    for (std::size_t i = 0; i < list.items.size(); ++i) {
      const Node& item = list.items[i];
      const std::string at = what + "[" + std::to_string(i + 1) + "]";
      const Node* s = item.type == Node::Type::Table ? item.field("s") : nullptr;
      const Node* rail = item.type == Node::Type::Table ? item.field("rail") : nullptr;
      if (!s || !rail || item.fields.size() != 2 || !item.items.empty()) {
        r.error(item, at + " must be { s = <m>, rail = \"60e1\" or a rail profile file }, got " +
                          item.describe());
        continue;
      }
      if (s->type != Node::Type::Number || !std::isfinite(s->number) || s->number < 0.0) {
        r.error(*s, at + ".s must be a track arc length >= 0 [m], got " + s->describe());
        continue;
      }
      if (rail->type != Node::Type::String || rail->string.empty()) {
        r.error(*rail,
                at + ".rail must be \"60e1\" or a rail profile file, got " + rail->describe());
        continue;
      }
      if (!out.empty() && !(s->number > out.back().s)) {
        r.error(*s, at + ".s = " + formatNumber(s->number) +
                        " m: the slices' s must increase strictly (the one before is at " +
                        formatNumber(out.back().s) + " m)");
        continue;
      }
      dynamics::RailSliceSpec sl;
      sl.s = s->number;
      sl.loc = item.loc;
      if (rail->string == "60e1") {
        sl.rail = "60e1";
      } else {
        try {
          sl.rail = host.resolveDataFile(rail->string, item.loc);
        } catch (const InputError& e) {
          r.error(*rail, at + ".rail: " + e.diagnostics().front().message);
          continue;
        }
      }
      out.push_back(std::move(sl));
    }
    p.rail_slices[side] = std::move(out);
  }
}

}  // namespace

void buildProfiles(const Node& n, LuaHost& host, dynamics::ProfilesSpec& p, Diagnostics& d) {
  Reader r(n, block("profiles"), "profiles", d);
  p.loc = n.loc;
  const dynamics::ProfilesSpec builtin;
  p.wheel = profileSource(r, n, "wheel", builtin.wheel, host);
  for (auto [key, target] :
       {std::pair{"wheel_left", &p.wheel_left}, std::pair{"wheel_right", &p.wheel_right}})
    if (r.has(key)) *target = profileSource(r, n, key, builtin.wheel, host);
  p.rail = profileSource(r, n, "rail", builtin.rail, host);
  p.back_to_back = r.number("back_to_back");
  p.gauge = r.number("gauge");
  p.r0 = r.number("r0");
  p.inclination = r.number("inclination");
  p.lw = r.number("lw");
  p.lr = r.number("lr");
  p.refined_tables = r.boolean("refined_tables");
  railSlices(r, host, p);
  if (r.has("lw") && r.has("back_to_back"))
    r.error(n, "give either lw or back_to_back, not both (lw overrides the positioning)");
  if (r.has("lr") && r.has("gauge"))
    r.error(n, "give either lr or gauge, not both (lr overrides the positioning)");
}

}  // namespace rb::scenario
