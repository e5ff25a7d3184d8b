#pragma once
// Ride comfort of EN 12299:2009 (railway applications, ride comfort for passengers): the
// frequency weightings Wb, Wc, Wd (Annex A), the continuous comfort N_cx, N_cy, N_cz (6.7.1) and
// the mean comfort standard method N_MV (6.7.2). Formulas, parameters, sources and assumptions:
// docs/assessment.md.
//
// Weighting W(s) = H_h(s) H_l(s) H_t(s) H_s(s) (the ISO 2631-1 / ISO 8041 structure), w_i = 2 pi
// f_i:
//   H_h = s^2 / (s^2 + w1 s / Q1 + w1^2)                          band-limiting high-pass
//   H_l = w2^2 / (s^2 + w2 s / Q2 + w2^2)                         band-limiting low-pass
//   H_t = (1 + s / w3) / (1 + s / (Q4 w4) + s^2 / w4^2)           acceleration-velocity transition
//   H_s = K (1 + s / (Q5 w5) + s^2 / w5^2) / (1 + s / (Q6 w6) + s^2 / w6^2)   upward step
// (H_s is written with unit static gain times K, the convention of EN 12299's table, where Wb has
// K = 0.4; the ISO 8041 table writes the same Wb step with unit high-frequency gain and K = 1.024.)
// Each section is mapped to a digital section by the bilinear transform prewarped at its own
// characteristic frequency (f1, f2, f4, sqrt(f5 f6)).
//
// Accelerations in m/s^2 in the car-body frame (x longitudinal, y lateral, z vertical), sampled
// at dt [s]; comfort indices are dimensionless.
#include <complex>
#include <span>
#include <vector>

#include "workbench/assessment/signal.hpp"

namespace rb::assessment::en12299 {

enum class Weighting { Wb, Wc, Wd };

// Parameters of one weighting [Hz, -]; an infinite frequency drops its section.
struct WeightingParameters {
  double f1, Q1;          // band-limiting high-pass
  double f2, Q2;          // band-limiting low-pass
  double f3, f4, Q4;      // acceleration-velocity transition
  double f5, Q5, f6, Q6;  // upward step
  double K;               // gain
};
WeightingParameters parameters(Weighting w);

// The continuous weighting W(j 2 pi f) [-].
std::complex<double> response(Weighting w, double f_hz);

// The digital weighting filter at the sample interval dt. The band-limiting low-pass (f2 =
// 100 Hz) is left out when f2 >= 0.4 / dt: below 0.4 fs its gain differs from 1 by less than
// 2.6 % at 40 Hz, and the comfort bands end near 20 Hz.
Cascade weightingFilter(Weighting w, double dt);

// The weighted signal (the weighting applied to a).
std::vector<double> weighted(std::span<const double> a, Weighting w, double dt);

constexpr double kBlockDuration = 5.0;       // rms block length [s] (6.6.2)
constexpr double kComfortPercentile = 95.0;  // [%] (6.6.3)
constexpr double kComfortableLimit = 2.0;    // upper bound of the "comfortable" class [-]

// Comfort scale of EN 12299 (6.7): N < 1 very comfortable, 1 <= N < 2 comfortable, 2 <= N < 4
// medium, 4 <= N < 5 uncomfortable, N >= 5 very uncomfortable.
const char* comfortClass(double n);

// Mean comfort, standard method:
//   N_MV = 6 sqrt((a_XP95^Wd)^2 + (a_YP95^Wd)^2 + (a_ZP95^Wb)^2)
// with a_P95 the 95th percentile of the rms values of consecutive 5 s blocks of the weighted
// accelerations. The check's limit is the caller's target (default: the "comfortable" bound 2;
// EN 12299 sets no limit values).
struct MeanComfort {
  Check check;             // value = N_MV [-], limit [-], margin [-]
  double a_x95 = 0.0;      // a_XP95^Wd [m/s^2]
  double a_y95 = 0.0;      // a_YP95^Wd [m/s^2]
  double a_z95 = 0.0;      // a_ZP95^Wb [m/s^2]
  std::size_t blocks = 0;  // number of 5 s blocks (the standard asks for 60, i.e. 5 minutes)
};
MeanComfort meanComfort(std::span<const double> ax, std::span<const double> ay,
                        std::span<const double> az, double dt, double limit = kComfortableLimit);

enum class Axis { X, Y, Z };

// Continuous comfort N_c(t) = 4 a_rms^W(t): the rms over the trailing 5 s of the weighted
// acceleration, Wd for x and y, Wb for z [-], at every sample.
std::vector<double> continuousComfort(std::span<const double> a, Axis axis, double dt);

}  // namespace rb::assessment::en12299
