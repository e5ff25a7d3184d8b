#pragma once
// Linear stability of the single wheelset of scenarios/stability/wickens.lua and the classical
// closed form it is verified against (derivation: tests/wickens/README.md).
//
// Our side: the full nonlinear 3-D contact model (run::compile, run::makeVehicleOde), linearised
// at the centred steady state on tangent track by vehicle::finiteDifferenceJacobian, its
// eigenvalues by Eigen::EigenSolver; the linear critical speed is where the largest real part of
// the oscillatory (complex) eigenvalues crosses zero (bracket and bisection on the speed).
//
// Closed-form side: every parameter taken from the same compiled model at the centred position
// (CentredParameters), never tuned.
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "workbench/run/compile.hpp"

namespace rbtest::wickens {

// A compiled case. The speed enters the contact vehicle only through VehicleModel::speedAt(), so
// setSpeed() changes the compiled model's V0 instead of compiling the scenario again (the contact
// tables stay).
struct Case {
  std::unique_ptr<rb::run::Model> model;
  void setSpeed(double v) { model->vehicles.front().vehicle.speed = v; }
};

// A scenario of scenarios/stability/ (e.g. "wickens.lua") with `overrides` (--set key=value).
Case compileCase(const std::string& scenario, const std::vector<std::string>& overrides);

// The parameters of the closed form at the centred static equilibrium (both wheels together
// where the closed form takes sums). Contact quantities of one wheel are the left wheel's (the
// case is symmetric).
struct CentredParameters {
  int patches_per_wheel = 0;               // active contact patches of a wheel (KEC band: 2)
  double r0 = 0.0;                         // [m] rolling radius at the centred contact
  double l0 = 0.0;                         // [m] half lateral distance of the contact points
  double lambda = 0.0;                     // [-] d(r_l - r_r)/dy / 2 at y = 0
  double dgamma_dy = 0.0;                  // [rad/m] d(gamma_l - gamma_r)/dy at y = 0
  double gamma0 = 0.0;                     // [rad] centred contact angle
  double normal = 0.0;                     // [N] normal force of one wheel
  double a = 0.0, b = 0.0;                 // [m] Hertz semi-axes (rolling, lateral)
  double c11 = 0.0, c22 = 0.0, c23 = 0.0;  // Kalker coefficients at a/b, nu
  double f11 = 0.0, f22 = 0.0;             // [N] G c^2 C11, G c^2 C22 of one wheel
  double c33 = 0.0;                        // UNVERIFIED in the table (kalker.hpp)
  double f23 = 0.0;                        // [N m] G c^3 C23 of one wheel
  double f33 = 0.0;                        // [N m^2] G c^4 C33 of one wheel
  // [N/m] lateral stiffness of the contact forces at zero rates: -dF_y/dy of the normal forces
  // (gravitational stiffness, contact-angle effect) and of the creep forces (the spin creepage
  // changes with the contact angle), from the model.
  double k_gravity = 0.0, k_spin = 0.0;
  double mass = 0.0, yaw_inertia = 0.0;  // [kg], [kg m^2] of the wheelset
  // [rad/m] d(roll)/dy of the wheelset on its contact constraints at y = 0, and its roll inertia
  // [kg m^2]: the contact points move laterally by (1 + r0 d(roll)/dy) dy (README.md).
  double roll_slope = 0.0, roll_inertia = 0.0;
  double spin_inertia = 0.0;  // [kg m^2] I_yy: gyroscopic coupling of roll and yaw
};

// At the centred state of `c` (its current speed), with central differences of step dy [m].
CentredParameters centredParameters(Case& c, double dy = 1e-5);

// The spring constants of the scene (from the compiled elements, not from the scenario's text):
// ky = sum of the lateral stiffnesses, kpsi = sum of kx b^2 of the longitudinal ones.
struct Springs {
  double ky = 0.0, kpsi = 0.0;
};
Springs springs(const Case& c);

// Closed form (README.md): the Routh-Hurwitz boundary of the 2-dof quartic,
//   V_c^2 = A1 A3 B2 / (m I A1^2 + a0 A3^2 - A1 A3 B0),
// 0 when no speed is stable (A1 = 0: no spring), +inf when every speed is.
// k_lateral_extra [N/m] is added to ky (0: Wickens' model without gravitational stiffness).
double closedFormCriticalSpeed(const CentredParameters& p, const Springs& s,
                               double k_lateral_extra = 0.0);

// Eigenvalues of the 2-dof model of the closed form (README.md) at speed v, for comparing the
// modes themselves (not only the stability boundary). With `spin`, the model also carries every
// spin-creep term of Kalker's linear theory (README.md, "The spin terms") and the gravitational
// and spin-creep lateral stiffnesses.
std::vector<std::complex<double>> twoDofEigenvalues(const CentredParameters& p, const Springs& s,
                                                    double v, bool spin = false);
// Critical speed of twoDofEigenvalues(p, s, v, spin) by bisection in [v_lo, v_hi].
double twoDofCriticalSpeed(const CentredParameters& p, const Springs& s, bool spin, double v_lo,
                           double v_hi, double rel_tol);

// Eigenvalues of the linearised full model at speed v (the zero eigenvalue of the cyclic spin
// angle dropped), and the rhs evaluations spent.
struct Linearisation {
  std::vector<std::complex<double>> eigenvalues;
  // At the centred state: max |f| over the rows of y, psi and their rates (zero at a steady
  // state), and the spin acceleration theta_ddot (the spin moments of Kalker's theory about the
  // inclined normals have a net component about the axle: a small rolling resistance, in the
  // symmetric motion that the lateral modes do not couple to at first order).
  double residual = 0.0;
  double spin_acceleration = 0.0;
  long evaluations = 0;
  // The oscillatory eigenvalue (Im > 0) with the largest real part.
  std::complex<double> leastDamped() const;
};
Linearisation linearise(Case& c, double v);

// Klingel's kinematic frequency omega = V sqrt(lambda / (r0 l0)) [rad/s].
double klingelFrequency(const CentredParameters& p, double v);

// Linear critical speed: bracket [v_lo, v_hi] (stable at v_lo, unstable at v_hi, checked) and
// bisection to rel_tol. evaluations accumulates the rhs calls.
double linearCriticalSpeed(Case& c, double v_lo, double v_hi, double rel_tol, long* evaluations);

}  // namespace rbtest::wickens
