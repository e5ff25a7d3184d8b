#pragma once
// Number formatting for input-error messages (internal to the track module).
#include <charconv>
#include <cstdio>
#include <string>

namespace rb::track::detail {

// Shortest text that reads back to the same double ("-500", "0.1", "1e-07"): echoes user input.
inline std::string num(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

// Four significant digits, for derived values and limits ("0.003333").
inline std::string num4(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

}  // namespace rb::track::detail
