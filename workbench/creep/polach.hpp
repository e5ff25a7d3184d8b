#pragma once
// Tangential wheel/rail contact forces (paper section 2.5: Polach creep theory [29, 30]).
//
// polachForce(): O. Polach, "A fast wheel-rail forces calculation computer code", Vehicle System
// Dynamics 33 (Suppl.) (1999) 728-739, with the optional extension of O. Polach, "Creep forces in
// simulations of traction vehicles running on adhesion limit", Wear 258 (2005) 992-1000.
// The formulas of these two papers:
//
//   s_yC = s_y + phi a  if |s_y + phi a| > |s_y|,  else s_y                 (1999, see below)
//   s_C  = sqrt(s_x^2 + s_yC^2),   s = sqrt(s_x^2 + s_y^2)
//   C    = sqrt((c11 s_x / s)^2 + (c22 s_y / s)^2)                           (Kalker, kalker.hpp)
//   eps  = pi G a b C s_C / (4 Q mu)                    (= (2/3) C_P pi a^2 b s_C / (Q mu))
//   F    = (2 Q mu / pi) (k_A eps / (1 + (k_A eps)^2) + atan(k_S eps))     (1999: k_A = k_S = 1)
//   K_M  = 1 + 6.3 (1 - exp(-a/b))                       (load-independent: a/b = m/n, hertz.hpp)
//   eps_s = (8/3) G b sqrt(a b) c23 |s_yC| / (Q mu K_M)
//   F_yS = (9/16) a Q mu K_M [eps_s (-d^3/3 + d^2/2 - 1/6) + (1 - d^2)^(3/2)/3] phi / s_C,
//          d = (eps_s^2 - 1)/(eps_s^2 + 1)
//        = (3/8) a Q mu K_M eps_s / (1 + eps_s^2)^2 * phi / s_C       (same expression, simplified:
//          -d^3/3 + d^2/2 - 1/6 = -(1 - d)^2 (2 d + 1)/6 gives the bracket 2 eps_s / (3 (1 +
//          eps_s^2)^2); no cancellation and no inf/inf at large eps_s)
//   F_x = -F s_x / D,   F_y = -(F s_y / D + w F_yS)                          (forces on the WHEEL)
//   w    = 1 / (1 + (k_S eps s / s_C)^2),   D = s + w (s_C - s)   (railbench; Polach: w = 1)
//
// Saturation. Polach's components F s_x / s_C and F s_y / s_C add up to F s / s_C, less than F
// whenever spin enlarges s_C (s_yC = s_y + phi a), while F_yS fades as eps_s grows: a patch that
// slides entirely carries only s / s_C of mu Q. Against Kalker's exact theory (CONTACT's results
// for the Manchester patches, tests/creep/test_creep_exact.cpp) that lost 3-7 % of mu Q on
// the flanging wheel's tread and 14-24 % on its flange, where CONTACT carries 0.997-1.000 mu Q
// along (s_x, s_y) within 1 degree: the spin's slip (-phi y, phi x) averages out over a sliding
// patch. The divisor D therefore moves from s_C to s as the creepage (s_x, s_y) on its own
// saturates the patch, with the adhesion weight w = 1 / (1 + eps_own^2) of eps_own = k_S eps s /
// s_C (the creep part's eps without the spin), and the spin's own share w F_yS fades with it.
// While the patch adheres w = 1 - O(eps_own^2), so the linear theory (Kalker's C11, C22 and C23
// at vanishing creepage) is Polach's exactly; at full sliding w -> 0, D -> s and |F| -> mu Q along
// (s_x, s_y); pure spin (s = 0) keeps w = 1. w weights F_yS whichever sign the spin has, so the
// force is continuous where s_yC switches (s_C = s there, and D = s_C). The resultant stays
// below mu Q without the cap over the test sweep. The weight is a choice of ours, not fitted to
// the reference: it is the simplest one with those two limits, and its effect in the transition
// is measured in docs/creep.md.
//
// Signs: creepages as in creepages.hpp (wheel relative to rail); the forces act on the wheel and
// oppose the creepage; the rail receives the opposite forces. Positive spin phi gives a NEGATIVE
// lateral force, as a positive s_y does (Kalker: F_y = -G c^2 C22 s_y - G c^3 C23 phi).
//
// The s_yC condition. The reference note transcribes Polach's definition as above, but notes that a
// Cython port of Polach's FORTRAN tests it the other way round (s_yC = s_y + phi a when
// |s_y + phi a| <= |s_y|). We use Polach's definition (an independent public Python implementation
// uses it too; the paper's full text was not accessible here): with the reversed test, pure spin
// (s_x = s_y = 0) gives s_C = 0 and therefore NO lateral force, whereas Polach's method is built to
// reproduce the spin force of Kalker's theory (small pure spin must give F_y -> -G c^3 c23 phi,
// which our test checks to < 1e-6). Polach's choice also guarantees s_C >= |s_yC| >= |phi a|/2, so
// phi / s_C stays bounded (<= 2/a) and the lateral force is continuous at zero creepage. Tests:
// Polach.SmallPureSpinEqualsKalkerLinear, Polach.SpinCorrectionCondition,
// Polach.PureSpinSignAndMagnitude.
//
// Friction (2005 option): mu(w) = mu_0 ((1 - A) exp(-B w) + A), w = s_C * V_ref the magnitude of
// the slip velocity [m/s] (Creepages::v); A = 1 (default) is constant friction. The reduction
// factors k_A, k_S apply to F only; the spin term F_yS is kept in its 1999 form (Polach 2005 was
// not available to check how it treats spin: UNVERIFIED).
//
// Limits handled without NaN: Q <= 0, mu <= 0 or a, b <= 0 give zero force; zero creepage gives
// zero force (the limit); very large creepage saturates to |F| -> mu Q. F itself is bounded by
// mu Q (1999 form and k_S <= k_A <= 1), but F_y' + F_yS is not bounded by construction; over
// physical creepages (|s| <= 1, |phi| <= 1e3 1/m) our sweeps found |F| <= mu Q, and at absurd
// combinations (|s_y| ~ 1e20 and more) it exceeded by 2e-4 relative, so the resultant is capped at
// mu Q.
//
// Spin moment: Polach's method gives none (M_z is not part of it); polachForce returns forces only.
// kalkerLinearForce() gives Kalker's linear M_z (with the UNVERIFIED C33).
//
// All functions are pure and allocation-free.
#include <string>

