#pragma once
// A scenario as a plain tree of values, converted from Lua tables once the script has run. The
// validator and spec builders work on this tree, so nothing below scenario/ sees Lua. A Lua
// function value (e.g. a user PSD) is kept as a callable that evaluates it with one number.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "workbench/core/error.hpp"

namespace rb::scenario {

struct Node {
  // Declared so that clang 14 with libstdc++ 12 in C++20 accepts the pair of a still-incomplete
  // Node in `fields` (it otherwise checks pair's conditional explicit constructor too early).
  Node() = default;
  enum class Type { Nil, Bool, Number, String, Table, Function };
  Type type = Type::Nil;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<std::pair<std::string, Node>> fields;  // named entries, sorted by name
  std::vector<Node> items;                           // array part, Lua index 1..n
  std::string kind;  // constructor that made this table ("track", "curve", ...); "" if plain
  SourceLoc loc;     // where the constructor was called (plain tables inherit their parent's)
  // For Type::Function: evaluates the Lua function with one number (throws InputError).
  std::shared_ptr<std::function<double(double)>> function;

  const Node* field(const std::string& name) const;
  Node* field(const std::string& name);
  Node& setField(const std::string& name, Node value);
  static const char* typeName(Type t);
  std::string describe() const;  // "number 3", "string \"abc\"", "table", ...
};

// Every text of the tree (string values and keys) that holds a NUL byte, as "path must not hold
// a NUL byte" at its file:line. A C library call cuts a name at its first NUL, so "a.txt\0b"
// would open a.txt: a file the scenario does not name. `path` names `n` ("" for the root).
void reportNulBytes(const Node& n, const std::string& path, Diagnostics& d);

// `text` with each NUL byte written as \0, for messages (a raw NUL would cut them too).
std::string showNul(const std::string& text);

}  // namespace rb::scenario
