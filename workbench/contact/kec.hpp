#pragma once
// Knife-edge equivalent contact (KEC, paper section 2.4, Eq. 22-23, Fig. 8-10).
//
// Equivalent profiles. A knife edge fixed at the rail profile origin (sigma Lr + y_ir, z_ir)
// touches an equivalent wheel profile which, in the wheelset intermediate frame, is the curve
// (sigma Lr + s_k, -(r0 + f_k(s_k))). Eq. (22) in our form:
//   y + s_lk + phi (r0 + f_lk) - y_lir = 0
//   y + s_rk + phi (r0 + f_rk) - y_rir = 0
//   z + phi ( Lr + s_lk) - r0 - f_lk - z_lir = 0
//   z + phi (-Lr + s_rk) - r0 - f_rk - z_rir = 0
// (the paper writes Lw in the last two rows; measuring s_k from Lr in all four rows makes the
// knife a single point, so the KEC solution reproduces the real-profile contact kinematics exactly;
// with Lw the rows would disagree by (Lr - Lw) phi, ~1e-5 m).
//
// Table build (zero irregularity, section 2.4 steps 1-4): the real contact (Eq. 12 on the whole
// profiles, no tread/flange windows) is followed from y = 0 toward each flange by continuation in
// the knife position s_k of the wheel approaching its flange. s_k stays regular where y(s_k) folds;
// it covers both of the paper's branches: tread-tread (y independent) and, after the tread-flange
// two-point contact, wheel climbing (z independent) up to the flange tip or the end of the grid.
// Contact-point jumps (two-point contacts) are found by the sampled penetration of another point
// of the wheel, located by bisection on its Eq. (15) indentation; where a branch ends without one
// (a fold, or the degenerate conformal contact of the S1002 R13 root on the 60E1 R13 gauge corner)
// the contact moves to the nearest point giving a penetration-free contact.
//
// Regularisation (Fig. 9-10; the paper's ref. [17] is not available, so this is our design): each
// jump at s_j is bridged over [lo, hi] = [s_j - L_low, s_j + L_high] with L = kec_dhat on the
// flange side of the jump and kec_dbar on the field side (left profile: flange side = smaller
// s_lk; right profile: larger s_rk), cut where neighbouring jumps are closer. Inside:
//   f        C2 quintic Hermite matching f, f', f'' of the real branch below at lo and of the real
//            branch above at hi (so f stays C2 and its slope turns from the tread to the flange
//            contact angle over the transition);
//   maps     s_w, s_r and the contact angle, radius and curvatures ramp linearly from the
//   field-side
//            end A (tread-end point) to the flange-side end B (flange-start point): the contact
//            point C crosses the forbidden zone of the real profile linearly (Fig. 10);
//   weight   w = weight of B, 0 at A and 1 at B, with A and B stored, for the force split of
//            Eq. (26): Q = (1 - w) Q at A + w Q at B.
// Jumps of the other wheel (small kinks of this equivalent profile) are bridged the same way.
// Outside transitions the channels are the real branch. Everything is resampled on the uniform
// kec_s grid (Table 9): f as a not-a-knot cubic spline (C2), the other channels as local cubic
// Hermite data with exact node derivatives (C1, no ringing at the ramp ends). A table with
// config.interpolation = Linear evaluates every channel, f included, as straight segments between
// the nodes (the paper's, section 5.5; C0, kec_solve.cpp).
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "workbench/contact/config.hpp"
#include "workbench/contact/lut.hpp"
#include "workbench/core/spline.hpp"

