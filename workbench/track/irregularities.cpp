#include "workbench/track/irregularities.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <numbers>
#include <string_view>

#include "workbench/track/format.hpp"
#include "workbench/track/psd.hpp"

namespace rb::track {

using detail::num;

const char* channelName(Channel c) {
  switch (c) {
    case Channel::Alignment:
      return "alignment";
    case Channel::Vertical:
      return "vertical";
    case Channel::Gauge:
      return "gauge";
    case Channel::CrossLevel:
      return "cross_level";
  }
  return "?";
}

std::uint64_t channelSeed(std::uint64_t seed, Channel c) {
  // SplitMix64 (Steele, Lea, Flood 2014) applied to a per-channel offset of the seed.
  std::uint64_t z = seed + (static_cast<std::uint64_t>(c) + 1u) * 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

CosineSeries makeCosineSeries(const IrregularitySpec& spec, Channel c) {
  const auto spectrum = parseSpectrum(spec.spectrum);
  RB_CHECK(spectrum.has_value(), "unknown spectrum '" + spec.spectrum + "'");
  RB_CHECK(spec.components >= 1 && spec.wavelength_min > 0.0 &&
               spec.wavelength_max > spec.wavelength_min,
           "invalid synthesis band");
  const auto n = static_cast<std::size_t>(spec.components);
  const auto ci = static_cast<std::size_t>(c);
  const double lo = 2.0 * std::numbers::pi / spec.wavelength_max;
  const double hi = 2.0 * std::numbers::pi / spec.wavelength_min;
  const double dOmega = (hi - lo) / static_cast<double>(n);
  const bool active =
      spec.enabled[ci] && (*spectrum != Spectrum::User || !spec.user[ci].omega.empty());
  std::mt19937_64 rng(channelSeed(spec.seed, c));
  CosineSeries out;
  out.omega.resize(n);
  out.amplitude.resize(n);
  out.phase.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    out.phase[k] = 2.0 * std::numbers::pi * uniform01(rng);
    const double offset = spec.randomize_frequencies ? uniform01(rng) : 0.5;
    out.omega[k] = lo + (static_cast<double>(k) + offset) * dOmega;
    const double g = !active                       ? 0.0
                     : *spectrum == Spectrum::User ? psdTableValue(spec.user[ci], out.omega[k])
                                                   : spectrumPsd(*spectrum, c, out.omega[k]);
    out.amplitude[k] = spec.scale * std::sqrt(2.0 * g * dOmega);
  }
  return out;
}

void evaluateCosineSeries(const CosineSeries& series, double h, std::span<double> out) {
  constexpr std::size_t kBlock = 256;
  const std::size_t n = series.omega.size();
  std::vector<double> c(n), s(n), cd(n), sd(n);
  const double* amp = series.amplitude.data();
  for (std::size_t k = 0; k < n; ++k) {
    cd[k] = std::cos(series.omega[k] * h);
    sd[k] = std::sin(series.omega[k] * h);
  }
  for (std::size_t j0 = 0; j0 < out.size(); j0 += kBlock) {
    const double s0 = static_cast<double>(j0) * h;
    for (std::size_t k = 0; k < n; ++k) {
      const double arg = series.omega[k] * s0 + series.phase[k];
      c[k] = std::cos(arg);
      s[k] = std::sin(arg);
    }
    const std::size_t j1 = std::min(out.size(), j0 + kBlock);
    for (std::size_t j = j0; j < j1; ++j) {
      // Four partial sums in a fixed order (k mod 4): deterministic, and not limited by the
      // latency of one long chain of additions.
      double a0 = 0.0, a1 = 0.0, a2 = 0.0, a3 = 0.0;
      std::size_t k = 0;
      for (; k + 4 <= n; k += 4) {
        a0 += amp[k] * c[k];
        a1 += amp[k + 1] * c[k + 1];
        a2 += amp[k + 2] * c[k + 2];
        a3 += amp[k + 3] * c[k + 3];
      }
      for (; k < n; ++k) a0 += amp[k] * c[k];
      out[j] = (a0 + a1) + (a2 + a3);
      // Advance every phase by Omega_k h (element-wise, vectorisable).
      for (std::size_t q = 0; q < n; ++q) {
        const double cn = c[q] * cd[q] - s[q] * sd[q];
        s[q] = s[q] * cd[q] + c[q] * sd[q];
        c[q] = cn;
      }
    }
  }
}

IrregularityTable synthesizeIrregularities(const IrregularitySpec& spec, double track_length) {
  RB_CHECK(spec.step > 0.0 && track_length > 0.0, "invalid synthesis length or step");
  const auto intervals =
      static_cast<std::size_t>(std::max(1.0, std::ceil(track_length / spec.step - 1e-9)));
  IrregularityTable t;
  t.s.resize(intervals + 1);
  for (std::size_t j = 0; j <= intervals; ++j) t.s[j] = static_cast<double>(j) * spec.step;
  for (int c = 0; c < kChannels; ++c) {
    auto& ch = t.channel[static_cast<std::size_t>(c)];
    ch.assign(t.s.size(), 0.0);
    const CosineSeries series = makeCosineSeries(spec, static_cast<Channel>(c));
    if (std::all_of(series.amplitude.begin(), series.amplitude.end(),
                    [](double a) { return a == 0.0; })) {
      continue;
    }
    evaluateCosineSeries(series, spec.step, ch);
  }
  return t;
}

Irregularities::Irregularities(IrregularityTable table, double rail_lr)
    : table_(std::move(table)), rail_lr_(rail_lr) {
  RB_CHECK(rail_lr_ > 0.0, "rail_lr must be > 0");
  std::vector<std::vector<double>> ys(table_.channel.begin(), table_.channel.end());
  spline_ = CubicSplineSet(SplineGrid(table_.s), ys, SplineEnd::NotAKnot);
}

IrregularityPoint Irregularities::at(double s) const {
  IrregularityPoint p;
  if (!(s >= table_.s.front() && s <= table_.s.back())) return p;
  spline_.eval(s, p.xi, p.xi_s, p.xi_ss);
  const auto a = static_cast<std::size_t>(Channel::Alignment);
  const auto v = static_cast<std::size_t>(Channel::Vertical);
  const auto g = static_cast<std::size_t>(Channel::Gauge);
  const auto c = static_cast<std::size_t>(Channel::CrossLevel);
  p.y_l = p.xi[a] + 0.5 * p.xi[g];
  p.y_r = p.xi[a] - 0.5 * p.xi[g];
  p.z_l = p.xi[v] + 0.5 * p.xi[c];
  p.z_r = p.xi[v] - 0.5 * p.xi[c];
  p.delta = (p.z_l - p.z_r) / (2.0 * rail_lr_);
  p.y_l_s = p.xi_s[a] + 0.5 * p.xi_s[g];
  p.y_r_s = p.xi_s[a] - 0.5 * p.xi_s[g];
  p.z_l_s = p.xi_s[v] + 0.5 * p.xi_s[c];
  p.z_r_s = p.xi_s[v] - 0.5 * p.xi_s[c];
  p.delta_s = (p.z_l_s - p.z_r_s) / (2.0 * rail_lr_);
  return p;
}

namespace {

std::string_view trim(std::string_view v) {
  const auto b = v.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = v.find_last_not_of(" \t\r\n");
  return v.substr(b, e - b + 1);
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> out;
  char sep = 0;
  if (line.find(',') != std::string_view::npos) {
    sep = ',';
  } else if (line.find(';') != std::string_view::npos) {
    sep = ';';
  }
  if (sep != 0) {
    std::size_t start = 0;
    while (true) {
      const auto pos = line.find(sep, start);
      out.push_back(trim(line.substr(start, pos == std::string_view::npos ? pos : pos - start)));
      if (pos == std::string_view::npos) break;
      start = pos + 1;
    }
  } else {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
      const std::size_t b = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
      if (i > b) out.push_back(line.substr(b, i - b));
    }
  }
  return out;
}

bool parseDouble(std::string_view text, double& x) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto r = std::from_chars(text.data(), text.data() + text.size(), x);
  return r.ec == std::errc() && r.ptr == text.data() + text.size() && std::isfinite(x);
}

