#include "workbench/assessment/sections.hpp"

#include <cctype>
#include <cmath>

#include "workbench/assessment/spec.hpp"

namespace rb::assessment {

TestZone testZone(double radius) {
  const double r = std::abs(radius);
  if (std::isnan(r)) return TestZone::None;
  if (r >= kZone1MinRadius) return TestZone::Zone1;
  if (r >= kZone2MinRadius) return TestZone::Zone2;
  if (r >= kZone3MinRadius) return TestZone::Zone3;
  if (r >= kZone4MinRadius) return TestZone::Zone4;
  return TestZone::Zone5;
}

bool validSectionName(const std::string& name) {
  if (name.empty() || name.size() > 64) return false;
  for (const char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  return true;
}

double trackShiftAlpha(VehicleCategory c) {
  return c == VehicleCategory::Freight ? 0.85 : 1.0;
}

}  // namespace rb::assessment
