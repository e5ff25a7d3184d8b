#pragma once
// Contact lookup table (paper section 2.3, Eq. 11-14): the solution of Eq. (12) and the flange
// indentation of Eq. (15)/(21) on a grid of wheelset lateral displacement y and gauge variation
// xi_g (Table 10), with a fast interpolant.
//
// Interpolation (config.interpolation): bicubic Hermite (the default, below) or bilinear (the
// paper's "linear interpolation between the stored data", section 5.5: 4 terms per channel, C0,
// first derivatives the slopes of the cell, see lut_eval.cpp).
// Bicubic Hermite on the uniform grid (O(1) cell lookup, 16 terms per channel). Node derivatives:
// along y, a not-a-knot cubic spline on each run of nodes between detected contact-point jumps
// (O(h^4) where the geometry is smooth; no ringing carried across a jump); along xi_g and for the
// cross derivative, the modified Akima rule (local, no overshoot where the jump position moves with
// the gauge). The interpolant is C1 everywhere: values and first derivatives are continuous across
// cells, which the equations of motion (Eq. 17 Jacobian) and variable-step integrators need; second
// derivatives exist inside cells and jump across cell edges. Evaluation is allocation-free.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "workbench/contact/config.hpp"
#include "workbench/contact/geometry.hpp"

namespace rb::contact {

// Tread quantities per side (block of kTreadQuantities channels) and flange quantities per side.
enum class TreadQuantity : std::size_t {
  Sw,       // [m] wheel surface parameter s_w
  Sr,       // [m] rail surface parameter s_r
  Gamma,    // [rad] contact angle
  Radius,   // [m] rolling radius h_w(s_w)
  KwTrans,  // [1/m] wheel transverse curvature (convex positive)
  KwLong,   // [1/m] wheel rolling-direction curvature
  KrTrans,  // [1/m] rail transverse curvature
  Count
};
enum class FlangeQuantity : std::size_t {
  Delta,       // [m] indentation (Eq. 21), > 0 penetration, < 0 gap ("gap to the flange" = -delta)
  Sw,          // [m]
  Sr,          // [m]
  Gamma,       // [rad]
  Radius,      // [m]
  KwTrans,     // [1/m]
  KwLong,      // [1/m]
  KrTrans,     // [1/m]
  Ny,          // [-] unit outward wheel normal n_w, Y component (= d delta / d y)
  Nz,          // [-] Z component (= d delta / d z)
  DdeltaDphi,  // [m] d delta / d phi at fixed y, z
  Count
};
inline constexpr std::size_t kTreadQuantities = static_cast<std::size_t>(TreadQuantity::Count);
inline constexpr std::size_t kFlangeQuantities = static_cast<std::size_t>(FlangeQuantity::Count);
// Channel layout: z, phi, left tread, right tread, left flange, right flange.
inline constexpr std::size_t kLutZ = 0;
inline constexpr std::size_t kLutPhi = 1;
inline constexpr std::size_t kLutChannels = 2 + 2 * kTreadQuantities + 2 * kFlangeQuantities;
constexpr std::size_t lutChannel(Side side, TreadQuantity q) {
  return 2 + (side == Side::Left ? 0 : kTreadQuantities) + static_cast<std::size_t>(q);
}
constexpr std::size_t lutChannel(Side side, FlangeQuantity q) {
  return 2 + 2 * kTreadQuantities + (side == Side::Left ? 0 : kFlangeQuantities) +
         static_cast<std::size_t>(q);
}
// "z", "phi", "left.s_w", ..., "right.flange.delta", ...
std::string lutChannelName(std::size_t channel);

// Per-node flags.
enum LutNodeFlag : std::uint8_t {
  kLutLeftEdge = 1,  // left tread contact pinned at the tread/flange boundary
  kLutRightEdge = 2,
  kLutRestarted = 4,        // warm start rejected: global search (contact-point jump into node)
  kLutFailed = 8,           // Eq. (12) not solved: values copied from the neighbour (warning)
  kLutLeftFlangeEdge = 16,  // left flange indentation largest at the window end
  kLutRightFlangeEdge = 32,
};

// A discontinuity of the contact point between two neighbouring y nodes.
struct LutJump {
  double xi_g = 0.0;
  Side side = Side::Left;
  double y_before = 0.0, y_after = 0.0;  // neighbouring nodes (ordered away from y = 0)
  double s_w_before = 0.0, s_w_after = 0.0;
};

// Two-point contact: the flange indentation (an interior stationary point of Eq. 15 in the flange
// window) reaches zero while the tread constraint holds.
struct TwoPointContact {
  double xi_g = 0.0;
  Side side = Side::Left;
  bool tread_edge = false;  // the tread contact is pinned at the tread/flange boundary there
  double y = 0.0, z = 0.0, phi = 0.0;  // [m], [m], [rad]
  double s_w_tread = 0.0, s_r_tread = 0.0, gamma_tread = 0.0;
  double s_w_flange = 0.0, s_r_flange = 0.0, gamma_flange = 0.0;
};

struct TableBuildStats {
  double build_seconds = 0.0;
  std::size_t bytes = 0;  // memory of the table data
  std::size_t nodes = 0;  // grid nodes (LUT) or equivalent-profile samples (KEC)
  long newton_iterations = 0;
  std::size_t restarts = 0;           // global-search restarts
  std::size_t failures = 0;           // unsolved nodes / failed continuation steps
  std::vector<std::string> warnings;  // problems the user should act on
  std::vector<std::string> notes;     // information (where branches ended, ranges)
};

// Values and first derivatives of all channels at one point.
struct LutSample {
  std::array<double, kLutChannels> value{};
  std::array<double, kLutChannels> d_dy{};
  std::array<double, kLutChannels> d_dxi{};
  bool inside = true;  // false: (y, xi_g) outside the grid, values extrapolated from the end cells
};

// The tread contact point of one wheel on each side of a contact-point jump (treadBranches): in a
// table cell whose corner nodes put that wheel's contact point on different branches of Eq. (12)
// (a tread/root or tread/tread jump between them), the interpolant of the cell blends two
// different contact points into one that is on neither branch. value[0] is the branch nearer the
// centred wheelset (fewer jumps from y = 0), value[1] the other; each is interpolated from the
// nodes of its own branch (extrapolated into the cell from the neighbouring cell of that branch).
struct LutTreadBranches {
  bool split = false;  // the cell holds a jump of this wheel's contact point
  std::array<std::array<double, kTreadQuantities>, 2> value{};
};

// One channel with first and second derivatives.
struct LutValue {
  double v = 0.0, dy = 0.0, dxi = 0.0, dyy = 0.0, dyxi = 0.0, dxixi = 0.0;
  bool inside = true;
};

class LutTable {
 public:
  LutTable() = default;

