#pragma once
// The Shen-Hedrick-Elkins creep force law: Z. Y. Shen, J. K. Hedrick and J. A. Elkins, "A
// comparison of alternative creep force models for rail vehicle dynamic analysis", Proceedings of
// the 8th IAVSD Symposium (1983), Swets & Zeitlinger, 591-605. Kalker's linear forces
// (kalkerLinearForce, kalker.hpp coefficients) are scaled down together so that their resultant
// follows the cubic saturation curve Johnson and Vermeulen derived for a circular patch
// (J. Appl. Mech. 31 (1964) 350-354):
//
//   F_R   = sqrt(F_x^2 + F_y^2)                                   (linear theory)
//   u     = F_R / (mu N)
//   F_R'  = mu N (u - u^2 / 3 + u^3 / 27)   for u <= 3,   mu N   for u > 3
//   F_x'  = eps F_x,  F_y' = eps F_y,  eps = F_R' / F_R              (forces on the WHEEL)
//
// so the law equals Kalker's linear theory at small creepage (eps = 1 - u/3 + ...), its resultant
// rises monotonically to mu N, reaches it with zero slope at u = 3 and stays there. The direction
// of the resultant is that of the linear forces (the spin's lateral term C23 included), unlike
// Polach's, whose direction follows the creepages.
//
// Spin moment: the law as published saturates the forces; the spin moment returned here is
// Kalker's linear M_z scaled by the same eps (an ASSUMPTION, as several implementations do; it uses
// the UNVERIFIED C33 of kalker.hpp). Only the wear number T gamma reads it.
//
// Limits without NaN: N <= 0, mu <= 0 or a degenerate patch give zero forces; zero creepage gives
// zero force. Pure and allocation-free.
#include "workbench/creep/creepages.hpp"
#include "workbench/creep/polach.hpp"

namespace rb::creep {

struct SaturatedCreepForce {
  double fx = 0.0;  // [N] longitudinal force on the wheel
  double fy = 0.0;  // [N] lateral force on the wheel
  double mz = 0.0;  // [N m] spin moment on the wheel (see above: an assumption)
};

// The saturation factor eps(u) = (u - u^2/3 + u^3/27) / u for u <= 3, 1/u above (1 at u = 0).
double shenHedrickElkinsFactor(double u);

// p.mu and p.G are used (mu constant: the 2005 falling friction of polach.hpp does not apply).
SaturatedCreepForce shenHedrickElkinsForce(const CreepParams& p, const ContactPatch& patch,
                                           const Creepages& s);

}  // namespace rb::creep
