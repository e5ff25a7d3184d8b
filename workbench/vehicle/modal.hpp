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

// What a central difference quotient divides by: the step actually taken (y + h and y - h are
// rounded to doubles; the linearised stability analysis), or the nominal 2 h (the fixed-step
// check at the start of a run, run/step_limit.hpp, whose recorded limits were computed so).
enum class DifferenceQuotient { StepTaken, NominalStep };

// The one central-difference Jacobian of the workbench: rows and columns `keep` of df/dy at
// (t, y) with the step steps[c] for state c (c in keep), J(i, j) = d f_keep[i] / d y_keep[j], the
// columns in the order of `keep` (f+ then f- of each). The states outside `keep` stay at y.
// Counts 2 rhs evaluations per column tried in *evaluations. Returns the state index whose
// perturbed rhs failed (sys.lastError() says why; J is incomplete), or -1; *failed_plus says
// which side failed when given. J is not checked for finite values.
int centralDifferenceJacobian(integ::OdeSystem& sys, double t, const Eigen::VectorXd& y,
                              const Eigen::VectorXd& steps, const std::vector<int>& keep,
                              DifferenceQuotient quotient, Eigen::MatrixXd& J, long& evaluations,
                              bool* failed_plus = nullptr);

// The Jacobian of the reduced system (centralDifferenceJacobian over the step taken) for the
// linearised analyses: the states outside `keep` are cyclic coordinates such as the wheelset spin
// angles, on which f does not depend. Adds the rhs evaluations to *evaluations when given and the
// Jacobian is formed. Throws std::runtime_error naming the state when the rhs fails, and when a
// difference quotient is not finite.
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
