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

// The constructor of an external force (ExternalForceSpec). Not an ElementKind: it joins no two
// bodies and has no deformation; it is listed in vehicle.elements beside the suspension elements.
inline constexpr const char* kExternalForceKind = "external_force";

inline constexpr std::array<NameEntry<ForceFrame>, 2> kForceFrameNames = {{
    {ForceFrame::Track, "track",
     "the body's track frame: x along the track, y lateral (left +), z up from the track plane"},
    {ForceFrame::Body, "body", "the body's own frame (a wheelset: its axle-box frame)"},
}};
constexpr const auto& nameTable(ForceFrame /*tag*/) {
  return kForceFrameNames;
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
