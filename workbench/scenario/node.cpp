#include "workbench/scenario/node.hpp"

#include <algorithm>
#include <sstream>

namespace rb::scenario {

const Node* Node::field(const std::string& name) const {
  for (const auto& [k, v] : fields)
    if (k == name) return &v;
  return nullptr;
}

Node* Node::field(const std::string& name) {
  for (auto& [k, v] : fields)
    if (k == name) return &v;
  return nullptr;
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
      os << "number " << number;
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

}  // namespace rb::scenario