namespace rb::contact {

enum class KecQuantity : std::size_t {
  F,        // [m] equivalent profile f_k(s_k) (radius increase over r0 at the knife)
  Sw,       // [m] real wheel surface parameter s_w(s_k) (regularised map, Eq. 23)
  Sr,       // [m] real rail surface parameter s_r(s_k)
  Gamma,    // [rad] contact angle (blended in transitions)
  Radius,   // [m] rolling radius
  KwTrans,  // [1/m] curvatures (blended in transitions)
  KwLong,
  KrTrans,
  Weight,  // [-] weight of the flange-side branch B in a transition, 0 elsewhere
  SwA,     // [m] field-side branch point A (s_w, s_r) of a transition; = Sw, Sr elsewhere
  SrA,
  SwB,  // [m] flange-side branch point B
  SrB,
  Count
};
inline constexpr std::size_t kKecQuantities = static_cast<std::size_t>(KecQuantity::Count);
std::string kecQuantityName(KecQuantity q);

// A regularised jump on one equivalent profile.
struct KecTransition {
  double s_jump = 0.0;        // [m] s_k of the two-point contact
  double lo = 0.0, hi = 0.0;  // [m] blend interval
  bool own = true;            // the jump is on this wheel (false: the other wheel jumps)
  bool flange = false;        // tread-flange jump (true) or tread-tread jump
  double s_w_field = 0.0, s_w_flange = 0.0;  // [m] real contact points at the jump (A, B)
  double y = 0.0;  // [m] wheelset lateral displacement at the two-point contact
};

struct KecPoint {
  std::array<double, kKecQuantities> value{};
  std::array<double, kKecQuantities> d_ds{};
  double d2f = 0.0;    // d2 f_k / d s_k^2
  bool inside = true;  // s_k inside the computed (valid) range
};

class KecTable {
 public:
  KecTable() = default;

  const GridSpec& grid() const { return grid_; }
  double r0() const { return r0_; }
  double railLr() const { return lr_; }
  std::uint64_t configHash() const { return hash_; }
  // How eval / evalValues / f interpolate between the nodes (config.interpolation).
  TableInterpolation interpolation() const { return interp_; }
  const TableBuildStats& stats() const { return stats_; }
  // s_k range computed from contact geometry; outside it the table is extrapolated linearly.
  double validMin(Side side) const { return valid_[idx(side)][0]; }
  double validMax(Side side) const { return valid_[idx(side)][1]; }
  const std::vector<KecTransition>& transitions(Side side) const { return trans_[idx(side)]; }
  // True when s_k lies in the blend interval of a transition.
  bool inTransition(Side side, double s_k) const;

  // All quantities with first derivatives (and f''). Allocation-free. Linear tables: the
  // derivatives are the slopes of the segment holding s_k (the right-hand one at a node) and
  // f'' = 0.
  void eval(Side side, double s_k, KecPoint& out) const;
  // Values of the quantities after F (Sw ... SrB) and `inside`, bit-identical to eval()'s except
  // that a point channel (SwA ... SrB) constant over the interval (equal node values, zero slopes)
  // returns exactly that constant (eval() may be 1 ulp off); F, the derivatives and d2f are left
  // untouched. The dynamics' per-evaluation lookup. Allocation-free.
  void evalValues(Side side, double s_k, KecPoint& out) const;
  // Equivalent profile f_k with first and second derivatives. Allocation-free.
  double f(Side side, double s_k, double* df = nullptr, double* d2f = nullptr) const;
  // f with the interpolation fixed (f dispatches to these): solveKec picks one once per solve, so
  // that the Newton loop calls a function the compiler can inline.
  double fCubic(Side side, double s_k, double* df, double* d2f) const;
  double fLinear(Side side, double s_k, double* df, double* d2f) const {
    return fLinear(idx(side), s_k, df, d2f);
  }
  // Stored grid values.
  double node(Side side, KecQuantity q, std::size_t i) const {
    return herm_[idx(side)][(i * kKecQuantities + static_cast<std::size_t>(q)) * 2];
  }

