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
  bool empty() const { return diags_.empty(); }

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

// MiniProf files (Greenwood Engineering's profile instrument; .whl wheels, .ban rails, .mpt
// several profiles or profile parts). No published specification was available; the layout was
// learnt from the example files of the CONTACT test bank (eve70a/CONTACT d431cdb, testbank/
// profiles/*.whl, *.ban, SNX00500.mpt, examples/MBench_UIC60_v3.ban) and from CONTACT's reader
// (matlab/read_miniprof.m, Apache-2.0), which was read, not copied:
// - "Old" files (a line "MINIPROF ..." among the first three): free-text header lines, among them
//   "Sd Sh qR" followed by "(Sd/Sh/qR)"; the points follow the first empty line.
// - Keyword files (.whl, .ban): "Key=Value" header lines (ColumnDef, XYPoints, Sd, Sh, qR, ...),
//   then the points, with or without an empty line between.
// - .mpt files: "[FileInfo]", "[Profile<N>Info]" (keywords) and "[Profile<N>Points]" sections.
// - `"`, `%` and `!` start a comment; MiniProf and CONTACT mark dropped points with a leading `"`
//   (counted by XYPoints, so they count for the truncation check).
// - Coordinates are in millimetres (no file states a unit; the coordinate plausibility check
//   refuses metres).
enum class MiniprofLayout { Old, Keyword, Multi };

bool asciiIEquals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c + 32) : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

// All tokens numeric: their values; otherwise an empty vector.
std::vector<double> numbers(std::string_view text) {
  std::vector<double> v;
  for (const std::string_view t : tokens(text)) {
    double x = 0.0;
    if (!parseNumber(t, x)) return {};
    v.push_back(x);
  }
  return v;
}

class MiniprofReader {
 public:
  MiniprofReader(std::string path, ProfileKind kind) : path_(std::move(path)), kind_(kind) {}

  void line(std::string_view raw, int ln) {
    const SourceLoc loc{path_, ln};
    if (raw.find('\0') != std::string_view::npos) {
      diags_.add(loc, "NUL byte in the file: a MiniProf profile is text");
      diags_.throwIfAny();
    }
    if (ln <= 3 && raw.find("MINIPROF") != std::string_view::npos) layout_ = MiniprofLayout::Old;
    const std::string_view whole = trim(raw);
    if (ln == 1 && whole == "[FileInfo]") layout_ = MiniprofLayout::Multi;
    if (whole.empty()) {
      if (layout_ == MiniprofLayout::Old) afterBlank_ = true;
      return;
    }
    const std::size_t cut = whole.find_first_of("\"%!");
    const std::string_view text = trim(whole.substr(0, std::min(cut, whole.size())));
    if (text.empty()) {
      // A commented-out point in the data: XYPoints counts it.
      if (inData() && whole.front() == '"' && !numbers(whole.substr(1)).empty()) ++commented_;
      return;
    }
    if (layout_ == MiniprofLayout::Multi && text.front() == '[' && text.back() == ']') {
      section(text, loc);
      return;
    }
    if (const auto eq = text.find('='); eq != std::string_view::npos) {
      if (!y_.empty() && layout_ != MiniprofLayout::Multi) {
        diags_.add(loc, "a header line after the profile points");
        return;
      }
      keyword(trim(text.substr(0, eq)), trim(text.substr(eq + 1)), loc);
      return;
    }
    std::vector<double> v = numbers(text);
    if (!inData() || (layout_ == MiniprofLayout::Keyword && v.empty() && y_.empty())) {
      headerText(text, v, loc);
      return;
    }
    point(text, v, loc);
  }

  bool full() const { return diags_.full(); }

