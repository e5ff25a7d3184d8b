#include "workbench/profiles/profile_io.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string_view>
#include <utility>

#include "workbench/core/error.hpp"
#include "workbench/core/files.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/profiles/sampling.hpp"
#include "workbench/profiles/smoothing_spline.hpp"

namespace rb::profiles {
namespace {

constexpr std::size_t kMinPoints = 10;
constexpr std::size_t kMaxDiagnostics = 20;
// [m] Kept points closer than this are duplicates for any profile measurement (the benchmark
// files have 1 nm steps only on the vertical flanks, which the slope filter cuts), and at subnormal
// spacings the spline system becomes singular.
constexpr double kMinPointSpacing = 1e-9;
// Point weights are relative; with ratios beyond this range the smoothing-spline system (terms
// lambda / w) loses its positive definiteness in floating point.
constexpr double kMinWeight = 1e-6;
constexpr double kMaxWeight = 1e6;

// True when alignedGrid(a, b, ds) has its minimum of 4 nodes inside [a, b] (the same test).
bool gridFits(double a, double b, double ds) {
  const double tol = 1e-9;
  return std::floor(b / ds + tol) - std::ceil(a / ds - tol) >= 3.0;
}

constexpr double kMinWheelRadius = 0.2;  // [m]
constexpr double kMaxWheelRadius = 0.7;  // [m]

std::string_view trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// Removes a `!` comment (outside single or double quotes).
std::string_view stripBang(std::string_view s) {
  char quote = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '!') {
      return s.substr(0, i);
    }
  }
  return s;
}

std::vector<std::string_view> tokens(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  auto sep = [](char c) { return c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r'; };
  while (i < s.size()) {
    while (i < s.size() && sep(s[i])) ++i;
    const std::size_t b = i;
    while (i < s.size() && !sep(s[i])) ++i;
    if (i > b) out.push_back(s.substr(b, i - b));
  }
  return out;
}

bool parseNumber(std::string_view t, double& v) {
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  return r.ec == std::errc() && r.ptr == t.data() + t.size() && std::isfinite(v);
}

// The lines of a text one at a time (without their '\n'), as views into it: a file of millions of
// lines costs no index of them.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const std::size_t e = text_.find('\n', pos_);
    const std::size_t end = e == std::string_view::npos ? text_.size() : e;
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++count_;
    return true;
  }
  int count() const { return count_; }  // lines returned so far = number of the last one

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int count_ = 0;
};

std::string readProfileText(const std::string& path) {
  std::string why;
  std::optional<std::string> text = readRegularFile(path, why, kMaxProfileFileBytes);
  if (!text) {
    throw InputError(SourceLoc{path, 0},
                     "cannot open profile file" + (why == "no such file" ? "" : ": " + why));
  }
  return std::move(*text);
}

// Diagnostics of one file, bounded: a file of garbage reports its first problems, not millions.
class FileDiagnostics {
 public:
  bool full() const { return diags_.size() >= kMaxDiagnostics; }
  void add(const SourceLoc& loc, std::string message) {
    if (full()) return;
    diags_.add(loc, std::move(message));
    if (full()) {
      diags_.add(loc, "too many problems; the rest of the file was not checked");
    }
  }
  void throwIfAny() const { diags_.throwIfAny(); }

 private:
  Diagnostics diags_;
};

std::string tooManyPoints() {
  return "more than " + std::to_string(kMaxProfilePoints) +
         " profile points (a measured profile has a few thousand): thin the data";
}

// Parses "y z [weight]"; on failure adds a diagnostic and returns false.
bool parsePoint(std::string_view text, const SourceLoc& loc, FileDiagnostics& diags, double& y,
                double& z, double& w) {
  const auto tk = tokens(text);
  double v[3] = {0.0, 0.0, 1.0};
  for (std::size_t i = 0; i < tk.size() && i < 3; ++i) {
    if (!parseNumber(tk[i], v[i])) {
      diags.add(loc, "non-numeric profile data \"" + std::string(tk[i]) + "\"");
      return false;
    }
  }
  if (tk.size() < 2 || tk.size() > 3) {
    diags.add(loc,
              "expected \"y z\" or \"y z weight\", got " + std::to_string(tk.size()) + " value(s)");
    return false;
  }
  if (!(v[2] > 0.0)) {
    diags.add(loc, "point weight must be positive, got " + formatNumber(v[2]));
    return false;
  }
  if (v[2] < kMinWeight || v[2] > kMaxWeight) {
    diags.add(loc, "point weight " + formatNumber(v[2]) + " is outside " +
                       formatNumber(kMinWeight) + " .. " + formatNumber(kMaxWeight) +
                       " (weights are relative: scale them)");
    return false;
  }
  y = v[0];
  z = v[1];
  w = v[2];
  return true;
}

