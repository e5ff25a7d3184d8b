#pragma once
// Planar wheel/rail contact geometry (paper section 2.2-2.3): contact points in the Y-Z plane of
// the wheelset track frame (s_w2 = pi/2, wheelset yaw neglected for the contact location, as the
// paper says), found from the one-point contact constraints of Eq. (12) on both wheels, and the
// flange maximum-indentation condition of Eq. (15) with the indentation of Eq. (21).
//
// Kinematics, exactly as Eq. (4)-(10) with s_r1 = s_w, s_w2 = pi/2 and psi = theta = 0:
//   wheel point   r_wc = (y, z) + A (sigma Lw + s_w, -h_w(s_w)),   A = [[1, -phi], [phi, 1]]
//   rail point    r_rc = (sigma (Lr + xi_g / 2), 0) + Rx(sigma beta) (s_r, h_r(s_r))
// with sigma = +1 (left) / -1 (right). A is the Y-Z block of Eq. (9): the roll angle enters
// LINEARISED (A is not orthogonal: it is sqrt(1 + phi^2) times a rotation), exactly as the paper
// writes it, so the table z, phi satisfy the same kinematics the equations of motion use.
// y is the lateral displacement of the wheelset frame (positive to the LEFT), z the height of the
// wheelset frame (axle centre) above the track frame: z is about r0 for a centred wheelset (not
// 0; the offset is z(0) - r0 = rail height at the contact for a 1:40 60E1 rail and S1002 wheel).
//
// Signs at a contact point: the rail normal points out of the rail into the wheel; the contact
// angle gamma is the angle between that normal and the track vertical Z, positive when the normal
// leans toward the track centre (gamma ~ beta on a flat tread, ~ +70 deg on either flange), so
// left and right mirror each other. Curvatures are principal curvatures, positive when the surface
// is convex toward the other body (Hertz convention, A + B = (sum of curvatures) / 2):
//   wheel transverse  k = -h_w'' / (1 + h_w'^2)^1.5        (profile curvature, convex tread > 0)
//   wheel rolling     k = 1 / (h_w sqrt(1 + h_w'^2))       (surface of revolution: cos(alpha)/r,
//                                                            alpha = atan|h_w'| the profile slope)
//   rail transverse   k = -h_r'' / (1 + h_r'^2)^1.5        (convex crown > 0)
//   rail longitudinal k = 0                                 (tangent track)
//
// Tread and flange windows (LUT, section 2.3: tread by constraint, flange by the elastic hybrid).
// Each wheel profile is split at the flange boundary (config.flange_boundary; by default where the
// profile slope reaches 45 deg: S1002 at s_w = -35.5 mm, in the R13 flange root). The tread
// constraint is the maximum indentation over the tread window: Eq. (12) where it is an interior
// point, and the window end (Edge mode: s_w pinned at the boundary, tangency row dropped) where the
// wheel would otherwise have to run onto the flange; the flange is the maximum indentation over
// the flange window (flange tip to boundary), Eq. (15) or its window end. Both are defined for
// every y, so the LUT is continuous to |y| = 18 mm even though the rigid contact climbs the flange.
#include <array>
#include <limits>
#include <vector>

#include "workbench/contact/config.hpp"