 private:
  friend KecTable buildKec(const ContactGeometryConfig& config);
  friend class TableIo;  // binary cache files (table_io.hpp)
  static std::size_t idx(Side s) { return s == Side::Left ? 0 : 1; }
  // fspl_[k] from the F node values in herm_[k] on grid_ (buildKec and the cache loader: the same
  // inputs give bit-identical coefficients).
  void makeFSpline(std::size_t k);
  // eval / evalValues / f of a linear table.
  void evalLinear(std::size_t k, double s_k, KecPoint& out, bool derivatives) const;
  double fLinear(std::size_t k, double s_k, double* df, double* d2f) const;
  GridSpec grid_;
  std::size_t n_ = 0;
  double r0_ = 0.0, lr_ = 0.0;
  std::uint64_t hash_ = 0;
  TableInterpolation interp_ = TableInterpolation::Cubic;
  // f: not-a-knot cubic spline over the grid values (C2; f is C2 by construction). All quantities
  // also as local cubic Hermite data (value and exact derivative at each node; C1, no ringing at
  // the kinks of the linear ramps): herm_[side][(i * kKecQuantities + q) * 2 + {0: value, 1:
  // d/ds}].
  // (A one-channel CubicSplineSet: value and derivatives from one interval lookup, the same
  // polynomials as CubicSpline's, bit-identical.)
  std::array<CubicSplineSet, 2> fspl_;
  std::array<std::vector<double>, 2> herm_;
  std::array<std::array<double, 2>, 2> valid_{};
  std::array<std::vector<KecTransition>, 2> trans_;
  TableBuildStats stats_;
};

// Builds the KEC tables (see the header comment). Throws rb::InputError for a bad config; problems
// of the geometry (short transitions, steep maps, unresolved transitions, branches that could not
// be continued) are warnings in stats().warnings.
KecTable buildKec(const ContactGeometryConfig& config);

// ---- Online KEC constraints (Eq. 22) ------------------------------------------------------------

struct KecInput {
  double y = 0.0;                   // [m] wheelset lateral displacement
  double y_lir = 0.0, y_rir = 0.0;  // [m] lateral rail irregularities (gauge = y_lir - y_rir)
  double z_lir = 0.0, z_rir = 0.0;  // [m] vertical rail irregularities
};

// 0 ok; > 0 recoverable (the dynamics returns it to the integrator, which retries with a smaller
// step): 1 Newton did not converge, 2 a knife left the valid range of the table.
enum class KecStatus : int { Ok = 0, NotConverged = 1, OutOfTable = 2 };

struct KecSolution {
  KecStatus status = KecStatus::NotConverged;
  int code() const { return static_cast<int>(status); }
  int iterations = 0;
  double residual = 0.0;          // max |g| at return
  double z = 0.0, phi = 0.0;      // [m], [rad]
  double s_lk = 0.0, s_rk = 0.0;  // [m]
  double f_lk = 0.0, f_rk = 0.0;  // [m] and derivatives at the solution
  double df_lk = 0.0, df_rk = 0.0, d2f_lk = 0.0, d2f_rk = 0.0;
  Eigen::Matrix4d g_x = Eigen::Matrix4d::Zero();  // dg/dx, x = (z, phi, s_lk, s_rk)
  // dx/dp, p = (y, y_lir, y_rir, z_lir, z_rir): velocity-level relation xdot = dx_dp pdot.
  Eigen::Matrix<double, 4, 5> dx_dp = Eigen::Matrix<double, 4, 5>::Zero();
};

// Newton on Eq. (22) from `warm` (a previous solution, e.g. the last step) or from a flat start.
// With a linear table, f_k is piecewise linear and Newton uses its segment slopes (kec_solve.cpp).
// Allocation-free.
KecSolution solveKec(const KecTable& table, const KecInput& in, const KecSolution* warm = nullptr);

// Acceleration level: xddot = dx_dp pddot + kecQuadraticTerm(sol, xdot), with xdot = dx_dp pdot.
Eigen::Vector4d kecQuadraticTerm(const KecSolution& sol, const Eigen::Vector4d& xdot);

}  // namespace rb::contact