std::string stem(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

// A SIMPACK profile file (.prw / .prr) read line by line: the header block (type), the spline
// block (units, mirroring; transformations and bounds are rejected) and the point block.
class SimpackReader {
 public:
  explicit SimpackReader(std::string path) : path_(std::move(path)) {}

  FileDiagnostics diags;
  bool inPoints = false;  // inside point.begin ... point.end

  // A line inside the point block: a point, point.end, or another block keyword (point.end is
  // missing).
  void pointLine(std::string_view text, int ln) {
    const SourceLoc loc{path_, ln};
    if (text == "point.end") {
      inPoints = false;
      pointEnd_ = ln;
      return;
    }
    if (text.ends_with(".end") || text.ends_with(".begin")) {
      inPoints = false;
      unterminated_ = true;
      block_ = text == "header.begin"   ? Block::Header
               : text == "spline.begin" ? Block::Spline
                                        : Block::None;
      return;
    }
    if (ry_.size() == kMaxProfilePoints) {
      diags.add(loc, tooManyPoints());
      diags.throwIfAny();
    }
    double y = 0, z = 0, w = 1;
    if (parsePoint(text, loc, diags, y, z, w)) {
      ry_.push_back(y);
      rz_.push_back(z);
      rw_.push_back(w);
      rl_.push_back(ln);
    }
  }

  // A line outside the point block: a block keyword or "key = value".
  void blockLine(std::string_view text, int ln) {
    const SourceLoc loc{path_, ln};
    if (text == "header.begin") {
      block_ = Block::Header;
    } else if (text == "spline.begin") {
      block_ = Block::Spline;
    } else if (text == "header.end" || text == "spline.end") {
      block_ = Block::None;
    } else if (text == "point.begin") {
      if (pointBegin_ != 0) diags.add(loc, "a second point.begin block");
      pointBegin_ = ln;
      inPoints = true;
    } else if (const auto eq = text.find('='); eq != std::string_view::npos) {
      const std::string_view key = trim(text.substr(0, eq));
      const std::string_view value = trim(text.substr(eq + 1));
      if (block_ == Block::Header && key == "type") {
        double v = 0.0;
        number(key, value, loc, v);
        // Only the exact values 0 and 1 name a type; anything else (0.5, 1e300, nan) must stay
        // invalid rather than be truncated, and a cast of a huge value to int is undefined.
        typeValue_ = v == 0.0 ? 0 : v == 1.0 ? 1 : -2;
        typeLine_ = ln;
      } else if (block_ == Block::Spline) {
        splineKey(key, value, ln);
      }
    }
  }

  // End of the file: block structure, unsupported bounds, the profile type (from the extension
  // when the header does not give it). Throws the collected diagnostics.
  void finish(int lastLine) {
    if (inPoints || unterminated_) {
      diags.add(SourceLoc{path_, pointBegin_}, "point.begin without point.end");
    } else if (pointBegin_ == 0) {
      diags.add(SourceLoc{path_, lastLine},
                "no point.begin ... point.end block with profile points");
    }
    for (int a = 0; a < 2; ++a) {
      if (boundMin_[a] < boundMax_[a]) {
        diags.add(SourceLoc{path_, unitLine_},
                  std::string(a == 0 ? "bound.y" : "bound.z") +
                      " limits are not supported (set min > max to disable them)");
      }
    }
    if (typeValue_ != 0 && typeValue_ != 1) {
      const std::string ext = std::filesystem::path(path_).extension().string();
      if (typeLine_ == 0 && (ext == ".prw" || ext == ".prr")) {
        typeValue_ = ext == ".prw" ? 1 : 0;
      } else {
        diags.add(SourceLoc{path_, typeLine_},
                  "header type must be 0 (rail profile) or 1 (wheel profile)");
      }
    }
    diags.throwIfAny();
  }

  // The points in metres, z up (rail z is downward in SIMPACK files), mirrored as the file says.
  ProfilePoints points() const {
    ProfilePoints pts;
    pts.file = path_;
    pts.kind = typeValue_ == 1 ? ProfileKind::Wheel : ProfileKind::Rail;
    pts.endLine = pointEnd_;
    pts.kindLine = typeLine_;
    pts.unitsHint = "set units.len.f (1000 for millimetres)";
    const double sy = mirrorY_ != 0.0 ? -1.0 : 1.0;
    const double szFile = mirrorZ_ != 0.0 ? -1.0 : 1.0;
    const double sz = pts.kind == ProfileKind::Rail ? -szFile : szFile;
    for (std::size_t i = 0; i < ry_.size(); ++i) {
      pts.y.push_back(sy * ry_[i] / unitFactor_);
      pts.z.push_back(sz * rz_[i] / unitFactor_);
      pts.w.push_back(rw_[i]);
      pts.line.push_back(rl_[i]);
    }
    return pts;
  }

 private:
  enum class Block { None, Header, Spline };

  void number(std::string_view key, std::string_view value, const SourceLoc& loc, double& out) {
    if (!parseNumber(value, out)) {
      diags.add(loc,
                "non-numeric value for " + std::string(key) + ": \"" + std::string(value) + "\"");
    }
  }

  // "key = value" in the spline block.
  void splineKey(std::string_view key, std::string_view value, int ln) {
    const SourceLoc loc{path_, ln};
    if (key == "units.len.f") {
      number(key, value, loc, unitFactor_);
      unitLine_ = ln;
      if (!(unitFactor_ > 0.0)) diags.add(loc, "units.len.f must be positive");
    } else if (key == "mirror.y") {
      number(key, value, loc, mirrorY_);
    } else if (key == "mirror.z") {
      number(key, value, loc, mirrorZ_);
    } else if (key == "shift.y" || key == "shift.z" || key == "rotate") {
      double v = 0.0;
      number(key, value, loc, v);
      if (v != 0.0) {
        diags.add(loc, std::string(key) + " = " + formatNumber(v) +
                           " is not supported (only 0); transform the points with "
                           "ProfileReadOptions instead");
      }
    } else if (key == "bound.y.min" || key == "bound.z.min") {
      number(key, value, loc, boundMin_[key == "bound.y.min" ? 0 : 1]);
    } else if (key == "bound.y.max" || key == "bound.z.max") {
      number(key, value, loc, boundMax_[key == "bound.y.max" ? 0 : 1]);
    }
  }

  std::string path_;
  Block block_ = Block::None;
  int typeValue_ = -1, typeLine_ = 0, pointBegin_ = 0, pointEnd_ = 0, unitLine_ = 0;
  double unitFactor_ = 1.0, mirrorY_ = 0.0, mirrorZ_ = 0.0;
  double boundMin_[2] = {1.0, 1.0}, boundMax_[2] = {0.0, 0.0};
  std::vector<double> ry_, rz_, rw_;
  std::vector<int> rl_;
  bool unterminated_ = false;
};

}  // namespace