namespace rb::contact {

// Wheelset coordinates relative to the wheelset track frame (Eq. 3, planar subset).
struct WheelsetPose {
  double y = 0.0;    // [m] lateral, positive to the left
  double z = 0.0;    // [m] vertical (axle centre), positive up
  double phi = 0.0;  // [rad] roll about X (left wheel up for phi > 0)
};

// Local geometry of one contact point.
struct ContactPoint {
  double s_w = 0.0, s_r = 0.0;  // [m] wheel and rail surface parameters
  double y = 0.0, z = 0.0;      // [m] contact (rail) point in the wheelset track frame
  double n_y = 0.0, n_z = 1.0;  // [-] unit rail normal (out of the rail), track frame
  double gamma = 0.0;           // [rad] contact angle (see the header comment)
  double radius = 0.0;          // [m] rolling radius h_w(s_w)
  double k_wheel_trans = 0.0;   // [1/m] principal curvatures, convex positive
  double k_wheel_long = 0.0;
  double k_rail_trans = 0.0;
  double k_rail_long = 0.0;
};

// How the contact of one wheel is constrained. Tangent: Eq. (12) (points coincide, wheel tangent
// orthogonal to the rail normal). Edge: the wheel point is pinned at the end of the tread window
// (s_w = flange boundary) and only the two coincidence equations hold: the window-constrained
// maximum indentation sits on the window end (see "Tread and flange windows" in the docs).
enum class ContactMode { Tangent, Edge };

// Solution of Eq. (12) at given y and gauge variation.
struct TreadContact {
  double y = 0.0, xi_g = 0.0;
  double z = 0.0, phi = 0.0;
  std::array<double, 4> s{};  // s_lw, s_lr, s_rw, s_rr
  std::array<ContactMode, 2> mode{ContactMode::Tangent, ContactMode::Tangent};  // left, right
  ContactPoint left, right;
  int iterations = 0;  // Newton iterations (all attempts)
  bool converged = false;
  bool restarted = false;    // the warm-started solution was replaced by the global search
  double penetration = 0.0;  // [m] largest sampled tread-window penetration after convergence
};

// Flange contact by maximum indentation, Eq. (15), with the indentation of Eq. (21).
struct FlangeContact {
  bool exists = false;  // the wheel has a flange window
  bool converged = false;
  ContactMode mode = ContactMode::Tangent;  // Edge: largest indentation at the window end
  int iterations = 0;
  ContactPoint point;              // rail point, contact angle, curvatures at the flange contact
  double delta = 0.0;              // [m] indentation (r_w - r_r) . n_w, > 0 penetration, < 0 gap
  double nw_y = 0.0, nw_z = -1.0;  // unit outward wheel normal n_w (track frame)
  // Partial derivatives of delta (envelope theorem: exact at the Eq. 15 solution).
  double ddelta_dy = 0.0, ddelta_dz = 0.0, ddelta_dphi = 0.0, ddelta_dxi = 0.0;
  // The interior stationary point of Eq. (15) inside the window, also when the window end is
  // deeper (NaN when none was found): used to tell a real flange touch from the window end.
  double interior_delta = std::numeric_limits<double>::quiet_NaN();
  double interior_s_w = 0.0, interior_s_r = 0.0;
};

// Full planar configuration used by the continuation solvers: wheelset coordinates and the four
// surface parameters [s_lw, s_lr, s_rw, s_rr] (on either wheel the point may be a tread or a
// flange point: Eq. 12 does not distinguish).
struct ContactState {
  double y = 0.0, z = 0.0, phi = 0.0;
  std::array<double, 4> s{};
};

// The parameter held fixed by the continuation Newton (the other six of y, z, phi, s are solved):
// the lateral displacement y (LUT, KEC tread-tread branch), the height z (wheel climbing, section
// 2.4 step 2), or the position s_k of the left/right knife edge in the equivalent profile
// (regular through folds of y(s_k), used by the KEC build).
enum class Parameter { Y, Z, LeftKnife, RightKnife };

// Which wheel samples a global search looks at.
enum class Window { Tread, Flange, All };

// Knife-edge point of one rail (the rail profile origin (sigma Lr + y_ir, z_ir)) expressed in the
// equivalent-profile coordinates of Eq. (22): the wheelset intermediate frame point
// (sigma Lr + s_k, -(r0 + f_k)) with the linearised A of Eq. (9). See docs (KEC) for why s_k is
// measured from Lr.
struct KnifePoint {
  double s_k = 0.0;  // [m]
  double f_k = 0.0;  // [m]
};
KnifePoint knifePoint(double sigma, double lr, double r0, double y, double z, double phi,
                      double y_ir = 0.0, double z_ir = 0.0);

class ContactSolver {
 public:
  explicit ContactSolver(ContactGeometryConfig config);  // checkConfig() first

  const ContactGeometryConfig& config() const { return cfg_; }
  // Tread/flange boundary and flange tip (largest radius) of a wheel, in that wheel's s_w.
  double flangeBoundary(Side side) const { return side_[idx(side)].boundary; }
  double flangeTip(Side side) const { return side_[idx(side)].tip; }
  bool hasFlange(Side side) const { return side_[idx(side)].has_flange; }

  // Eq. (12) at (y, xi_g): Newton from `warm` (continuation) or from the global search, then a
  // sampled check of the tread windows; a warm solution that leaves penetration elsewhere (a
  // contact-point jump) is replaced by the global-search solution. Allocation-free.
  TreadContact solveTread(double y, double xi_g, const TreadContact* warm = nullptr) const;

