#pragma once
// 60E1 (UIC60) rail head, EN 13674-1, from its arcs (shared/reference/rail_profiles.md): R300 crown
// for |y| <= 20.456/2, R80 to |y| = 52.053/2, R13 gauge corner until the side slope is 1:20, then
// the straight 1:20 head side. All arcs are tangent-continuous; the centres are derived here from
// these defining numbers (not copied).
//
// Units: the rail60E1* functions work in MILLIMETRES: y lateral from the rail centreline
// (symmetric), z up, z = 0 at the crown top of the UNINCLINED head. rail60E1() returns a Profile
// in SI (metres). The inclination beta is not applied: the rail profile frame rotation of Eq. 5
// does that (see positioning.hpp for the inclined-frame helpers).
#include "workbench/profiles/profile.hpp"

namespace rb::profiles {

struct Rail60E1Geometry {
  double crownRadius = 300.0;      // R300 [mm]
  double crownHalfWidth = 10.228;  // end of R300 [mm] (20.456 / 2)
  double shoulderRadius = 80.0;    // R80 [mm]
  double shoulderEnd = 26.0265;    // end of R80 [mm] (52.053 / 2)
  double cornerRadius = 13.0;      // R13 gauge corner [mm]
  double sideSlope = 20.0;         // head side 1:20: |dz/dy| = 20
  // Derived (tangent construction), y >= 0 half:
  double c2y = 0, c2z = 0;  // centre of R80
  double c3y = 0, c3z = 0;  // centre of R13
  double y1 = 0, z1 = 0;    // R300 / R80 tangent point
  double y2 = 0, z2 = 0;    // R80 / R13 tangent point
  double y3 = 0, z3 = 0;    // R13 / 1:20 side tangent point (half head width)
};
const Rail60E1Geometry& rail60E1Geometry();

// Exact head height z(y) and slope dz/dy of the uninclined head [mm], symmetric in y, including
// the 1:20 side for |y| > y3 (continued indefinitely).
double rail60E1Z(double y_mm);
double rail60E1dZ(double y_mm);

// Profile domain half width [m]: the rounded head (|y| <= y3 = 35.9998 mm) plus 0.25 mm of the
// 1:20 side (5 mm down the side), so the head width can be found from the Profile. Beyond that the
// side continues 1:20 into the R3 fillet and the head underside, where the head is no longer a
// function of s: not represented.
inline constexpr double kRail60E1HalfWidth = 0.03625;
inline constexpr double kRail60E1DefaultStep = 1.0e-5;  // [m] grid step (0.01 mm)

// The 60E1 head, uninclined: LEFT rail h(s) = z(y = s) (s > 0 field side, which is the same as
// the gauge side mirrored since the head is symmetric); RIGHT rail the exact mirror image.
Profile rail60E1(RailSide side, double ds = kRail60E1DefaultStep);

}  // namespace rb::profiles
