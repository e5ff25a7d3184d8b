#include "workbench/core/eigen_decomposition.hpp"

#include <Eigen/Eigenvalues>

namespace rb {

EigenDecomposition eigenDecomposition(const Eigen::MatrixXd& matrix, bool vectors) {
  const Eigen::EigenSolver<Eigen::MatrixXd> es(matrix, vectors);
  EigenDecomposition out;
  out.ok = es.info() == Eigen::Success;
  out.values = es.eigenvalues();
  if (vectors) out.vectors = es.eigenvectors();
  return out;
}

}  // namespace rb
