#pragma once
// Nominal dimensions measured on a Profile (EN 13715 wheel flange measures, rail head width).
// Computed from the profile, not tabulated: they check the profile geometry.
//
// Wheel (left or right; the flange side is found as the side of the highest point, the flange tip):
// - flange height Sh: flange tip above the tape circle (S1002: 28 mm);
// - flange thickness Sd: from the back of the flange to the flange face, measured 10 mm above the
//   tape circle (S1002: 32.5 mm); the flange back lies flangeBackDistance from the tape circle
//   toward the flange (S1002: 70 mm; the profile itself stops short of the vertical flange back);
// - qR: lateral distance between the face point 10 mm above the tape circle and the face point
//   2 mm below the flange tip (S1002: 10.8 mm).
// Rail: head width between the two points where the head side reaches the side slope (60E1: the
// 1:20 side, 72 mm).
#include <optional>

#include "workbench/profiles/profile.hpp"

namespace rb::profiles {

struct WheelDimensions {
  double flangeHeight = 0.0;     // Sh [m]
  double flangeThickness = 0.0;  // Sd [m]
  double qR = 0.0;               // [m]
  double flangeTipS = 0.0;       // s of the flange tip
  double sdPointS = 0.0;         // s of the face point 10 mm above the tape circle
  double qrPointS = 0.0;         // s of the face point 2 mm below the tip
};

inline constexpr double kSdHeight = 0.010;    // [m] Sd measured 10 mm above the tape circle
inline constexpr double kQrBelowTip = 0.002;  // [m] qR upper point 2 mm below the flange tip

// tapeCircleS: profile parameter of the tape circle (0 for the built-in profiles).
WheelDimensions wheelDimensions(const Profile& wheel, double flangeBackDistance = 0.070,
                                double tapeCircleS = 0.0);
// The same for a profile that may have no flange, or not reach the tape circle (a file read from
// the user): nullopt instead of an internal error.
std::optional<WheelDimensions> measureWheel(const Profile& wheel, double flangeBackDistance = 0.070,
                                            double tapeCircleS = 0.0);
double flangeHeight(const Profile& wheel, double tapeCircleS = 0.0);
double flangeThickness(const Profile& wheel, double flangeBackDistance = 0.070,
                       double tapeCircleS = 0.0);
double flangeQR(const Profile& wheel, double tapeCircleS = 0.0);

// Width between the outermost points, on either side of the highest point, up to which
// |h'(s)| < sideSlope (the start of the straight side). 60E1: sideSlope 20.
double railHeadWidth(const Profile& rail, double sideSlope = 20.0);

}  // namespace rb::profiles