  const GridSpec& yGrid() const { return y_; }
  const GridSpec& gaugeGrid() const { return g_; }
  std::size_t ny() const { return ny_; }
  std::size_t ng() const { return ng_; }
  std::uint64_t configHash() const { return hash_; }
  // How the evaluations below interpolate between the nodes (config.interpolation).
  TableInterpolation interpolation() const { return interp_; }
  const TableBuildStats& stats() const { return stats_; }
  const std::vector<LutJump>& jumps() const { return jumps_; }
  const std::vector<TwoPointContact>& twoPointContacts() const { return two_point_; }
  bool hasFlange(Side side) const { return has_flange_[side == Side::Left ? 0 : 1]; }

  // All channels, values and first derivatives. Allocation-free.
  void eval(double y, double xi_g, LutSample& out) const;
  // All channels, values only (out.d_dy, out.d_dxi are left unchanged): a third of eval()'s work,
  // for the dynamics, which needs no derivatives of the contact-point quantities. Values are
  // bit-identical to eval()'s. Allocation-free.
  void evalValues(double y, double xi_g, LutSample& out) const;
  // The same for the channels [first, last) only (others unchanged; out.inside is set): the
  // dynamics reads the flange contact point of a side only when its indentation is positive.
  void evalValues(double y, double xi_g, LutSample& out, std::size_t first, std::size_t last) const;
  // One channel with first and second derivatives. Allocation-free.
  LutValue evalChannel(std::size_t channel, double y, double xi_g) const;
  // z and phi only (the LUT constraints of Eq. 17), with first and second derivatives.
  void evalZPhi(double y, double xi_g, LutValue& z, LutValue& phi) const;
  // The tread contact points of wheel `side` on both branches of a contact-point jump in the cell
  // of (y, xi_g) (LutTreadBranches); out.split = false (value untouched) in a cell without one.
  // Allocation-free.
  void treadBranches(double y, double xi_g, Side side, LutTreadBranches& out) const;
  // Branch of Eq. (12) the contact point of wheel `side` is on at a node: the signed count of that
  // wheel's contact-point jumps (|delta s_w| > the config's jump_threshold) between the centre
  // node and this one along its gauge line (+ toward +y).
  int branch(std::size_t iy, std::size_t ig, Side side) const {
    return branch_[(ig * ny_ + iy) * 2 + (side == Side::Left ? 0 : 1)];
  }