  // Eq. (15) on one wheel at a given pose, restricted to the flange window: the largest of the
  // indentation at the window end (Edge) and of the interior stationary points found by Newton
  // from the warm start and from the deepest sampled gap minima. Allocation-free.
  FlangeContact flange(Side side, const WheelsetPose& pose, double xi_g,
                       const FlangeContact* warm = nullptr) const;

  // Geometry at given surface parameters (no solve).
  ContactPoint describe(Side side, const WheelsetPose& pose, double xi_g, double s_w,
                        double s_r) const;

  // Newton on Eq. (12) plus "parameter = value" for all seven of y, z, phi, s; a side in Edge
  // mode has s_w fixed at its flange boundary instead of the tangency equation. Returns the number
  // of iterations, or -1 when it did not converge (x is then unspecified). Allocation-free.
  int newton(ContactState& x, Parameter param, double value, double xi_g,
             std::array<ContactMode, 2> modes = {ContactMode::Tangent, ContactMode::Tangent}) const;
  // Value of a continuation parameter at a state.
  double parameterValue(const ContactState& x, Parameter param) const;

  // Eq. (15) on one wheel from a starting pair (s_w, s_r), anywhere on the profiles (no window):
  // the stationary point of the indentation reached by Newton. Allocation-free.
  FlangeContact indentation(Side side, const WheelsetPose& pose, double xi_g, double s_w,
                            double s_r) const;
  // Residual of Eq. (12) (6 components: left Y, Z, t.n, right Y, Z, t.n).
  std::array<double, 6> residual(const ContactState& x, double xi_g) const;

  // Global search at given pose: the smallest gap between wheel and rail over the wheel samples of
  // one window, and the wheel/rail parameters where it occurs (rail point below the wheel sample
  // along the rail frame vertical). Tread window: the vertical gap; flange and all: the distance to
  // the rail tangent line there. Negative gap = penetration. False when no sample is over the rail.
  struct Gap {
    double gap = 0.0;
    double s_w = 0.0;
    double s_r = 0.0;
  };
  bool minimumGap(Side side, const WheelsetPose& pose, double xi_g, Window window, Gap& out) const;
  // Candidate contact points: up to four deepest local minima of the sampled gap (distance to the
  // rail tangent line) in a window, ignoring samples within `exclude_radius` of s_w = exclude_s;
  // with exclude_radius > 0 the deepest sample on either side beyond the excluded band is offered
  // too (where the gap has no separate dip, e.g. next to a conformal zone). Pass exclude_radius =
  // 0 to keep all. Returns how many were found, deepest first. Allocation-free.
  int localMinima(Side side, const WheelsetPose& pose, double xi_g, Window window, double exclude_s,
                  double exclude_radius, std::array<Gap, 4>& out) const;
  // Rail parameter below the wheel point s_w (along the rail frame vertical) at a pose.
  double railBelow(Side side, const WheelsetPose& pose, double xi_g, double s_w) const;
  // First guess of Eq. (12): iterate z, phi until both windows just touch (gaps zero).
  bool globalGuess(double y, double xi_g, ContactState& x) const;

 private:
  static std::size_t idx(Side s) { return s == Side::Left ? 0 : 1; }
  struct SideData {
    double sigma = 1.0;
    const profiles::Profile* wheel = nullptr;
    const profiles::Profile* rail = nullptr;
    double boundary = 0.0;  // s_w of the tread/flange split
    double tip = 0.0;       // s_w of the flange tip
    bool has_flange = false;
    // Wheel samples (search_step) in the tread and flange windows, and from the flange tip to
    // the field-side end (All).
    std::vector<double> tread_s, tread_h, flange_s, flange_h, all_s, all_h;
  };
  bool acceptTread(const ContactState& x, std::array<ContactMode, 2> modes, double xi_g,
                   double& penetration) const;

  bool interiorIndentation(const SideData& sd, Side side, const WheelsetPose& pose, double xi_g,
                           double s_w, double s_r, FlangeContact& fc) const;
  void edgeFlange(const SideData& sd, Side side, const WheelsetPose& pose, double xi_g,
                  FlangeContact& fc) const;
  void sideResidual(const SideData& sd, double y, double z, double phi, double s_w, double s_r,
                    double xi_g, double* f, double (*jac)[5]) const;

  ContactGeometryConfig cfg_;
  double cb_ = 1.0, sb_ = 0.0;  // cos(beta), sin(beta)
  std::array<SideData, 2> side_;
};

}  // namespace rb::contact
