#pragma once
// --set overrides: "block.key=value", "block.list[2].key=value" or "block.list.2.key=value"
// applied to the scenario tree after the script ran and before validation, so an override is
// checked exactly like a value written in the file (reported at <command line>).
//
// Named parameters: in a list of named tables (vehicle.bodies, vehicle.elements) a token that is
// not a list position selects the item with that name, vehicle.elements.prim_x_ws1_l.stiffness;
// vehicle.groups.GROUP.KEY sets KEY in every element of the group (the vehicle's
// groups = { GROUP = { "name", "prim_x_*", ... } }, element names or globs with '*').
#include <optional>
#include <string>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/scenario/node.hpp"

namespace rb::scenario {

// Where a --set override is written when it comes from the command line.
inline const SourceLoc kCommandLineLoc{"<command line>", 0};

// The value of an override: a number, true/false, or a string (quotes around it are removed).
// `loc` is where it is written: the validator reports a bad value there.
Node parseOverrideValue(const std::string& text, const SourceLoc& loc = kCommandLineLoc);

// Applies one "path=value" to `root`; problems are added to `d` at <command line>.
void applyOverride(Node& root, const std::string& assignment, Diagnostics& d);
// The same for an override written in a file (a study's matrix value or case entry): the value
// and every problem with it are located at `loc` (an empty loc.file means the command line).
void applyOverride(Node& root, const std::string& assignment, const SourceLoc& loc, Diagnostics& d);

// Applies one "path=value" to `root` and returns what is wrong with it (without the "--set"
// prefix and location), nullopt when it was applied. The values and tables it adds carry `loc`.
std::optional<std::string> overrideProblem(Node& root, const std::string& assignment,
                                           const SourceLoc& loc = kCommandLineLoc);

// True when `name` matches the group pattern `pattern` ('*' stands for any run of characters).
bool globMatch(const std::string& pattern, const std::string& name);

// The name of a named table (its `name` string field), "" when it has none.
std::string itemName(const Node& item);

// One group of vehicle.groups resolved against the vehicle's elements.
struct GroupMembers {
  std::vector<std::size_t> elements;  // positions in vehicle.elements (0-based), list order
  std::vector<std::string> problems;  // a pattern matching nothing, a body named, a bad entry
};

// Members of the group `group` (a list of element names or globs) of the vehicle table `vehicle`.
GroupMembers groupMembers(const Node& vehicle, const Node& group);

// True when `name` can be a --set path token (letters, digits, _; not starting with a digit).
bool isParameterName(const std::string& name);

}  // namespace rb::scenario
