#pragma once
// Normal contact problem per patch of the elastic contact method: Hertz theory
// (creep/hertz.hpp) from the relative curvatures the search found (elastic_search.hpp), the
// normal force from the approach, N = K_H(A, B) delta^1.5 (K_H the Hertz constant of that
// ellipse, not a hand-tuned penalty), the semi-axes and the maximum pressure. docs/
// elastic_contact.md.
//
// Lateral curvature. By default (ElasticNormalSpec::span_curvature) B is the search's B_span, the
// relative curvature measured over +-1 mm (ElasticSearchSpec::curvature_span), not the pointwise
// one: the pointwise B jumps at the profiles' arc/line joints (S1002 throat R13 to its 70 deg
// flank) and the force with it.
//
// Curvature policy. Hertz needs A > 0 and B > 0. A = cos(alpha) / (2 r) is always positive on a
// wheel. At a gap minimum B >= 0 (the gap's second derivative is 2 B), but a near-conformal
// contact (the S1002 R13 throat on the UIC60 R13 gauge corner, a hollow tread on the crown) gives
// B -> 0+, where Hertz's half-space assumptions fail, the contact width is set by how far the two
// profiles stay close and Hertz gives b -> infinity; B_span can also be negative across a curvature
// joint. We floor B smoothly at
//   B_min = min_ratio * A        (default min_ratio = 0.1: b / a stays below about 4.6)
// with the C1 blend  B_eff = B_min + B^2 / (4 B_min)  for 0 <= B <= 2 B_min,  B_min for B < 0,
// B for B >= 2 B_min (value and slope continuous, so the force stays C1 in the pose). A fraction
// of A keeps the policy scale-free and bounds the ellipse's aspect ratio; 0.1 is a stated choice,
// not a fit: the widest CONTACT patch of the Manchester benchmark A-2.2 (the conformal tread at
// y = 0, 15.8 mm by 5 mm) has an aspect ratio of 3.2, below the 4.6 allowed, and no patch of
// reaches the floor (smallest B/A = 0.35).
//
// Smoothness: N = K_H delta^1.5 -> 0 continuously (with dN/ddelta -> 0) as delta -> 0+, and the
// search's shared-overlap delta makes a patch that dies, merges or swaps depth with a neighbour
// change its force continuously. Damping (for the dynamic method, not used here): the
// Hunt-Crossley form
//   N = K_H delta^1.5 (1 + c_d d(delta)/dt),  c_d = 3 (1 - e) / (2 v_impact) ~ [s/m],
// keeps N continuous at contact birth (the viscous part also vanishes with delta), unlike a
// Kelvin-Voigt c delta-dot term (Hunt & Crossley, J. Appl. Mech. 42 (1975) 440-445).
#include "workbench/contact/elastic_search.hpp"
#include "workbench/creep/hertz.hpp"

namespace rb::contact {

struct ElasticNormalSpec {
  creep::Material material{};   // E = 2.1e11 Pa, nu = 0.28
  double min_ratio = 0.1;       // B floored smoothly at min_ratio * A (header comment)
  bool span_curvature = true;   // use the geometry's B_span (curvature over +-w) instead of the
                                // pointwise B (header comment)
  double min_curvature = 1e-3;  // [1/m] absolute floor of A (never reached by a wheel)
};

// Normal contact of one patch.
struct ElasticPatchNormal {
  double A = 0.0, B = 0.0;  // [1/m] relative curvatures used (after the policy)
  bool B_floored = false;   // the policy changed B
  double N = 0.0;           // [N] normal force
  double k_hertz = 0.0;     // [N/m^1.5] N = k_hertz delta^1.5
  double a = 0.0, b = 0.0;  // [m] semi-axes along the rolling and the lateral direction
  double p0 = 0.0;          // [Pa] maximum pressure, 3 N / (2 pi a b)
};

// The C1 floor of the curvature policy: x for x >= 2 m, m + x^2 / (4 m) for 0 <= x < 2 m, m below.
double smoothCurvatureFloor(double x, double m);
// The curvatures used for a patch (A floored at min_curvature, B by the policy).
creep::RelativeCurvatures policyCurvatures(const ElasticPatchGeometry& g,
                                           const ElasticNormalSpec& spec,
                                           bool* B_floored = nullptr);
// Hertz normal problem at the patch's approach (delta = g.approach).
ElasticPatchNormal elasticNormal(const ElasticPatchGeometry& g, const ElasticNormalSpec& spec);

// All patches of one wheel, with their normal problems, and the total force on the wheel.
struct ElasticWheelContact {
  ElasticWheelGeometry geometry;
  std::array<ElasticPatchNormal, kMaxElasticPatches> normal{};
  double force_y = 0.0, force_z = 0.0;  // [N] sum of N n over the patches (force on the wheel)
  double normal_sum = 0.0;              // [N] sum of N
};
void elasticWheelContact(const ElasticContactSearch& search, const ElasticPose& pose,
                         const ElasticNormalSpec& spec, ElasticWheelContact& out,
                         ElasticSearchWorkspace& ws, const ElasticWheelGeometry* seed = nullptr);

// Quasi-static load case of one wheel (the Manchester contact benchmark solves each wheel alone):
// the wheelset height z for which the wheel carries `target` newtons, with y, phi, psi of `pose`.
enum class WheelLoad {
  Vertical,  // sum of N n_z (frictionless vertical force) = target
  Normal,    // sum of N = target
};
struct WheelLoadSolution {
  bool converged = false;
  int iterations = 0;
  double z = 0.0;  // [m]
  ElasticWheelContact contact;
};
WheelLoadSolution solveWheelLoad(const ElasticContactSearch& search, const ElasticPose& pose,
                                 const ElasticNormalSpec& spec, double target, WheelLoad mode,
                                 double rel_tol = 1e-9);

// Both wheels of a wheelset under their loads: z and the roll phi (y and psi of `pose`) for which
// each wheel solved alone (solveWheelLoad) needs the same height, i.e. the rigid wheelset carries
// `target_left` and `target_right` (the Manchester benchmark's own iteration, CONTACT user guide,
// example mbench_a22). Secant on phi of z_left(phi) - z_right(phi).
struct WheelsetLoadSolution {
  bool converged = false;
  int iterations = 0;
  double z = 0.0, phi = 0.0;
  WheelLoadSolution left, right;
};
WheelsetLoadSolution solveWheelsetLoad(const ElasticContactSearch& left,
                                       const ElasticContactSearch& right, const ElasticPose& pose,
                                       const ElasticNormalSpec& spec, double target_left,
                                       double target_right, WheelLoad mode, double z_tol = 1e-10);

}  // namespace rb::contact