constexpr const char* kColumns[5] = {"s", "alignment", "vertical", "gauge", "cross_level"};
constexpr std::size_t kMaxCsvErrors = 20;

}  // namespace

std::optional<IrregularityTable> parseIrregularityCsv(std::istream& in,
                                                      const std::string& file_name,
                                                      Diagnostics& diags) {
  const std::string prefix = "irregularity csv: ";
  IrregularityTable t;
  std::size_t errors = 0;
  auto report = [&](int line, const std::string& msg) {
    ++errors;
    if (errors <= kMaxCsvErrors) {
      diags.add({file_name, line}, prefix + msg);
    } else if (errors == kMaxCsvErrors + 1) {
      diags.add({file_name, line}, prefix + "further errors not shown");
    }
  };
  std::string raw;
  int lineNo = 0;
  bool firstContent = true;
  while (std::getline(in, raw)) {
    ++lineNo;
    std::string_view line = raw;
    if (const auto hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    line = trim(line);
    if (line.empty()) continue;
    const auto fields = splitFields(line);
    double vals[5] = {0, 0, 0, 0, 0};
    bool numeric = fields.size() == 5;
    std::size_t badField = 0;
    for (std::size_t i = 0; numeric && i < 5; ++i) {
      if (!parseDouble(fields[i], vals[i])) numeric = false, badField = i;
    }
    const bool header = firstContent && !numeric &&
                        std::none_of(fields.begin(), fields.end(), [](std::string_view f) {
                          double x;
                          return parseDouble(f, x);
                        });
    firstContent = false;
    if (header) continue;
    if (fields.size() != 5) {
      report(lineNo, "expected 5 columns (s, alignment, vertical, gauge, cross_level), got " +
                         std::to_string(fields.size()));
      continue;
    }
    if (!numeric) {
      report(lineNo, "column " + std::to_string(badField + 1) + " (" + kColumns[badField] +
                         ") is not a finite number: '" + std::string(fields[badField]) + "'");
      continue;
    }
    if (!t.s.empty() && !(vals[0] > t.s.back())) {
      report(lineNo, "s = " + num(vals[0]) +
                         " m must be greater than the previous s = " + num(t.s.back()) + " m");
      continue;
    }
    t.s.push_back(vals[0]);
    for (std::size_t c = 0; c < 4; ++c) t.channel[c].push_back(vals[c + 1]);
  }
  if (errors == 0 && t.s.size() < 2) {
    report(0, "at least 2 data rows are required, got " + std::to_string(t.s.size()));
  }
  if (errors > 0) return std::nullopt;
  return t;
}

std::optional<IrregularityTable> readIrregularityCsv(const std::string& path, const SourceLoc& loc,
                                                     Diagnostics& diags) {
  std::ifstream in(path);
  if (!in) {
    diags.add(loc, "track.irregularities: cannot read csv file '" + path + "'");
    return std::nullopt;
  }
  return parseIrregularityCsv(in, path, diags);
}

}  // namespace rb::track
