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
  void dataset(const std::string& path, const std::vector<double>& data, const std::string& units) {
    c.items.emplace_back(TrackContent::Dataset{path, units, data});
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
