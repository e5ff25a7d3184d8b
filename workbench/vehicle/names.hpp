#pragma once
// Names of the vehicle's enums (scenario keywords of body{} and the element constructors, HDF5
// attributes of /bodies and /elements), one table per enum of vehicle/spec.hpp
// (core/names.hpp).
#include <array>

#include "workbench/core/names.hpp"
#include "workbench/vehicle/spec.hpp"

namespace rb::vehicle {

inline constexpr std::array<NameEntry<BodyKind>, 4> kBodyKindNames = {{
    {BodyKind::CarBody, "car", "car body"},
    {BodyKind::Bogie, "bogie", "bogie frame"},
    {BodyKind::Wheelset, "wheelset", "wheelset"},
    {BodyKind::Frame, "frame", "a frame that follows the track centreline kinematically"},
}};
constexpr const auto& nameTable(BodyKind /*tag*/) {
  return kBodyKindNames;
}

// Constructor names of the suspension elements (Appendix A); the schema holds each one's keys.
inline constexpr std::array<NameEntry<ElementKind>, 5> kElementKindNames = {{
    {ElementKind::SpringDamper, "spring_damper", "spring and damper in parallel"},
    {ElementKind::SeriesSpringDamper, "series_damper", "damper in series with a spring"},
    {ElementKind::ShearSpring, "shear_spring", "shear spring"},
    {ElementKind::BendingSpring, "bending_spring", "bending spring"},
    {ElementKind::Bumpstop, "bumpstop", "nonlinear bumpstop"},
}};
constexpr const auto& nameTable(ElementKind /*tag*/) {
  return kElementKindNames;
}

inline constexpr std::array<NameEntry<Direction>, 4> kDirectionNames = {{
    {Direction::Axial, "axial", "along the line between the points (Eq. 30)"},
    {Direction::X, "x",
     "longitudinal component of the relative displacement in the master track "
     "frame (bending: rotation axis)"},
    {Direction::Y, "y", "lateral component (bending: rotation axis)"},
    {Direction::Z, "z", "vertical component (bending: rotation axis)"},
}};
constexpr const auto& nameTable(Direction /*tag*/) {
  return kDirectionNames;
}

}  // namespace rb::vehicle