#include "workbench/creep/creepages.hpp"
#include "workbench/creep/hertz.hpp"
#include "workbench/creep/kalker.hpp"

namespace rb::creep {

// [-] The paper's friction coefficient (section 5.1): the default of contact.mu and of a creep
// law's parameters.
inline constexpr double kDefaultMu = 0.2364;

struct CreepParams {
  double mu = kDefaultMu;            // friction coefficient mu_0 [-] (paper section 5.1)
  double G = 2.1e11 / (2.0 * 1.28);  // shear modulus E / (2 (1 + nu)) [Pa] (paper: E, nu of 5.3)
  // Polach (2005) reduction factors of the initial slope, k_S <= k_A <= 1; 1, 1 = Polach (1999).
  double k_A = 1.0;
  double k_S = 1.0;
  // Polach (2005) falling friction mu(w) = mu ((1 - A) exp(-B w) + A); A = mu_inf / mu_0.
  double friction_A = 1.0;  // [-], 1 = constant friction
  double friction_B = 0.0;  // [s/m]
};

// Empty when the parameters are valid, else a description of the problem (for the scenario's
// diagnostics): mu >= 0, G > 0, 0 < k_S <= k_A <= 1, 0 <= A <= 1, B >= 0, all finite.
std::string creepParamsProblem(const CreepParams& p);

// Contact patch seen by the creep law.
struct ContactPatch {
  double Q = 0.0;    // normal force [N]
  double a = 0.0;    // semi-axis along the rolling direction [m]
  double b = 0.0;    // lateral semi-axis [m]
  double c11 = 0.0;  // Kalker coefficients at a/b and nu (kalker.hpp)
  double c22 = 0.0;
  double c23 = 0.0;
  double c33 = 0.0;  // UNVERIFIED (kalker.hpp); only kalkerLinearForce() uses it
  // Polach's spin factor K_M = polachSpinFactor(a / b) of the ellipse's shape, when the patch was
  // made from its PatchConstants (makeContactPatch); 0: polachForce computes it from a and b.
  double km = 0.0;
};

// Polach's (1999) spin factor K_M = 1 + 6.3 (1 - exp(-a/b)) for the semi-axis ratio a/b: a
// function of the ellipse's shape alone, not of its load.
double polachSpinFactor(double a_over_b);

// Hertz ellipse (hertz.hpp) and Kalker coefficients (kalker.hpp) for normal force N. N <= 0 gives
// a patch with Q = a = b = 0 (zero creep forces) and the coefficients of the load-independent
// shape.
ContactPatch makeContactPatch(const Material& mat, const RelativeCurvatures& k, double N);
// The same with a precomputed shape (hertzShape(k.A, k.B)): allocation- and iteration-free.
ContactPatch makeContactPatch(const Material& mat, const RelativeCurvatures& k,
                              const HertzShape& shape, double N);

// The load-independent part of makeContactPatch(mat, k, shape, N): Kalker coefficients, the Hertz
// coefficients of the semi-axes and the denominator of c0^3. A patch whose geometry is fixed while
// its normal force is iterated (the dynamics' normal/tangential fixed point: ~2 force
// evaluations per patch and rhs) computes them once.
struct PatchConstants {
  double denom = 0.0;  // 4 E* (A + B): c0 = cbrt(3 N / denom)
  double m = 1.0, n = 1.0;
  bool rolling_major = true;
  KalkerCoefficients c;
  // polachSpinFactor(a/b) with a/b = m/n (rolling major) or n/m: Polach's exponential once per
  // patch instead of once per force evaluation. The semi-axes' own ratio (m c0)/(n c0) can differ
  // from m/n in the last bit, so K_M may differ from the one of a hand-made patch by an ulp.
  double km = 1.0;
};
PatchConstants patchConstants(const Material& mat, const RelativeCurvatures& k,
                              const HertzShape& shape);
// Bit-identical to makeContactPatch(mat, k, shape, N) for pc = patchConstants(mat, k, shape).
ContactPatch makeContactPatch(const PatchConstants& pc, double N);

struct CreepForce {
  double fx = 0.0;  // longitudinal force on the wheel [N]
  double fy = 0.0;  // lateral force on the wheel [N]
  double mu = 0.0;  // friction coefficient used (mu(w) for falling friction) [-]
};

// mu(w) of the 2005 option at slip velocity w [m/s] (mu_0 when friction_A = 1).
double frictionCoefficient(const CreepParams& p, double slip_velocity);

CreepForce polachForce(const CreepParams& p, const ContactPatch& patch, const Creepages& s);

struct LinearCreepForce {
  double fx = 0.0;  // [N]
  double fy = 0.0;  // [N]
  double mz = 0.0;  // spin moment on the wheel about n [N m] (uses the UNVERIFIED C33)
};

// Kalker's linear theory (reference, unbounded): c = sqrt(a b),
// F_x = -G c^2 c11 s_x, F_y = -G c^2 c22 s_y - G c^3 c23 phi, M_z = G c^3 c23 s_y - G c^4 c33 phi.
LinearCreepForce kalkerLinearForce(double G, const ContactPatch& patch, const Creepages& s);

}  // namespace rb::creep
