#pragma once
// Typed, validated access to one block of a scenario tree (node.hpp) driven by its BlockSpec
// (schema.hpp): every value is checked against the key's type, range and choices, and every
// problem is added to the Diagnostics as file:line: block: message, so a scenario reports all of
// its problems at once. Unknown keys are reported when the Reader is made.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "workbench/core/error.hpp"
#include "workbench/core/names.hpp"
#include "workbench/scenario/node.hpp"
#include "workbench/scenario/schema.hpp"

namespace rb::scenario {

// x as the integer type T when it is finite and inside T's range, else T{}: a key's value outside
// its range is reported by Reader::number and never used, but converting it first would be
// undefined behaviour (a seed of -1 to std::uint64_t).
template <class T>
T toInteger(double x) {
  if (!(x >= static_cast<double>(std::numeric_limits<T>::min()) &&
        x < static_cast<double>(std::numeric_limits<T>::max())))
    return T{};
  return static_cast<T>(x);
}

class Reader {
 public:
  Reader(const Node& node, const BlockSpec& spec, std::string path, Diagnostics& d);

  const std::string& path() const { return path_; }
  const SourceLoc& loc() const { return node_.loc; }
  void error(const Node& at, const std::string& msg) { d_.add(at.loc, label_ + ": " + msg); }
  void errorAt(const SourceLoc& loc, const std::string& msg) { d_.add(loc, label_ + ": " + msg); }

  // The value of a key, nullptr if absent or nil (a missing required key is an error).
  const Node* value(const std::string& name);
  // A number in the key's range (its default if absent or wrong).
  double number(const std::string& name);
  // One of the key's choices (its default if absent or wrong).
  std::string choice(const std::string& name);
  // A choice as the enum value of its name table (core/names.hpp).
  template <class E>
  E choiceOf(const std::string& name) {
    return parse<E>(choice(name)).value_or(E{});
  }
  std::string string(const std::string& name);
  // {min, max} with min < max, both in the key's range; false if absent or malformed.
  bool pair(const std::string& name, double& a, double& b);
  // A nested constructor block (kinds) or plain table (sub); nullptr if absent or wrong.
  const Node* blockValue(const std::string& name);
  // A list of constructor blocks of the key's kinds (wrong entries are reported and skipped).
  std::vector<const Node*> blockList(const std::string& name);
  // A list of the key's choices; all of them if absent.
  std::vector<std::string> stringList(const std::string& name);
  bool boolean(const std::string& name);
  // {x, y, z}: true when present and well-formed (out stays zero otherwise).
  bool vec3(const std::string& name, Eigen::Vector3d& out);
  // {{a, b}, ...}: fills a and b; false if absent or malformed.
  bool pairList(const std::string& name, std::vector<double>& a, std::vector<double>& b);
  // A list of free-form names {"a", "b"} (checked later against the model).
  std::vector<std::string> names(const std::string& name);
  bool has(const std::string& name) const;

 private:
  const KeySpec& key(const std::string& name) const;
  void checkRange(const Node& at, const KeySpec& k, double x);

  const Node& node_;
  const BlockSpec& spec_;
  std::string path_;
  std::string label_;
  Diagnostics& d_;
};

}  // namespace rb::scenario
