#pragma once
// Spec builders shared by the track tests.
#include "workbench/track/spec.hpp"

namespace rbtest {

inline rb::track::SegmentSpec tangent(double length, int line = 10) {
  rb::track::SegmentSpec s;
  s.kind = rb::track::SegmentKind::Tangent;
  s.length = length;
  s.loc = {"t.lua", line};
  return s;
}

inline rb::track::SegmentSpec transition(double length, double radius,
                                         rb::track::Side side = rb::track::Side::Left,
                                         double cant = 0.0, int line = 11) {
  rb::track::SegmentSpec s;
  s.kind = rb::track::SegmentKind::Transition;
  s.length = length;
  s.radius = radius;
  s.side = side;
  s.cant = cant;
  s.loc = {"t.lua", line};
  return s;
}

inline rb::track::SegmentSpec curve(double length, double radius,
                                    rb::track::Side side = rb::track::Side::Left, double cant = 0.0,
                                    int line = 12) {
  rb::track::SegmentSpec s;
  s.kind = rb::track::SegmentKind::Curve;
  s.length = length;
  s.radius = radius;
  s.side = side;
  s.cant = cant;
  s.loc = {"t.lua", line};
  return s;
}

// Paper section 5.2, case 1: 30 m tangent + 50 m transition + 40 m left curve of radius R.
inline rb::track::TrackSpec paperCase1(double radius, double cant = 0.0) {
  rb::track::TrackSpec t;
  t.segments = {tangent(30.0), transition(50.0, radius, rb::track::Side::Left, cant),
                curve(40.0, radius, rb::track::Side::Left, cant)};
  t.step = 0.5;
  t.loc = {"t.lua", 1};
  t.irregularities.loc = {"t.lua", 20};
  return t;
}

// Paper section 5.2, case 2: 100 m tangent + 50 m transition + 350 m left curve, R = 500 m.
inline rb::track::TrackSpec paperCase2(double cant = 0.0) {
  rb::track::TrackSpec t;
  t.segments = {tangent(100.0), transition(50.0, 500.0, rb::track::Side::Left, cant),
                curve(350.0, 500.0, rb::track::Side::Left, cant)};
  t.step = 0.5;
  t.loc = {"t.lua", 1};
  t.irregularities.loc = {"t.lua", 20};
  return t;
}

}  // namespace rbtest
