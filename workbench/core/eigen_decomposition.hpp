#pragma once
// Eigenvalues and eigenvectors of a real square matrix (Eigen's EigenSolver). Compiled once, here:
// the solver's instantiation costs about 13 s of compile time in every translation unit that
// uses it, and the stability analysis, the modal analysis and the fixed-step limit all do.
#include <Eigen/Dense>

namespace rb {

struct EigenDecomposition {
  bool ok = false;           // the solver converged
  Eigen::VectorXcd values;   // eigenvalues, in the solver's order
  Eigen::MatrixXcd vectors;  // eigenvectors as columns (empty unless asked for)
};

EigenDecomposition eigenDecomposition(const Eigen::MatrixXd& matrix, bool vectors);

}  // namespace rb
