#include "workbench/track/irregularities.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <istream>
#include <numbers>
#include <sstream>
#include <string_view>

#include "workbench/core/files.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/track/format.hpp"
#include "workbench/track/psd.hpp"

namespace rb::track {

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

void applyFadeIn(IrregularityTable& t, double length) {
  if (!(length > 0.0)) return;
  for (std::size_t j = 0; j < t.s.size(); ++j) {
    const double s = t.s[j];
    if (s >= length) continue;
    const double w = s <= 0.0 ? 0.0 : 0.5 * (1.0 - std::cos(std::numbers::pi * s / length));
    for (auto& ch : t.channel) ch[j] *= w;
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
  applyFadeIn(t, spec.fade_in);
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

constexpr std::size_t kMaxCsvErrors = 20;

std::string lower(std::string_view v) {
  std::string out(v);
  for (char& ch : out) {
    if (ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
  }
  return out;
}

double unitFactor(CsvUnit u) {
  return u == CsvUnit::Millimetre ? 1e-3 : 1.0;
}
const char* unitName(CsvUnit u) {
  return u == CsvUnit::Millimetre ? "mm" : "m";
}

// One header field: a column name and, optionally, its unit in brackets ("alignment [mm]").
struct HeaderField {
  std::string name;
  std::string unit;  // empty if not given
  bool bracket_ok = true;
};

HeaderField parseHeaderField(std::string_view f) {
  HeaderField h;
  const auto open = f.find('[');
  if (open == std::string_view::npos) {
    h.name = lower(trim(f));
    return h;
  }
  const auto close = f.find(']', open);
  h.name = lower(trim(f.substr(0, open)));
  if (close == std::string_view::npos || !trim(f.substr(close + 1)).empty()) {
    h.bracket_ok = false;
    return h;
  }
  h.unit = lower(trim(f.substr(open + 1, close - open - 1)));
  return h;
}

// Column roles: -1 is s, 0..3 a Channel.
constexpr int kColumnS = -1;

// The measured-irregularity CSV read line by line: the header line (column names and units), then
// the data rows. Errors are collected (at most kMaxCsvErrors shown); any error rejects the file.
class MeasuredCsvReader {
 public:
  MeasuredCsvReader(const std::string& file_name, const CsvReadOptions& options, Diagnostics& diags)
      : file_name_(file_name),
        options_(options),
        diags_(diags),
        factor_(unitFactor(options.unit)) {}

  bool haveHeader() const { return have_header_; }
  std::size_t errors() const { return errors_; }

  // The header line; false when the file cannot be read further.
  bool header(const std::vector<std::string_view>& fields, int lineNo) {
    have_header_ = true;
    double x = 0.0;
    if (!fields.empty() && parseDouble(fields.front(), x)) {
      report(lineNo,
             "the first line must be a header naming the columns, e.g. 's, alignment, vertical, "
             "gauge, cross_level' (any order; a channel that is not named is zero)");
      return false;
    }
    const std::vector<std::string> names = headerNames(fields);
    const std::size_t before = errors_;
    std::array<bool, kChannels + 1> seen{};
    for (std::size_t i = 0; i < names.size(); ++i) headerColumn(i, names[i], lineNo, seen);
    if (errors_ == before) checkNamedColumns(seen, lineNo);
    return errors_ == before;
  }

  // One data row: s and the channels (in metres), checked and appended to the table.
  void row(const std::vector<std::string_view>& fields, int lineNo) {
    double s = 0.0;
    std::array<double, kChannels> v{};
    if (!parseRow(fields, lineNo, s, v)) return;
    IrregularityTable& t = out_.table;
    if (!(std::abs(s) <= kMaxTrackLength)) {
      report(lineNo, "s = " + formatNumberExact(s) + " m is beyond the longest track (" +
                         formatNumberExact(kMaxTrackLength) + " m)");
      return;
    }
    if (!t.s.empty() && !(s > t.s.back())) {
      report(lineNo, "s = " + formatNumberExact(s) + " m must be greater than the previous s = " +
                         formatNumberExact(t.s.back()) + " m");
      return;
    }
    noteImplausible(v, lineNo);
    if (static_cast<double>(t.s.size()) >= options_.max_rows) {
      if (!too_many_) {
        report(lineNo, "more than " + formatNumberExact(options_.max_rows) +
                           " data rows (track.max_points); raise track.max_points to read it");
      }
      too_many_ = true;
      return;
    }
    if (t.s.empty()) out_.first_line = lineNo;
    out_.last_line = lineNo;
    t.s.push_back(s);
    for (std::size_t c = 0; c < kChannels; ++c) t.channel[c].push_back(v[c]);
  }

  // End of the file: the implausible magnitudes, an empty file or too few rows.
  std::optional<MeasuredTable> finish(int lineNo) {
    reportImplausible();
    if (!have_header_) {
      report(0,
             "the file is empty: it needs a header naming the columns (s, alignment, vertical, "
             "gauge, cross_level) and at least 2 rows");
    } else if (errors_ == 0 && out_.table.s.size() < 2) {
      report(lineNo,
             "at least 2 data rows are required, got " + std::to_string(out_.table.s.size()));
    }
    if (errors_ > 0) return std::nullopt;
    return std::move(out_);
  }

 private:
  // Implausible magnitudes: reported once per channel (first line, largest value, count), so a
  // file in the wrong unit gives one clear message per column rather than one per row.
  struct Implausible {
    int line = 0;
    double first = 0.0;
    std::size_t count = 0;
  };

  void report(int line, const std::string& msg) {
    ++errors_;
    if (errors_ <= kMaxCsvErrors) {
      diags_.add({file_name_, line}, kPrefix + msg);
    } else if (errors_ == kMaxCsvErrors + 1) {
      diags_.add({file_name_, line}, kPrefix + "further errors not shown");
    }
  }

  // With white space between fields, "alignment [mm]" splits in two: rejoin the unit.
  static std::vector<std::string> headerNames(const std::vector<std::string_view>& fields) {
    std::vector<std::string> names;
    for (const auto f : fields) {
      if (!f.empty() && f.front() == '[' && !names.empty()) {
        names.back() += std::string(f);
      } else {
        names.emplace_back(f);
      }
    }
    return names;
  }

  // Header field i: a known, not repeated column name with a unit that agrees with the declared
  // one; its role is appended.
  void headerColumn(std::size_t i, const std::string& field, int lineNo,
                    std::array<bool, kChannels + 1>& seen) {
    const HeaderField h = parseHeaderField(field);
    const std::string col = "column " + std::to_string(i + 1);
    if (!h.bracket_ok) {
      report(lineNo, col + " '" + field + "': write a unit as name [unit], e.g. 'alignment [mm]'");
      return;
    }
    if (h.name.empty()) {
      report(lineNo, col + " has no name (columns: " + kKnownList + ")");
      return;
    }
    const auto it = std::find(kKnown.begin(), kKnown.end(), h.name);
    if (it == kKnown.end()) {
      const std::string hint = closestMatch(h.name, kKnown);
      report(lineNo, "unknown column '" + h.name + "'" +
                         (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                         "; columns: " + kKnownList);
      return;
    }
    const int r = static_cast<int>(it - kKnown.begin()) - 1;
    if (seen[static_cast<std::size_t>(r) + 1]) {
      report(lineNo, "column '" + h.name + "' is named twice");
      return;
    }
    seen[static_cast<std::size_t>(r) + 1] = true;
    if (!h.unit.empty()) checkUnit(h, r, lineNo);
    role_.push_back(r);
    col_name_.push_back(h.name);
  }

  // A unit in the header: s is in metres; a channel in m or mm, the declared unit.
  void checkUnit(const HeaderField& h, int r, int lineNo) {
    if (r == kColumnS && h.unit != "m") {
      report(lineNo, "column 's' is the arc length in metres, got unit '" + h.unit + "'");
    } else if (r != kColumnS && h.unit != "m" && h.unit != "mm") {
      report(lineNo, "column '" + h.name + "': unit '" + h.unit + "' is not m or mm");
    } else if (r != kColumnS && h.unit != unitName(options_.unit)) {
      report(lineNo, "column '" + h.name + "' is in " + h.unit +
                         " by its header, but the declared unit is " + unitName(options_.unit) +
                         " (measured { unit = \"" + h.unit + "\" } to read the file in " + h.unit +
                         ")");
    }
  }

  // The header names s and at least one channel.
  void checkNamedColumns(const std::array<bool, kChannels + 1>& seen, int lineNo) {
    if (!seen[0]) report(lineNo, "the header names no column 's' (arc length [m])");
    bool any = false;
    for (int c = 0; c < kChannels; ++c) {
      out_.present[static_cast<std::size_t>(c)] = seen[static_cast<std::size_t>(c) + 1];
      any = any || out_.present[static_cast<std::size_t>(c)];
    }
    if (!any) {
      report(lineNo,
             "the header names no irregularity column (alignment, vertical, gauge, "
             "cross_level)");
    }
  }

  // The numbers of a data row: s [m] and the channels scaled to metres.
  bool parseRow(const std::vector<std::string_view>& fields, int lineNo, double& s,
                std::array<double, kChannels>& v) {
    if (fields.size() != role_.size()) {
      std::string names;
      for (const auto& n : col_name_) names += (names.empty() ? "" : ", ") + n;
      report(lineNo, "expected " + std::to_string(role_.size()) + " columns (" + names + "), got " +
                         std::to_string(fields.size()));
      return false;
    }
    for (std::size_t i = 0; i < fields.size(); ++i) {
      double x = 0.0;
      if (!parseDouble(fields[i], x)) {
        report(lineNo, "column " + std::to_string(i + 1) + " (" + col_name_[i] +
                           ") is not a finite number: '" + std::string(fields[i]) + "'");
        return false;
      }
      if (role_[i] == kColumnS) {
        s = x;
      } else {
        v[static_cast<std::size_t>(role_[i])] = x * factor_;
      }
    }
    return true;
  }

  void noteImplausible(const std::array<double, kChannels>& v, int lineNo) {
    for (std::size_t c = 0; c < kChannels; ++c) {
      if (std::abs(v[c]) > kMaxIrregularity) {
        Implausible& im = implausible_[c];
        if (im.count++ == 0) {
          im.line = lineNo;
          im.first = v[c];
        }
      }
    }
  }

  void reportImplausible() {
    for (std::size_t c = 0; c < kChannels; ++c) {
      const Implausible& im = implausible_[c];
      if (im.count == 0) continue;
      const std::string name = channelName(static_cast<Channel>(c));
      std::string msg =
          name + " = " + formatNumberExact(im.first / factor_) + " " + unitName(options_.unit);
      if (options_.unit == CsvUnit::Millimetre) msg += " (" + formatNumberExact(im.first) + " m)";
      msg += " is larger than a track irregularity can be (" + formatNumberExact(kMaxIrregularity) +
             " m)";
      if (im.count > 1) msg += " here and on " + std::to_string(im.count - 1) + " more rows";
      if (options_.unit == CsvUnit::Metre) {
        msg += "; is the file in millimetres? Declare it: measured { unit = \"mm\" }";
      }
      report(im.line, msg);
    }
  }

  inline static const std::string kPrefix = "irregularity csv: ";
  inline static const std::vector<std::string> kKnown = {"s", "alignment", "vertical", "gauge",
                                                         "cross_level"};
  inline static const std::string kKnownList = "s, alignment, vertical, gauge, cross_level";

  const std::string& file_name_;
  const CsvReadOptions& options_;
  Diagnostics& diags_;
  double factor_;
  MeasuredTable out_;
  std::size_t errors_ = 0;
  std::vector<int> role_;              // per column
  std::vector<std::string> col_name_;  // per column, for messages
  bool have_header_ = false;
  std::array<Implausible, kChannels> implausible_{};
  bool too_many_ = false;
};

}  // namespace

std::optional<MeasuredTable> parseMeasuredCsv(std::string_view text, const std::string& file_name,
                                              const CsvReadOptions& options, Diagnostics& diags) {
  MeasuredCsvReader reader(file_name, options, diags);
  std::size_t pos = 0;
  int lineNo = 0;
  while (pos < text.size()) {
    auto eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view line = text.substr(pos, eol - pos);
    pos = eol + 1;
    ++lineNo;
    if (const auto hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    line = trim(line);
    if (line.empty()) continue;
    const auto fields = splitFields(line);
    if (!reader.haveHeader()) {
      if (!reader.header(fields, lineNo)) return std::nullopt;
      continue;
    }
    reader.row(fields, lineNo);
  }
  return reader.finish(lineNo);
}

std::optional<MeasuredTable> readMeasuredCsv(const std::string& path, const SourceLoc& loc,
                                             const CsvReadOptions& options, Diagnostics& diags) {
  std::string why;
  const std::optional<std::string> text = readRegularFile(path, why);
  if (!text) {
    diags.add(loc, "track.irregularities: csv file '" + detail::displayPath(path) + "': " + why);
    return std::nullopt;
  }
  return parseMeasuredCsv(*text, detail::displayPath(path), options, diags);
}

std::optional<IrregularityTable> parseIrregularityCsv(std::istream& in,
                                                      const std::string& file_name,
                                                      Diagnostics& diags) {
  std::ostringstream text;
  text << in.rdbuf();
  auto t = parseMeasuredCsv(text.str(), file_name, CsvReadOptions{}, diags);
  if (!t) return std::nullopt;
  return std::move(t->table);
}

std::optional<IrregularityTable> readIrregularityCsv(const std::string& path, const SourceLoc& loc,
                                                     Diagnostics& diags) {
  auto t = readMeasuredCsv(path, loc, CsvReadOptions{}, diags);
  if (!t) return std::nullopt;
  return std::move(t->table);
}

}  // namespace rb::track
