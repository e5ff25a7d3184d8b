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
  if (r.has("lw") && r.has("back_to_back"))
    r.error(n, "give either lw or back_to_back, not both (lw overrides the positioning)");
  if (r.has("lr") && r.has("gauge"))
    r.error(n, "give either lr or gauge, not both (lr overrides the positioning)");
}

}  // namespace rb::scenario
