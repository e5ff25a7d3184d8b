#pragma once
// Scalar metrics of one sampled signal over a window of its abscissa (distance along the track
// [m] or time [s]): the statistics a study extracts from each case (docs/studies.md, "Metrics").
// Pure functions: vectors in, a number (or the reason there is none) out.
//
// Window rule: the samples with from <= x <= to. A window that reaches beyond the sampled range
// by more than one sample spacing is refused (a run that stopped early must not give a maximum
// over the part it happened to cover), as is an empty window and a NaN inside the window.
#include <limits>
#include <string>
#include <vector>

namespace rb::assessment::metrics {

enum class Stat { Max, Min, MaxAbs, Mean, Rms, Std, HalfPeakToPeak, Final };

// "max", "min", "max_abs", "mean", "rms", "std", "half_peak_to_peak", "final".
const std::vector<std::string>& statNames();
bool statFromName(const std::string& name, Stat& out);

struct Window {
  double from = -std::numeric_limits<double>::infinity();
  double to = std::numeric_limits<double>::infinity();
};

// A metric's value, or why there is none (value NaN, why not empty). `note` qualifies a value
// that was computed (e.g. "not steady").
struct Value {
  double value = std::numeric_limits<double>::quiet_NaN();
  std::string why;
  std::string note;
  bool ok() const { return why.empty(); }
  static Value fail(std::string reason) {
    Value v;
    v.why = std::move(reason);
    return v;
  }
};

// Indices [first, last) of the samples inside `w`; false with `why` when the window is empty,
// reaches beyond the sampled range, or x and y differ in length.
bool windowRange(const std::vector<double>& x, std::size_t ny, const Window& w, std::size_t& first,
                 std::size_t& last, std::string& why);

// The statistic of y over the samples in the window. Std is the population standard deviation
// (divides by n); rms is sqrt(mean(y^2)); half_peak_to_peak is (max - min) / 2; final is the
// last sample inside the window.
Value statistic(const std::vector<double>& x, const std::vector<double>& y, const Window& w,
                Stat s);

// Steady-state value: the mean of y over the last `length` of the window (length <= 0: the last
// kSteadyFraction of the window). Steady when, over that part, both the drift (difference of the
// means of its two halves) and the half peak-to-peak are at most `tolerance` (tolerance < 0:
// kSteadyRelTol times the largest |y| of the part); otherwise the value is given with a note
// saying it is not steady and by how much.
inline constexpr double kSteadyFraction = 0.2;
inline constexpr double kSteadyRelTol = 0.01;
Value steady(const std::vector<double>& x, const std::vector<double>& y, const Window& w,
             double length, double tolerance);

// y(x) linearly interpolated at xq (x non-decreasing; exact at a sample: y[k] when xq == x[k]).
// False when xq is outside [x.front(), x.back()].
bool interpolate(const std::vector<double>& x, const std::vector<double>& y, double xq,
                 double& out);

// max |y(xr) - yr| over the reference samples xr inside the window, y interpolated onto them.
// Reference samples beyond the case's range by less than one of its sample spacings are left out;
// further out, the difference is refused (no extrapolation). A non-finite value of the case's
// signal or of the reference's inside the window is an infinite error with a note (the rule of
// study/run_error.hpp).
Value maxAbsDifference(const std::vector<double>& x, const std::vector<double>& y,
                       const std::vector<double>& xr, const std::vector<double>& yr,
                       const Window& w);

}  // namespace rb::assessment::metrics
