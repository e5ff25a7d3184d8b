#pragma once
// S1002 wheel profile (EN 13715 / UIC 510-2) from its piecewise analytic definition, sections A-H
// (shared/reference/s1002_analytic_EN13715.md), and the smoothed Profile built from it.
//
// Units: the s1002* functions work in MILLIMETRES, in the EN 13715 coordinates: S [mm] lateral
// from the tape circle (S > 0 toward the field side / outer face, flange at S ~ -55 mm, flange back
// at S = -70 mm), F [mm] radius increase over the tape-circle radius (r = r0 + F, F(0) = 0, flange
// tip F = 28 mm at S = -55 mm). s1002Wheel() returns a Profile in SI (metres).
//
// Smoothing: the published coefficients make F jump by 1.2e-4 mm at the D/C joint (S = -35 mm)
// and 3.6e-5 mm at the C/B joint (S = -26 mm), with slope jumps of 4e-5 and 2e-5. s1002FSmooth()
// blends the two neighbouring sections with a C2 quintic step over a 2 mm window centred on each of
// these joints: F_s = (1 - w) F_left + w F_right. It is C2 there and stays within the size of the
// jump (< 1.2e-4 mm) of both published sections. All other joints are tangent-continuous by
// construction (arc/arc, arc/line); their curvature jumps are part of the design of S1002 and are
// kept (the cubic spline of the Profile spreads each jump over one grid step).
#include "workbench/profiles/profile.hpp"

namespace rb::profiles {

enum class S1002Section { A, B, C, D, E, F, G, H };

// Domain of the analytic definition [mm].
inline constexpr double kS1002SMinMm = -70.0;  // flange back (vertical tangent)
inline constexpr double kS1002SMaxMm = 60.0;   // outer (field-side) end of the tread
// Section boundaries [mm]: A|B, B|C, C|D, D|E, E|F, F|G, G|H.
inline constexpr double kS1002BreaksMm[7] = {
    32.15796, -26.0, -35.0, -38.426669071, -39.764473993, -49.662510381, -62.764705882};
// Half width of the blending windows at the D/C and C/B joints [mm].
inline constexpr double kS1002BlendHalfWidthMm = 1.0;

// Section holding S (S outside [-70, 60] maps to the end sections).
S1002Section s1002Section(double S_mm);
// The published sections, exactly as given (S and F in mm). Outside [-70, 60] the end sections are
// continued (the circle of section H is clamped at its vertical tangent, S = -70).
double s1002F(double S_mm);
double s1002dF(double S_mm);  // dF/dS [-]
// One published section evaluated at S (for continuity checks), outside its interval too when the
// formula allows it.
double s1002SectionF(S1002Section section, double S_mm);
double s1002SectionDF(S1002Section section, double S_mm);
// The blended, C2-at-the-published-jumps version used for the Profile (mm).
double s1002FSmooth(double S_mm);
double s1002dFSmooth(double S_mm);

// Profile domain [m]: from S = -69.62 mm (the benchmark file starts at -69.6126 mm; at the flange
// back S = -70 mm the tangent is vertical, so the profile is not a function of S there: h' ~ 5.1 at
// S = -69.62 mm) to S = +60 mm. The grid is aligned so that s = 0 (tape circle) is a knot.
inline constexpr double kS1002ProfileSMin = -0.06962;
inline constexpr double kS1002ProfileSMax = 0.060;
inline constexpr double kS1002DefaultStep = 2.0e-5;  // [m] grid step of the Profile (0.02 mm)

// The S1002 wheel profile for tape-circle radius r0 [m]. LEFT wheel: h(s) = r0 + F(S = s) with s
// in metres (s > 0 field side); RIGHT wheel: its exact mirror image h_r(s) = h_l(-s).
Profile s1002Wheel(double r0, WheelSide side, double ds = kS1002DefaultStep);

}  // namespace rb::profiles
