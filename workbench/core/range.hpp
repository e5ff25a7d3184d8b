#pragma once
// A closed, open or half-open interval of admissible values of one input parameter. The scenario
// schema states each key's range with it, and a compiled module that guards its own inputs (for
// callers that build their Specs without a scenario) checks the same constant, so a range is
// written once.
#include <cmath>
#include <limits>
#include <string>

#include "workbench/core/strings.hpp"

namespace rb {

struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;  // min < value rather than min <= value
  bool max_exclusive = false;  // value < max rather than value <= max

  // False for NaN and infinities.
  bool contains(double x) const {
    const bool above = min_exclusive ? x > min : x >= min;
    const bool below = max_exclusive ? x < max : x <= max;
    return std::isfinite(x) && above && below;
  }
  // "[0, 0.5]", "(0, 1)", "[1e+09, 1e+12]", "(0, inf)"
  std::string text() const {
    return std::string(min_exclusive ? "(" : "[") + formatNumber(min) + ", " + formatNumber(max) +
           (max_exclusive || std::isinf(max) ? ")" : "]");
  }
};

}  // namespace rb