ProfilePoints readSimpackPoints(const std::string& path) {
  return parseSimpackPoints(readProfileText(path), path);
}

ProfilePoints parseSimpackPoints(std::string_view fileText, const std::string& path) {
  Lines lines(fileText);
  SimpackReader rd(path);
  std::string_view raw;
  while (!rd.diags.full() && lines.next(raw)) {
    const int ln = lines.count();
    const std::string_view text = trim(stripBang(raw));
    if (text.empty()) continue;
    if (rd.inPoints) {
      rd.pointLine(text, ln);
    } else {
      rd.blockLine(text, ln);
    }
  }
  rd.finish(lines.count());
  return rd.points();
}

ProfilePoints readTextPoints(const std::string& path, ProfileKind kind, LengthUnit units) {
  return parseTextPoints(readProfileText(path), path, kind, units);
}

ProfilePoints parseTextPoints(std::string_view fileText, const std::string& path, ProfileKind kind,
                              LengthUnit units) {
  Lines lines(fileText);
  ProfilePoints pts;
  pts.file = path;
  pts.kind = kind;
  pts.unitsHint =
      units == LengthUnit::Metre ? "the units argument says m" : "the units argument says mm";
  const double f = units == LengthUnit::Metre ? 1.0 : 1e-3;
  FileDiagnostics diags;
  bool dataStarted = false;
  std::string_view raw;
  while (!diags.full() && lines.next(raw)) {
    const int ln = lines.count();
    std::string_view text = trim(raw);
    if (text.empty() || text.front() == '#' || text.front() == '!' || text.front() == '%' ||
        text.substr(0, 2) == "//") {
      continue;
    }
    text = trim(text.substr(0, std::min(text.find('#'), text.find('!'))));
    if (text.empty()) continue;
    const auto tk = tokens(text);
    double first = 0.0;
    // A header line (or one of separators only) before the data.
    if (!dataStarted && (tk.empty() || !parseNumber(tk.front(), first))) continue;
    dataStarted = true;
    if (pts.y.size() == kMaxProfilePoints) {
      diags.add(SourceLoc{path, ln}, tooManyPoints());
      diags.throwIfAny();
    }
    double y = 0, z = 0, w = 1;
    if (parsePoint(text, SourceLoc{path, ln}, diags, y, z, w)) {
      pts.y.push_back(f * y);
      pts.z.push_back(f * z);
      pts.w.push_back(w);
      pts.line.push_back(ln);
      pts.endLine = ln;
    }
  }
  diags.throwIfAny();
  if (pts.endLine == 0) pts.endLine = lines.count();
  return pts;
}

