#pragma once
// A wheel or rail profile as used by the contact geometry (paper section 2.2, Eq. 6 and 10,
// Fig. 6): a smooth function h(s) of the transverse surface parameter s in the profile's own frame,
// with first and second derivatives. Implemented as a cubic spline on a fine uniform grid built
// from an analytic definition (S1002, 60E1) or from a smoothed point file.
//
// Conventions (SI: metres):
// - Wheel (Eq. 10): h_w(s_w) is the wheel RADIUS at lateral parameter s_w, measured from the wheel
//   profile origin, which sits at +Lw (left wheel) or -Lw (right wheel) along Y of the wheelset
//   frame. The contact point in the wheelset intermediate frame is (0, +-Lw + s_w, -h_w(s_w)).
//   For the LEFT wheel s_w > 0 points to the field side (+Y); the RIGHT wheel is the mirror image,
//   h_rw(s) = h_lw(-s), so for it s_w > 0 points to the flange side. For S1002: h_lw(s) = r0 +
//   F(S = s) with S the EN 13715 coordinate (S > 0 field side, flange at S ~ -55 mm).
// - Rail (Eq. 6): h_r(s_r) is the head height (z up) at transverse parameter s_r in the rail
//   profile frame, which sits at +-Lr and is rotated by +-beta + delta (Eq. 5). For the LEFT rail
//   s_r > 0 points to the field side (+Y); the RIGHT rail is the mirror image, h_rr(s) = h_lr(-s).
//   For 60E1 the origin is the crown top of the uninclined head (h(0) = 0).
// - Mirroring is exact: a mirrored profile evaluates the same spline at -s, so
//   right.at(-s).h == left.at(s).h bit for bit (and dh changes sign exactly).
#include <memory>
#include <string>
#include <vector>

#include "workbench/core/spline.hpp"

namespace rb::profiles {

enum class ProfileKind { Wheel, Rail };

// Which side of the wheelset / track (paper Fig. 5: the left side is at +Y).
enum class Side { Left, Right };
using WheelSide = Side;
using RailSide = Side;

struct ProfilePoint {
  double h = 0.0;    // [m] radius (wheel) or height (rail)
  double dh = 0.0;   // [-] dh/ds
  double d2h = 0.0;  // [1/m] d2h/ds2
};

class Profile {
 public:
  // Samples h on a uniform grid over [s_min, s_max] (step ds) and splines it (not-a-knot).
  Profile(std::string name, ProfileKind kind, double s_min, double ds,
          const std::vector<double>& h);

  const std::string& name() const { return name_; }
  ProfileKind kind() const { return kind_; }
  double sMin() const { return mirror_ ? -spline_.grid().back() : spline_.grid().front(); }
  double sMax() const { return mirror_ ? -spline_.grid().front() : spline_.grid().back(); }
  double step() const { return ds_; }  // grid step ds [m]
  bool isMirrored() const { return mirror_; }
  bool inside(double s) const { return s >= sMin() && s <= sMax(); }
  // Allocation-free; outside [sMin, sMax] the end cubics are extended (callers check inside()).
  ProfilePoint at(double s) const;
  // The mirror image h(-s) (left <-> right), same name with suffix " (mirrored)".
  Profile mirrored() const;
  Profile mirrored(std::string name) const;  // same, with the given name
  // Signed curvature of the curve (s, h(s)): h'' / (1 + h'^2)^1.5 [1/m].
  double curvature(double s) const;
  // Samples for output/plots (knots in increasing s).
  std::vector<double> knots() const;
  std::vector<double> values() const;

 private:
  std::string name_;
  ProfileKind kind_;
  double ds_;
  // One channel of a spline set rather than a CubicSpline: at() gets h, h', h'' from ONE interval
  // lookup (CubicSplineSet::eval; the same polynomial expressions as CubicSpline's value, deriv1,
  // deriv2, so bit-identical). at() is on the dynamics' hot path (KEC transition bands).
  CubicSplineSet spline_;
  bool mirror_ = false;  // evaluate spline_ at -s (exact mirror image)
};

}  // namespace rb::profiles
