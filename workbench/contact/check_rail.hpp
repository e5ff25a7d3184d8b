#pragma once
// Contact of a check rail with the back of a wheel's flange (docs/sliced_rails.md, "Check
// rails"). A check rail runs beside a running rail on the track-centre side of it and holds the
// wheelset sideways by the back of that wheel's flange: its face meets the flat back face of the
// wheel (a disc at the flange-back distance from the tape circle) or the rounded edge between
// that face and the flange tip. The wheel profile, a function of the lateral
// coordinate, cannot hold that vertical face; the contact is searched laterally instead:
//
// - The wheel's back, as a function of the distance rho from the axle: s_back(rho) = s_face (the
//   flat face) up to rho_face, the radius where the profile's flange-back branch begins (its
//   first point), then that branch (the profile's s where h(s) = rho, rising to the flange tip
//   rho_tip). s is the left profile's lateral parameter (field side positive); the wheel's
//   material lies at s >= s_back(rho).
// - A check-rail point (s_r, h_r(s_r)) of its profile (blended between slices as any rail), on a
//   line along the track, meets the wheel at the points x of that line where rho(x) <= rho_tip;
//   its lateral penetration into the wheel's back is d(x) = sigma L(x) - Lw - s_back(rho(x)), L
//   the lateral coordinate in the wheelset frame. d is linear in x over the flat face (its slope
//   the wheelset's yaw relative to the rail): its largest value is at the face's edge, or beyond
//   it on the rounded edge; the rounded part is sampled (kBackSamples in rho).
// - The deepest line over the check rail's samples (refined by golden section) is the contact:
//   one patch, its normal the wheel back's (the axle direction on the flat face), its deepest
//   penetration along that normal the approach. On the flat face the patch sits at the centroid
//   of the penetration along the chord (linear from the deepest edge), continuous in the yaw:
//   the chord's middle without yaw, nearer the edge as the yaw grows. The flat face is flat in
//   every direction: the relative curvatures are the check rail head's transverse curvature and 0
//   along the track (the normal problem's floor, ElasticNormalSpec::min_curvature, applies).
#include "workbench/contact/elastic_search.hpp"
#include "workbench/profiles/profile.hpp"

namespace rb::contact {

// The back of one wheel's flange (left profile convention).
class FlangeBack {
 public:
  FlangeBack() = default;
  // `wheel` drawn as a left wheel; s_face the lateral parameter of the flat back face (the
  // positioning's flange-back distance: -70 mm for S1002 and every EN 13715 wheel), or the
  // profile's first point where that lies farther back.
  FlangeBack(const profiles::Profile& wheel, double s_face);
  double sFace() const { return s_face_; }
  double rhoFace() const { return rho_face_; }
  double rhoTip() const { return rho_tip_; }
  // s_back(rho) and ds_back/drho for rho_face < rho <= rho_tip (linear between the samples of
  // the branch); s_face and 0 below.
  double sBack(double rho, double* slope = nullptr) const;

 private:
  double s_face_ = 0.0, rho_face_ = 0.0, rho_tip_ = 0.0;
  std::vector<double> rho_, s_;  // the branch, rho increasing
};

inline constexpr int kBackSamples = 16;

// The contact of the check rail `rail` (its pair's rail, blended with rail_next by pose.blend,
// placed as the pair places it) with the back of the pair's wheel at `pose`: out.count 0 or 1.
// out.min_gap is the largest lateral penetration found (negative: the clearance).
void searchCheckRail(const ElasticContactSearch& rail, const FlangeBack& back,
                     const ElasticPose& pose, ElasticWheelGeometry& out);

}  // namespace rb::contact
