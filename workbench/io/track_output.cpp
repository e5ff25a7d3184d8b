#include "workbench/io/track_output.hpp"

#include "workbench/track/names.hpp"

namespace rb::io {
namespace {
std::vector<double> toDouble(const std::vector<int>& v) {
  return {v.begin(), v.end()};
}
}  // namespace

void writeTrack(ResultFile& f, const track::TrackSpec& spec, const track::TrackSamples& t) {
  f.attr("/track", "length", t.s.empty() ? 0.0 : t.s.back());
  f.attr("/track", "step", spec.step);
  f.attr("/track", "cant_base", spec.cant_base);
  f.attr("/track", "gauge", spec.gauge);
  f.attr("/track", "rail_lr", spec.rail_lr);
  f.attr("/track", "rail_inclination", spec.rail_inclination);
  const std::string c = "/track/centreline/";
  f.dataset(c + "s", t.s, "m");
  f.dataset(c + "x", t.x, "m");
  f.dataset(c + "y", t.y, "m");
  f.dataset(c + "z", t.z, "m");
  f.dataset(c + "heading", t.heading, "rad");
  f.dataset(c + "slope", t.slope, "rad");
  f.dataset(c + "cant_angle", t.cant_angle, "rad");
  f.dataset(c + "curvature", t.curvature, "1/m");
  f.dataset(c + "cant", t.cant, "m");
  const std::string g = "/track/segments/";
  f.dataset(g + "start", t.seg_start, "m");
  f.dataset(g + "length", t.seg_length, "m");
  f.dataset(g + "kind", toDouble(t.seg_kind), "-");
  f.attr("/track/segments", "codes", std::string("0=tangent,1=transition,2=curve"));
  f.dataset(g + "radius", t.seg_radius, "m");
  f.dataset(g + "side", toDouble(t.seg_side), "-");
  f.dataset(g + "cant", t.seg_cant, "m");
  if (t.irr_s.empty()) return;

  const auto& irr = spec.irregularities;
  const std::string r = "/track/irregularities";
  bool psd = irr.source == track::IrregularitySource::Psd;
  f.attr(r, "source", std::string(psd ? "psd" : "csv"));
  if (psd) {
    f.attr(r, "step", irr.step);
    f.attr(r, "spectrum", irr.spectrum);
    f.attr(r, "psd_verified", std::int64_t{t.psd_verified ? 1 : 0});
    f.attr(r, "seed", static_cast<std::int64_t>(irr.seed));
    f.attr(r, "wavelength_min", irr.wavelength_min);
    f.attr(r, "wavelength_max", irr.wavelength_max);
    f.attr(r, "components", static_cast<std::int64_t>(irr.components));
    f.attr(r, "scale", irr.scale);
  } else {
    f.attr(r, "csv_path", irr.csv_path);
    f.attr(r, "csv_unit", std::string(nameOf(irr.csv_unit)));
    f.attr(r, "beyond", std::string(nameOf(irr.beyond)));
  }
  f.dataset(r + "/s", t.irr_s, "m");
  f.dataset(r + "/alignment", t.alignment, "m");
  f.dataset(r + "/vertical", t.vertical, "m");
  f.dataset(r + "/gauge", t.gauge, "m");
  f.dataset(r + "/cross_level", t.cross_level, "m");
  f.dataset(r + "/left_y", t.left_y, "m");
  f.dataset(r + "/left_z", t.left_z, "m");
  f.dataset(r + "/right_y", t.right_y, "m");
  f.dataset(r + "/right_z", t.right_z, "m");
  f.dataset(r + "/delta", t.delta, "rad");
  if (t.psd_omega.empty()) return;
  const std::string p = r + "/target_psd/";
  f.dataset(p + "omega", t.psd_omega, "rad/m");
  f.dataset(p + "alignment", t.psd_alignment, "m^2/(rad/m)");
  f.dataset(p + "vertical", t.psd_vertical, "m^2/(rad/m)");
  f.dataset(p + "gauge", t.psd_gauge, "m^2/(rad/m)");
  f.dataset(p + "cross_level", t.psd_cross_level, "m^2/(rad/m)");
  f.attr(r + "/target_psd", "convention",
         std::string("one-sided G(Omega), variance = integral over Omega > 0"));
}

}  // namespace rb::io
