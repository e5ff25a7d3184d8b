#pragma once
// Specs shared by the vehicle tests: tracks, and a C++ copy of
// scenarios/vehicles/manchester_wagon1.lua (tests compare the two).
#include <string>
#include <vector>

#include "workbench/track/spec.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/spec.hpp"

namespace rbtest {

using rb::vehicle::BodyKind;
using rb::vehicle::BodySpec;
using rb::vehicle::Direction;
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

inline BodySpec body(const std::string& name, BodyKind kind, double mass, Eigen::Vector3d inertia,
                     double x, double height, int line) {
  BodySpec b;
  b.name = name;
  b.kind = kind;
  b.mass = mass;
  b.inertia = inertia;
  b.x = x;
  b.height = height;
  b.loc = {"wagon.lua", line};
  return b;
}

inline ElementSpec element(const std::string& name, ElementKind kind, const std::string& from,
                           const std::string& to, Eigen::Vector3d at_from, Eigen::Vector3d at_to,
                           Direction dir, int line) {
  ElementSpec e;
  e.name = name;
  e.kind = kind;
  e.body1 = from;
  e.body2 = to;
  e.point1 = at_from;
  e.point2 = at_to;
  e.direction = dir;
  e.loc = {"wagon.lua", line};
  return e;
}

// C++ twin of scenarios/vehicles/manchester_wagon1.lua (same order, names and numbers).
inline VehicleSpec manchesterFixture(double speed = 20.0, double start = 0.0) {
  const double h_car = 1.8, h_bogie = 0.6, r0 = 0.46, h_sec = 0.8275, h_bump = 0.65;
  const double a_bogie = 9.5, a_axle = 1.28, b_prim = 1.0, b_sec = 1.0;
  const std::vector<double> td = {0, 0.025, 0.030, 0.035, 0.040, 0.045, 0.050, 0.055, 0.060, 0.065};
  const std::vector<double> tf = {0, 0, 600, 1760, 3730, 6870, 11580, 17170, 29200, 230000};
  VehicleSpec v;
  v.name = "manchester_wagon1";
  v.speed = speed;
  v.wheel_radius = r0;
  v.start = start;
  v.loc = {"wagon.lua", 1};
  v.bodies.push_back(body("car", BodyKind::CarBody, 32000, {56800, 1970000, 1970000}, 0, h_car, 2));
  int line = 10;
  for (int b = 1; b <= 2; ++b) {
    const double xb = b == 1 ? a_bogie : -a_bogie;
    const std::string bogie = "bogie" + std::to_string(b);
    v.bodies.push_back(body(bogie, BodyKind::Bogie, 2615, {1722, 1476, 3067}, xb, h_bogie, line++));
    for (int a = 1; a <= 2; ++a) {
      const double xa = a == 1 ? a_axle : -a_axle;
      const std::string ws = "ws" + std::to_string(2 * (b - 1) + a);
      v.bodies.push_back(
          body(ws, BodyKind::Wheelset, 1813, {1120, 112, 1120}, xb + xa, r0, line++));
      for (const auto& [tag, sy] : {std::pair<const char*, double>{"l", 1.0}, {"r", -1.0}}) {
        const Eigen::Vector3d at_b(xa, sy * b_prim, r0 - h_bogie), at_w(0, sy * b_prim, 0);
        auto z = element("prim_z_" + ws + "_" + tag, ElementKind::SeriesSpringDamper, bogie, ws,
                         at_b, at_w, Direction::Z, line++);
        z.stiffness = 1220e3;
        z.damping = 4e3;
        z.series_stiffness = 1000e3;
        v.elements.push_back(z);
        auto x = element("prim_x_" + ws + "_" + tag, ElementKind::SpringDamper, bogie, ws, at_b,
                         at_w, Direction::X, line++);
        x.stiffness = 31391e3;
        x.damping = 15e3;
        v.elements.push_back(x);
        auto y = element("prim_y_" + ws + "_" + tag, ElementKind::SpringDamper, bogie, ws, at_b,
                         at_w, Direction::Y, line++);
        y.stiffness = 3884e3;
        y.damping = 2e3;
        v.elements.push_back(y);
      }
    }
    const auto at_car = [&](double y, double h) { return Eigen::Vector3d(xb, y, h - h_car); };
    const auto at_bg = [&](double y, double h) { return Eigen::Vector3d(0, y, h - h_bogie); };
    for (const auto& [tag, sy] : {std::pair<const char*, double>{"l", 1.0}, {"r", -1.0}}) {
      const Eigen::Vector3d pc = at_car(sy * b_sec, h_sec), pb = at_bg(sy * b_sec, h_sec);
      auto z = element("sec_z_" + bogie + "_" + tag, ElementKind::SeriesSpringDamper, "car", bogie,
                       pc, pb, Direction::Z, line++);
      z.stiffness = 430e3;
      z.damping = 4e3;
      z.series_stiffness = 1000e3;
      v.elements.push_back(z);
      auto sx = element("sec_shear_x_" + bogie + "_" + tag, ElementKind::ShearSpring, "car", bogie,
                        pc, pb, Direction::X, line++);
      sx.stiffness = 160e3;
      v.elements.push_back(sx);
      auto sy2 = element("sec_shear_y_" + bogie + "_" + tag, ElementKind::ShearSpring, "car", bogie,
                         pc, pb, Direction::Y, line++);
      sy2.stiffness = 160e3;
      v.elements.push_back(sy2);
      auto bend = element("sec_bend_" + bogie + "_" + tag, ElementKind::BendingSpring, "car", bogie,
                          pc, pb, Direction::Z, line++);
      bend.stiffness = 10.5e3;
      v.elements.push_back(bend);
      auto lat = element("sec_y_" + bogie + "_" + tag, ElementKind::SeriesSpringDamper, "car", bogie,
                         pc, pb, Direction::Y, line++);
      lat.series_stiffness = 6000e3;
      lat.damping = 32e3;
      v.elements.push_back(lat);
    }
    auto lon = element("sec_x_" + bogie, ElementKind::SpringDamper, "car", bogie, at_car(0, h_sec),
                       at_bg(0, h_sec), Direction::X, line++);
    lon.stiffness = 5000e3;
    lon.damping = 25e3;
    v.elements.push_back(lon);
    auto bump = element("bump_y_" + bogie, ElementKind::Bumpstop, "car", bogie, at_car(0, h_bump),
                        at_bg(0, h_bump), Direction::Y, line++);
    bump.table_d = td;
    bump.table_f = tf;
    v.elements.push_back(bump);
  }
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
