#include "workbench/scenario/reader.hpp"

#include <cmath>

#include "workbench/core/strings.hpp"

namespace rb::scenario {
namespace {

std::string unitText(const KeySpec& k) {
  return (k.unit.empty() || k.unit == "-") ? std::string() : " [" + k.unit + "]";
}

bool isKind(const Node& n, const KeySpec& k) {
  for (const auto& kind : k.kinds)
    if (n.kind == kind) return true;
  return false;
}

std::string expected(const KeySpec& k) {
  if (k.kinds.empty()) return "a table { ... }";
  std::string s;
  for (std::size_t i = 0; i < k.kinds.size(); ++i)
    s += (i ? (i + 1 == k.kinds.size() ? " or " : ", ") : "") + k.kinds[i] + "{...}";
  return s;
}

bool isChoice(const KeySpec& k, const std::string& s) {
  for (const auto& c : k.choices)
    if (c == s) return true;
  return false;
}

bool isNumberPair(const Node& v) {
  return v.type == Node::Type::Table && v.items.size() == 2 && v.fields.empty() &&
         v.items[0].type == Node::Type::Number && v.items[1].type == Node::Type::Number;
}

}  // namespace

Reader::Reader(const Node& node, const BlockSpec& spec, std::string path, Diagnostics& d)
    : node_(node), spec_(spec), path_(std::move(path)), d_(d) {
  label_ = path_;
  if (!node.kind.empty() && node.kind != path_) label_ += " (" + node.kind + ")";
  for (const auto& [k, v] : node.fields) {
    if (spec.key(k)) continue;
    std::string msg = "unknown key '" + k + "'";
    std::string hint = closestMatch(k, spec.keyNames());
    if (!hint.empty())
      msg += " (did you mean '" + hint + "'?)";
    else
      msg += " (valid keys: " + join(spec.keyNames(), ", ") + ")";
    error(v, msg);
  }
  if (!node.items.empty())
    error(node, "expects named values (key = value), not a list of " +
                    std::to_string(node.items.size()) + " entries");
}

const Node* Reader::value(const std::string& name) {
  const KeySpec& k = key(name);
  const Node* v = node_.field(name);
  if (v && v->type == Node::Type::Nil) v = nullptr;
  if (!v && k.required) error(node_, "missing required key '" + name + "'");
  return v;
}

double Reader::number(const std::string& name) {
  const KeySpec& k = key(name);
  const Node* v = value(name);
  if (!v) return k.num_default;
  if (v->type != Node::Type::Number) {
    error(*v, name + " must be a number" + unitText(k) + ", got " + v->describe());
    return k.num_default;
  }
  checkRange(*v, k, v->number);
  if (k.type == ValueType::Integer && v->number != std::floor(v->number))
    error(*v, name + " must be a whole number, got " + formatNumber(v->number));
  return v->number;
}

std::string Reader::choice(const std::string& name) {
  const KeySpec& k = key(name);
  const Node* v = value(name);
  if (!v) return k.def;
  if (v->type != Node::Type::String) {
    error(*v, name + " must be one of " + join(k.choices, ", ") + "; got " + v->describe());
    return k.def;
  }
  if (isChoice(k, v->string)) return v->string;
  std::string msg = name + ": unknown value '" + v->string + "'";
  std::string hint = closestMatch(v->string, k.choices);
  if (!hint.empty()) msg += " (did you mean '" + hint + "'?)";
  msg += "; valid: " + join(k.choices, ", ");
  error(*v, msg);
  return k.def;
}

std::string Reader::string(const std::string& name) {
  const Node* v = value(name);
  if (!v) return {};
  if (v->type != Node::Type::String) {
    error(*v, name + " must be a string, got " + v->describe());
    return {};
  }
  return v->string;
}

bool Reader::pair(const std::string& name, double& a, double& b) {
  const KeySpec& k = key(name);
  const Node* v = value(name);
  if (!v) return false;
  if (!isNumberPair(*v)) {
    error(*v,
          name + " must be a pair of numbers {min, max}" + unitText(k) + ", got " + v->describe());
    return false;
  }
  a = v->items[0].number;
  b = v->items[1].number;
  checkRange(*v, k, a);
  checkRange(*v, k, b);
  if (!(a < b))
    error(*v, name + " must be {min, max} with min < max, got {" + formatNumber(a) + ", " +
                  formatNumber(b) + "}");
  return true;
}

const Node* Reader::blockValue(const std::string& name) {
  const KeySpec& k = key(name);
  const Node* v = value(name);
  if (!v) return nullptr;
  if (v->type != Node::Type::Table || (!k.kinds.empty() && !isKind(*v, k))) {
    error(*v, name + " must be " + expected(k) + ", got " + v->describe());
    return nullptr;
  }
  return v;
}

std::vector<const Node*> Reader::blockList(const std::string& name) {
  const KeySpec& k = key(name);
  const Node* v = value(name);
  std::vector<const Node*> out;
  if (!v) return out;
  if (v->type != Node::Type::Table || !v->fields.empty()) {
    error(*v, name + " must be a list of " + expected(k) + ", got " + v->describe());
    return out;
  }
  if (v->items.empty()) error(*v, name + " must not be empty");
  for (std::size_t i = 0; i < v->items.size(); ++i) {
    const Node& item = v->items[i];
    if (item.type != Node::Type::Table || !isKind(item, k)) {
      error(item, name + "[" + std::to_string(i + 1) + "] must be " + expected(k) + ", got " +
                      item.describe());
      continue;
    }
    out.push_back(&item);
  }
  return out;
}

std::vector<std::string> Reader::stringList(const std::string& name) {
  const KeySpec& k = key(name);
  const Node* v = value(name);
  std::vector<std::string> out;
  if (!v) return k.choices;
  if (v->type != Node::Type::Table || !v->fields.empty()) {
    error(*v, name + " must be a list of names from: " + join(k.choices, ", "));
    return out;
  }
  for (const auto& item : v->items) {
    if (item.type == Node::Type::String && isChoice(k, item.string)) {
      out.push_back(item.string);
      continue;
    }
    std::string msg = name + ": unknown entry " + item.describe();
    if (item.type == Node::Type::String) {
      std::string hint = closestMatch(item.string, k.choices);
      if (!hint.empty()) msg += " (did you mean '" + hint + "'?)";
    }
    error(item, msg + "; valid: " + join(k.choices, ", "));
  }
  return out;
}

bool Reader::boolean(const std::string& name) {
  const KeySpec& k = key(name);
  const Node* v = value(name);
  if (!v) return k.num_default != 0.0;
  if (v->type != Node::Type::Bool) {
    error(*v, name + " must be true or false, got " + v->describe());
    return k.num_default != 0.0;
  }
  return v->boolean;
}

bool Reader::vec3(const std::string& name, Eigen::Vector3d& out) {
  const KeySpec& k = key(name);
  const Node* v = value(name);
  out.setZero();
  if (!v) return false;
  bool ok = v->type == Node::Type::Table && v->fields.empty() && v->items.size() == 3;
  for (std::size_t i = 0; ok && i < 3; ++i) ok = v->items[i].type == Node::Type::Number;
  if (!ok) {
    error(*v, name + " must be {x, y, z} of numbers" + unitText(k) + ", got " + v->describe());
    return false;
  }
  for (int i = 0; i < 3; ++i) out[i] = v->items[static_cast<std::size_t>(i)].number;
  if (!out.allFinite()) {
    error(*v, name + " must be finite");
    return false;
  }
  return true;
}

bool Reader::pairList(const std::string& name, std::vector<double>& a, std::vector<double>& b) {
  const Node* v = value(name);
  if (!v) return false;
  if (v->type != Node::Type::Table || !v->fields.empty() || v->items.empty()) {
    error(*v, name + " must be a list of pairs {{a, b}, ...}, got " + v->describe());
    return false;
  }
  for (std::size_t i = 0; i < v->items.size(); ++i) {
    const Node& p = v->items[i];
    if (!isNumberPair(p)) {
      error(*v, name + "[" + std::to_string(i + 1) + "] must be a pair of numbers {a, b}");
      return false;
    }
    a.push_back(p.items[0].number);
    b.push_back(p.items[1].number);
  }
  return true;
}

std::vector<std::string> Reader::names(const std::string& name) {
  const Node* v = value(name);
  std::vector<std::string> out;
  if (!v) return out;
  if (v->type != Node::Type::Table || !v->fields.empty()) {
    error(*v, name + " must be a list of names {\"a\", \"b\"}, got " + v->describe());
    return out;
  }
  for (const auto& item : v->items) {
    if (item.type != Node::Type::String) {
      error(item, name + ": entries must be strings, got " + item.describe());
      continue;
    }
    out.push_back(item.string);
  }
  return out;
}

bool Reader::has(const std::string& name) const {
  const Node* v = node_.field(name);
  return v && v->type != Node::Type::Nil;
}

const KeySpec& Reader::key(const std::string& name) const {
  const KeySpec* k = spec_.key(name);
  RB_CHECK(k != nullptr, "schema of '" + spec_.name + "' has no key '" + name + "'");
  return *k;
}

void Reader::checkRange(const Node& at, const KeySpec& k, double x) {
  if (const auto problem = rangeProblem(k, x)) error(at, k.name + " must be " + *problem);
}

}  // namespace rb::scenario
