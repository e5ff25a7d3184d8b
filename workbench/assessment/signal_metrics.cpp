#include "workbench/assessment/signal_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "workbench/core/strings.hpp"

namespace rb::assessment::metrics {
namespace {

const std::vector<std::string> kStatNames = {"max", "min", "max_abs",           "mean",
                                             "rms", "std", "half_peak_to_peak", "final"};

// Mean of y[first, last).
double meanOf(const std::vector<double>& y, std::size_t first, std::size_t last) {
  double sum = 0.0;
  for (std::size_t k = first; k < last; ++k) sum += y[k];
  return sum / static_cast<double>(last - first);
}

double statOver(const std::vector<double>& y, std::size_t first, std::size_t last, Stat s) {
  const auto b = y.begin() + static_cast<std::ptrdiff_t>(first);
  const auto e = y.begin() + static_cast<std::ptrdiff_t>(last);
  const double n = static_cast<double>(last - first);
  switch (s) {
    case Stat::Max:
      return *std::max_element(b, e);
    case Stat::Min:
      return *std::min_element(b, e);
    case Stat::MaxAbs: {
      double m = 0.0;
      for (auto it = b; it != e; ++it) m = std::max(m, std::fabs(*it));
      return m;
    }
    case Stat::Mean:
      return meanOf(y, first, last);
    case Stat::Rms: {
      double sq = 0.0;
      for (auto it = b; it != e; ++it) sq += *it * *it;
      return std::sqrt(sq / n);
    }
    case Stat::Std: {
      // Two passes: the mean first, so a large offset does not cancel the variance.
      const double m = meanOf(y, first, last);
      double sq = 0.0;
      for (auto it = b; it != e; ++it) sq += (*it - m) * (*it - m);
      return std::sqrt(sq / n);
    }
    case Stat::HalfPeakToPeak: {
      const auto [lo, hi] = std::minmax_element(b, e);
      return 0.5 * (*hi - *lo);
    }
    case Stat::Final:
      return y[last - 1];
  }
  return std::nan("");
}

// The first NaN or infinity of y[first, last), as a reason; "" when there is none.
std::string nonFinite(const std::vector<double>& x, const std::vector<double>& y, std::size_t first,
                      std::size_t last) {
  for (std::size_t k = first; k < last; ++k)
    if (!std::isfinite(y[k]))
      return "the signal is " + formatNumber(y[k]) + " at " + formatNumber(x[k]);
  return {};
}

}  // namespace

const std::vector<std::string>& statNames() {
  return kStatNames;
}

bool statFromName(const std::string& name, Stat& out) {
  const auto it = std::find(kStatNames.begin(), kStatNames.end(), name);
  if (it == kStatNames.end()) return false;
  out = static_cast<Stat>(it - kStatNames.begin());
  return true;
}

bool windowRange(const std::vector<double>& x, std::size_t ny, const Window& w, std::size_t& first,
                 std::size_t& last, std::string& why) {
  if (x.size() != ny) {
    why = "the signal has " + std::to_string(ny) + " samples but its abscissa " +
          std::to_string(x.size());
    return false;
  }
  if (x.empty()) {
    why = "the signal has no samples";
    return false;
  }
  // One sample spacing of slack: a window end at the run's end must not depend on where the last
  // output sample happened to fall.
  const double slack = x.size() > 1 ? std::fabs(x[x.size() - 1] - x[x.size() - 2]) : 0.0;
  if (std::isfinite(w.to) && w.to > x.back() + slack) {
    why =
        "the window ends at " + formatNumber(w.to) + " but the signal at " + formatNumber(x.back());
    return false;
  }
  if (std::isfinite(w.from) && w.from < x.front() - slack) {
    why = "the window starts at " + formatNumber(w.from) + " but the signal at " +
          formatNumber(x.front());
    return false;
  }
  first = 0;
  while (first < x.size() && !(x[first] >= w.from)) ++first;
  last = first;
  while (last < x.size() && x[last] <= w.to) ++last;
  if (last == first) {
    why = "no sample in the window [" + formatNumber(w.from) + ", " + formatNumber(w.to) + "]";
    return false;
  }
  return true;
}

Value statistic(const std::vector<double>& x, const std::vector<double>& y, const Window& w,
                Stat s) {
  std::size_t first = 0, last = 0;
  std::string why;
  if (!windowRange(x, y.size(), w, first, last, why)) return Value::fail(why);
  if (std::string bad = nonFinite(x, y, first, last); !bad.empty()) return Value::fail(bad);
  Value v;
  v.value = statOver(y, first, last, s);
  return v;
}

Value steady(const std::vector<double>& x, const std::vector<double>& y, const Window& w,
             double length, double tolerance) {
  std::size_t first = 0, last = 0;
  std::string why;
  if (!windowRange(x, y.size(), w, first, last, why)) return Value::fail(why);
  if (std::string bad = nonFinite(x, y, first, last); !bad.empty()) return Value::fail(bad);
  const double span = x[last - 1] - x[first];
  const double part = length > 0.0 ? length : kSteadyFraction * span;
  const double start = x[last - 1] - part;
  std::size_t p = first;
  while (p < last && x[p] < start) ++p;
  if (last - p < 2) return Value::fail("fewer than 2 samples in the last " + formatNumber(part));
  Value v;
  v.value = meanOf(y, p, last);
  const std::size_t mid = p + (last - p) / 2;
  const double drift = std::fabs(meanOf(y, mid, last) - meanOf(y, p, mid));
  const double half = statOver(y, p, last, Stat::HalfPeakToPeak);
  const double tol =
      tolerance >= 0.0 ? tolerance : kSteadyRelTol * statOver(y, p, last, Stat::MaxAbs);
  if (drift > tol || half > tol)
    v.note = "not steady over the last " + formatNumber(part) + " (drift " + formatNumber(drift) +
             ", half peak-to-peak " + formatNumber(half) + " > tolerance " + formatNumber(tol) +
             ")";
  return v;
}

bool interpolate(const std::vector<double>& x, const std::vector<double>& y, double xq,
                 double& out) {
  if (x.empty() || x.size() != y.size() || !(xq >= x.front() && xq <= x.back())) return false;
  // The last sample at or before xq: a query at a sample returns that sample exactly.
  const auto it = std::upper_bound(x.begin(), x.end(), xq);
  const std::size_t k = static_cast<std::size_t>(it - x.begin()) - 1;
  if (x[k] == xq || k + 1 == x.size()) {
    out = y[k];
    return true;
  }
  const double t = (xq - x[k]) / (x[k + 1] - x[k]);
  out = y[k] + t * (y[k + 1] - y[k]);
  return true;
}

Value maxAbsDifference(const std::vector<double>& x, const std::vector<double>& y,
                       const std::vector<double>& xr, const std::vector<double>& yr,
                       const Window& w) {
  std::size_t first = 0, last = 0;
  std::string why;
  if (!windowRange(xr, yr.size(), w, first, last, why)) return Value::fail("reference: " + why);
  if (x.size() != y.size() || x.empty()) return Value::fail("the case's signal has no samples");
  // The rule of every comparison of runs (study/run_error.hpp): a non-finite value of either
  // signal (a diverged run) is an infinite error, never a value left out or no value at all.
  std::string bad = nonFinite(xr, yr, first, last);
  if (!bad.empty()) bad = "reference: " + bad;
  if (bad.empty()) bad = nonFinite(x, y, 0, x.size());
  if (!bad.empty()) {
    Value v;
    v.value = std::numeric_limits<double>::infinity();
    v.note = bad + ": a diverged run, an infinite error";
    return v;
  }
  // Reference samples beyond the case's range by less than one of its sample spacings are left
  // out: two runs sampled in time end a fraction of a spacing apart along the track.
  const double slack = x.size() > 1 ? std::fabs(x[x.size() - 1] - x[x.size() - 2]) : 0.0;
  Value v;
  v.value = 0.0;
  std::size_t used = 0;
  for (std::size_t k = first; k < last; ++k) {
    double yi = 0.0;
    if ((xr[k] < x.front() && xr[k] >= x.front() - slack) ||
        (xr[k] > x.back() && xr[k] <= x.back() + slack))
      continue;
    ++used;
    if (!interpolate(x, y, xr[k], yi))
      return Value::fail("the reference's sample at " + formatNumber(xr[k]) +
                         " is outside the case's range [" + formatNumber(x.front()) + ", " +
                         formatNumber(x.back()) + "]");
    v.value = std::max(v.value, std::fabs(yi - yr[k]));
  }
  if (used == 0) return Value::fail("no reference sample inside the case's range");
  return v;
}

}  // namespace rb::assessment::metrics
