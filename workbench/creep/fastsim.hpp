#pragma once
// FASTSIM: J.J. Kalker, "A fast algorithm for the simplified theory of rolling contact", Vehicle
// System Dynamics 11 (1982) 1-13; the simplified theory in J.J. Kalker, "Three-dimensional elastic
// bodies in rolling contact", Kluwer (1990), chapter 3.
//
// Simplified theory. The elastic displacement difference u (wheel minus rail) at a surface point
// depends only on the traction p there: u = L p, with one flexibility per creepage component
// (Kalker 1982, Eq. 6-8), chosen so that the theory reproduces Kalker's linear creep coefficients
// (kalker.hpp) at vanishing creepage:
//   L1 = 8 a / (3 C11 G),   L2 = 8 a / (3 C22 G),   L3 = pi a sqrt(a/b) / (4 C23 G)
// (the same expressions as CONTACT's simpflex in src/m_hertz.f90, eve70a/CONTACT; checked in
// tests/creep/test_fastsim.cpp against the flexibilities printed by CONTACT).
// Derivation of the three: with the leading edge at x = +a, adhesion everywhere and u = 0 at the
// leading edge, u_x(x) = -(s_x / L1)(a(y) - x) etc. Integrating over the ellipse,
// F_x = -(8/3) a^2 b s_x / L1, F_y(spin) = -(pi/4) a^3 b phi / L3, which equal Kalker's
// -G a b C11 s_x and -G (a b)^(3/2) C23 phi for the L above.
//
// Steady rolling, material flowing from the leading edge x = +a(y) to the trailing edge
// x = -a(y) along each strip y = const (Kalker 1982, Eq. 10-12): in adhesion the traction grows by
// the rigid slip over an element dx,
//   p_H(x - dx) = p(x) - dx (s_x / L1 - phi y / L3,  s_y / L2 + phi x_m / L3)
// (x_m the middle of the element: the spin term is integrated exactly), and where |p_H| exceeds
// the traction bound g = mu p_n(x - dx, y) the element slips: p = g p_H / |p_H| (Coulomb, the slip
// opposing the traction). p_n is the normal pressure of the simplified theory,
//   parabolic (Kalker 1982, default): p_n = (2 Q / (pi a b)) (1 - x^2/a^2 - y^2/b^2),
//   elliptic (Hertz):                 p_n = (3 Q / (2 pi a b)) sqrt(1 - x^2/a^2 - y^2/b^2).
// Kalker chose the parabola because it is the normal pressure of the simplified theory itself;
// with it FASTSIM is closer to the exact theory in the transition range. The Hertz bound is the
// option (CONTACT B = 2): its infinite slope at the trailing edge gives a different slip area
// (CONTACT's example fastsim.inp shows both).
//
// Discretisation. `strips` strips of equal width 2b/strips across y (centres y_j), each with
// `elements` equal elements along its own length 2 a(y_j) (Kalker's grid). The traction is
// computed at the middle of every element (the first step from the leading edge is half an
// element) and integrated by the midpoint rule in x and y, so that full adhesion (linear traction
// along x) is integrated exactly along x and no trailing-edge node is forced to zero. The bound is
// normalised so that its discrete integral is exactly mu Q: in full slip the resultant is exactly
// mu Q and never above (|sum p_i w_i| <= sum g_i w_i = mu Q).
// Accuracy (tests/creep/test_fastsim.cpp prints it; docs/creep.md "FASTSIM"):
//   linear range: relative error 1/(2 strips^2) for F_x, F_y (midpoint rule of 1 - eta^2 across
//   y), about the same for spin; 0.2 % with the default grid;
//   transition range: first order in 1/elements, as Kalker's scheme (E.A.H. Vollebregt,
//   P. Wilders, "FASTSIM2: a second-order accurate frictional rolling contact algorithm",
//   Computational Mechanics 47 (2011) 105-116): against a 200 x 200 grid the default 16 x 32 grid
//   is within 0.1 % of mu Q without spin and within 1.5 % of mu Q at strong pure spin (phi a ~
//   3 times the saturation creepage); the error is almost all from the elements along x.
//
// Signs and frames: creepages.hpp (wheel relative to rail, leading edge at x = +a), forces and
// moment on the WHEEL, as polachForce and kalkerLinearForce. Pure s_y > 0 gives F_y < 0 and
// M_z > 0; pure spin phi > 0 gives F_y < 0. Odd symmetry F(-s) = -F(s) holds exactly.
//
// Limits: Q <= 0, mu <= 0, G <= 0, a <= 0 or b <= 0 (or any of them NaN) give zero; zero creepage
// gives zero; creepages beyond 1e100 (and infinite ones) are scaled down along their direction,
// which does not change the full-slip result, so huge inputs give |F| = mu Q and no overflow.
// NaN creepages give NaN forces (the dynamics reports non-finite values). Friction is the
// constant mu of CreepParams (the Polach 2005 options k_A, k_S, friction_A/B are not used).
//
// Cost: strips x elements element updates (a multiply-add per component, a compare, and a square
// root and a division where the element slips), plus `elements` square roots for the elliptic
// bound; no allocation (the node weights live on the stack). The measured time per patch is in
// docs/creep.md.
#include "workbench/core/range.hpp"
#include "workbench/creep/creepages.hpp"
#include "workbench/creep/polach.hpp"

namespace rb::creep {

enum class FastsimBound { Parabolic, Elliptic };

// Admissible grid sizes (scenario keys contact.fastsim.strips / .elements and fastsimForce's own
// clamp): at least 2 elements, since the leading and trailing nodes carry no traction.
inline constexpr Range kFastsimStripsRange{1.0, 200.0};
inline constexpr Range kFastsimElementsRange{2.0, 200.0};

struct FastsimGrid {
  int strips = 16;    // strips across the ellipse (lateral direction)
  int elements = 32;  // elements along each strip (rolling direction)
  FastsimBound bound = FastsimBound::Parabolic;
};

struct FastsimFlexibilities {
  double L1 = 0.0;  // [m^3/N] longitudinal
  double L2 = 0.0;  // [m^3/N] lateral
  double L3 = 0.0;  // [m^3/N] spin
};

// Kalker's three flexibilities (above) of a patch with semi-axes a, b > 0 and coefficients
// c11, c22, c23 > 0 (a zero coefficient gives an infinite flexibility: no force from it).
FastsimFlexibilities fastsimFlexibilities(double G, const ContactPatch& patch);

struct FastsimForce {
  double fx = 0.0;  // longitudinal force on the wheel [N]
  double fy = 0.0;  // lateral force on the wheel [N]
  double mz = 0.0;  // spin moment on the wheel about n [N m]
};

// Forces of FASTSIM on the patch (p.mu, p.G; patch Q, a, b, c11, c22, c23). Allocation-free; the
// grid is clamped to the ranges above.
FastsimForce fastsimForce(const CreepParams& p, const ContactPatch& patch, const Creepages& s,
                          const FastsimGrid& grid = {});

}  // namespace rb::creep
