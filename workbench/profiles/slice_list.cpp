#include "workbench/profiles/slice_list.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "workbench/core/error.hpp"
#include "workbench/core/files.hpp"
#include "workbench/core/strings.hpp"

namespace rb::profiles {
namespace {

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

struct Line {
  int number = 0;
  std::string text;  // without the comment
};

// The data lines: comments (from '%') removed, blank lines dropped.
std::vector<Line> dataLines(const std::string& content) {
  std::vector<Line> out;
  std::istringstream in(content);
  std::string raw;
  int n = 0;
  while (std::getline(in, raw)) {
    ++n;
    // A '%' inside a quoted file name is part of the name.
    bool quoted = false;
    char quote = 0;
    std::size_t cut = raw.size();
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const char c = raw[i];
      if (quoted) {
        quoted = c != quote;
      } else if (c == '\'' || c == '"') {
        quoted = true;
        quote = c;
      } else if (c == '%') {
        cut = i;
        break;
      }
    }
    std::string t = raw.substr(0, cut);
    if (t.find_first_not_of(" \t\r") == std::string::npos) continue;
    out.push_back({n, t});
  }
  return out;
}

// The leading numbers of a line (at most `max`), stopping at the first token that is not one.
std::vector<double> leadingNumbers(const std::string& text, std::size_t max) {
  std::istringstream in(text);
  std::vector<double> v;
  std::string tok;
  while (v.size() < max && in >> tok) {
    // Fortran-style exponents ("1.0d3") are numbers too.
    for (char& c : tok)
      if (c == 'd' || c == 'D') c = 'e';
    char* end = nullptr;
    const double x = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end != '\0' || !std::isfinite(x)) break;
    v.push_back(x);
  }
  return v;
}

}  // namespace

SliceList readSliceList(const std::string& path) {
  std::string why;
  const auto content = readRegularFile(path, why, std::size_t{4} << 20);
  if (!content) throw InputError(SourceLoc{path, 0}, "cannot read the slices-file: " + why);
  const std::vector<Line> lines = dataLines(*content);
  SliceList out;
  out.path = path;
  std::size_t k = 0;
  const auto next = [&](const char* what) -> const Line& {
    if (k >= lines.size())
      throw InputError(SourceLoc{path, lines.empty() ? 0 : lines.back().number},
                       std::string("the slices-file ends before ") + what);
    return lines[k++];
  };
  const auto numbers = [&](const Line& l, std::size_t n, const char* what) {
    const std::vector<double> v = leadingNumbers(l.text, n);
    if (v.size() < n)
      throw InputError(SourceLoc{path, l.number},
                       std::string("expected ") + what + ", got '" + trim(l.text) + "'");
    return v;
  };
  const auto count = [&](double x, int lo, int hi, const Line& l, const char* what) {
    if (!(x == std::floor(x) && x >= lo && x <= hi))
      throw InputError(SourceLoc{path, l.number},
                       std::string(what) + " must be a whole number in [" + std::to_string(lo) +
                           ", " + std::to_string(hi) + "], got " + formatNumber(x));
    return static_cast<int>(x);
  };
  const Line& l1 = next("U_OFFSET, U_SCALE");
  const std::vector<double> scale = numbers(l1, 2, "U_OFFSET U_SCALE (two numbers)");
  if (!(scale[1] > 0.0))
    throw InputError(SourceLoc{path, l1.number},
                     "U_SCALE must be > 0 [mm/usr], got " + formatNumber(scale[1]));
  const Line& l2 = next("NSLC");
  const int nslc = count(numbers(l2, 1, "NSLC (the number of slices)")[0], 1,
                         static_cast<int>(kMaxSlices), l2, "NSLC");
  const Line& l3 = next("NFEAT, NKINK, NACCEL");
  const std::vector<double> f = numbers(l3, 3, "NFEAT NKINK NACCEL (three whole numbers)");
  out.features = count(f[0], 0, 1000, l3, "NFEAT");
  out.kinks = count(f[1], 0, 1000, l3, "NKINK");
  out.accelerations = count(f[2], 0, 1000, l3, "NACCEL");
  const Line& l4 = next("U_INTPOL");
  const std::vector<double> ip = leadingNumbers(l4.text, 2);
  if (ip.empty()) numbers(l4, 1, "U_INTPOL (1 or 2)");
  out.interpolation = count(ip[0], 1, 2, l4, "U_INTPOL");
  if (ip.size() > 1 && ip[1] != 0.0)
    throw InputError(SourceLoc{path, l4.number},
                     "PERTURB = " + formatNumber(ip[1]) +
                         ": surface perturbations (corrugation, polygonisation) are not supported; "
                         "give PERTURB = 0");
  for (int i = 0; i < nslc; ++i) {
    const Line& l = next("its NSLC slices");
    const std::vector<double> u = leadingNumbers(l.text, 1);
    const std::size_t open = l.text.find_first_of("'\"");
    const std::size_t close =
        open == std::string::npos ? std::string::npos : l.text.find(l.text[open], open + 1);
    if (u.empty() || close == std::string::npos || close == open + 1)
      throw InputError(SourceLoc{path, l.number},
                       "slice " + std::to_string(i + 1) + " of " + std::to_string(nslc) +
                           " must be: U_SLC 'profile file', got '" + trim(l.text) + "'");
    SliceListEntry e;
    e.u_fc = scale[1] * (scale[0] + u[0]) * 1e-3;
    e.file = l.text.substr(open + 1, close - open - 1);
    e.line = l.number;
    if (!out.slices.empty() && !(e.u_fc - out.slices.back().u_fc >= 1e-6))
      throw InputError(SourceLoc{path, l.number},
                       "slice " + std::to_string(i + 1) + ": U_SLC = " + formatNumber(u[0]) +
                           " is not at least 0.001 mm after the slice before it (the slices must "
                           "be in increasing order)");
    out.slices.push_back(std::move(e));
  }
  return out;
}

}  // namespace rb::profiles
