#include "workbench/io/track_output.hpp"

#include <cstdio>
#include <cstring>

#include "workbench/track/names.hpp"

namespace rb::io {
namespace {

std::vector<double> toDouble(const std::vector<int>& v) {
  return {v.begin(), v.end()};
}

class Builder {
 public:
  void attr(const std::string& group, const std::string& name,
            std::variant<std::string, double, std::int64_t> value) {
    c.items.emplace_back(TrackContent::Attr{group, name, std::move(value)});
  }
  void dataset(const std::string& path, const std::vector<double>& data, const std::string& units,
               const std::string& meaning, const std::string& codes = {}) {
    c.items.emplace_back(TrackContent::Dataset{path, units, data, meaning, codes});
  }
  TrackContent c;
};

void addIrregularities(Builder& f, const track::TrackSpec& spec, const track::TrackSamples& t) {
  const auto& irr = spec.irregularities;
  const std::string r = "/track/irregularities";
  const bool psd = irr.source == track::IrregularitySource::Psd;
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
    f.attr(r, "fade_in", irr.fade_in);
  } else {
    f.attr(r, "csv_path", irr.csv_path);
    f.attr(r, "csv_unit", std::string(nameOf(irr.csv_unit)));
    f.attr(r, "beyond", std::string(nameOf(irr.beyond)));
    f.attr(r, "fade_in", irr.fade_in);
  }
  f.dataset(r + "/s", t.irr_s, "m", "arc length of the irregularity samples");
  f.dataset(r + "/alignment", t.alignment, "m",
            "alignment: lateral displacement of the centreline");
  f.dataset(r + "/vertical", t.vertical, "m",
            "vertical profile: vertical displacement of the centreline");
  f.dataset(r + "/gauge", t.gauge, "m",
            "gauge variation: deviation of the gauge from its nominal value");
  f.dataset(r + "/cross_level", t.cross_level, "m",
            "cross level: height difference z_l - z_r of the rails");
  f.dataset(r + "/left_y", t.left_y, "m", "lateral displacement of the left rail");
  f.dataset(r + "/left_z", t.left_z, "m", "vertical displacement of the left rail");
  f.dataset(r + "/right_y", t.right_y, "m", "lateral displacement of the right rail");
  f.dataset(r + "/right_z", t.right_z, "m", "vertical displacement of the right rail");
  f.dataset(r + "/delta", t.delta, "rad", "cross-level angle of the rails");
  if (t.psd_omega.empty()) return;
  const std::string p = r + "/target_psd/";
  f.dataset(p + "omega", t.psd_omega, "rad/m", "spatial angular frequency Omega of the target PSD");
  f.dataset(p + "alignment", t.psd_alignment, "m^2/(rad/m)",
            "target PSD of the alignment, one-sided");
  f.dataset(p + "vertical", t.psd_vertical, "m^2/(rad/m)",
            "target PSD of the vertical profile, one-sided");
  f.dataset(p + "gauge", t.psd_gauge, "m^2/(rad/m)",
            "target PSD of the gauge variation, one-sided");
  f.dataset(p + "cross_level", t.psd_cross_level, "m^2/(rad/m)",
            "target PSD of the cross level, one-sided");
  f.attr(r + "/target_psd", "convention",
         std::string("one-sided G(Omega), variance = integral over Omega > 0"));
}

constexpr std::string_view kSegmentKindEnum = "segment_kind", kSegmentSideEnum = "segment_side";

__extension__ using U128 = unsigned __int128;

// FNV-1a with the 128-bit parameters (offset basis and prime of the FNV specification).
class Fnv128 {
 public:
  void bytes(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
      h_ ^= b[i];
      h_ *= kPrime;
    }
  }
  // Length-prefixed, so that no two different item lists give the same byte stream.
  void field(const std::string& s) {
    count(s.size());
    bytes(s.data(), s.size());
  }
  void count(std::uint64_t n) { bytes(&n, sizeof n); }
  void number(double x) { bytes(&x, sizeof x); }
  std::string hex() const {
    char buf[33];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(h_ >> 64),
                  static_cast<unsigned long long>(h_));
    return buf;
  }

 private:
  static constexpr U128 kPrime = (static_cast<U128>(1) << 88) + 0x13b;  // 2^88 + 2^8 + 0x3b
  U128 h_ = (static_cast<U128>(0x6c62272e07bb0142ULL) << 64) | 0x62b821756295c58dULL;
};

}  // namespace

