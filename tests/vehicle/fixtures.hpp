#pragma once
// Shared by the vehicle tests: synthetic tracks, and the Manchester wagon loaded from
// scenarios/vehicles/manchester_wagon1.lua through tests/vehicle/data/manchester_tangent.lua (the
// Lua file is the only copy of the wagon data).
#include <string>

#include "workbench/scenario/scenario.hpp"
#include "workbench/track/spec.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/spec.hpp"

namespace rbtest {

using rb::vehicle::ElementKind;
using rb::vehicle::ElementSpec;
using rb::vehicle::VehicleSpec;

inline rb::track::SegmentSpec segment(rb::track::SegmentKind kind, double length, double radius = 0,
                                      rb::track::Side side = rb::track::Side::Left, double cant = 0,
                                      double gradient = 0) {
  rb::track::SegmentSpec s;
  s.kind = kind;
  s.length = length;
  s.radius = radius;
  s.side = side;
  s.cant = cant;
  s.gradient = gradient;
  s.loc = {"track.lua", 3};
  return s;
}

inline rb::track::TrackSpec tangentTrack(double length = 300.0) {
  rb::track::TrackSpec t;
  t.segments = {segment(rb::track::SegmentKind::Tangent, length)};
  t.loc = {"track.lua", 1};
  return t;
}

// Tangent, clothoid with cant ramp, constant canted curve (to `side`), then a long curve.
inline rb::track::TrackSpec curveTrack(rb::track::Side side, double radius, double cant,
                                       double tangent = 40.0, double transition = 60.0,
                                       double curve = 400.0, double gradient = 0.0) {
  using K = rb::track::SegmentKind;
  rb::track::TrackSpec t;
  t.segments = {segment(K::Tangent, tangent),
                segment(K::Transition, transition, radius, side, cant, gradient),
                segment(K::Curve, curve, radius, side, cant, gradient)};
  t.step = 0.5;
  t.loc = {"track.lua", 1};
  return t;
}

// A scenario file of tests/vehicle/data, loaded with the project root as the Lua search root.
inline rb::scenario::ScenarioSpec loadTestScenario(const std::string& file) {
  rb::scenario::LoadOptions o;
  o.root = RB_SOURCE_DIR;
  return rb::scenario::loadScenario(std::string(RB_SOURCE_DIR) + "/tests/vehicle/data/" + file, o);
}

// The Manchester wagon of scenarios/vehicles/manchester_wagon1.lua (loaded once) with the given
// speed and start (the file's `speed` and `start` options set exactly these two fields).
inline VehicleSpec manchesterWagon(double speed = 20.0, double start = 0.0) {
  static const VehicleSpec wagon = loadTestScenario("manchester_tangent.lua").vehicle;
  VehicleSpec v = wagon;
  v.speed = speed;
  v.start = start;
  return v;
}

// The wagon without dampers: damping 0, series dampers reduced to their parallel spring.
inline VehicleSpec withoutDampers(VehicleSpec v) {
  for (ElementSpec& e : v.elements) {
    e.damping = 0.0;
    if (e.kind == ElementKind::SeriesSpringDamper) {
      e.kind = ElementKind::SpringDamper;
      e.series_stiffness = 0.0;
    }
  }
  return v;
}

}  // namespace rbtest
