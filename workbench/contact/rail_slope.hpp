#pragma once
// The elastic contact search over a rail that rises or moves sideways along the track
// (docs/sliced_rails.md, "Slope along the track").
//
// ElasticContactSearch takes the rail as a prism along the track X. A crossing nose rising at
// 1:10, a wing rail diverging at 1:10, a switch blade's top: seen from a wheel, the rail near the
// contact is a prism along its own direction t = (1, y_s, z_s) (d(Y, Z)/ds of a point of fixed
// profile parameter), pitched by atan(z_s) and yawed by atan(y_s). Neglecting that, a wheel of
// radius r over a rail rising at slope p meets the rail at r p ahead of its centre and sees a gap
// too large by about r p^2 / 2 (2.3 mm at 1:10, twenty times a Hertz approach).
//
// Here the search runs in the rail's frame: the rotation R = Rz(atan y_s) Ry(-atan2(z_s,
// sqrt(1 + y_s^2))) takes e_X to t / |t| and keeps the rail frame's Y horizontal. About a pivot P
// on the rail (in the slice plane X = 0), the wheelset centre c and axle a become
//   c' = P + R^T (c - P),   a' = R^T a,
// the pose (y, z, phi, psi) of c' and a' (a body of revolution does not see its spin), and the
// search's patches come back as p = P + R (p' - P), n = R n'. The wheel angle theta of a patch is
// measured in the wheelset's own intermediate frame: R^T R_ws = R' Ry(chi), so theta = theta' +
// chi's share, computed from the rotation that maps the searched wheel frame onto the wheelset's.
//
// The rail's cross-section perpendicular to t is the slice (drawn at fixed s) projected along t:
// the slice itself to second order in (the slope) x (distance from P). A first search pivots at the
// rail profile origin and finds the deepest patch; the second pivots at that patch's rail point
// (carried back to X = 0 along t), where the projection is exact, and adds the slope of a blended
// rail there: its surface at fixed profile parameter u rises by blend_s (h_next - h)(u) along the
// rail frame's vertical per unit s (sliced_rail.hpp). The second search is the result, except
// for a further patch of the first search whose rail rises otherwise (two heads in one blended
// slice): it is searched again about its own rail point with its own slope, and that search's
// patch nearest to it takes its place. A rail without slope (a prismatic rail, identical slices,
// no offsets' slope) is one plain search, bit for bit.
//
// Not included: the irregularity's slope (below 1e-2; its r p^2 / 2 is below 0.05 mm at 1e-2 and
// 0.2 um at the 1e-3 of measured track), which the dynamics keep in the normal damping.
#include "workbench/contact/elastic_search.hpp"

namespace rb::contact {

// The rail's slope along the track at the wheelset (track frame): a point of fixed profile
// parameter moves by (y_s, z_s) per unit s; a blended rail's surface moves along the rail frame's
// vertical by blend_s (h_next - h)(u) per unit s (blend_s = d(blend)/ds, 0 on a prismatic rail).
struct RailSlope {
  double y_s = 0.0, z_s = 0.0;  // [-]
  double blend_s = 0.0;         // [1/m]
};

// The workspaces of the searches after the first (kept per wheel and rail, so that each one's
// certificates and last-pose cache follow its own sequence of poses): the search about the
// deepest patch's rail point, and those about the further patches' own points.
struct SlopedSearchWorkspace {
  ElasticSearchWorkspace second;
  ElasticSearchWorkspace further;
};

// The search of `search` at `pose` over its rail with `slope` (see the header comment). `first` is
// the first search's workspace. out's patches are in the track frame with n_x set; a rail without
// slope leaves `sloped` unused.
void searchSlopedRail(const ElasticContactSearch& search, const ElasticPose& pose,
                      const RailSlope& slope, ElasticWheelGeometry& out,
                      ElasticSearchWorkspace& first, SlopedSearchWorkspace& sloped);

}  // namespace rb::contact
