#pragma once
// Linearised model: finite-difference Jacobian of an OdeSystem's rhs and its eigenvalues (Eigen
// EigenSolver). Used to check free-decay frequencies and to print the modes of a vehicle.
#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "workbench/integrators/ode.hpp"
#include "workbench/vehicle/guided.hpp"

namespace rb::vehicle {

// J = df/dy at (t, y) by central differences with the step h_i = rel_step * max(|y_i|, 1).
Eigen::MatrixXd finiteDifferenceJacobian(integ::OdeSystem& sys, double t, const Eigen::VectorXd& y,
                                         double rel_step = 1e-6);

// The Jacobian of the reduced system: rows and columns `keep` of df/dy at (t, y) by central
// differences with the step steps[c] for state c (c in keep), J(i, j) = d f_keep[i] / d y_keep[j].
// The states outside `keep` stay at y (cyclic coordinates such as the wheelset spin angles, on
// which f does not depend). Adds the rhs evaluations to *evaluations when given. Throws
// std::runtime_error naming the state when the rhs fails.
Eigen::MatrixXd finiteDifferenceJacobian(integ::OdeSystem& sys, double t, const Eigen::VectorXd& y,
                                         const Eigen::VectorXd& steps, const std::vector<int>& keep,
                                         long* evaluations = nullptr);

struct Mode {
  std::complex<double> eigenvalue;  // lambda = -zeta w0 + i wd
  double frequency_hz = 0.0;        // damped frequency |Im lambda| / (2 pi)
  double undamped_hz = 0.0;         // |lambda| / (2 pi)
  double damping_ratio = 0.0;       // -Re lambda / |lambda|
  // Share of each free position coordinate in the mode (|v_c|^2 M_cc, normalised to sum 1; M_cc
  // the diagonal of the free bodies' mass matrices), indexed like the state positions.
  Eigen::VectorXd participation;
  int dominant = -1;       // position index with the largest participation
  Eigen::VectorXcd shape;  // eigenvector (full state)
};

// Oscillatory modes (Im lambda > 0) of the guided vehicle linearised at (t, y), sorted by
// frequency.
std::vector<Mode> guidedModes(GuidedVehicleOde& ode, double t, const Eigen::VectorXd& y);

}  // namespace rb::vehicle