  // Stored node value (the solved geometry, no interpolation) and flags.
  double node(std::size_t channel, std::size_t iy, std::size_t ig) const {
    return data_[((ig * ny_ + iy) * kLutChannels + channel) * 4];
  }
  std::uint8_t flags(std::size_t iy, std::size_t ig) const { return flags_[ig * ny_ + iy]; }

 private:
  template <bool kDerivatives>
  void evalRange(double y, double xi_g, LutSample& out, std::size_t first, std::size_t last) const;
  friend LutTable buildLut(const ContactGeometryConfig& config);
  friend class TableIo;  // binary cache files (table_io.hpp)
  struct Cell {
    std::size_t i = 0, j = 0;
    double t = 0.0, u = 0.0;
    bool inside = true;
  };
  Cell locate(double y, double xi_g) const;
  // evalChannel at a located cell (evalZPhi shares one lookup between z and phi).
  LutValue channelAt(std::size_t channel, const Cell& c) const;
  // evalRange and channelAt of a linear table: bilinear cells (linear in y when the gauge grid
  // has one node), derivatives the slopes of the cell.
  template <bool kDerivatives>
  void evalRangeLinear(const Cell& c, LutSample& out, std::size_t first, std::size_t last) const;
  LutValue channelAtLinear(std::size_t channel, const Cell& c) const;
  // treadBranches: channel `ch` of wheel k (0 left, 1 right) on its branch b, along gauge line jj
  // at the cell's y (false: no node of the cell on that line is on branch b).
  bool branchLineValue(std::size_t ch, std::size_t k, const Cell& c, std::size_t jj, int b,
                       double& v) const;

  GridSpec y_, g_;
  std::size_t ny_ = 0, ng_ = 0;
  double hy_ = 1.0, hg_ = 1.0;
  // Node data: ((ig * ny + iy) * kLutChannels + c) * 4 + {f, f_y, f_xi, f_yxi}.
  std::vector<double> data_;
  std::vector<std::uint8_t> flags_;
  std::vector<std::int8_t> branch_;  // [(ig * ny + iy) * 2 + side], see branch()
  double jump_threshold_ = 1.0e-3;   // [m] the config's: branches closer than this are one
  std::vector<LutJump> jumps_;
  std::vector<TwoPointContact> two_point_;
  std::array<bool, 2> has_flange_{false, false};
  std::uint64_t hash_ = 0;
  TableInterpolation interp_ = TableInterpolation::Cubic;
  TableBuildStats stats_;
};

// Solves Eq. (12) and the flange search on every node (continuation in y from y = 0 outward for
// each gauge value, global search where the warm start fails or leaves penetration), detects
// jumps and two-point contacts, and builds the interpolant. Throws rb::InputError for a bad config.
LutTable buildLut(const ContactGeometryConfig& config);

// Modified Akima derivative estimates at the nodes of x (strictly increasing, n >= 2).
void makimaSlopes(const double* x, const double* f, std::size_t n, double* d);

}  // namespace rb::contact
