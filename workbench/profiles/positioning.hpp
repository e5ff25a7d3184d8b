#pragma once
// Placing the wheel and rail profiles (paper Table 1 and Eq. 5, 10; shared/reference/
// positioning.md): wheel profile frames at +-Lw from the wheelset centre, rail profile frames at
// +-Lr from the track centreline, the rail frames rotated by +-beta (+ delta).
//
// Both positions follow from measurable quantities:
// - Lw = B/2 + d_fb, with B the back-to-back distance of the wheels and d_fb the distance from the
//   back of the flange to the wheel profile origin (S1002: the tape circle, d_fb = 70 mm).
// - Lr = G/2 + |y_gp|, with G the track gauge measured between the gauge points and y_gp the
//   lateral offset of the gauge point from the rail profile origin, in the inclined rail frame.
//   The gauge point lies kGaugePointDepth = 14 mm below the highest point of the inclined head, on
//   its gauge side; for 60E1 at 1:40, |y_gp| = 35.53 mm (computed by gaugePoint(), not hard-coded).
#include <optional>
#include <vector>

#include "workbench/profiles/profile.hpp"

namespace rb::profiles {

struct ProfilePositioning {
  double Lw = 0.0;    // [m] wheel profile origin from the wheelset centre
  double Lr = 0.0;    // [m] rail profile origin from the track centreline
  double r0 = 0.0;    // [m] nominal rolling (tape-circle) radius
  double beta = 0.0;  // [rad] rail inclination
};

// The paper's Table 1. These numbers belong to its S1002 wheel on the LB-140-Area (AREA 140 lb)
// rail, whose head geometry is not public; with 60E1 they would imply B = 1363 mm and G ~ 1440 mm.
// beta is given as 1/40 rad in the paper (tan beta = 1/40 would be atan(1/40) = 0.0249948 rad).
namespace paper_table1 {
inline constexpr double kLw = 0.7515;        // [m]
inline constexpr double kLr = 0.7555;        // [m]
inline constexpr double kR0 = 0.457;         // [m]
inline constexpr double kBeta = 1.0 / 40.0;  // [rad]
inline constexpr ProfilePositioning kPositioning{kLw, kLr, kR0, kBeta};
}  // namespace paper_table1

// S1002: the tape circle (profile origin, S = 0) is 70 mm from the back of the flange (S = -70 mm).
inline constexpr double kS1002TapeCircleS = 0.0;           // [m] in the left-wheel profile frame
inline constexpr double kS1002FlangeBackS = -0.070;        // [m] in the left-wheel profile frame
inline constexpr double kS1002FlangeBackDistance = 0.070;  // [m] flange back to tape circle
inline constexpr double kGaugePointDepth = 0.014;  // [m] below the highest point of the rail

// ---- Rail profile in its rotated (inclined) frame -------------------------------------------
struct PlanePoint {
  double y = 0.0;  // [m] lateral, same direction as s at zero angle
  double z = 0.0;  // [m] up
};

// Angle of the rail profile frame in Eq. 5: +beta + delta (left rail), -beta + delta (right).
double railFrameAngle(RailSide side, double beta, double delta = 0.0);

// The rail profile point at s expressed in the frame rotated by `angle` about the profile origin
// (Eq. 4-6 without Lr and irregularities): y = s cos a - h sin a, z = s sin a + h cos a.
PlanePoint rotatedPoint(const Profile& rail, double s, double angle);
// All knots of the profile in the rotated frame (for plots and comparisons with canted files).
std::vector<PlanePoint> rotatedPoints(const Profile& rail, double angle);

// Highest point of the rotated profile: where h'(s) = -tan(angle).
struct TopPoint {
  double s = 0.0;  // profile parameter of the highest point
  PlanePoint p;    // its position in the rotated frame
};
TopPoint highestPoint(const Profile& rail, double angle);

// The gauge point of the rotated rail: `depth` below the highest point, on the gauge side (s < 0
// for the left rail, s > 0 for the right rail). Returns its position in the rotated frame (y < 0
// for the left rail) and, through s_out if given, its profile parameter.
PlanePoint gaugePoint(const Profile& rail, RailSide side, double angle,
                      double depth = kGaugePointDepth, double* s_out = nullptr);

// The inclination a rail profile is drawn with: the angle by which its points must be rotated
// (rotatedPoint) for the head to be symmetric about the vertical through its highest point,
// measured by the chord `depth` below the top (a rail head is symmetric about its axis, so an
// upright 60E1 gives 0 and a profile drawn at 1:40 about 0.025 in magnitude). nullopt when the
// profile does not reach `depth` on both sides of its top or no angle in +-0.06 rad makes it
// symmetric (not a rail head).
std::optional<double> drawnInclination(const Profile& rail, double depth = 0.008);

// ---- Positions ---------------------------------------------------------------------------------
// Lw = B/2 + flangeBackDistance, Lr = G/2 + gaugePointOffset (both offsets > 0).
ProfilePositioning positionProfiles(double backToBack, double gauge, double r0, double beta,
                                    double flangeBackDistance, double gaugePointOffset);
// S1002 on 60E1 inclined by beta: gauge point offset computed from the 60E1 head.
ProfilePositioning positionS1002On60E1(double backToBack, double gauge, double r0, double beta);
// |y| of the 60E1 gauge point at inclination beta (35.53 mm at 1:40).
double rail60E1GaugePointOffset(double beta, double depth = kGaugePointDepth);

// Where the wheel landmarks sit along Y of the wheelset frame (left side +Y).
struct WheelLandmarks {
  double tapeCircleY = 0.0;  // profile origin: +-Lw
  double flangeBackY = 0.0;  // +-(Lw - flangeBackDistance) = +-B/2
};
WheelLandmarks wheelLandmarks(const ProfilePositioning& pos, WheelSide side,
                              double flangeBackDistance = kS1002FlangeBackDistance);

}  // namespace rb::profiles
