#pragma once
// A rail that changes along the track (docs/sliced_rails.md): rail profile slices at given track
// arc lengths s_0 < s_1 < ... < s_n-1, each a profile in the rail frame of its side (origin at
// sigma Lr, inclined by sigma beta, as config.hpp places the rail). Between two slices the rail is
// their linear blend at fixed profile parameter u,
//   h_r(u; s) = h_k(u) + b (h_k+1(u) - h_k(u)),   b = (s - s_k) / (s_k+1 - s_k),
// over the part of u both slices cover; before the first slice and after the last the rail is that
// slice, prismatic. Linear blending at fixed u is an assumption of this model (docs/
// sliced_rails.md): it suits slices drawn over the same lateral axis whose heights change (a rail
// ground or worn gradually, a rising switch blade, a crossing nose), not a rail that moves
// sideways faster than its profile's features are wide. Wherever two slices are the same profile
// the blend is that profile exactly: a track of identical slices is the prismatic rail, bit for
// bit.
//
// The contact search of each piece is an ElasticContactSearch whose pair has rail (slice k) and
// rail_next (slice k+1, null on the prismatic ends); SlicedRailSearch::at(s) returns the piece
// under the wheel and its blend. Only the elastic contact method searches the rail online; the
// constraint methods' tables hold one rail profile.
#include <memory>
#include <vector>

#include "workbench/contact/elastic_search.hpp"

namespace rb::contact {

struct RailSlice {
  double s = 0.0;  // [m] track arc length of the slice
  std::shared_ptr<const profiles::Profile> rail;
  // [m] offset of the slice's rail frame: dy toward the field side (+Y for the left rail, -Y for
  // the right), dz up; interpolated linearly between slices like the heights (a rail that moves
  // sideways, a nose or blade that rises, is the same profile at other offsets: an exact
  // translation, not a blend of two shapes).
  double dy = 0.0, dz = 0.0;
};

class SlicedRailSearch {
 public:
  // `pair` gives the wheel, side and placement; its rail is replaced by the slices (sorted by
  // strictly increasing s, at least one). Throws InputError when two neighbouring slices share
  // no profile parameter.
  // bounded: the rail exists only from its first slice to its last (a switch blade, a crossing
  // nose, a check rail); otherwise it runs on, prismatic, before the first and after the last.
  SlicedRailSearch(const WheelRailPair& pair, std::vector<RailSlice> slices,
                   const ElasticSearchSpec& spec, bool bounded = false);

  // The rail under a wheel at track arc length s: the search of its piece (null where a bounded
  // rail does not exist), the blend b and db/ds [1/m] (0 on the prismatic ends), the offsets and
  // their slopes along the track.
  struct Place {
    const ElasticContactSearch* search = nullptr;
    double blend = 0.0;
    double blend_ds = 0.0;
    double dy = 0.0, dz = 0.0;        // [m]
    double dy_ds = 0.0, dz_ds = 0.0;  // [-]
    int piece = 0;  // 0: before the first slice, k: between slices k-1 and k, n: after the last
  };
  Place at(double s) const;

  const std::vector<RailSlice>& slices() const { return slices_; }
  bool bounded() const { return bounded_; }
  std::size_t pieces() const { return pieces_.size(); }
  const ElasticContactSearch& piece(std::size_t k) const { return pieces_[k]; }

 private:
  std::vector<RailSlice> slices_;
  std::vector<ElasticContactSearch> pieces_;
  bool bounded_ = false;
};

}  // namespace rb::contact
