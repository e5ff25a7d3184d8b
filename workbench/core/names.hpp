#pragma once
// One name table per enum that appears in scenario files and result files: the value, its name
// (the scenario keyword and the HDF5 attribute text) and a one-line help. The schema (choice
// lists and help), the scenario reader, the writers and the generated reference all read the same
// table, so a name is written once.
//
// A table is declared next to its enum (or in the module's names.hpp) as
//   inline constexpr std::array<rb::NameEntry<E>, N> kSomethingNames = {{...}};
//   constexpr const auto& nameTable(E) { return kSomethingNames; }
// and found by argument-dependent lookup from the generic helpers below.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rb {

template <class E>
struct NameEntry {
  E value;
  std::string_view name;
  std::string_view help;
};

// The name of `e` in its table; "?" for a value missing from the table (an internal error that the
// tests of every table rule out).
template <class E>
constexpr std::string_view nameOf(E e) {
  for (const auto& entry : nameTable(E{}))
    if (entry.value == e) return entry.name;
  return "?";
}

// The enum value named `name`; nullopt when the table has no such name.
template <class E>
constexpr std::optional<E> parse(std::string_view name) {
  for (const auto& entry : nameTable(E{}))
    if (entry.name == name) return entry.value;
  return std::nullopt;
}

// Every name of E in table order (the schema's choice list).
template <class E>
std::vector<std::string> namesOf() {
  std::vector<std::string> out;
  for (const auto& entry : nameTable(E{})) out.emplace_back(entry.name);
  return out;
}

// "name: help; name: help" of every entry with a help text (the schema's help of a choice).
template <class E>
std::string helpOf() {
  std::string out;
  for (const auto& entry : nameTable(E{})) {
    if (entry.help.empty()) continue;
    if (!out.empty()) out += "; ";
    out.append(entry.name).append(": ").append(entry.help);
  }
  return out;
}

}  // namespace rb
