#pragma once
// Wear number T-gamma and frictional power of a wheel/rail contact patch (the energy dissipated
// by creep per unit distance rolled; Pearce & Sherratt, Wear 144 (1991) 343-351; the Whole Life
// Rail Model, Burstow, RSSB 2003; Iwnicki (ed.), Handbook of Railway Vehicle Dynamics, 2006,
// chapter on wheel-rail contact). Formulas and assumptions: docs/assessment.md.
//
//   T gamma = |F_x nu_x| + |F_y nu_y| + |M_z phi|        [N = J/m]
//   P       = T gamma V                                  [W]
// with F_x, F_y the longitudinal and lateral creep forces [N], nu_x, nu_y the creepages [-],
// M_z the spin moment [N m] and phi the spin creepage [1/m] (the spin term is left out when M_z is
// not known), and V the rolling speed [m/s]: the creep forces times the slip velocities nu V.
// A wheel's value is the sum over its contact patches.
#include <span>

namespace rb::assessment::wear {

struct PatchCreep {
  double fx = 0.0;   // longitudinal creep force [N]
  double fy = 0.0;   // lateral creep force [N]
  double mz = 0.0;   // spin moment [N m] (0 when not known)
  double nux = 0.0;  // longitudinal creepage [-]
  double nuy = 0.0;  // lateral creepage [-]
  double phi = 0.0;  // spin creepage [1/m]
};

// T gamma of one patch [N].
double tGamma(const PatchCreep& p);

// Frictional power of one patch at rolling speed V [m/s]: T gamma V [W].
double frictionalPower(const PatchCreep& p, double speed);

// T gamma per sample of one patch [N]; mz and phi may be empty (no spin term). All non-empty
// inputs and out have the same length.
void tGammaSeries(std::span<const double> fx, std::span<const double> fy,
                  std::span<const double> mz, std::span<const double> nux,
                  std::span<const double> nuy, std::span<const double> phi, std::span<double> out);

// Adds a patch's series into a wheel's total (the sum over the wheel's patches).
void addPatch(std::span<double> wheel_total, std::span<const double> patch);

struct WearSummary {
  double mean = 0.0;    // mean T gamma over the samples [N]
  double max = 0.0;     // largest T gamma [N]
  double energy = 0.0;  // dissipated energy: integral of T gamma over distance s [J]
};
// Summary of a T gamma series over the distances s [m] of its samples (trapezoidal rule).
WearSummary summarize(std::span<const double> tgamma, std::span<const double> s);

}  // namespace rb::assessment::wear