TrackContent trackContent(const track::TrackSpec& spec, const track::TrackSamples& t) {
  Builder f;
  f.attr("/track", "length", t.length);
  f.attr("/track", "step", spec.step);
  f.attr("/track", "cant_base", spec.cant_base);
  f.attr("/track", "gauge", spec.gauge);
  f.attr("/track", "rail_lr", spec.rail_lr);
  f.attr("/track", "rail_inclination", spec.rail_inclination);
  const std::string c = "/track/centreline/";
  f.dataset(c + "s", t.s, "m", "arc length of the centreline samples");
  f.dataset(c + "x", t.x, "m", "centreline position x (global frame)");
  f.dataset(c + "y", t.y, "m", "centreline position y (global frame)");
  f.dataset(c + "z", t.z, "m", "centreline position z (global frame)");
  f.dataset(c + "heading", t.heading, "rad", "heading of the centreline");
  f.dataset(c + "slope", t.slope, "rad", "slope of the centreline");
  f.dataset(c + "cant_angle", t.cant_angle, "rad", "design cant angle");
  f.dataset(c + "curvature", t.curvature, "1/m",
            "curvature of the centreline, positive to the left");
  f.dataset(c + "cant", t.cant, "m", "design cant (height of the outer rail over the cant base)");
  const std::string g = "/track/segments/";
  f.dataset(g + "start", t.seg_start, "m", "arc length where the segment starts");
  f.dataset(g + "length", t.seg_length, "m", "length of the segment");
  f.dataset(g + "kind", toDouble(t.seg_kind), "-", "segment kind (codes in /schema/enums)",
            std::string(kSegmentKindEnum));
  f.attr("/track/segments", "codes", codesOf<track::SegmentKind>());
  f.dataset(g + "radius", t.seg_radius, "m",
            "radius of the segment's curve (end radius of a transition)");
  f.dataset(g + "side", toDouble(t.seg_side), "-",
            "side of the curvature centre (codes in /schema/enums)", std::string(kSegmentSideEnum));
  f.dataset(g + "cant", t.seg_cant, "m", "cant of the segment (end cant of a transition)");
  if (!t.irr_s.empty()) addIrregularities(f, spec, t);
  return std::move(f.c);
}

void writeTrackContent(ResultFile& f, const TrackContent& c) {
  for (const auto& item : c.items) {
    if (const auto* a = std::get_if<TrackContent::Attr>(&item))
      std::visit([&](const auto& v) { f.attr(a->group, a->name, v); }, a->value);
    else if (const auto* d = std::get_if<TrackContent::Dataset>(&item))
      f.dataset(d->path, d->data, d->units);
  }
}

std::vector<TrackContent::Attr> trackGroupAttrs(const TrackContent& c) {
  std::vector<TrackContent::Attr> out;
  for (const auto& item : c.items)
    if (const auto* a = std::get_if<TrackContent::Attr>(&item); a && a->group == "/track")
      out.push_back(*a);
  return out;
}

std::vector<SchemaEntry> trackSchema(const TrackContent& c) {
  std::vector<SchemaEntry> out;
  for (const auto& item : c.items)
    if (const auto* d = std::get_if<TrackContent::Dataset>(&item))
      out.push_back({d->path, d->units, d->meaning, d->codes});
  return out;
}

std::vector<std::pair<std::string, std::string>> trackEnums() {
  // The side as track/samples.cpp stores it: +1 left, -1 right.
  const std::string side = "1=" + std::string(nameOf(track::Side::Left)) +
                           ",-1=" + std::string(nameOf(track::Side::Right));
  // The irregularity channels name datasets, not codes: their table gives a reader their names
  // and order (paper Fig. 3).
  return {{std::string(kSegmentKindEnum), codesOf<track::SegmentKind>()},
          {std::string(kSegmentSideEnum), side},
          {"irregularity_channel", codesOf<track::Channel>()}};
}

std::string trackHash(const TrackContent& c) {
  Fnv128 h;
  h.field("railbench track content");
  for (const auto& item : c.items) {
    if (const auto* a = std::get_if<TrackContent::Attr>(&item)) {
      h.field("attr");
      h.field(a->group);
      h.field(a->name);
      h.count(a->value.index());
      if (const auto* s = std::get_if<std::string>(&a->value))
        h.field(*s);
      else if (const auto* x = std::get_if<double>(&a->value))
        h.number(*x);
      else
        h.count(static_cast<std::uint64_t>(std::get<std::int64_t>(a->value)));
    } else {
      const auto& d = std::get<TrackContent::Dataset>(item);
      h.field("dataset");
      h.field(d.path);
      h.field(d.units);
      h.count(d.data.size());
      h.bytes(d.data.data(), d.data.size() * sizeof(double));
    }
  }
  return h.hex();
}

}  // namespace rb::io
