#include "workbench/scenario/node.hpp"

#include <algorithm>
#include <sstream>

#include "workbench/core/strings.hpp"

namespace rb::scenario {

namespace {
// Fields are kept sorted by name, so a lookup is a binary search even in a table of many keys.
template <typename Fields>
auto findField(Fields& fields, const std::string& name) {
  auto it = std::lower_bound(fields.begin(), fields.end(), name,
                             [](const auto& kv, const std::string& n) { return kv.first < n; });
  return it != fields.end() && it->first == name ? &it->second : nullptr;
}
}  // namespace

const Node* Node::field(const std::string& name) const {
  return findField(fields, name);
}

Node* Node::field(const std::string& name) {
  return findField(fields, name);
}

Node& Node::setField(const std::string& name, Node value) {
  if (Node* existing = field(name)) {
    *existing = std::move(value);
    return *existing;
  }
  auto it = std::lower_bound(fields.begin(), fields.end(), name,
                             [](const auto& kv, const std::string& n) { return kv.first < n; });
  it = fields.emplace(it, name, std::move(value));
  return it->second;
}

const char* Node::typeName(Type t) {
  switch (t) {
    case Type::Nil:
      return "nil";
    case Type::Bool:
      return "boolean";
    case Type::Number:
      return "number";
    case Type::String:
      return "string";
    case Type::Table:
      return "table";
    case Type::Function:
      return "function";
  }
  return "?";
}

std::string Node::describe() const {
  std::ostringstream os;
  switch (type) {
    case Type::Number:
      os << "number " << formatNumber(number);
      break;
    case Type::String:
      os << "string \"" << string << "\"";
      break;
    case Type::Bool:
      os << "boolean " << (boolean ? "true" : "false");
      break;
    case Type::Table:
      if (!kind.empty())
        os << kind << "{...}";
      else
        os << "table";
      break;
    default:
      os << typeName(type);
  }
  return os.str();
}

std::string showNul(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text)
    if (c == '\0')
      out += "\\0";
    else
      out += c;
  return out;
}

void reportNulBytes(const Node& n, const std::string& path, Diagnostics& d) {
  const auto has = [](const std::string& s) { return s.find('\0') != std::string::npos; };
  const std::string here = path.empty() ? "scenario" : path;
  if (n.type == Node::Type::String && has(n.string))
    d.add(n.loc, here + " must not hold a NUL byte (\\0), got \"" + showNul(n.string) + "\"");
  for (const auto& [key, value] : n.fields) {
    const std::string sub = path.empty() ? key : path + "." + key;
    if (has(key))
      d.add(value.loc, here + ": the key \"" + showNul(key) + "\" must not hold a NUL byte (\\0)");
    reportNulBytes(value, showNul(sub), d);
  }
  for (std::size_t i = 0; i < n.items.size(); ++i)
    reportNulBytes(n.items[i], here + "[" + std::to_string(i + 1) + "]", d);
}

}  // namespace rb::scenario
