#pragma once
// Track centreline geometry and track frames (paper section 2.1, Eq. 1-2 and Eq. 5).
//
// Sign conventions (global frame <O;X,Y,Z>, Z up):
// - s is the arc length along the 3-D centreline [m].
// - psi (heading) is measured from X towards Y. Curvature kappa = dpsi/ds [1/m] is positive for a
//   LEFT curve (centre on the +Y side of the track frame), so psi increases in a left curve.
//   A segment of length L and radius R turns the heading by L/R.
// - theta (slope) is positive when the track goes DOWN in the forward direction (paper, after
//   Eq. 1): theta = -atan(gradient), gradient = rise/run, positive uphill.
// - phi (cant angle) is the right-handed rotation about X_t of Eq. (1): A_t = Rz(psi) Ry(theta)
//   Rx(phi). Y_t points to the LEFT rail, so positive phi LIFTS THE LEFT RAIL. The signed cant u
//   [m] is positive when the track is banked towards +Y (left), i.e. the right rail is higher:
//   phi = -asin(u / cant_base). A left curve with positive spec cant (outer = right rail raised)
//   has u > 0 and phi < 0, so the track frame rolls towards the curve centre; a right curve with
//   positive cant has u < 0 and phi > 0.
// - The tangent dR/ds = (cos(theta) cos(psi), cos(theta) sin(psi), -sin(theta)) is the first column
//   of A_t (Eq. 1).
//
// Segments (spec.hpp): a Transition is a clothoid whose curvature, signed cant and gradient are
// linear in s from the end values of the previous segment (the track starts straight, level and
// without cant); Tangent and Curve have constant values.
//
// Two evaluations are offered:
// - at(s): the preprocessor of paper Fig. 4: x, y, z, psi, theta, phi sampled every `step` and
//   interpolated with not-a-knot cubic splines; derivatives are the spline derivatives. This is
//   what the simulation uses (allocation-free).
// - exactAt(s): closed-form angles and their derivatives, positions by composite 8-point
//   Gauss-Legendre quadrature of the tangent (error ~1e-12 m). The reference for tests.
// Outside [0, length()] both extend the track as a straight line along the end tangent with the end
// angles held constant (all angle derivatives zero).
#include <Eigen/Dense>
#include <vector>

#include "workbench/core/spline.hpp"
#include "workbench/track/spec.hpp"

namespace rb::track {

// Rotation matrix A_t of Eq. (1) from the track frame to the global frame.
Eigen::Matrix3d trackRotation(double psi, double theta, double phi);

// Angular rate of the track frame per unit arc length, in track-frame coordinates (A^T dA/ds =
// skew(w)), for A = Rz(psi) Ry(theta) Rx(phi), and its s-derivative.
Eigen::Vector3d trackAngularRate(double theta, double phi, double psi_s, double theta_s,
                                 double phi_s);
Eigen::Vector3d trackAngularRateDerivative(double theta, double phi, double psi_s, double theta_s,
                                           double phi_s, double psi_ss, double theta_ss,
                                           double phi_ss);

// Ideal rail profile frames relative to the track frame, Eq. (5): r_lrp = (0, Lr, 0),
// r_rrp = (0, -Lr, 0); A_t,lrp = Rx(beta + delta), A_t,rrp = Rx(-beta + delta), beta the rail
// inclination [rad] and delta the linearised irregularity angle (z_l - z_r)/(2 Lr).
Eigen::Vector3d leftRailFramePosition(double rail_lr);
Eigen::Vector3d rightRailFramePosition(double rail_lr);
Eigen::Matrix3d leftRailFrameRotation(double beta, double delta);
Eigen::Matrix3d rightRailFrameRotation(double beta, double delta);

// Track frame at arc length s (Eq. 1-2) with first (_s) and second (_ss) s-derivatives.
struct TrackFrame {
  double s = 0.0;
  Eigen::Vector3d R = Eigen::Vector3d::Zero();        // [m] centreline position R_t(s)
  Eigen::Vector3d R_s = Eigen::Vector3d::Zero();      // [-] dR/ds (unit tangent)
  Eigen::Vector3d R_ss = Eigen::Vector3d::Zero();     // [1/m] d2R/ds2
  double psi = 0.0, theta = 0.0, phi = 0.0;           // [rad] heading, slope, cant angle
  double psi_s = 0.0, theta_s = 0.0, phi_s = 0.0;     // [rad/m]
  double psi_ss = 0.0, theta_ss = 0.0, phi_ss = 0.0;  // [rad/m^2]
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();    // A_t(s), Eq. (1)
  Eigen::Vector3d w = Eigen::Vector3d::Zero();        // [rad/m] angular rate, track frame
  Eigen::Vector3d w_s = Eigen::Vector3d::Zero();      // [rad/m^2]
  double curvature = 0.0;                             // [1/m] dpsi/ds, positive left
  double cant = 0.0;      // [m] signed cant u = -cant_base sin(phi), positive banked left
  double gradient = 0.0;  // [-] -tan(theta), positive uphill
};

// A compiled segment: its place on the track and the linear laws of curvature, signed cant and
// gradient over it.
struct Segment {
  SegmentKind kind = SegmentKind::Tangent;
  double s0 = 0.0;      // [m] start arc length
  double length = 0.0;  // [m]
  double radius = 0.0;  // [m] spec radius (0 for a tangent or a transition ending straight)
  Side side = Side::Left;
  double cant = 0.0;                  // [m] spec cant (unsigned height at the segment end)
  double kappa0 = 0.0, kappa1 = 0.0;  // [1/m] curvature at start and end (positive left)
  double u0 = 0.0, u1 = 0.0;          // [m] signed cant at start and end (positive banked left)
  double g0 = 0.0, g1 = 0.0;          // [-] gradient at start and end
  // Exact state at the segment start.
  double x0 = 0.0, y0 = 0.0, z0 = 0.0, psi0 = 0.0;
};

class TrackGeometry {
 public:
  TrackGeometry() = default;
  // Builds from a VALID spec (compileTrack() validates first); violations are internal errors.
  explicit TrackGeometry(const TrackSpec& spec);

  double length() const { return length_; }
  double step() const { return grid_step_; }  // [m] actual spline knot spacing (<= spec.step)
  double cantBase() const { return cant_base_; }
  double railLr() const { return rail_lr_; }
  double railInclination() const { return beta_; }
  const std::vector<Segment>& segments() const { return segments_; }
  // Index of the segment containing s (clamped to the first/last segment).
  std::size_t segmentIndex(double s) const;

  // Spline (preprocessor) evaluation; allocation-free.
  TrackFrame at(double s) const;
  // Exact evaluation by quadrature (tests, reference); allocation-free.
  TrackFrame exactAt(double s) const;

  // Spline knots (the sampled preprocessor table: s, x, y, z, psi, theta, phi).
  const SplineGrid& knots() const { return spline_.grid(); }

 private:
  TrackFrame fromAngles(double s, const double* v, const double* d1, const double* d2) const;
  std::vector<Segment> segments_;
  double length_ = 0.0;
  double grid_step_ = 0.0;
  double cant_base_ = 1.5;
  double rail_lr_ = 0.7555;
  double beta_ = 1.0 / 40.0;
  CubicSplineSet spline_;  // channels x, y, z, psi, theta, phi
};

}  // namespace rb::track
