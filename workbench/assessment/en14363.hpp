#pragma once
// Running safety and track loading assessment quantities of EN 14363 (acceptance of running
// characteristics of railway vehicles; the 2005 edition and UIC leaflet 518, 4th ed. 2009, share
// these definitions). Every formula, limit and assumption is listed in docs/assessment.md.
//
// Processing (EN 14363:2005 / UIC 518 table of assessment quantities, as tabulated in the GENSYS
// course notes "Acceptance test according to UIC 518 and EN 14363", gensys.se):
//   quantity        filter              processing                    statistic
//   (sum Y)_2m      low-pass 20 Hz      sliding mean 2 m, step 0.5 m  0.15 % / 99.85 %
//   (Y/Q)_2m        low-pass 20 Hz      sliding mean 2 m, step 0.5 m  0.15 % / 99.85 %
//   Q               low-pass 20 Hz      -                             99.85 %
//   Y_qst, Q_qst    low-pass 20 Hz      -                             50 %
//   instability     band-pass f0 +- 2 Hz sliding rms (100 m, 10 m)   maximum
// The low-pass is a 4th-order Butterworth filter (the standard states the cut-off frequency, not
// the filter type; assumption, see docs/assessment.md).
//
// Units: forces in N, distances in m, accelerations in m/s^2, masses in kg, angles in rad.
// Y is the lateral wheel/rail force and Q the vertical wheel/rail force in the track frame, per
// wheel; s the distance travelled at each sample; dt the sample interval.
#include <cstddef>
#include <span>
#include <vector>

#include "workbench/assessment/signal.hpp"