namespace {

// Plausibility of the length unit (coordinates in metres, |v| <= 1 m, extent >= 1 mm) and of the
// wheel radii r0 + z.
void checkCoordinates(const ProfilePoints& p, const ProfileReadOptions& opt) {
  const std::size_t n = p.y.size();
  auto at = [&](std::size_t i) { return SourceLoc{p.file, p.line[i]}; };
  double extent = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    for (const double v : {p.y[i], p.z[i]}) {
      if (std::abs(v) > 1.0) {
        throw InputError(at(i), "coordinate " + formatNumber(v) +
                                    " m is implausible for a profile (> 1 m): the data seem "
                                    "to be in millimetres (" +
                                    p.unitsHint + ")");
      }
      extent = std::max(extent, std::abs(v));
    }
  }
  if (extent < 1e-3) {
    throw InputError(at(0), "all coordinates are below 1 mm: the data seem to be in metres (" +
                                p.unitsHint + ")");
  }
  if (p.kind == ProfileKind::Wheel) {
    for (std::size_t i = 0; i < n; ++i) {
      const double r = opt.r0 + p.z[i];
      if (r < kMinWheelRadius || r > kMaxWheelRadius) {
        throw InputError(at(i), "wheel radius " + formatNumber(r) + " m (r0 " +
                                    formatNumber(opt.r0) + " + z " + formatNumber(p.z[i]) +
                                    ") is outside 0.2 .. 0.7 m: check r0 and the "
                                    "units");
      }
    }
  }
}

