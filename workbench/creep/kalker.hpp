#pragma once
// Kalker's linear-theory creepage and spin coefficients C11, C22, C23 (and C33) for an elliptic
// contact, from Kalker, "Three-dimensional elastic bodies in rolling contact" (1990), Table E.3,
// as carried in tests/data/creep/kalker_creep_coefficients_tableE3.txt (C11, C22, C23 copied
// from CONTACT src/m_hertz.f90, subroutine linrol, Apache-2.0).
//
//   C33 is UNVERIFIED: no primary source was available for that column (the table file says so).
//   It is only used by kalkerLinearForce() for the spin moment, never by polachForce().
//
// Linear theory (sign convention of the table file; forces on the WHEEL, creepages of
// creepages.hpp, c = sqrt(a b)):
//   F_x = -G c^2 C11 s_x,  F_y = -G c^2 C22 s_y - G c^3 C23 phi,  M_z = G c^3 C23 s_y - G c^4 C33
//   phi
//
// Table layout: two halves of 10 rows each, both indexed by a ratio g <= 1 on the uniform grid
// 0.1, 0.2, ..., 1.0:
//   a <= b ("a<b" rows): g = a/b,       a = semi-axis in the ROLLING direction, b lateral;
//   a >  b ("a>b" rows): g = b/a.
// Both halves share the circular row g = 1, so the lookup is continuous in a/b.
// Interpolation: linear in g inside the half (as CONTACT's linrol) and linear in nu between the
// columns nu = 0, 0.25, 0.5. (CONTACT interpolates 1/C quadratically in nu; at nu = 0.28 the two
// differ by up to 1.7 % over the table, the largest for C23 at a/b = 0.1.)
// Beyond the table (g < 0.1: a/b < 0.1 or a/b > 10; flange patches reach a/b ~ 15-25) C11, C22
// and C23 come from Kalker's asymptotes for g -> 0 (kalkerAsymptote, the expressions of CONTACT's
// linrol and of the table file), scaled so that they meet the table's last row (they differ there
// by up to 7 %) with a scale that goes linearly to 1 as g -> 0: continuous in a/b, and exact in the
// limit. C33 (UNVERIFIED) keeps the last row's value. nu is clamped to [0, 0.5].
//
// Allocation-free (the table is a constexpr array), ~10 ns.

namespace rb::creep {

struct KalkerCoefficients {
  double c11 = 0.0;
  double c22 = 0.0;
  double c23 = 0.0;
  double c33 = 0.0;  // UNVERIFIED (see above)
};

// a_over_b = a/b with a along the rolling direction; nu Poisson's ratio. a_over_b must be > 0 and
// finite (always-on check).
KalkerCoefficients kalkerCoefficients(double a_over_b, double nu);

// Kalker's asymptotic C11, C22, C23 of a very elongated ellipse (exact as g = min(a/b, b/a) -> 0;
// c33 is left 0): a/b <= 1 uses the g = a/b branch, a/b > 1 the g = b/a branch. 0 <= nu < 1.
KalkerCoefficients kalkerAsymptote(double a_over_b, double nu);

// True when (a_over_b, nu) lies inside the table (no asymptote, no clamping).
bool kalkerInTable(double a_over_b, double nu);

}  // namespace rb::creep
