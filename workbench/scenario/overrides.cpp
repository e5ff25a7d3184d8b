#include "workbench/scenario/overrides.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <optional>
#include <vector>

#include "workbench/core/strings.hpp"
#include "workbench/scenario/lua_host.hpp"
#include "workbench/scenario/schema.hpp"

namespace rb::scenario {
namespace {

const SourceLoc& kCommandLine = kCommandLineLoc;

bool isIndexToken(const std::string& t) {
  return !t.empty() && t.find_first_not_of("0123456789") == std::string::npos;
}

// Tokens of a path: names and 1-based list positions, "a.b[2].c" or "a.b.2.c". A token left
// empty ("solver..step", ".a", "a.", "a[]", "a[2]b") is a malformed path, never skipped: reading
// "solver..step" as "solver.step" would set a key the user did not write.
std::optional<std::vector<std::string>> pathTokens(const std::string& path) {
  std::vector<std::string> tokens;
  std::string cur;
  bool inBracket = false;  // between '[' and ']'
  bool closed = false;     // just after ']': '.', '[' or the end must follow
  for (char c : path) {
    const bool sep = c == '.' || c == '[' || c == ']';
    if (!sep) {
      if (closed) return std::nullopt;  // "a[2]b"
      cur += c;
      continue;
    }
    if (c == ']' ? !inBracket || cur.empty() : inBracket) return std::nullopt;
    if (cur.empty() && !closed) return std::nullopt;  // "a..b", ".a", "a.[2]"
    if (!cur.empty()) tokens.push_back(cur);
    cur.clear();
    inBracket = c == '[';
    closed = c == ']';
  }
  if (inBracket || (cur.empty() && !closed)) return std::nullopt;  // "a[2", "a."
  if (!cur.empty()) tokens.push_back(cur);
  return tokens;
}

// The tokens [0, n) as a dotted path, for messages.
std::string prefix(const std::vector<std::string>& tokens, std::size_t n) {
  std::vector<std::string> head(tokens.begin(), tokens.begin() + static_cast<std::ptrdiff_t>(n));
  return join(head, ".");
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string hint = closestMatch(word, candidates);
  return hint.empty() ? "" : " (did you mean '" + hint + "'?)";
}

Node commandLineTable(const std::string& kind, const SourceLoc& loc) {
  Node t;
  t.type = Node::Type::Table;
  t.kind = kind;
  t.loc = loc;
  return t;
}

// The top-level block named `name`, made empty when the scenario has none; an unknown block is
// the returned message.
Node* topBlock(Node& root, const std::string& name, const SourceLoc& loc, std::string& problem) {
  if (Node* node = root.field(name)) return node;
  const auto& tops = topLevelBlocks();
  bool known = false;
  for (const auto& t : tops) known = known || t == name;
  if (!known) {
    problem = "unknown block '" + name + "'" + didYouMean(name, tops);
    return nullptr;
  }
  return &root.setField(name, commandLineTable(name, loc));
}

// A list of named tables (vehicle.bodies, vehicle.elements): a list whose items carry names.
bool isNamedList(const Node& list) {
  return list.fields.empty() && std::any_of(list.items.begin(), list.items.end(),
                                            [](const Node& i) { return !itemName(i).empty(); });
}

// What the items of the list at `listPath` are called in messages.
std::string itemWord(const std::string& listPath) {
  if (listPath == "vehicle.elements") return "element";
  if (listPath == "vehicle.bodies") return "body";
  return "item";
}

// The item of a named list called `name`; the problem (unknown name, with the nearest one, or a
// name given twice) otherwise.
Node* namedItem(Node& list, const std::string& listPath, const std::string& name,
                std::string& problem) {
  std::vector<std::string> names;
  Node* found = nullptr;
  int count = 0;
  for (Node& item : list.items) {
    const std::string n = itemName(item);
    if (n == name) {
      found = found ? found : &item;
      ++count;
    }
    if (!n.empty()) names.push_back(n);
  }
  const std::string word = itemWord(listPath);
  if (count > 1)
    problem = listPath + ": " + std::to_string(count) + " " + word + "s are named '" + name +
              "'; address one by its list position";
  else if (!found)
    problem = listPath + ": no " + word + " named '" + name + "'" + didYouMean(name, names);
  return count == 1 ? found : nullptr;
}

// The value of an override as text, without reading it as a number.
Node textValue(const std::string& text, const SourceLoc& loc) {
  Node n = parseOverrideValue(text, loc);
  if (n.type == Node::Type::String) return n;
  n.type = Node::Type::String;
  n.string = text;
  return n;
}

// Whether key t of the table at `path` holds text (a file or profile name): the schema says so,
// or the scenario gave it text. "--set profiles.rail=60e1" is then the rail's name, not the
// number 600.
bool holdsText(const Node& table, const std::string& path, const std::string& t) {
  if (const Node* v = table.field(t); v != nullptr && v->type == Node::Type::String) return true;
  // The block by its whole path ("profiles") or by its last name (a train vehicle's own
  // "train.vehicles.2.profiles").
  const std::string last = path.substr(path.find_last_of('.') + 1);
  for (const std::string& name : {path, last})
    for (const auto& b : schema())
      if (b.name == name) {
        const KeySpec* k = b.key(t);
        return k != nullptr && k->type == ValueType::String;
      }
  return false;
}

// Walks tokens[from..] from `node` and sets the last one to `value`; the problem otherwise.
std::optional<std::string> setPath(Node* node, const std::vector<std::string>& tokens,
                                   std::size_t from, const std::string& value,
                                   const SourceLoc& loc) {
  for (std::size_t i = from; i < tokens.size(); ++i) {
    const std::string& t = tokens[i];
    const bool last = i + 1 == tokens.size();
    if (node->type != Node::Type::Table)
      return "'" + tokens[i - 1] + "' is not a table, cannot set '" + t + "' in it";
    if (isIndexToken(t)) {
      // More digits than any list can have: out of range, without overflowing the conversion.
      const std::size_t idx = t.size() > 9 ? 0 : std::stoul(t);
      if (idx < 1 || idx > node->items.size())
        return "list position " + t + " out of range 1.." + std::to_string(node->items.size());
      if (last) {
        node->items[idx - 1] = parseOverrideValue(value, loc);
        return std::nullopt;
      }
      node = &node->items[idx - 1];
    } else if (node->field(t) == nullptr && isNamedList(*node)) {
      std::string problem;
      Node* item = namedItem(*node, prefix(tokens, i), t, problem);
      if (item == nullptr) return problem;
      if (last) {
        const std::string word = itemWord(prefix(tokens, i));
        return prefix(tokens, i + 1) + " is a whole " + word + "; name one of its keys, e.g. " +
               prefix(tokens, i + 1) + (word == "body" ? ".mass" : ".stiffness");
      }
      node = item;
    } else if (last) {
      node->setField(t, holdsText(*node, prefix(tokens, i), t) ? textValue(value, loc)
                                                               : parseOverrideValue(value, loc));
      return std::nullopt;
    } else {
      Node* next = node->field(t);
      node = next ? next : &node->setField(t, commandLineTable("", loc));
    }
  }
  return std::nullopt;
}

// The schema block of an element's kind, nullptr for a table that is not an element constructor
// (the validator reports it).
const BlockSpec* kindBlock(const Node& element) {
  for (const auto& b : schema())
    if (!element.kind.empty() && b.name == element.kind) return &b;
  return nullptr;
}

// The group of vehicle.groups named tokens[2] and its members; the problem otherwise.
std::optional<std::string> resolveGroup(const Node& vehicle, const std::vector<std::string>& tokens,
                                        GroupMembers& members) {
  if (tokens.size() < 3) return "name a group and a key, e.g. vehicle.groups.GROUP.stiffness";
  const Node* groups = vehicle.field("groups");
  std::vector<std::string> names;
  if (groups != nullptr && groups->type == Node::Type::Table)
    for (const auto& kv : groups->fields) names.push_back(kv.first);
  const std::string& name = tokens[2];
  const Node* group = groups != nullptr ? groups->field(name) : nullptr;
  if (group == nullptr)
    return "vehicle.groups: no group named '" + name + "'" +
           (names.empty() ? std::string(" (the vehicle defines no groups)")
                          : didYouMean(name, names));
  if (tokens.size() < 4)
    return "vehicle.groups." + name + " is a group; name the key to set in every member, e.g. " +
           "vehicle.groups." + name + ".stiffness";
  members = groupMembers(vehicle, *group);
  if (!members.problems.empty()) return "vehicle.groups." + name + ": " + members.problems.front();
  return std::nullopt;
}

// vehicle.groups.GROUP.KEY...=value: KEY set in every member element. A member whose kind has no
// such key is an error naming it (never a silent skip), checked before any member is changed.
std::optional<std::string> setGroup(Node& vehicle, const std::vector<std::string>& tokens,
                                    const std::string& value, const SourceLoc& loc) {
  GroupMembers members;
  if (auto p = resolveGroup(vehicle, tokens, members)) return p;
  Node* elements = vehicle.field("elements");
  const std::string where = "vehicle.groups." + tokens[2];
  const std::string& key = tokens[3];
  for (const std::size_t i : members.elements) {
    const Node& e = elements->items[i];
    const BlockSpec* bs = kindBlock(e);
    if (bs != nullptr && bs->key(key) == nullptr)
      return where + ": element '" + itemName(e) + "' (" + e.kind + ") has no key '" + key + "'" +
             didYouMean(key, bs->keyNames()) + "; its keys: " + join(bs->keyNames(), ", ");
  }
  for (const std::size_t i : members.elements)
    if (auto p = setPath(&elements->items[i], tokens, 3, value, loc))
      return where + ": element '" + itemName(elements->items[i]) + "': " + *p;
  return std::nullopt;
}

// Why `pattern` of a group selects no element: a body's name, a glob matching nothing, or an
// unknown name with the nearest element name.
std::string noMatch(const std::string& pattern, const std::vector<std::string>& elements,
                    const Node* bodies) {
  if (bodies != nullptr)
    for (const Node& b : bodies->items)
      if (!itemName(b).empty() && globMatch(pattern, itemName(b)))
        return "'" + pattern + "' names a body ('" + itemName(b) +
               "'); a group holds suspension elements (set a body's key by its name, "
               "vehicle.bodies." +
               itemName(b) + ".mass)";
  if (pattern.find('*') != std::string::npos) return "pattern '" + pattern + "' matches no element";
  return "no element named '" + pattern + "'" + didYouMean(pattern, elements);
}

}  // namespace

bool globMatch(const std::string& pattern, const std::string& name) {
  // Greedy wildcard match with backtracking to the last '*': linear in practice, at worst
  // |pattern| * |name| steps.
  std::size_t p = 0, n = 0, star = std::string::npos, mark = 0;
  while (n < name.size()) {
    if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      mark = n;
    } else if (p < pattern.size() && pattern[p] == name[n]) {
      ++p;
      ++n;
    } else if (star != std::string::npos) {
      p = star + 1;
      n = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::string itemName(const Node& item) {
  if (item.type != Node::Type::Table) return "";
  const Node* n = item.field("name");
  return n != nullptr && n->type == Node::Type::String ? n->string : "";
}

bool isParameterName(const std::string& t) {
  return !t.empty() && std::isdigit(static_cast<unsigned char>(t[0])) == 0 &&
         t.find_first_not_of(
             "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_"
             "0123456789") == std::string::npos;
}

GroupMembers groupMembers(const Node& vehicle, const Node& group) {
  GroupMembers out;
  if (group.type != Node::Type::Table || !group.fields.empty()) {
    out.problems.push_back(
        "must be a list of element names or patterns, e.g. { \"prim_x_*\" }, got " +
        group.describe());
    return out;
  }
  if (group.items.empty()) out.problems.emplace_back("lists no elements");
  static const Node kNone;
  const Node* elementsNode = vehicle.field("elements");
  const Node& elements = elementsNode != nullptr ? *elementsNode : kNone;
  std::vector<std::string> names;
  for (const Node& e : elements.items) names.push_back(itemName(e));
  std::vector<bool> taken(names.size(), false);
  for (const Node& entry : group.items) {
    if (entry.type != Node::Type::String || entry.string.empty()) {
      out.problems.push_back(
          "entries must be element names or patterns, got " +
          (entry.type == Node::Type::String ? std::string("an empty name") : entry.describe()));
      continue;
    }
    bool any = false;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (!names[i].empty() && globMatch(entry.string, names[i])) {
        any = true;
        taken[i] = true;
      }
    if (!any) out.problems.push_back(noMatch(entry.string, names, vehicle.field("bodies")));
  }
  for (std::size_t i = 0; i < taken.size(); ++i)
    if (taken[i]) out.elements.push_back(i);
  return out;
}

Node parseOverrideValue(const std::string& text, const SourceLoc& loc) {
  Node n;
  n.loc = loc;
  char* end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (!text.empty() && end && *end == '\0') {
    n.type = Node::Type::Number;
    n.number = v;
  } else if (text == "true" || text == "false") {
    n.type = Node::Type::Bool;
    n.boolean = text == "true";
  } else {
    n.type = Node::Type::String;
    n.string = text;
    if (n.string.size() >= 2 && (n.string.front() == '"' || n.string.front() == '\'') &&
        n.string.back() == n.string.front())
      n.string = n.string.substr(1, n.string.size() - 2);
  }
  return n;
}

std::optional<std::string> overrideProblem(Node& root, const std::string& assignment,
                                           const SourceLoc& loc) {
  auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) return "expected key=value, e.g. solver.step=5e-4";
  const auto parsed = pathTokens(assignment.substr(0, eq));
  if (!parsed)
    return "'" + assignment.substr(0, eq) +
           "' is not a key path: names and list positions joined by '.', e.g. solver.step or "
           "track.segments[2].radius";
  const std::vector<std::string>& tokens = *parsed;
  if (tokens.size() < 2) return "the key must name a block and a key, e.g. solver.step";
  for (const auto& t : tokens)
    if (!isIndexToken(t) && !isParameterName(t))
      return "'" + t + "' is neither a key name nor a list position (1, 2, ...)";
  std::string problem;
  Node* node = topBlock(root, tokens[0], loc, problem);
  if (!node) return problem;
  const std::string value = assignment.substr(eq + 1);
  if (tokens[0] == "vehicle" && tokens[1] == "groups") return setGroup(*node, tokens, value, loc);
  // train.vehicles[k].vehicle.groups.GROUP.KEY: the group of that vehicle's own table.
  if (tokens[0] == "train" && tokens.size() >= 5 && tokens[1] == "vehicles" &&
      isIndexToken(tokens[2]) && tokens[3] == "vehicle" && tokens[4] == "groups") {
    Node* list = node->field("vehicles");
    const std::size_t k = std::stoul(tokens[2]);
    if (list == nullptr || k < 1 || k > list->items.size())
      return "train.vehicles has no entry " + tokens[2];
    Node* vehicle = list->items[k - 1].field("vehicle");
    if (vehicle == nullptr || vehicle->type != Node::Type::Table)
      return "train.vehicles[" + tokens[2] + "] has no vehicle table";
    return setGroup(*vehicle, std::vector<std::string>(tokens.begin() + 3, tokens.end()), value,
                    loc);
  }
  return setPath(node, tokens, 1, value, loc);
}

void applyOverride(Node& root, const std::string& assignment, Diagnostics& d) {
  if (auto p = overrideProblem(root, assignment, kCommandLine))
    d.add(kCommandLine, "--set " + assignment + ": " + *p);
}

void applyOverride(Node& root, const std::string& assignment, const SourceLoc& loc,
                   Diagnostics& d) {
  if (loc.file.empty()) return applyOverride(root, assignment, d);
  const auto eq = assignment.find('=');
  if (auto p = overrideProblem(root, assignment, loc))
    d.add(loc, "\"" + assignment.substr(0, eq) + "\" = " +
                   (eq == std::string::npos ? "" : assignment.substr(eq + 1)) + ": " + *p);
}

}  // namespace rb::scenario