// Indices of the points in ascending y: y must be strictly monotone; decreasing files are
// reversed.
std::vector<std::size_t> ascendingOrder(const ProfilePoints& p) {
  const std::size_t n = p.y.size();
  auto at = [&](std::size_t i) { return SourceLoc{p.file, p.line[i]}; };
  const double dir = p.y[1] > p.y[0] ? 1.0 : -1.0;
  for (std::size_t i = 1; i < n; ++i) {
    if (!(dir * (p.y[i] - p.y[i - 1]) > 0.0)) {
      throw InputError(at(i),
                       "profile y values must be strictly monotone: y = " + formatNumber(p.y[i]) +
                           " m follows y = " + formatNumber(p.y[i - 1]) + " m");
    }
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = dir > 0 ? i : n - 1 - i;
  return order;
}

// A rail's cut keeps its head and drops what lies beyond a near-vertical flank: the flank's lower
// part, a floor, the web. Where the points beyond a cut first go down and then rise again by more
// than kRiseBeyondCut to within kWheelReach of the kept top, they are a second head (a wing rail
// beside a crossing nose, a check rail) or a step that a wheel's tread or flange can reach, and
// keeping one side of them would be a different rail: refused, at the highest such point.
constexpr double kRiseBeyondCut = 1.0e-3;  // [m]
constexpr double kWheelReach = 40.0e-3;    // [m] a flange's height (28 mm on S1002) with margin
void checkNothingReachableCut(const ProfilePoints& p, const std::vector<std::size_t>& order,
                              std::size_t begin, std::size_t len, double maxSlope) {
  const std::size_t n = order.size();
  double top = p.z[order[begin]];
  for (std::size_t k = begin; k < begin + len; ++k) top = std::max(top, p.z[order[k]]);
  std::size_t worst = n;
  double rise = 0.0;
  // Walk outward from one end of the kept run (step -1 or +1 through the ascending order).
  auto walk = [&](std::size_t from, bool left) {
    double lowest = p.z[order[from]];
    for (std::size_t k = from; left ? k-- > 0 : ++k < n;) {
      const std::size_t i = order[k];
      lowest = std::min(lowest, p.z[i]);
      const double up = p.z[i] - lowest;
      if (up > kRiseBeyondCut && p.z[i] > top - kWheelReach &&
          (worst == n || p.z[i] > p.z[worst])) {
        worst = i;
        rise = up;
      }
    }
  };
  walk(begin, true);
  walk(begin + len - 1, false);
  if (worst == n) return;
  throw InputError(
      SourceLoc{p.file, p.line[worst]},
      "the profile is kept from y = " + formatNumber(p.y[order[begin]]) + " to " +
          formatNumber(p.y[order[begin + len - 1]]) +
          " m (the longest run with |dz/dy| <= " + formatNumber(maxSlope) +
          "), but beyond a steeper flank it rises again by " + formatNumber(rise * 1e3) +
          " mm to a height the wheel reaches (y = " + formatNumber(p.y[worst]) +
          " m): a second rail head or a step would be cut away (give "
          "the slice a larger max_slope to keep every point, or cut the file to one head)");
}

}  // namespace

