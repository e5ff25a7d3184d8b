#include "workbench/vehicle/modal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "workbench/core/eigen_decomposition.hpp"

namespace rb::vehicle {

Eigen::MatrixXd finiteDifferenceJacobian(integ::OdeSystem& sys, double t, const Eigen::VectorXd& y,
                                         double rel_step) {
  const int n = sys.size();
  Eigen::VectorXd steps(n);
  std::vector<int> all(static_cast<std::size_t>(n));
  for (int c = 0; c < n; ++c) {
    steps[c] = rel_step * std::max(std::abs(y[c]), 1.0);
    all[static_cast<std::size_t>(c)] = c;
  }
  return finiteDifferenceJacobian(sys, t, y, steps, all);
}

int centralDifferenceJacobian(integ::OdeSystem& sys, double t, const Eigen::VectorXd& y,
                              const Eigen::VectorXd& steps, const std::vector<int>& keep,
                              DifferenceQuotient quotient, Eigen::MatrixXd& J, long& evaluations,
                              bool* failed_plus) {
  const int n = sys.size();
  const auto m = static_cast<Eigen::Index>(keep.size());
  J.resize(m, m);
  Eigen::VectorXd yp = y, fp(n), fm(n);
  for (Eigen::Index j = 0; j < m; ++j) {
    const int c = keep[static_cast<std::size_t>(j)];
    const double h = steps[c];
    evaluations += 2;
    yp[c] = y[c] + h;
    const double hp = yp[c] - y[c];
    const bool plus_ok = sys.rhs(t, yp.data(), fp.data()) == 0;
    yp[c] = y[c] - h;
    const double hm = y[c] - yp[c];
    const bool minus_ok = plus_ok && sys.rhs(t, yp.data(), fm.data()) == 0;
    yp[c] = y[c];
    if (!minus_ok) {
      if (failed_plus != nullptr) *failed_plus = !plus_ok;
      return c;
    }
    // The perturbed values are rounded to doubles: over the step taken, hp + hm is the exact
    // distance between the two states.
    const double denominator = quotient == DifferenceQuotient::StepTaken ? hp + hm : 2.0 * h;
    for (Eigen::Index i = 0; i < m; ++i) {
      const int r = keep[static_cast<std::size_t>(i)];
      J(i, j) = (fp[r] - fm[r]) / denominator;
    }
  }
  return -1;
}

Eigen::MatrixXd finiteDifferenceJacobian(integ::OdeSystem& sys, double t, const Eigen::VectorXd& y,
                                         const Eigen::VectorXd& steps, const std::vector<int>& keep,
                                         long* evaluations) {
  Eigen::MatrixXd J;
  long count = 0;
  bool plus = false;
  const int failed = centralDifferenceJacobian(sys, t, y, steps, keep,
                                               DifferenceQuotient::StepTaken, J, count, &plus);
  if (failed >= 0)
    throw std::runtime_error("rhs failed at " + sys.componentName(failed) +
                             (plus ? " + h: " : " - h: ") + sys.lastError());
  if (evaluations != nullptr) *evaluations += count;
  // The rhs refuses non-finite states, but a finite state can still give difference quotients
  // that overflow: never hand a non-finite Jacobian to the eigensolver.
  if (!J.allFinite()) throw std::runtime_error("the finite-difference Jacobian is not finite");
  return J;
}

std::vector<Mode> guidedModes(GuidedVehicleOde& ode, double t, const Eigen::VectorXd& y) {
  const Eigen::MatrixXd J = finiteDifferenceJacobian(ode, t, y);
  const EigenDecomposition es = eigenDecomposition(J, true);
  const VehicleLayout& l = ode.layout();
  const int n = 5 * l.n_free;
  // Diagonal mass weights of the free coordinates at y.
  Eigen::VectorXd yd(ode.size());
  ode.rhs(t, y.data(), yd.data());
  Eigen::VectorXd w(n);
  for (int k = 0; k < l.n_free; ++k) {
    const auto b = static_cast<std::size_t>(l.free_bodies[static_cast<std::size_t>(k)]);
    for (int c = 0; c < 5; ++c) w[5 * k + c] = ode.workspace().mass[b](1 + c, 1 + c);
  }
  std::vector<Mode> out;
  for (int i = 0; i < es.values.size(); ++i) {
    const std::complex<double> lam = es.values[i];
    // Oscillatory: Im > 0, and not a pair split off a double real root by round-off of the
    // finite-difference Jacobian (such a pair has Im / |lambda| of order sqrt(eps_J) ~ 1e-5 and a
    // damping ratio of 1 to 6 digits; a physical mode with zeta < 0.9999995 passes).
    if (!(lam.imag() > 1e-9 && lam.imag() > 1e-3 * std::abs(lam))) continue;
    Mode m;
    m.eigenvalue = lam;
    m.frequency_hz = lam.imag() / (2.0 * std::numbers::pi);
    m.undamped_hz = std::abs(lam) / (2.0 * std::numbers::pi);
    m.damping_ratio = -lam.real() / std::abs(lam);
    m.shape = es.vectors.col(i);
    m.participation.resize(n);
    for (int c = 0; c < n; ++c) m.participation[c] = std::norm(m.shape[c]) * w[c];
    const double sum = m.participation.sum();
    if (sum > 0.0) m.participation /= sum;
    m.participation.maxCoeff(&m.dominant);
    out.push_back(std::move(m));
  }
  std::sort(out.begin(), out.end(),
            [](const Mode& a, const Mode& b) { return a.frequency_hz < b.frequency_hz; });
  return out;
}

}  // namespace rb::vehicle
