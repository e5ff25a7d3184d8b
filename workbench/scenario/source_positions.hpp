#pragma once
// Where the entries of a Lua table constructor are written in the source text.
//
// Lua keeps no line for the fields of a table: a constructor call (run { ... }) knows the line of
// the call, a plain table (assessment = { alpha = 5 }) nothing at all. So that a problem with a
// key is reported at the key's own line, the converter (lua_host.cpp) reads the constructor's
// text: the entries at the top level of `{ ... }` (name = value, ["name"] = value, or a
// positional value) with the offset where each value starts, and recurses into values that are
// themselves written as `{ ... }`.
//
// This reads the text as written, not the table the script built: a key the script set in code
// (t.alpha = 5) or a table passed through a variable has no entry here, and the caller keeps the
// enclosing location for it. Lua's lexical rules that matter for nesting are honoured: strings
// ('..', "..", with escapes), long strings and comments ([[..]], [==[..]==], --[[..]], -- to the
// end of the line) and brackets ( [ {. Work is linear in the length of the scanned table.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rb::scenario {

struct TableEntries {
  std::vector<std::pair<std::string, std::size_t>> fields;  // key -> offset of its value
  std::vector<std::size_t> items;  // offsets of the positional values, in order (Lua index 1..)
};

// The entries of the table constructor whose '{' is at `open` (text[open] must be '{'); nullopt
// when the text there is not a complete constructor.
std::optional<TableEntries> scanTable(std::string_view text, std::size_t open);

// The offset of the '{' of a call `kind { ... }` or `kind({ ... })` written on line `line`
// (1-based), when exactly one such call of `kind` is on that line (two on one line are
// ambiguous); nullopt otherwise.
std::optional<std::size_t> constructorBrace(std::string_view text, int line,
                                            const std::string& kind);

// The 1-based line of `offset`, from a table of line starts (lineStarts(text)).
std::vector<std::size_t> lineStarts(std::string_view text);
int lineOf(const std::vector<std::size_t>& starts, std::size_t offset);

}  // namespace rb::scenario
