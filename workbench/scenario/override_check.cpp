#include "workbench/scenario/override_check.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "workbench/core/strings.hpp"
#include "workbench/scenario/build.hpp"
#include "workbench/scenario/lua_host.hpp"
#include "workbench/scenario/overrides.hpp"
#include "workbench/scenario/schema.hpp"
#include "workbench/vehicle/names.hpp"

namespace rb::scenario {
namespace {

// The line of the study text where the key is written as a string ("key" or 'key') outside a
// comment, 0 if none.
// Lua records no line for the fields of a plain table, so the text is searched.
int keyLine(const std::string& text, const std::string& key) {
  std::istringstream in(text);
  std::string line;
  for (int no = 1; std::getline(in, line); ++no) {
    line = line.substr(0, line.find("--"));  // a Lua comment may mention the key
    if (line.find('"' + key + '"') != std::string::npos ||
        line.find('\'' + key + '\'') != std::string::npos)
      return no;
  }
  return 0;
}

// The distinct override assignments of the study per base scenario (first value of each key).
// A set of the keys seen: every case repeats the study's keys, so a search of a list per override
// was quadratic (100 cases of 2000 overrides took a minute to load).
std::map<std::string, std::vector<std::string>> assignmentsByBase(const StudySpec& study) {
  std::map<std::string, std::vector<std::string>> out;
  std::map<std::string, std::set<std::string>> keys;
  for (const auto& c : study.cases) {
    auto& seen = keys[c.base];
    for (const auto& o : c.overrides)
      if (seen.insert(o.substr(0, o.find('='))).second) out[c.base].push_back(o);
  }
  return out;
}

// The keys of a schema block a sweep varies: all but the ones that name and place the item.
std::vector<std::string> settableKeys(const std::string& kind) {
  static const std::vector<std::string> kFixed = {"name",  "kind",      "from", "to", "at_from",
                                                  "at_to", "direction", "body", "at", "frame"};
  std::vector<std::string> out;
  for (const auto& b : schema())
    if (b.name == kind)
      for (const auto& k : b.keys)
        if (std::find(kFixed.begin(), kFixed.end(), k.name) == kFixed.end()) out.push_back(k.name);
  return out;
}

// "stiffness=3.1391e+07 damping=15000 length0 preload": the settable keys, with the values the
// vehicle gives the number keys.
std::string keysWithValues(const Node& item) {
  std::vector<std::string> parts;
  for (const auto& k : settableKeys(item.kind)) {
    const Node* v = item.field(k);
    parts.push_back(
        v != nullptr && v->type == Node::Type::Number ? k + "=" + formatNumber(v->number) : k);
  }
  return join(parts, " ");
}

// The settable keys every member of a group has.
std::vector<std::string> commonKeys(const Node& elements, const std::vector<std::size_t>& members) {
  std::vector<std::string> keys;
  for (std::size_t j = 0; j < members.size(); ++j) {
    const std::vector<std::string> own = settableKeys(elements.items[members[j]].kind);
    if (j == 0) {
      keys = own;
      continue;
    }
    std::erase_if(keys, [&](const std::string& k) {
      return std::find(own.begin(), own.end(), k) == own.end();
    });
  }
  return keys;
}

void listGroups(std::ostream& os, const Node& vehicle) {
  const Node* groups = vehicle.field("groups");
  const Node* elements = vehicle.field("elements");
  if (groups == nullptr || groups->fields.empty() || elements == nullptr) {
    os << "\nGroups: none (define them in the vehicle table: groups = { NAME = { \"prim_x_*\" } "
          "})\n";
    return;
  }
  os << "\nGroups (--set vehicle.groups.GROUP.KEY=VALUE sets KEY in every member):\n";
  for (const auto& [name, g] : groups->fields) {
    const GroupMembers m = groupMembers(vehicle, g);
    std::vector<std::string> names;
    for (const std::size_t i : m.elements) names.push_back(itemName(elements->items[i]));
    os << "  " << name << " (" << names.size() << "): " << join(names, " ") << "\n"
       << "      keys: " << join(commonKeys(*elements, m.elements), " ") << "\n";
  }
}

// "primary_longitudinal" -> "primary longitudinal".
std::string words(std::string s) {
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

const BlockSpec* findBlock(const std::string& name) {
  for (const auto& b : schema())
    if (b.name == name) return &b;
  return nullptr;
}

// The unit of `key` in the blocks of `kinds` when they agree ("" when none has it or they differ).
std::string unitOfKinds(const std::vector<std::string>& kinds, const std::string& key) {
  std::string unit;
  bool first = true;
  for (const auto& k : kinds) {
    const BlockSpec* b = findBlock(k);
    const KeySpec* ks = b != nullptr ? b->key(key) : nullptr;
    if (ks == nullptr) continue;
    if (!first && ks->unit != unit) return "";
    unit = ks->unit;
    first = false;
  }
  return unit;
}

// The tokens of a path: "track.segments[2].radius" -> track, segments, 2, radius.
std::vector<std::string> tokens(const std::string& path) {
  std::vector<std::string> out;
  std::string cur;
  for (char ch : path) {
    if (ch == '.' || ch == '[' || ch == ']') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += ch;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

// The item of a list of named tables by name or 1-based position (nullptr when none).
const Node* listItem(const Node* list, const std::string& token) {
  if (list == nullptr) return nullptr;
  for (const Node& it : list->items)
    if (itemName(it) == token) return &it;
  if (!token.empty() && std::all_of(token.begin(), token.end(), ::isdigit)) {
    const std::size_t i = std::stoul(token);
    if (i >= 1 && i <= list->items.size()) return &list->items[i - 1];
  }
  return nullptr;
}

// A named vehicle parameter (vehicle.<groups|elements|bodies|initial>.<name>.<key>): the element
// or group (its members' kind) or the body decides its unit; nullopt for any other path.
std::optional<ParameterLabel> vehicleParameterLabel(const Node* vehicle, const std::string& path,
                                                    const std::vector<std::string>& t) {
  if (t[0] != "vehicle" || t.size() != 4) return std::nullopt;
  const std::string& what = t[1];
  const std::string& name = t[2];
  const std::string& key = t[3];
  const Node* elements = vehicle != nullptr ? vehicle->field("elements") : nullptr;
  if (what == "groups" && vehicle != nullptr && elements != nullptr) {
    const Node* groups = vehicle->field("groups");
    const Node* g = groups != nullptr ? groups->field(name) : nullptr;
    if (g != nullptr) {
      std::vector<std::string> kinds;
      for (std::size_t i : groupMembers(*vehicle, *g).elements)
        kinds.push_back(elements->items[i].kind);
      return ParameterLabel{path, words(name) + " " + words(key), unitOfKinds(kinds, key)};
    }
  }
  if (what == "elements") {
    if (const Node* e = listItem(elements, name))
      return ParameterLabel{path,
                            words(itemName(*e).empty() ? name : itemName(*e)) + " " + words(key),
                            unitOfKinds({e->kind}, key)};
  }
  if (what == "bodies")
    return ParameterLabel{path, words(name) + " " + words(key), unitOfKinds({"body"}, key)};
  if (what == "initial")
    return ParameterLabel{path, "initial " + words(name) + " " + words(key),
                          unitOfKinds({"vehicle.initial.<body>"}, key)};
  return std::nullopt;
}

}  // namespace

ParameterLabel parameterLabel(const Node& tree, const std::string& path) {
  ParameterLabel out{path, path, ""};
  const std::vector<std::string> t = tokens(path);
  if (t.size() < 2) return out;
  if (auto named = vehicleParameterLabel(tree.field("vehicle"), path, t)) return *named;
  // A schema path: block.key, block.sub.key, block.list[n].key.
  const BlockSpec* b = findBlock(t[0]);
  const Node* node = tree.field(t[0]);
  std::vector<std::string> label = {words(t[0])};
  for (std::size_t i = 1; b != nullptr && i < t.size(); ++i) {
    const KeySpec* ks = b->key(t[i]);
    if (ks == nullptr) return out;
    label.push_back(words(t[i]));
    const Node* child = node != nullptr ? node->field(t[i]) : nullptr;
    if (i + 1 == t.size()) {
      out.label = join(label, " ");
      out.unit = ks->unit;
      return out;
    }
    if (ks->type == ValueType::BlockList) {
      const Node* item = listItem(child, t[i + 1]);
      if (item == nullptr) return out;
      label.push_back(t[i + 1]);
      ++i;
      b = findBlock(item->kind);
      node = item;
    } else if (ks->type == ValueType::Block) {
      b = findBlock(!ks->sub.empty()                           ? ks->sub
                    : child != nullptr && !child->kind.empty() ? child->kind
                                                               : b->name + "." + t[i]);
      node = child;
    } else {
      return out;
    }
  }
  return out;
}

std::vector<ParameterLabel> studyParameterLabels(const StudySpec& study) {
  std::vector<ParameterLabel> out;
  std::vector<std::string> seen;
  std::map<std::string, Node> trees;
  for (const auto& c : study.cases)
    for (const auto& o : c.overrides) {
      const std::string key = o.substr(0, o.find('='));
      if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
      seen.push_back(key);
      auto it = trees.find(c.base);
      if (it == trees.end()) {
        Node tree;
        try {
          HostOptions ho;
          ho.root = study.root;
          LuaHost host(ho);
          tree = host.runFile(c.base);
        } catch (const InputError&) {
          // The base's own problem, reported by its runs: its paths keep their text.
        }
        it = trees.emplace(c.base, std::move(tree)).first;
      }
      out.push_back(parameterLabel(it->second, key));
    }
  return out;
}

void checkStudyOverrides(const StudySpec& study, const std::string& studyText,
                         const std::string& root) {
  Diagnostics d;
  const auto byBase = assignmentsByBase(study);
  for (const auto& [base, assignments] : byBase) {
    HostOptions ho;
    ho.root = root;
    LuaHost host(ho);
    Node tree;
    try {
      tree = host.runFile(base);
    } catch (const InputError&) {
      continue;  // the base's own problem: every run of it reports that
    }
    for (const auto& a : assignments) {
      const std::string key = a.substr(0, a.find('='));
      // Only the block the path starts in is copied: the override changes nothing else.
      const std::string top = key.substr(0, key.find_first_of(".["));
      Node scratch;
      scratch.type = Node::Type::Table;
      if (const Node* b = tree.field(top)) scratch.setField(top, *b);
      const auto problem = overrideProblem(scratch, a);
      if (!problem) continue;
      const int line = keyLine(studyText, key);
      d.add(line > 0 ? SourceLoc{study.file, line} : study.loc,
            "study: \"" + key + "\": " + *problem +
                (byBase.size() > 1 ? " (base scenario " + base + ")" : ""));
    }
  }
  d.throwIfAny();
}

// The named parameters of one vehicle table; `path` is what its --set paths begin with
// ("vehicle", or "train.vehicles[2].vehicle").
void vehicleParameters(std::ostream& os, const Node& v, const std::string& path,
                       const std::string& scenarioPath) {
  Diagnostics d;
  vehicle::VehicleSpec spec;
  buildVehicle(v, spec, d);
  d.throwIfAny();
  os << "Named parameters of the vehicle '" << spec.name << "' of " << scenarioPath
     << (path == "vehicle" ? std::string() : " at " + path)
     << " (--set paths for run, check and study; SI units):\n";
  os << "\nBodies (--set " << path
     << ".bodies.NAME.KEY=VALUE; keys: " << join(settableKeys("body"), " ") << "):\n";
  for (const auto& b : spec.bodies)
    os << "  " << b.name << " (" << nameOf(b.kind) << "): mass=" << formatNumber(b.mass) << "\n";
  os << "\nElements (--set " << path << ".elements.NAME.KEY=VALUE):\n";
  if (const Node* elements = v.field("elements"))
    for (const Node& e : elements->items)
      os << "  " << itemName(e) << " (" << e.kind << "): " << keysWithValues(e) << "\n";
  std::ostringstream groups;
  listGroups(groups, v);
  std::string text = groups.str();
  // The group paths of a train's vehicle begin with its own path.
  for (std::size_t at = 0; (at = text.find("--set vehicle.", at)) != std::string::npos;
       at += path.size())
    text.replace(at + 6, 7, path);
  os << text;
}

std::string vehicleParametersText(const std::string& scenarioPath, const std::string& root) {
  HostOptions ho;
  ho.root = root;
  LuaHost host(ho);
  const Node tree = host.runFile(scenarioPath);
  std::ostringstream os;
  if (const Node* v = tree.field("vehicle")) {
    vehicleParameters(os, *v, "vehicle", scenarioPath);
    return os.str();
  }
  // A train: every vehicle's, under its own path.
  const Node* train = tree.field("train");
  const Node* list = train != nullptr ? train->field("vehicles") : nullptr;
  if (list == nullptr || list->items.empty())
    throw InputError({scenarioPath, 0},
                     "no vehicle{} or train{} block: give a scenario that uses the vehicle, e.g. "
                     "scenarios/studies/case3_base.lua");
  for (std::size_t k = 0; k < list->items.size(); ++k) {
    const Node* v = list->items[k].field("vehicle");
    if (v == nullptr) continue;
    if (k > 0) os << "\n";
    vehicleParameters(os, *v, "train.vehicles[" + std::to_string(k + 1) + "].vehicle",
                      scenarioPath);
  }
  return os.str();
}

}  // namespace rb::scenario
