#include "workbench/contact/sliced_rail.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "workbench/core/error.hpp"

namespace rb::contact {

SlicedRailSearch::SlicedRailSearch(const WheelRailPair& pair, std::vector<RailSlice> slices,
                                   const ElasticSearchSpec& spec, bool bounded)
    : slices_(std::move(slices)), bounded_(bounded) {
  if (slices_.empty()) throw InputError(SourceLoc{}, "sliced rail: no slice");
  for (std::size_t k = 0; k < slices_.size(); ++k) {
    if (!slices_[k].rail) throw InputError(SourceLoc{}, "sliced rail: a slice has no profile");
    if (k > 0 && !(slices_[k].s > slices_[k - 1].s))
      throw InputError(SourceLoc{}, "sliced rail: the slices' s must increase strictly");
    if (!std::isfinite(slices_[k].dy) || !std::isfinite(slices_[k].dz))
      throw InputError(SourceLoc{}, "sliced rail: a slice's offsets must be finite");
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
  if (k == 0 || k == slices_.size()) {
    const RailSlice& end = k == 0 ? slices_.front() : slices_.back();
    // A bounded rail ends at its last slice (there it still is: s_last belongs to it).
    if (bounded_ && (k == 0 || s > end.s)) return out;
    out.search = &pieces_[k];
    out.dy = end.dy;
    out.dz = end.dz;
    return out;
  }
  out.search = &pieces_[k];
  const RailSlice& a = slices_[k - 1];
  const RailSlice& b = slices_[k];
  const double len = b.s - a.s;
  out.blend = std::clamp((s - a.s) / len, 0.0, 1.0);
  out.blend_ds = 1.0 / len;
  out.dy = a.dy + out.blend * (b.dy - a.dy);
  out.dz = a.dz + out.blend * (b.dz - a.dz);
  out.dy_ds = (b.dy - a.dy) / len;
  out.dz_ds = (b.dz - a.dz) / len;
  return out;
}

}  // namespace rb::contact