  ProfilePoints finish(int lastLine, ProfileFileInfo* info) {
    const SourceLoc end{path_, lastLine};
    if (columnsLine_ != 0 && (xCol_ < 0 || yCol_ < 0)) {
      diags_.add(SourceLoc{path_, columnsLine_},
                 "ColumnDef names no X and Y column: the profile's coordinates are unknown");
    }
    if (y_.empty() && diags_.empty()) {
      diags_.add(end,
                 "no profile points: the header is not followed by data (the file is cut "
                 "short?)");
    } else if (y_.size() < kMinPoints && diags_.empty()) {
      diags_.add(end, "only " + std::to_string(y_.size()) + " profile points; at least " +
                          std::to_string(kMinPoints) + " are needed");
    }
    if (declared_ >= 0 && diags_.empty() &&
        static_cast<long long>(y_.size()) + static_cast<long long>(commented_) != declared_) {
      diags_.add(end, "XYPoints = " + std::to_string(declared_) + " (line " +
                          std::to_string(declaredLine_) + ") but the file holds " +
                          std::to_string(y_.size() + commented_) +
                          " point lines: the file is truncated or was edited");
    }
    diags_.throwIfAny();
    ProfilePoints pts;
    pts.file = path_;
    pts.kind = kind_;
    pts.unitsHint = "MiniProf files are in millimetres";
    pts.endLine = lastLine;
    orient(pts);
    pts.line = lines_;
    if (info != nullptr) {
      info->format = "MiniProf";
      if (sd_ && sh_ && qr_) {
        info->hasHeaderDimensions = true;
        info->headerSd = *sd_ * 1e-3;
        info->headerSh = *sh_ * 1e-3;
        info->headerQr = *qr_ * 1e-3;
        info->headerDimensionsLine = dimLine_;
      }
    }
    return pts;
  }

 private:
  bool inData() const {
    switch (layout_) {
      case MiniprofLayout::Old:
        return afterBlank_;
      case MiniprofLayout::Multi:
        return inPoints_;
      case MiniprofLayout::Keyword:
        return true;
    }
    return true;
  }

  void section(std::string_view name, const SourceLoc& loc) {
    inPoints_ = name.starts_with("[Profile") && name.ends_with("Points]");
    if (!inPoints_) return;
    if (++profiles_ > 1) {
      diags_.add(loc, "a second profile in the file (" + std::string(name) +
                          "): railbench reads one profile per file; keep the one wanted");
      diags_.throwIfAny();
    }
  }

  void keyword(std::string_view key, std::string_view value, const SourceLoc& loc) {
    auto num = [&](std::optional<double>& out) {
      if (value.empty()) return;  // a keyword the instrument left empty
      double v = 0.0;
      if (!parseNumber(value, v)) {
        diags_.add(
            loc, "non-numeric value for " + std::string(key) + ": \"" + std::string(value) + "\"");
        return;
      }
      out = v;
      dimLine_ = loc.line;
    };
    if (asciiIEquals(key, "ColumnDef")) {
      columnsLine_ = loc.line;
      columns_ = 0;
      xCol_ = yCol_ = -1;
      std::size_t b = 0;
      while (b <= value.size()) {
        const std::size_t e = std::min(value.find(',', b), value.size());
        const std::string_view c = trim(value.substr(b, e - b));
        if (c == "X") xCol_ = columns_;
        if (c == "Y") yCol_ = columns_;
        ++columns_;
        b = e + 1;
      }
    } else if (asciiIEquals(key, "XYPoints")) {
      double v = 0.0;
      if (!parseNumber(value, v) || v < 0.0 || v > static_cast<double>(kMaxProfilePoints) ||
          v != std::floor(v)) {
        diags_.add(loc, "XYPoints must be a point count up to " +
                            std::to_string(kMaxProfilePoints) + ", got \"" + std::string(value) +
                            "\"");
        return;
      }
      declared_ = static_cast<long long>(v);
      declaredLine_ = loc.line;
    } else if (asciiIEquals(key, "Sd")) {
      num(sd_);
    } else if (asciiIEquals(key, "Sh")) {
      num(sh_);
    } else if (asciiIEquals(key, "qR")) {
      num(qr_);
    } else if (asciiIEquals(key, "WheelDiameterTaperline")) {
      // The instrument's tape line, from the flange back. railbench's wheel frame has it at 70 mm
      // (EN 13715); another tape line would shift the wheel against profiles.back_to_back.
      std::optional<double> tape;
      num(tape);
      if (tape && std::abs(*tape - kTapeX) > 1e-9) {
        diags_.add(loc, "the tape line is " + formatNumber(*tape) +
                            " mm from the flange back; railbench reads wheels whose tape circle "
                            "is 70 mm from it (EN 13715)");
      }
    }
  }

