#include "workbench/track/samples.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace rb::track {

namespace {

// The index range [first, last) of the sorted samples `s` inside [s_from, s_to], widened by one
// sample on either side where there is one.
std::pair<std::size_t, std::size_t> stretch(const std::vector<double>& s, double s_from,
                                            double s_to) {
  auto lo = static_cast<std::size_t>(std::lower_bound(s.begin(), s.end(), s_from) - s.begin());
  auto hi = static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), s_to) - s.begin());
  if (lo > 0) --lo;
  if (hi < s.size()) ++hi;
  return {lo, std::max(lo, hi)};
}

}  // namespace

TrackSamples sampleTrack(const TrackModel& model, double s_from, double s_to) {
  TrackSamples out;
  const TrackGeometry& g = model.geometry();
  out.length = g.length();
  const std::vector<double>& knots = g.knots().knots();
  const auto [k0, k1] = stretch(knots, s_from, s_to);
  for (std::size_t k = k0; k < k1; ++k) {
    const double s = knots[k];
    const TrackFrame f = g.at(s);
    out.s.push_back(s);
    out.x.push_back(f.R.x());
    out.y.push_back(f.R.y());
    out.z.push_back(f.R.z());
    out.heading.push_back(f.psi);
    out.slope.push_back(f.theta);
    out.cant_angle.push_back(f.phi);
    out.curvature.push_back(f.curvature);
    out.cant.push_back(f.cant);
  }
  for (const Segment& sg : g.segments()) {
    out.seg_start.push_back(sg.s0);
    out.seg_length.push_back(sg.length);
    out.seg_kind.push_back(static_cast<int>(sg.kind));
    out.seg_radius.push_back(sg.radius);
    out.seg_side.push_back(sg.side == Side::Left ? 1 : -1);
    out.seg_cant.push_back(sg.cant);
  }
  if (const auto& irr = model.irregularities()) {
    const std::vector<double>& irr_s = irr->samples().s;
    const auto [i0, i1] = stretch(irr_s, s_from, s_to);
    for (std::size_t i = i0; i < i1; ++i) {
      const double s = irr_s[i];
      const IrregularityPoint p = irr->at(s);
      out.irr_s.push_back(s);
      out.alignment.push_back(p.xi[static_cast<std::size_t>(Channel::Alignment)]);
      out.vertical.push_back(p.xi[static_cast<std::size_t>(Channel::Vertical)]);
      out.gauge.push_back(p.xi[static_cast<std::size_t>(Channel::Gauge)]);
      out.cross_level.push_back(p.xi[static_cast<std::size_t>(Channel::CrossLevel)]);
      out.left_y.push_back(p.y_l);
      out.left_z.push_back(p.z_l);
      out.right_y.push_back(p.y_r);
      out.right_z.push_back(p.z_r);
      out.delta.push_back(p.delta);
    }
  }
  const IrregularitySpec& is = model.spec().irregularities;
  if (is.source == IrregularitySource::Psd) {
    const double lo = 2.0 * std::numbers::pi / is.wavelength_max;
    const double hi = 2.0 * std::numbers::pi / is.wavelength_min;
    for (int i = 0; i < kPsdSamplePoints; ++i) {
      const double r = static_cast<double>(i) / (kPsdSamplePoints - 1);
      // Endpoints exactly on the band limits (targetPsd() is zero outside).
      const double om = i == 0 ? lo : i == kPsdSamplePoints - 1 ? hi : lo * std::pow(hi / lo, r);
      out.psd_omega.push_back(om);
      out.psd_alignment.push_back(targetPsd(is, Channel::Alignment, om));
      out.psd_vertical.push_back(targetPsd(is, Channel::Vertical, om));
      out.psd_gauge.push_back(targetPsd(is, Channel::Gauge, om));
      out.psd_cross_level.push_back(targetPsd(is, Channel::CrossLevel, om));
    }
  }
  out.psd_verified = model.psdVerified();
  return out;
}

}  // namespace rb::track
