#include <cmath>
#include <string>

#include "workbench/core/strings.hpp"
#include "workbench/scenario/build.hpp"
#include "workbench/scenario/reader.hpp"
#include "workbench/track/names.hpp"

namespace rb::scenario {
namespace {

// Points of a user PSD function: log-spaced over a band a little wider than the synthesis band.
constexpr int kPsdFunctionPoints = 400;

track::PsdTable tabulatePsdFunction(const Node& v, const std::string& path, Reader& r,
                                    double omegaMin, double omegaMax) {
  track::PsdTable t;
  const int n = kPsdFunctionPoints;
  const double a = std::log(omegaMin / 2);
  const double b = std::log(omegaMax * 2);
  for (int i = 0; i < n; ++i) {
    const double om = std::exp(a + (b - a) * i / (n - 1));
    double g = 0;
    try {
      g = (*v.function)(om);
    } catch (const InputError& e) {
      // Where the function raised the error, not where the psd{} block starts.
      for (const auto& diag : e.diagnostics())
        r.errorAt(diag.loc.line > 0 ? diag.loc : v.loc, path + ": " + diag.message);
      return {};
    }
    if (!std::isfinite(g) || g < 0) {
      r.error(v, path + ": PSD function returned " + formatNumber(g) +
                     " at omega = " + formatNumber(om) + " rad/m; it must be finite and >= 0");
      return {};
    }
    t.omega.push_back(om);
    t.value.push_back(g);
  }
  return t;
}

track::PsdTable readPsdInput(const Node& v, const std::string& path, Reader& r, double omegaMin,
                             double omegaMax) {
  if (v.type == Node::Type::Function) return tabulatePsdFunction(v, path, r, omegaMin, omegaMax);
  if (v.type == Node::Type::Table && v.fields.empty()) {
    track::PsdTable t;
    for (std::size_t i = 0; i < v.items.size(); ++i) {
      const Node& p = v.items[i];
      if (p.type != Node::Type::Table || p.items.size() != 2 ||
          p.items[0].type != Node::Type::Number || p.items[1].type != Node::Type::Number) {
        r.error(v, path + "[" + std::to_string(i + 1) + "] must be a pair {omega, G}");
        return {};
      }
      t.omega.push_back(p.items[0].number);
      t.value.push_back(p.items[1].number);
    }
    return t;
  }
  r.error(
      v, path + " must be a function of omega or a table of {omega, G} pairs, got " + v.describe());
  return {};
}

void buildMeasured(const Node& n, const std::string& path, LuaHost& host,
                   track::IrregularitySpec& out, Diagnostics& d) {
  Reader r(n, block("measured"), path, d);
  out.source = track::IrregularitySource::Csv;
  const std::string file = r.string("file");
  out.csv_unit = r.choiceOf<track::CsvUnit>("unit");
  out.beyond = r.choiceOf<track::Beyond>("beyond");
  out.fade_in = r.number("fade_in");
  if (file.empty()) return;
  try {
    out.csv_path = host.resolveDataFile(file, n.loc);
  } catch (const InputError& e) {
    const Node* at = r.value("file");
    r.error(at != nullptr ? *at : n, "file: " + e.diagnostics().front().message);
  }
}

// The user PSDs of psd{}: one per channel given, only with spectrum = "user".
void readUserPsds(const Node& n, Reader& r, track::IrregularitySpec& out) {
  const bool user = out.spectrum == nameOf(track::Spectrum::User);
  bool anyUser = false;
  for (const auto& channel : track::kChannelNames) {
    const std::string name(channel.name);
    const Node* v = r.value(name);
    if (!v) continue;
    anyUser = true;
    if (!user) {
      const Node* given = n.field("spectrum");
      std::string named = given && given->type == Node::Type::String ? given->string : out.spectrum;
      r.error(*v, name + " gives a user PSD but spectrum is '" + named +
                      "'; set spectrum = \"user\" or remove it");
      continue;
    }
    if (out.wavelength_min > 0 && out.wavelength_max > out.wavelength_min)
      out.user[static_cast<int>(channel.value)] =
          readPsdInput(*v, name, r, 2 * M_PI / out.wavelength_max, 2 * M_PI / out.wavelength_min);
  }
  if (user && !anyUser)
    r.error(n, "spectrum = \"user\" needs at least one of alignment, vertical, gauge, cross_level");
}

void buildIrregularities(const Node& n, const std::string& path, LuaHost& host,
                         track::IrregularitySpec& out, Diagnostics& d) {
  out.loc = n.loc;
  if (n.kind == "measured") return buildMeasured(n, path, host, out, d);
  Reader r(n, block("psd"), path, d);
  out.source = track::IrregularitySource::Psd;
  out.spectrum = r.choice("spectrum");
  out.seed = toInteger<std::uint64_t>(r.number("seed"));
  out.components = toInteger<int>(r.number("components"));
  out.step = r.number("step");
  out.scale = r.number("scale");
  out.fade_in = r.number("fade_in");
  out.randomize_frequencies = r.boolean("randomize_frequencies");
  r.pair("wavelengths", out.wavelength_min, out.wavelength_max);
  const std::vector<std::string> channels = r.stringList("channels");
  for (const auto& channel : track::kChannelNames) {
    bool& enabled = out.enabled[static_cast<int>(channel.value)];
    enabled = false;
    for (const auto& s : channels) enabled = enabled || s == channel.name;
  }
  readUserPsds(n, r, out);
}

track::SegmentSpec buildSegment(const Node& s, const std::string& path, Diagnostics& d) {
  Reader sr(s, block(s.kind), path, d);
  track::SegmentSpec seg;
  seg.loc = s.loc;
  seg.kind = parse<track::SegmentKind>(s.kind).value_or(track::SegmentKind::Curve);
  seg.length = sr.number("length");
  seg.gradient = sr.number("gradient");
  if (seg.kind != track::SegmentKind::Tangent) {
    seg.radius = sr.number("radius");
    seg.side = sr.choiceOf<track::Side>("side");
    seg.cant = sr.number("cant");
  }
  return seg;
}

}  // namespace

void buildTrack(const Node& n, LuaHost& host, track::TrackSpec& t, bool& railsGiven,
                Diagnostics& d) {
  Reader r(n, block("track"), "track", d);
  railsGiven = r.has("rail_lr") || r.has("rail_inclination");
  t.loc = n.loc;
  t.step = r.number("step");
  t.cant_base = r.number("cant_base");
  t.gauge = r.number("gauge");
  t.rail_lr = r.number("rail_lr");
  t.rail_inclination = r.number("rail_inclination");
  t.max_points = r.number("max_points");
  auto segs = r.blockList("segments");
  for (std::size_t i = 0; i < segs.size(); ++i)
    t.segments.push_back(
        buildSegment(*segs[i], "track.segments[" + std::to_string(i + 1) + "]", d));
  if (const Node* irr = r.blockValue("irregularities"))
    buildIrregularities(*irr, "track.irregularities", host, t.irregularities, d);
}

}  // namespace rb::scenario
