#pragma once
// The scenario schema: every block, key, type, unit, range and default. The same tables drive
// validation (reader.hpp) and the generated reference (`workbench help scenario`), in the manner
// of Snort 3 / LOVE module schemas (architecture.md).
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace rb::scenario {

// contact.method for wheelsets that follow the track kinematically (no contact model; the other
// choices are dynamics::ContactMethod's names).
inline constexpr const char* kGuidedContact = "guided";

enum class ValueType {
  Number,   // real, SI unit in `unit`
  Integer,  // whole number
  String,   // free text (file names)
  Choice,   // one of `choices`
  Bool,
  Pair,        // {a, b} of numbers, a < b
  Block,       // a constructor call of one of `kinds`, or a plain table described by block `sub`
  BlockList,   // a list of constructor calls of `kinds`
  StringList,  // a list of `choices`
  PsdInput,    // a Lua function G(omega) or a table of {omega, G} pairs
  Vec3,        // {x, y, z} of numbers
  PairList,    // {{a, b}, ...} of numbers
  Table,       // a free-form table, read by the block's own builder
};

struct KeySpec {
  std::string name;
  ValueType type = ValueType::Number;
  std::string unit;  // SI unit, "-" for dimensionless
  std::string def;   // default as shown in help; empty for required or "none"
  std::string help;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;  // min < value rather than min <= value
  bool max_exclusive = false;  // value < max rather than value <= max
  bool required = false;
  // Values accepted outside [min, max]: a number that means "the default" rather than a
  // quantity (derailment_lift = -1). The valid set is the interval and these, so check, help
  // and the conformance test read them from here.
  std::vector<double> sentinels;
  std::vector<std::string> choices;      // Choice, StringList
  std::vector<std::string> choice_help;  // one line per choice (empty: none), from its name table
  std::vector<std::string> kinds;        // constructors allowed for Block, BlockList
  std::string sub;                       // Block given as a plain table: schema block name
  double num_default = 0.0;              // numeric default used by the reader
};

struct BlockSpec {
  std::string name;  // constructor name, or "run.output" for a plain sub-table
  std::string help;
  std::vector<KeySpec> keys;
  const KeySpec* key(const std::string& k) const;
  std::vector<std::string> keyNames() const;
};

const std::vector<BlockSpec>& schema();
const BlockSpec& block(const std::string& name);  // throws std::logic_error if unknown

// What is wrong with `x` as a value of the number key `k` ("finite, got inf", ">= 0 m, got -1",
// "< 1, got 1", "in [0.001, 0.1] m or -1, got -0.5"), nullopt when it lies in the key's range or
// is one of its sentinels: the one range check of the scenario.
std::optional<std::string> rangeProblem(const KeySpec& k, double x);
// The key's valid set as help prints it: "[0, 0.5]", "(0, inf)", "[0.001, 0.1] or -1"; empty
// for a key without bounds.
std::string rangeText(const KeySpec& k);

// Reference text of every block and key (workbench help scenario).
std::string referenceText();

}  // namespace rb::scenario
