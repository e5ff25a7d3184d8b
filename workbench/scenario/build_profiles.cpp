#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "workbench/core/strings.hpp"
#include "workbench/profiles/slice_list.hpp"
#include "workbench/scenario/build.hpp"
#include "workbench/scenario/reader.hpp"

namespace rb::scenario {
namespace {

// `text` as a profile: the built-in one's name, or the resolved path of a profile file below the
// scenario; nullopt when it is neither, with the error (`what`) at `at` and, for a near miss of
// the built-in name ("60E1", "S1002"), that name as the likely intent.
std::optional<std::string> profileName(Reader& r, const Node& at, const std::string& what,
                                       const std::string& text, const std::string& builtin,
                                       LuaHost& host) {
  if (text == builtin) return builtin;
  try {
    return host.resolveDataFile(text, at.loc);
  } catch (const InputError& e) {
    const std::string hint = closestMatch(text, {builtin});
    r.error(at, what + ": " + e.diagnostics().front().message +
                    (hint.empty() ? "" : " (did you mean the built-in profile '" + hint + "'?)"));
    return std::nullopt;
  }
}

// The profile of key `key` of the profiles{} block `n` (profileName); the built-in one when the
// key is not given or is not a profile.
std::string profileSource(Reader& r, const Node& n, const std::string& key,
                          const std::string& builtin, LuaHost& host) {
  const std::string v = r.string(key);
  if (v.empty()) return builtin;
  const Node* at = r.value(key);
  return profileName(r, at != nullptr ? *at : n, key, v, builtin, host).value_or(builtin);
}

// profiles.rail_slices = { left = { { s = 0, rail = "60e1", dy = 0, dz = 0 }, ... }, right = ... }
// and profiles.extra_rails = { right = { { name = "nose", slices = { ... } }, ... } }.
constexpr std::size_t kMaxRailSlices = 2000;  // per rail: a turnout needs tens
constexpr double kMaxRailOffset = 0.5;        // [m] |dy|, |dz| of a slice

constexpr double kMinMaxSlope = 1.0, kMaxMaxSlope = 100.0;  // [-] a slice's max_slope

// A slice's optional offsets dy, dz and max_slope (RailSliceSpec); false when one is given and
// not a number in its range.
bool sliceOptions(Reader& r, const Node& v, const std::string& what, dynamics::RailSliceSpec& sl) {
  bool ok = true;
  for (auto [key, target] : {std::pair{"dy", &sl.dy}, std::pair{"dz", &sl.dz}}) {
    const Node* o = v.field(key);
    if (!o) continue;
    if (o->type != Node::Type::Number || !(std::abs(o->number) <= kMaxRailOffset)) {
      r.error(*o, what + "." + key + " must be an offset of at most " +
                      formatNumber(kMaxRailOffset) + " m, got " + o->describe());
      ok = false;
      continue;
    }
    *target = o->number;
  }
  const Node* m = v.field("max_slope");
  if (!m) return ok;
  if (m->type != Node::Type::Number || !(m->number >= kMinMaxSlope && m->number <= kMaxMaxSlope)) {
    r.error(*m, what + ".max_slope must be a slope |dz/dy| from " + formatNumber(kMinMaxSlope) +
                    " to " + formatNumber(kMaxMaxSlope) +
                    " (the profile keeps its longest run of points no steeper), got " +
                    m->describe());
    return false;
  }
  sl.max_slope = m->number;
  return ok;
}

// A CONTACT slices-file for one rail: { slcs = "file.slcs", s = <m>, units = "mm" | "m",
// z = "down" | "up", dy = <m>, dz = <m>, max_slope = <-> }. The slices are at s + u_fc (u_fc of the
// file, in m), each moved by dy, dz; plain-text slice files are read in `units` with z `z`
// (CONTACT's canonical form: mm, z down), SIMPACK ones as their headers say.
bool sliceFile(Reader& r, LuaHost& host, const Node& v, const std::string& what,
               std::vector<dynamics::RailSliceSpec>& out,
               std::vector<dynamics::SliceListSpec>& lists) {
  const std::string form =
      "{ slcs = \"file.slcs\", s = <m> (track position of the file's u = 0), units = \"mm\" "
      "or \"m\", z = \"down\" or \"up\", dy = <m>, dz = <m>, max_slope = <|dz/dy|> }";
  bool ok = true;
  for (const auto& [key, value] : v.fields)
    if (key != "slcs" && key != "s" && key != "units" && key != "z" && key != "dy" && key != "dz" &&
        key != "max_slope") {
      r.error(value, what + ": unknown key '" + key + "' in " + form);
      ok = false;
    }
  const Node* file = v.field("slcs");
  const Node* s0 = v.field("s");
  if (file->type != Node::Type::String || file->string.empty()) {
    r.error(*file, what + ".slcs must be a slices-file name, got " + file->describe());
    return false;
  }
  if (!s0 || s0->type != Node::Type::Number || !std::isfinite(s0->number)) {
    r.error(s0 ? *s0 : v, what +
                              ".s must be the track arc length [m] of the slices-file's u = 0, "
                              "got " +
                              (s0 ? s0->describe() : std::string("nothing")));
    return false;
  }
  dynamics::RailSliceSpec base;
  base.loc = v.loc;
  const auto choice = [&](const char* key, const char* a, const char* b, bool& second) {
    const Node* n = v.field(key);
    if (!n) return;
    if (n->type == Node::Type::String && (n->string == a || n->string == b)) {
      second = n->string == b;
      return;
    }
    r.error(*n, what + "." + key + " must be \"" + a + "\" or \"" + b + "\", got " + n->describe());
    ok = false;
  };
  choice("units", "mm", "m", base.metres);
  bool up = false;
  choice("z", "down", "up", up);
  base.z_down = !up;
  ok = sliceOptions(r, v, what, base) && ok;
  if (!ok) return false;
  std::string path;
  profiles::SliceList list;
  try {
    path = host.resolveDataFile(file->string, file->loc);
    list = profiles::readSliceList(path);
  } catch (const InputError& e) {
    // The slices-file's own problems at its own line; a name that does not resolve at the
    // scenario's.
    const Diagnostic& diag = e.diagnostics().front();
    r.error(*file, what +
                       ".slcs: " + (diag.loc.file == file->loc.file ? "" : diag.loc.str() + ": ") +
                       diag.message);
    return false;
  }
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (const profiles::SliceListEntry& e : list.slices) {
    dynamics::RailSliceSpec sl = base;
    sl.s = s0->number + e.u_fc;
    const SourceLoc at{path, e.line};
    sl.loc = at;  // a slice's problems (its profile, its place) at its line of the slices-file
    if (!std::isfinite(sl.s) || sl.s < 0.0) {
      r.error(*s0, what + ": the slice at " + at.str() + " is at s = " + formatNumber(sl.s) +
                       " m, before the track's start or not a position (raise " + what +
                       ".s, or check U_OFFSET and U_SCALE)");
      return false;
    }
    if (!out.empty() && !(sl.s > out.back().s)) {
      r.error(*s0, what + ": the slice at " + at.str() + " lands at s = " + formatNumber(sl.s) +
                       " m, not after the one before it (" + formatNumber(out.back().s) +
                       " m): the slices-file's positions are too close for s = " +
                       formatNumber(s0->number) + " m");
      return false;
    }
    try {
      const std::filesystem::path f(e.file);
      sl.rail = host.resolveDataFile((f.is_absolute() ? f : folder / f).string(), at);
    } catch (const InputError& err) {
      r.error(*file, what + ".slcs: " + err.diagnostics().front().loc.str() + ": " +
                         err.diagnostics().front().message);
      return false;
    }
    out.push_back(std::move(sl));
  }
  lists.push_back({path, list.features, list.kinks, list.accelerations, file->loc});
  return true;
}

// One side's list of slices ("what" names it in messages); false when malformed.
bool sliceList(Reader& r, LuaHost& host, const Node& list, const std::string& what,
               std::vector<dynamics::RailSliceSpec>& out) {
  const std::string form =
      "{ s = <m>, rail = \"60e1\" or a rail profile file, dy = <m>, dz = <m>, max_slope = "
      "<|dz/dy|> }";
  if (list.type != Node::Type::Table || !list.fields.empty() || list.items.empty()) {
    r.error(list, what + " must be a non-empty list of slices " + form +
                      " or a CONTACT slices-file { slcs = \"file.slcs\", s = <m> }, got " +
                      list.describe());
    return false;
  }
  if (list.items.size() > kMaxRailSlices) {
    r.error(list, what + ": at most " + std::to_string(kMaxRailSlices) + " slices, got " +
                      std::to_string(list.items.size()));
    return false;
  }
  bool ok = true;
  for (std::size_t i = 0; i < list.items.size(); ++i) {
    const Node& item = list.items[i];
    const std::string at = what + "[" + std::to_string(i + 1) + "]";
    const bool table = item.type == Node::Type::Table && item.items.empty();
    const Node* s = table ? item.field("s") : nullptr;
    const Node* rail = table ? item.field("rail") : nullptr;
    bool known = table;
    if (table)
      for (const auto& [key, value] : item.fields)
        known = known &&
                (key == "s" || key == "rail" || key == "dy" || key == "dz" || key == "max_slope");
    if (!s || !rail || !known) {
      r.error(item,
              at + " must be " + form + " (dy, dz, max_slope optional), got " + item.describe());
      ok = false;
      continue;
    }
    if (s->type != Node::Type::Number || !std::isfinite(s->number) || s->number < 0.0) {
      r.error(*s, at + ".s must be a track arc length >= 0 [m], got " + s->describe());
      ok = false;
      continue;
    }
    if (rail->type != Node::Type::String || rail->string.empty()) {
      r.error(*rail, at + ".rail must be \"60e1\" or a rail profile file, got " + rail->describe());
      ok = false;
      continue;
    }
    if (!out.empty() && !(s->number > out.back().s)) {
      r.error(*s, at + ".s = " + formatNumber(s->number) +
                      " m: the slices' s must increase strictly (the one before is at " +
                      formatNumber(out.back().s) + " m)");
      ok = false;
      continue;
    }
    dynamics::RailSliceSpec sl;
    sl.s = s->number;
    sl.loc = item.loc;
    if (!sliceOptions(r, item, at, sl)) {
      ok = false;
      continue;
    }
    if (rail->string == "60e1") {
      sl.rail = "60e1";
    } else {
      try {
        sl.rail = host.resolveDataFile(rail->string, item.loc);
      } catch (const InputError& e) {
        r.error(*rail, at + ".rail: " + e.diagnostics().front().message);
        ok = false;
        continue;
      }
    }
    out.push_back(std::move(sl));
  }
  return ok;
}

// A rail's slices: a list (sliceList) or a CONTACT slices-file (sliceFile).
bool oneRailSlices(Reader& r, LuaHost& host, const Node& v, const std::string& what,
                   std::vector<dynamics::RailSliceSpec>& out,
                   std::vector<dynamics::SliceListSpec>& lists) {
  if (v.type == Node::Type::Table && v.items.empty() && v.field("slcs"))
    return sliceFile(r, host, v, what, out, lists);
  return sliceList(r, host, v, what, out);
}

// The sides of a { left = ..., right = ... } table; each side's value goes to `side`.
template <class Side>
void eachSide(Reader& r, const Node& v, const std::string& key, const std::string& form,
              Side side) {
  if (v.type != Node::Type::Table || !v.items.empty() || v.fields.empty()) {
    r.error(v, key + " must be a table " + form + ", got " + v.describe());
    return;
  }
  for (const auto& [name, list] : v.fields) {
    if (name != "left" && name != "right") {
      r.error(list, key + ": unknown side '" + name + "' (left or right)");
      continue;
    }
    side(name == "left" ? std::size_t{0} : std::size_t{1}, key + "." + name, list);
  }
}

// One further rail { name = ..., slices = ..., check = ... } of a side, appended to `rails`
// when well formed.
void extraRail(Reader& r, LuaHost& host, const Node& item, const std::string& at,
               std::vector<dynamics::ExtraRailSpec>& rails,
               std::vector<dynamics::SliceListSpec>& lists) {
  const Node* name = item.type == Node::Type::Table ? item.field("name") : nullptr;
  const Node* slices = item.type == Node::Type::Table ? item.field("slices") : nullptr;
  const Node* check = item.type == Node::Type::Table ? item.field("check") : nullptr;
  if (!name || !slices || item.fields.size() != (check ? 3U : 2U) || !item.items.empty() ||
      (check != nullptr && check->type != Node::Type::Bool) || name->type != Node::Type::String ||
      !dynamics::validRailName(name->string)) {
    r.error(item, at +
                      " must be { name = \"nose\" (1-32 letters, digits or '_'), "
                      "slices = { ... }, check = true or false (optional) }, got " +
                      item.describe());
    return;
  }
  const bool twice =
      name->string == "rail" || std::any_of(rails.begin(), rails.end(),
                                            [&](const auto& o) { return o.name == name->string; });
  if (twice) {
    r.error(*name, at + ".name '" + name->string +
                       "' is taken (\"rail\" is the running rail's, the others must differ)");
    return;
  }
  dynamics::ExtraRailSpec rail;
  rail.name = name->string;
  rail.check = check != nullptr && check->boolean;
  rail.loc = item.loc;
  if (oneRailSlices(r, host, *slices, at + ".slices", rail.slices, lists))
    rails.push_back(std::move(rail));
}

void railSlices(Reader& r, LuaHost& host, dynamics::ProfilesSpec& p) {
  if (const Node* v = r.value("rail_slices"))
    eachSide(r, *v, "rail_slices",
             "{ left = { { s = s0, rail = \"file\" }, ... }, right = { ... } } (s the track arc "
             "length [m], strictly increasing)",
             [&](std::size_t side, const std::string& what, const Node& list) {
               std::vector<dynamics::RailSliceSpec> out;
               if (oneRailSlices(r, host, list, what, out, p.slice_lists))
                 p.rail_slices[side] = std::move(out);
             });
  constexpr std::size_t kMaxExtra = dynamics::kMaxExtraRails;
  if (const Node* v = r.value("extra_rails"))
    eachSide(
        r, *v, "extra_rails",
        "{ right = { { name = \"nose\", slices = { { s = s0, rail = \"file\" }, ... } }, ... } }",
        [&](std::size_t side, const std::string& what, const Node& list) {
          if (list.type != Node::Type::Table || !list.fields.empty() || list.items.empty() ||
              list.items.size() > kMaxExtra) {
            r.error(list, what + " must be a list of 1 to " + std::to_string(kMaxExtra) +
                              " rails { name = \"...\", slices = { ... } }, got " +
                              list.describe());
            return;
          }
          std::vector<dynamics::ExtraRailSpec> rails;
          for (std::size_t i = 0; i < list.items.size(); ++i)
            extraRail(r, host, list.items[i], what + "[" + std::to_string(i + 1) + "]", rails,
                      p.slice_lists);
          p.extra_rails[side] = std::move(rails);
        });
}

// profiles.wheelsets = { ws2 = { wheel_right = "worn.txt" }, ws3 = { wheel = "b.prw" } }: the
// wheelsets with wheels of their own, by the wheelset body's name (checked against the vehicle
// when the contact model is compiled).
void wheelsetProfiles(Reader& r, LuaHost& host, dynamics::ProfilesSpec& p) {
  const Node* v = r.value("wheelsets");
  if (!v) return;
  const std::string form =
      "{ ws1 = { wheel = ..., wheel_left = ..., wheel_right = ... }, ... } (a wheelset's name "
      "and its own wheels: \"s1002\" or profile files)";
  if (v->type != Node::Type::Table || !v->items.empty() || v->fields.empty()) {
    r.error(*v, "wheelsets must be a table " + form + ", got " + v->describe());
    return;
  }
  const std::vector<std::string> keys = {"wheel", "wheel_left", "wheel_right"};
  const std::string builtin_wheel = dynamics::ProfilesSpec{}.wheel;
  for (const auto& [name, entry] : v->fields) {
    const std::string at = "wheelsets." + name;
    if (entry.type != Node::Type::Table || !entry.items.empty() || entry.fields.empty()) {
      r.error(entry, at +
                         " must be { wheel = ..., wheel_left = ..., wheel_right = ... } (at "
                         "least one), got " +
                         entry.describe());
      continue;
    }
    bool ok = true;
    for (const auto& [key, value] : entry.fields) {
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
        const std::string hint = closestMatch(key, keys);
        r.error(value, at + ": unknown key '" + key + "'" +
                           (hint.empty() ? " (wheel, wheel_left, wheel_right)"
                                         : " (did you mean '" + hint + "'?)"));
        ok = false;
      } else if (value.type != Node::Type::String || value.string.empty()) {
        r.error(value, at + "." + key + " must be \"s1002\" or a wheel profile file, got " +
                           value.describe());
        ok = false;
      }
    }
    // wheel is both wheels: with wheel_left or wheel_right as well, one side has two profiles
    // and one of them would be silently unused.
    if (ok && entry.field("wheel") != nullptr &&
        (entry.field("wheel_left") != nullptr || entry.field("wheel_right") != nullptr)) {
      r.error(entry, at + ": give wheel (both wheels) or wheel_left / wheel_right, not both");
      ok = false;
    }
    if (!ok) continue;
    dynamics::WheelsetProfilesSpec w;
    w.wheelset = name;
    w.loc = entry.loc;
    for (auto [key, target] : {std::pair{"wheel", &w.wheel}, std::pair{"wheel_left", &w.wheel_left},
                               std::pair{"wheel_right", &w.wheel_right}}) {
      const Node* f = entry.field(key);
      if (!f) continue;
      const auto source = profileName(r, *f, at + "." + key, f->string, builtin_wheel, host);
      if (source)
        *target = *source;
      else
        ok = false;
    }
    if (ok) p.wheelsets.push_back(std::move(w));
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
  wheelsetProfiles(r, host, p);
  if (r.has("lw") && r.has("back_to_back"))
    r.error(n, "give either lw or back_to_back, not both (lw overrides the positioning)");
  if (r.has("lr") && r.has("gauge"))
    r.error(n, "give either lr or gauge, not both (lr overrides the positioning)");
}

}  // namespace rb::scenario