Profile profileFromPoints(const ProfilePoints& p, const ProfileReadOptions& opt, std::string name) {
  const std::size_t n = p.y.size();
  RB_CHECK(p.z.size() == n && p.line.size() == n && (p.w.empty() || p.w.size() == n),
           "ProfilePoints arrays differ in size");
  RB_CHECK(opt.ds > 0.0 && opt.maxSlope > 0.0 && opt.smoothingLength >= 0.0,
           "ProfileReadOptions: ds > 0, maxSlope > 0, smoothingLength >= 0");
  const bool wheel = p.kind == ProfileKind::Wheel;
  if (n < kMinPoints) {
    throw InputError(SourceLoc{p.file, p.endLine}, "only " + std::to_string(n) +
                                                       " profile points; at least " +
                                                       std::to_string(kMinPoints) + " are needed");
  }
  checkCoordinates(p, opt);
  const std::vector<std::size_t> order = ascendingOrder(p);
  // Longest run of consecutive points with |dz/dy| <= maxSlope.
  std::size_t bestBegin = 0, bestLen = 1, runBegin = 0;
  for (std::size_t k = 1; k < n; ++k) {
    const std::size_t a = order[k - 1], b = order[k];
    const double slope = (p.z[b] - p.z[a]) / (p.y[b] - p.y[a]);
    if (std::abs(slope) > opt.maxSlope) runBegin = k;
    if (k - runBegin + 1 > bestLen) {
      bestLen = k - runBegin + 1;
      bestBegin = runBegin;
    }
  }
  if (bestLen < kMinPoints) {
    throw InputError(SourceLoc{p.file, p.endLine},
                     "only " + std::to_string(bestLen) +
                         " consecutive points with |dz/dy| <= " + formatNumber(opt.maxSlope) +
                         "; at least " + std::to_string(kMinPoints) + " are needed");
  }
  if (!wheel) checkNothingReachableCut(p, order, bestBegin, bestLen, opt.maxSlope);
  std::vector<double> s, h, w;
  std::vector<int> lines;
  const double ca = std::cos(opt.rotate), sa = std::sin(opt.rotate);
  const double my = opt.mirrorY ? -1.0 : 1.0;
  for (std::size_t k = bestBegin; k < bestBegin + bestLen; ++k) {
    const std::size_t i = order[k];
    const double y = my * p.y[i], z = p.z[i];
    s.push_back(y * ca - z * sa + opt.shiftS);
    h.push_back(y * sa + z * ca + opt.shiftH + (wheel ? opt.r0 : 0.0));
    w.push_back(p.w.empty() ? 1.0 : p.w[i]);
    lines.push_back(p.line[i]);
  }
  if (opt.mirrorY) {
    std::reverse(s.begin(), s.end());
    std::reverse(h.begin(), h.end());
    std::reverse(w.begin(), w.end());
    std::reverse(lines.begin(), lines.end());
  }
  for (std::size_t k = 1; k < s.size(); ++k) {
    if (!(s[k] > s[k - 1])) {
      throw InputError(SourceLoc{p.file, lines[k]},
                       "after the rotation by " + formatNumber(opt.rotate) +
                           " rad the points are no longer ordered along y (lower maxSlope)");
    }
    if (!(s[k] - s[k - 1] >= kMinPointSpacing)) {
      throw InputError(SourceLoc{p.file, lines[k]},
                       "y = " + formatNumber(s[k]) +
                           " m is closer than 1 nm to the previous point (y = " +
                           formatNumber(s[k - 1]) + " m): merge or drop duplicate points");
    }
  }
  const double s0 = s.front(), s1 = s.back();
  if (!gridFits(s0, s1, opt.ds)) {
    throw InputError(SourceLoc{p.file, p.endLine},
                     "the kept points span only " + formatNumber(1e3 * (s1 - s0)) +
                         " mm along y; the profile grid needs at least 4 steps of " +
                         formatNumber(1e3 * opt.ds) + " mm inside them");
  }
  const double lambda = SmoothingSpline::lambdaForLength(s, w, opt.smoothingLength);
  const SmoothingSpline fit(std::move(s), h, std::move(w), lambda, SplineEnd::NotAKnot);
  const UniformGrid g = alignedGrid(s0, s1, opt.ds);
  std::vector<double> hv(g.n);
  for (std::size_t i = 0; i < g.n; ++i) hv[i] = fit.value(g.at(i));
  return Profile(std::move(name), p.kind, g.s0, g.ds, hv);
}

namespace {

Profile simpackProfile(const ProfilePoints& pts, const ProfileReadOptions& options) {
  if (pts.kind == ProfileKind::Wheel && !(options.r0 > 0.0)) {
    throw InputError(SourceLoc{pts.file, pts.kindLine},
                     "a SIMPACK wheel profile gives the radius increase: the tape-circle radius "
                     "r0 is needed");
  }
  return profileFromPoints(pts, options, stem(pts.file));
}

const char* kindName(ProfileKind k) {
  return k == ProfileKind::Wheel ? "wheel" : "rail";
}

}  // namespace

Profile readSimpackProfile(const std::string& path, const ProfileReadOptions& options) {
  return simpackProfile(readSimpackPoints(path), options);
}

Profile readTextProfile(const std::string& path, ProfileKind kind, LengthUnit units,
                        const ProfileReadOptions& options) {
  ProfilePoints points = readTextPoints(path, kind, units);
  if (options.mirrorZ)
    for (double& z : points.z) z = -z;
  return profileFromPoints(points, options, stem(path));
}

Profile readProfileFile(const std::string& path, ProfileKind kind, LengthUnit units,
                        const ProfileReadOptions& options) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".prw" || ext == ".prr") {
    const ProfilePoints pts = readSimpackPoints(path);
    if (pts.kind != kind) {
      throw InputError(SourceLoc{path, pts.kindLine}, std::string("the file holds a ") +
                                                          kindName(pts.kind) + " profile, a " +
                                                          kindName(kind) + " profile is expected");
    }
    return simpackProfile(pts, options);
  }
  return readTextProfile(path, kind, units, options);
}

}  // namespace rb::profiles