  // Header text; old files give "Sd Sh qR" before "(Sd/Sh/qR)", on the same line or the one
  // before it.
  void headerText(std::string_view text, const std::vector<double>& v, const SourceLoc& loc) {
    if (!v.empty()) {
      lastNumbers_ = v;
      lastNumbersLine_ = loc.line;
      return;
    }
    const auto mark = text.find("(Sd/Sh/qR)");
    if (mark == std::string_view::npos) return;
    std::vector<double> d = numbers(trim(text.substr(0, mark)));
    int at = loc.line;
    if (d.empty() && lastNumbersLine_ == loc.line - 1) {
      d = lastNumbers_;
      at = lastNumbersLine_;
    }
    if (d.size() == 3) {
      sd_ = d[0];
      sh_ = d[1];
      qr_ = d[2];
      dimLine_ = at;
    }
  }

  void point(std::string_view text, const std::vector<double>& v, const SourceLoc& loc) {
    if (v.empty()) {
      diags_.add(loc, "non-numeric profile data \"" + std::string(text) + "\"");
      return;
    }
    const std::size_t need = columnsLine_ != 0 ? static_cast<std::size_t>(columns_) : 2;
    if (columnsLine_ != 0 ? v.size() != need : v.size() < need) {
      diags_.add(loc,
                 "expected " + std::to_string(need) + " values" +
                     (columnsLine_ != 0 ? " (ColumnDef, line " + std::to_string(columnsLine_) + ")"
                                        : std::string(" (X Y)")) +
                     ", got " + std::to_string(v.size()));
      return;
    }
    if (y_.size() == kMaxProfilePoints) {
      diags_.add(loc, tooManyPoints());
      diags_.throwIfAny();
    }
    const int xi = columnsLine_ != 0 ? std::max(xCol_, 0) : 0;
    const int yi = columnsLine_ != 0 ? std::max(yCol_, 0) : 1;
    x_.push_back(v[static_cast<std::size_t>(xi)]);
    y_.push_back(v[static_cast<std::size_t>(yi)]);
    lines_.push_back(loc.line);
  }

