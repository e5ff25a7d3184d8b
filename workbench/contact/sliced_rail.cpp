#include "workbench/contact/sliced_rail.hpp"

#include <algorithm>
#include <utility>

#include "workbench/core/error.hpp"

namespace rb::contact {

SlicedRailSearch::SlicedRailSearch(const WheelRailPair& pair, std::vector<RailSlice> slices,
                                   const ElasticSearchSpec& spec)
    : slices_(std::move(slices)) {
  if (slices_.empty()) throw InputError(SourceLoc{}, "sliced rail: no slice");
  for (std::size_t k = 0; k < slices_.size(); ++k) {
    if (!slices_[k].rail) throw InputError(SourceLoc{}, "sliced rail: a slice has no profile");
    if (k > 0 && !(slices_[k].s > slices_[k - 1].s))
      throw InputError(SourceLoc{}, "sliced rail: the slices' s must increase strictly");
  }
  pieces_.reserve(slices_.size() + 1);
  WheelRailPair p = pair;
  p.rail = slices_.front().rail;
  p.rail_next = nullptr;
  pieces_.emplace_back(p, spec);
  for (std::size_t k = 0; k + 1 < slices_.size(); ++k) {
    p.rail = slices_[k].rail;
    p.rail_next = slices_[k + 1].rail;
    pieces_.emplace_back(p, spec);
  }
  p.rail = slices_.back().rail;
  p.rail_next = nullptr;
  pieces_.emplace_back(p, spec);
}

SlicedRailSearch::Place SlicedRailSearch::at(double s) const {
  Place out;
  // The first slice with s_k > s: piece k lies between slices k-1 and k.
  const auto it = std::upper_bound(slices_.begin(), slices_.end(), s,
                                   [](double v, const RailSlice& r) { return v < r.s; });
  const auto k = static_cast<std::size_t>(it - slices_.begin());
  out.piece = static_cast<int>(k);
  out.search = &pieces_[k];
  if (k == 0 || k == slices_.size()) return out;
  const double len = slices_[k].s - slices_[k - 1].s;
  out.blend = std::clamp((s - slices_[k - 1].s) / len, 0.0, 1.0);
  out.blend_ds = 1.0 / len;
  return out;
}

}  // namespace rb::contact
