#pragma once
// The bound on the work of Lua's string pattern functions (find, match, gmatch, gsub) that the
// scenario host and the metric sandbox both enforce (lua_host.hpp explains the bound): a pattern
// whose worst case on its subject exceeds the budget is refused before it runs.
#include <cstddef>
#include <string_view>

namespace rb::scenario {

// Worst-case work of one call of a Lua pattern function on a subject of `subjectLen` bytes.
double patternWork(std::string_view pat, std::size_t subjectLen, bool anchorable);

// Whether `pat` has any magic character (a plain pattern is a plain search).
bool hasPatternSpecials(std::string_view pat);

}  // namespace rb::scenario