  // Which way is up is not written in the files (the benchmark rail MBench_UIC60_v3.ban has Y
  // down, the measured ones Y up), so it is read from the shape: a wheel's flange tip and a rail's
  // head are the highest part of the profile, above both of its ends (the flange back and the
  // outer face, the two flanks). Y up: the largest Y lies more than 1 mm above both ends; Y down:
  // the smallest lies more than 1 mm below both.
  void orient(ProfilePoints& pts) {
    trimFoldedEnds();
    const std::size_t n = x_.size();
    std::size_t lo = 0, hi = 0, top = 0, bottom = 0;
    for (std::size_t i = 1; i < n; ++i) {
      if (x_[i] < x_[lo]) lo = i;
      if (x_[i] > x_[hi]) hi = i;
      if (y_[i] > y_[top]) top = i;
      if (y_[i] < y_[bottom]) bottom = i;
    }
    constexpr double kRise = 1.0;  // [mm]
    double extent = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      extent = std::max({extent, std::abs(x_[i]), std::abs(y_[i])});
    double sign = 0.0;
    if (extent < 1.0) {
      // A wheel's shift by 70 mm would hide this from the unit check of profileFromPoints.
      throw InputError(SourceLoc{path_, lines_.front()},
                       "all coordinates are below 1 mm: the data seem to be in metres (MiniProf "
                       "files are in millimetres)");
    }
    if (y_[top] > std::max(y_[lo], y_[hi]) + kRise) {
      sign = 1.0;
    } else if (y_[bottom] < std::min(y_[lo], y_[hi]) - kRise) {
      sign = -1.0;
      top = bottom;
    } else {
      throw InputError(SourceLoc{path_, lines_[top]},
                       "cannot tell which way is up: no point lies 1 mm above (or below) both "
                       "ends of the profile, as a wheel's flange or a rail's head does");
    }
    const bool wheel = kind_ == ProfileKind::Wheel;
    if (wheel && !(x_[top] < kTapeX)) {
      throw InputError(SourceLoc{path_, lines_[top]},
                       "the flange tip lies at X = " + formatNumber(x_[top]) +
                           " mm, not between the flange back (X = 0) and the tape circle (X = "
                           "70 mm): a MiniProf wheel's X runs from the back of the flange");
    }
    // Wheel: s from the tape circle, toward the field side as the left wheel's (the files measure
    // X from the flange back toward the outer face), z the radius increase. Rail: X grows toward
    // the gauge side, so the left rail's s (field side positive) is -X. Evidence: CONTACT's
    // MBench_UIC60_v3.ban is its MBench_UIC60_v3.prr (gauge side at y < 0) with X = -y, and the
    // measured avg_HR.BAN reaches down the gauge face (to Y = -25 mm, for the gauge point 14 mm
    // below the top) at its X > 0 end and only 1.5 mm down on the other.
    const double x0 = wheel ? kTapeX : 0.0;
    const double sx = wheel ? 1.0 : -1.0;
    for (std::size_t i = 0; i < n; ++i) {
      pts.y.push_back(sx * (x_[i] - x0) * 1e-3);
      pts.z.push_back(sign * y_[i] * 1e-3);
    }
  }

  // A measured profile's near-vertical parts (a wheel's flange back and outer face, a rail's
  // flanks) may fold back in X: the instrument's points there stall or step backwards
  // (avg_wheel.whl repeats X = 139.70 mm down its outer face). Such steps are allowed where the
  // profile is steep (|dY| > 10 |dX|, the default slope cut of profileFromPoints, which would drop
  // these points anyway), and the points are cut to the longest run along which X advances. A
  // step backwards where the profile is flatter (a tread, a rail head, a flange tip measured with
  // a glitch) is refused at that step: cutting there would drop part of the running surface.
  void trimFoldedEnds() {
    const std::size_t n = x_.size();
    const double dir = x_[n - 1] > x_[0] ? 1.0 : -1.0;
    constexpr double kSteep = 10.0;
    for (std::size_t i = 1; i < n; ++i) {
      const double dx = x_[i] - x_[i - 1];
      if (dir * dx > 0.0 || dx == 0.0 || std::abs(y_[i] - y_[i - 1]) > kSteep * std::abs(dx))
        continue;
      throw InputError(SourceLoc{path_, lines_[i]},
                       "profile X values must advance: X = " + formatNumber(x_[i]) +
                           " mm follows X = " + formatNumber(x_[i - 1]) +
                           " mm where the profile is not steep (steps backwards are cut away "
                           "only on near-vertical flanks)");
    }
    std::size_t best = 0, len = 1, start = 0;
    for (std::size_t i = 1; i < n; ++i) {
      if (!(dir * (x_[i] - x_[i - 1]) > 0.0)) start = i;
      if (i - start + 1 > len) {
        len = i - start + 1;
        best = start;
      }
    }
    const auto keep = [&](auto& v) {
      v.erase(v.begin() + static_cast<std::ptrdiff_t>(best + len), v.end());
      v.erase(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(best));
    };
    keep(x_);
    keep(y_);
    keep(lines_);
  }

  static constexpr double kTapeX = 70.0;  // [mm] EN 13715 tape circle from the flange back

