#pragma once
// "The same state" for what is kept per state (t, y): the same bits, not merely close values;
// anything else is another state.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>

namespace rb {

inline bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// (t, y[0 .. y_kept.size())) against (t_kept, y_kept), bit for bit.
inline bool sameState(double t, const double* y, double t_kept, std::span<const double> y_kept) {
  return sameBits(t, t_kept) && std::equal(y_kept.begin(), y_kept.end(), y, sameBits);
}

}  // namespace rb
