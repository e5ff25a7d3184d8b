#pragma once
// --set overrides: "block.key=value", "block.list[2].key=value" or "block.list.2.key=value"
// applied to the scenario tree after the script ran and before validation, so an override is
// checked exactly like a value written in the file (reported at <command line>).
#include <string>

#include "workbench/core/error.hpp"
#include "workbench/scenario/node.hpp"

namespace rb::scenario {

// The value of an override: a number, true/false, or a string (quotes around it are removed).
Node parseOverrideValue(const std::string& text);

// Applies one "path=value" to `root`; problems are added to `d` at <command line>.
void applyOverride(Node& root, const std::string& assignment, Diagnostics& d);

}  // namespace rb::scenario
