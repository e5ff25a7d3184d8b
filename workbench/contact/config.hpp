#pragma once
// Configuration of the planar wheel/rail contact geometry (paper section 2.2-2.4): the four
// profiles, their positioning (Lw, Lr, beta, r0), the LUT and KEC grids (Tables 9 and 10) and the
// KEC tread-flange regularisation (Fig. 9-10). Plain data; buildLut()/buildKec() take it by const
// reference and the tables keep a copy (the profiles are shared, never copied).
//
// Conventions (see docs/contact_geometry.md): SI units; wheelset track frame with Y to the LEFT
// and Z UP; left rail at +(Lr + xi_g/2), right rail at -(Lr + xi_g/2); the profile conventions of
// workbench/profiles/profile.hpp (left s > 0 field side, right profiles mirrored).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "workbench/contact/interpolation.hpp"
#include "workbench/profiles/nominal.hpp"
#include "workbench/profiles/profile.hpp"

namespace rb::contact {

using Side = profiles::Side;                         // Left (+Y) / Right
inline constexpr double kSideSign[2] = {1.0, -1.0};  // sigma: +1 left, -1 right

// A uniform grid min, min + step, ..., max (max - min must be a multiple of step to 1e-9).
struct GridSpec {
  double min = 0.0;
  double max = 0.0;
  double step = 0.0;
  std::size_t count() const;  // number of nodes (0 when invalid)
  double at(std::size_t i) const { return min + static_cast<double>(i) * step; }
};

// Paper Table 10: LUT grid before refinement (y -18..18 mm step 0.1 mm; xi_g -5..5 mm step 1 mm)
// and after refinement (y step 0.05 mm, 721 x 11).
GridSpec table10LateralGrid();
GridSpec table10LateralGridRefined();
GridSpec table10GaugeGrid();
// Paper Table 9: KEC grid before refinement (s_k -46.4..46.4 mm step 0.2 mm, 465 points) and after
// refinement. The paper gives "step 0.018 mm" and "5001 points", which do not agree (92.8 / 0.018
// is not an integer and gives 5157 points); we keep the 5001 points, i.e. step 92.8 mm / 5000 =
// 0.01856 mm.
GridSpec table9KecGrid();
GridSpec table9KecGridRefined();

struct ContactGeometryConfig {
  // Profiles in the conventions of profile.hpp (right ones usually left.mirrored()).
  std::shared_ptr<const profiles::Profile> left_wheel, right_wheel, left_rail, right_rail;

  double wheel_lw = 0.750;   // [m] Lw: wheel profile origins at +-Lw (B = 1360 mm, S1002)
  double rail_lr = 0.75303;  // [m] Lr: rail profile origins at +-Lr (G = 1435 mm, 60E1 1:40)
  double beta = 1.0 / 40.0;  // [rad] rail inclination (paper Table 1 gives beta = 1/40 rad)
  // [m] nominal rolling radius used by the KEC constraints (Eq. 22)
  double r0 = profiles::kNominalWheelRadius;

  // Tread/flange split of the wheel profile, in LEFT-wheel coordinates (the right wheel uses the
  // mirror value -flange_boundary): the flange is s_w < flange_boundary, the tread s_w >=
  // flange_boundary. NaN: automatic, the first s_w from s_w = 0 toward the flange where the profile
  // slope angle atan|h'| reaches flange_angle (computed per wheel); when no point reaches it the
  // wheel has no flange window.
  double flange_boundary = std::numeric_limits<double>::quiet_NaN();
  double flange_angle = 0.7853981633974483;  // [rad] 45 deg, for the automatic boundary

  GridSpec lut_y = table10LateralGrid();    // [m] wheelset lateral displacement y
  GridSpec lut_gauge = table10GaugeGrid();  // [m] gauge variation xi_g
  GridSpec kec_s = table9KecGrid();         // [m] equivalent-profile parameter s_k
  // Interpolation between the nodes of both tables (interpolation.hpp). The stored node values
  // do not depend on it; the table evaluates with it, and its cache key and configHash include it.
  TableInterpolation interpolation = TableInterpolation::Cubic;

  // KEC regularisation (section 2.4, Fig. 9-10, docs/contact_geometry.md): every jump of the
  // contact point at s_k = s_j is bridged over [s_j - d, s_j + d'] on the s_k axis, d = kec_dhat on
  // the FLANGE side of the jump (smaller s_lk on the left wheel, larger s_rk on the right) and
  // d' = kec_dbar on the tread (field) side: f by the C2 quintic Hermite between the two real
  // branches, the surface-parameter maps by linear ramps from A (tread end) to B (flange start).
  double kec_dhat = 0.5e-3;  // [m] paper: Delta s-hat = 0.5 mm
  double kec_dbar = 1.0e-3;  // [m] paper: Delta s-bar = 1 mm
  // Warnings at build time (not a stall later): a transition length below kec_min_transition, a
  // bridged |f''| above kec_max_curvature (an equivalent profile radius below 0.05 mm), a ramp
  // |ds_w/ds_k| above kec_max_map_slope, or a transition spanning fewer than 3 KEC grid steps.
  double kec_min_transition = 0.05e-3;  // [m]
  double kec_max_curvature = 2.0e4;     // [1/m] (an equivalent profile radius below 0.05 mm)
  double kec_max_map_slope = 100.0;     // [-]
  // Spacing of the branch samples along s_k before resampling on kec_s; 0: min(kec_s.step / 4,
  // 0.05 mm).
  double kec_sample_step = 0.0;  // [m]

  double jump_threshold = 1.0e-3;  // [m] |delta s_w| between neighbouring y nodes flagged a jump
  double search_step = 0.1e-3;     // [m] wheel sampling of the global search (first guess, checks)
  double newton_tol = 1.0e-12;     // [m] residual tolerance of the Newton solvers
  int newton_max_iter = 50;

  // Table 10/9 refined grids (y step 0.05 mm, 5001 KEC points).
  void useRefinedGrids();
};

// Throws rb::InputError listing every problem (missing profile, wrong kind, bad grid, ...).
void checkConfig(const ContactGeometryConfig& config);

// FNV-1a 64 over the profile samples (knots and values of all four profiles) and every number of
// the config, so an application can cache tables by content. The interpolation enters only when
// it is not the default (cubic): a cubic table's hash does not depend on the option, and a linear
// table's differs from it.
std::uint64_t configHash(const ContactGeometryConfig& config);

}  // namespace rb::contact