namespace rb::assessment::en14363 {

constexpr double kForceCutoff = 20.0;       // low-pass cut-off of the wheel forces [Hz]
constexpr double kSlidingWindow = 2.0;      // sliding-mean window of (sum Y) and Y/Q [m]
constexpr double kSlidingStep = 0.5;        // step of the sliding mean [m]
constexpr double kUpperPercentile = 99.85;  // F2 [%]
constexpr double kLowerPercentile = 0.15;   // F1 [%]
constexpr double kMedianPercentile = 50.0;  // F0, quasi-static values [%]
constexpr double kStabilityWindow = 100.0;  // sliding rms window of the stability criterion [m]
constexpr double kStabilityStep = 10.0;     // its step [m]
constexpr double kStabilityHalfBand = 2.0;  // band-pass f0 -+ 2 Hz [Hz]

constexpr double kDerailmentQuotientLimit = 0.8;   // (Y/Q)_lim for curve radii R >= 250 m [-]
constexpr double kWheelUnloadingLimit = 0.6;       // (dQ/Q0)_lim [-] (assumption, see the docs)
constexpr double kQuasiStaticGuidingLimit = 60e3;  // Y_qst,lim [N]
constexpr double kQuasiStaticWheelLimit = 145e3;   // Q_qst,lim [N]
constexpr double kTrackShiftAlphaPassenger = 1.0;  // alpha: locomotives, passenger vehicles [-]
constexpr double kTrackShiftAlphaFreight = 0.85;   // alpha: freight wagons [-]

// The wheel forces low-pass filtered at kForceCutoff (4th-order Butterworth). When the sampling
// rate is below 2.5 kForceCutoff (dt > 20 ms) the series is returned unfiltered: it has no
// content above 0.4 fs left to remove.
std::vector<double> lowPassForce(std::span<const double> x, double dt);

// Percentiles F1, F2 and extremes of a processed series (one track section).
struct Extremes {
  double upper = 0.0;     // 99.85 % percentile [unit of the series]
  double lower = 0.0;     // 0.15 % percentile [unit of the series]
  double max = 0.0;       // largest value [unit]
  double min = 0.0;       // smallest value [unit]
  std::size_t count = 0;  // values evaluated
};
Extremes extremes(std::span<const double> x);

// A sliding-mean quantity: the check uses the larger magnitude of F1 and F2 (the sign of the
// flanging direction depends on the wheel side and the curve direction, so both are assessed).
struct SlidingAssessment {
  Check check;            // value = max(|F2|, |F1|) of the 2 m sliding mean [unit], limit, margin
  Extremes stats;         // of the 2 m sliding mean
  DistanceSeries series;  // the 2 m sliding mean at its window ends
};

// Nadal's limit of flange climbing, (Y/Q)_lim = (tan(gamma) - mu) / (1 + mu tan(gamma)), for the
// flange angle gamma [rad] and the wheel/rail friction coefficient mu [-] (Nadal 1908; Iwnicki,
// Handbook of Railway Vehicle Dynamics, 2006, chapter on wheel-rail contact and derailment).
double nadalLimit(double flange_angle, double mu);

// Derailment quotient of one wheel: Y and Q low-pass filtered, Y/Q per sample, 2 m sliding mean
// (step 0.5 m), percentiles; limit 0.8 (EN 14363 for R >= 250 m). A lifted wheel (Q < 1 N)
// enters with Q = 1 N, so its quotient is large and fails the check.
SlidingAssessment derailmentQuotient(std::span<const double> Y, std::span<const double> Q,
                                     std::span<const double> s, double dt,
                                     double limit = kDerailmentQuotientLimit);

// Prud'homme limit of the track shift force, (sum Y)_lim = alpha (10 kN + 2 Q0 / 3) [N], with Q0
// the static vertical wheel force [N] (= alpha (10 kN + P / 3) with the static axle load
// P = 2 Q0).
double trackShiftLimit(double static_wheel_force, double alpha = kTrackShiftAlphaPassenger);

// Track shift force of one wheelset: sum Y = Y_left + Y_right (track frame, same sign
// convention for both wheels), low-pass filtered, 2 m sliding mean (step 0.5 m), percentiles,
// against trackShiftLimit(). [N]
SlidingAssessment trackShiftForce(std::span<const double> Y_left, std::span<const double> Y_right,
                                  std::span<const double> s, double dt, double static_wheel_force,
                                  double alpha = kTrackShiftAlphaPassenger);

// Wheel unloading dQ/Q0 = (Q0 - Q) / Q0 of the low-pass filtered Q against the static wheel force
// Q0 [N]: value = largest dQ/Q0 of the series [-], limit 0.6 [-].
Check wheelUnloading(std::span<const double> Q, double dt, double static_wheel_force,
                     double limit = kWheelUnloadingLimit);

// Quasi-static and dynamic values of a wheel force over one (curve) section: the low-pass
// filtered signal's 50 % value (quasi-static) and its 0.15 % / 99.85 % values (dynamic). [N]
struct SectionValues {
  double quasi_static = 0.0;  // F0 = 50 % [N]
  double upper = 0.0;         // F2 = 99.85 % [N]
  double lower = 0.0;         // F1 = 0.15 % [N]
};
SectionValues sectionValues(std::span<const double> x, double dt);

// Quasi-static guiding force |Y_qst| of the outer leading wheel in a curve against 60 kN.
Check quasiStaticGuidingForce(std::span<const double> Y, double dt,
                              double limit = kQuasiStaticGuidingLimit);
// Quasi-static vertical wheel force Q_qst of the outer wheel against 145 kN.
Check quasiStaticWheelForce(std::span<const double> Q, double dt,
                            double limit = kQuasiStaticWheelLimit);
// Maximum vertical wheel force (99.85 % of the filtered Q) against Q_lim = 90 kN + Q0 [N].
Check maximumWheelForce(std::span<const double> Q, double dt, double static_wheel_force);

// A wheel's Y and Q low-pass filtered once (lowPassForce) for every quantity above that reads
// them: the overloads taking it give the values of those taking the raw series and dt.
struct FilteredWheelForces {
  std::vector<double> Y, Q;  // [N]
};
FilteredWheelForces filterWheelForces(std::span<const double> Y, std::span<const double> Q,
                                      double dt);
SlidingAssessment derailmentQuotient(const FilteredWheelForces& f, std::span<const double> s,
                                     double limit = kDerailmentQuotientLimit);
Check wheelUnloading(const FilteredWheelForces& f, double static_wheel_force,
                     double limit = kWheelUnloadingLimit);
Check quasiStaticGuidingForce(const FilteredWheelForces& f,
                              double limit = kQuasiStaticGuidingLimit);
Check quasiStaticWheelForce(const FilteredWheelForces& f, double limit = kQuasiStaticWheelLimit);
Check maximumWheelForce(const FilteredWheelForces& f, double static_wheel_force);

// Limit of the sliding rms of the bogie-frame lateral acceleration, (12 - m+ / 5) / 2 [m/s^2]
// with the bogie mass m+ in t (given here in kg).
double bogieAccelerationLimit(double bogie_mass);

// Running stability, simplified method: the bogie-frame lateral acceleration (above a wheelset)
// band-pass filtered to f0 -+ 2 Hz (f0 the instability frequency [Hz], > 2 Hz; a second-order
// band-pass of unit gain at f0 and 4 Hz bandwidth, resonatorBandPass()), its sliding rms
// over 100 m in 10 m steps; value = the largest sliding rms [m/s^2] against
// bogieAccelerationLimit(). Needs at least 100 m of track.
struct StabilityAssessment {
  Check check;            // [m/s^2]
  double position = 0.0;  // window end of the largest sliding rms [m]
  DistanceSeries series;  // the sliding rms at its window ends
};
StabilityAssessment stability(std::span<const double> bogie_lateral_acc, std::span<const double> s,
                              double dt, double f0, double bogie_mass);

}  // namespace rb::assessment::en14363
