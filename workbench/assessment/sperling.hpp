#pragma once
// Sperling's ride index Wz (Sperling and Betzhold 1956; the weighting in the form used by
// Deutsche Bahn and the ORE C 116 reports, as given by Forstberg, "Ride comfort and motion
// sickness in tilting trains", KTH 2000, and Garg & Dukkipati, "Dynamics of railway vehicle
// systems", 1984). Formulas and assumptions: docs/assessment.md.
//
// For one harmonic of peak acceleration a [cm/s^2] at frequency f [Hz]:
//   Wz = (a^3 B(f)^3)^(1/10) = (a B(f))^0.3
// (the classical form Wz = 0.896 (a^3 F(f) / f)^(1/10) with Sperling's piecewise correction F(f)
// is the same law with a tabulated weighting). Several harmonics combine as
// Wz = (sum_i Wz_i^10)^(1/10). The vertical weighting, with f in Hz:
//   B_z(f) = 0.588 sqrt((1.911 f^2 + (0.25 f^2)^2) /
//                       ((1 - 0.277 f^2)^2 + (1.563 f - 0.0368 f^3)^2)),
// the lateral one B_y(f) = 1.25 B_z(f).
// B_z is |H(j f)| of the rational function (p = j f, f in Hz)
//   H(p) = 0.588 (sqrt(1.911) p + 0.25 p^2) / (1 + 1.563 p + 0.277 p^2 + 0.0368 p^3),
// which index() applies as a digital filter (bilinear transform) to a time series. For a random
// signal index() uses the energy form Wz = (100 sqrt(2) a_B,rms)^0.3, a_B,rms the rms of the
// B-weighted acceleration in m/s^2: the peak of a harmonic of the same rms, so a pure sine gives
// exactly the harmonic formula.
#include <span>

#include "workbench/assessment/signal.hpp"

namespace rb::assessment::sperling {

enum class Direction { Vertical, Lateral };

// Customary target for passenger vehicles (Wz = 2.5: "more pronounced but not unpleasant"); not
// a limit of a standard.
constexpr double kTargetIndex = 2.5;

// The weighting B(f) [s^2/m scaled for cm/s^2; dimensionless in Sperling's use].
double weighting(double f_hz, Direction d);

// The digital weighting filter at dt (its continuous form evaluated in weighting()).
Cascade weightingFilter(Direction d, double dt);

// Wz of one harmonic of peak acceleration amplitude [m/s^2] at f_hz.
double indexOfHarmonic(double amplitude, double f_hz, Direction d);

// Wz of an acceleration series [m/s^2] sampled at dt (energy form, whole series) against the
// caller's target.
Check index(std::span<const double> a, double dt, Direction d, double target = kTargetIndex);

}  // namespace rb::assessment::sperling
