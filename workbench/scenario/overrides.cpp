#include "workbench/scenario/overrides.hpp"

#include <cctype>
#include <cstdlib>
#include <optional>
#include <vector>

#include "workbench/core/strings.hpp"
#include "workbench/scenario/lua_host.hpp"

namespace rb::scenario {
namespace {

const SourceLoc kCommandLine{"<command line>", 0};

bool isIndexToken(const std::string& t) {
  return !t.empty() && t.find_first_not_of("0123456789") == std::string::npos;
}

bool isNameToken(const std::string& t) {
  return !t.empty() && !std::isdigit(static_cast<unsigned char>(t[0])) &&
         t.find_first_not_of(
             "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_"
             "0123456789") == std::string::npos;
}

// Tokens of a path: names and 1-based list positions, "a.b[2].c" or "a.b.2.c".
std::vector<std::string> pathTokens(const std::string& path) {
  std::vector<std::string> tokens;
  std::string cur;
  for (char c : path) {
    if (c == '.' || c == '[' || c == ']') {
      if (!cur.empty()) tokens.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) tokens.push_back(cur);
  return tokens;
}

Node commandLineTable(const std::string& kind) {
  Node t;
  t.type = Node::Type::Table;
  t.kind = kind;
  t.loc = kCommandLine;
  return t;
}

// The top-level block named `name`, made empty when the scenario has none; an unknown block is
// the returned message.
Node* topBlock(Node& root, const std::string& name, std::string& problem) {
  if (Node* node = root.field(name)) return node;
  const auto& tops = topLevelBlocks();
  bool known = false;
  for (const auto& t : tops) known = known || t == name;
  if (!known) {
    const std::string hint = closestMatch(name, tops);
    problem =
        "unknown block '" + name + "'" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)");
    return nullptr;
  }
  return &root.setField(name, commandLineTable(name));
}

// Walks tokens[1..] from `node` and sets the last one to `value`; the problem otherwise.
std::optional<std::string> setPath(Node* node, const std::vector<std::string>& tokens,
                                   const std::string& value) {
  for (std::size_t i = 1; i < tokens.size(); ++i) {
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
        node->items[idx - 1] = parseOverrideValue(value);
        return std::nullopt;
      }
      node = &node->items[idx - 1];
    } else if (last) {
      node->setField(t, parseOverrideValue(value));
      return std::nullopt;
    } else {
      Node* next = node->field(t);
      node = next ? next : &node->setField(t, commandLineTable(""));
    }
  }
  return std::nullopt;
}

}  // namespace

Node parseOverrideValue(const std::string& text) {
  Node n;
  n.loc = kCommandLine;
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

void applyOverride(Node& root, const std::string& assignment, Diagnostics& d) {
  auto fail = [&](const std::string& msg) {
    d.add(kCommandLine, "--set " + assignment + ": " + msg);
  };
  auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) return fail("expected key=value, e.g. solver.step=5e-4");
  const std::vector<std::string> tokens = pathTokens(assignment.substr(0, eq));
  if (tokens.size() < 2) return fail("the key must name a block and a key, e.g. solver.step");
  for (const auto& t : tokens)
    if (!isIndexToken(t) && !isNameToken(t))
      return fail("'" + t + "' is neither a key name nor a list position (1, 2, ...)");
  std::string problem;
  Node* node = topBlock(root, tokens[0], problem);
  if (!node) return fail(problem);
  if (auto p = setPath(node, tokens, assignment.substr(eq + 1))) fail(*p);
}

}  // namespace rb::scenario