  std::string path_;
  ProfileKind kind_;
  FileDiagnostics diags_;
  MiniprofLayout layout_ = MiniprofLayout::Keyword;
  bool afterBlank_ = false, inPoints_ = false;
  int profiles_ = 0, columns_ = 0, xCol_ = -1, yCol_ = -1, columnsLine_ = 0;
  long long declared_ = -1;
  int declaredLine_ = 0, dimLine_ = 0, lastNumbersLine_ = 0;
  std::size_t commented_ = 0;
  std::vector<double> lastNumbers_;
  std::optional<double> sd_, sh_, qr_;
  std::vector<double> x_, y_;
  std::vector<int> lines_;
};

}  // namespace

ProfilePoints parseMiniprofPoints(std::string_view fileText, const std::string& path,
                                  ProfileKind kind, ProfileFileInfo* info) {
  Lines lines(fileText);
  MiniprofReader rd(path, kind);
  std::string_view raw;
  while (!rd.full() && lines.next(raw)) rd.line(raw, lines.count());
  return rd.finish(std::max(lines.count(), 1), info);
}

ProfilePoints readMiniprofPoints(const std::string& path, ProfileKind kind, ProfileFileInfo* info) {
  return parseMiniprofPoints(readProfileText(path), path, kind, info);
}

ProfileFormat profileFormat(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = c >= 'A' && c <= 'Z' ? static_cast<char>(c + 32) : c;
  if (ext == ".prw" || ext == ".prr") return ProfileFormat::Simpack;
  if (ext == ".whl" || ext == ".ban" || ext == ".mpt") return ProfileFormat::Miniprof;
  if (ext == ".whe" || ext == ".rai") return ProfileFormat::Vampire;
  return ProfileFormat::Text;
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
                        const ProfileReadOptions& options, ProfileFileInfo* info) {
  switch (profileFormat(path)) {
    case ProfileFormat::Simpack: {
      const ProfilePoints pts = readSimpackPoints(path);
      if (pts.kind != kind) {
        throw InputError(SourceLoc{path, pts.kindLine},
                         std::string("the file holds a ") + kindName(pts.kind) + " profile, a " +
                             kindName(kind) + " profile is expected");
      }
      if (info != nullptr) info->format = "SIMPACK";
      return simpackProfile(pts, options);
    }
    case ProfileFormat::Miniprof: {
      // .whl holds a wheel and .ban a rail (the instrument's two modes); .mpt either.
      const std::string ext = std::filesystem::path(path).extension().string();
      const bool whl = ext.size() == 4 && (ext[1] == 'w' || ext[1] == 'W');
      const bool ban = ext.size() == 4 && (ext[1] == 'b' || ext[1] == 'B');
      if ((whl && kind != ProfileKind::Wheel) || (ban && kind != ProfileKind::Rail)) {
        throw InputError(SourceLoc{path, 1}, std::string("a MiniProf ") + ext + " file holds a " +
                                                 (whl ? "wheel" : "rail") + " profile, a " +
                                                 kindName(kind) + " profile is expected");
      }
      const ProfilePoints pts = readMiniprofPoints(path, kind, info);
      if (kind == ProfileKind::Wheel && !(options.r0 > 0.0)) {
        throw InputError(SourceLoc{path, 1},
                         "a MiniProf wheel profile gives the radius increase: the tape-circle "
                         "radius r0 is needed");
      }
      return profileFromPoints(pts, options, stem(path));
    }
    case ProfileFormat::Vampire:
      // No public VAMPIRE profile file or format description was found to verify a reader
      // against (docs/profiles.md), so none is guessed.
      throw InputError(SourceLoc{path, 1},
                       "VAMPIRE profile files (.whe, .rai) are not read: no public example or "
                       "format description was available to verify a reader; convert the profile "
                       "to two-column text (y z in mm)");
    case ProfileFormat::Text:
      break;
  }
  if (info != nullptr) info->format = "text";
  return readTextProfile(path, kind, units, options);
}

}  // namespace rb::profiles
