#pragma once
// Small ODE/DAE systems with exact solutions and fault injection for the integrator tests.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "workbench/integrators/integrator.hpp"

namespace rb::integ::test {

// x' = v, v' = -x: x = cos t, v = -sin t.
class Oscillator : public OdeSystem {
 public:
  int size() const override { return 2; }
  int rhs(double, const double* y, double* yd) override {
    yd[0] = y[1];
    yd[1] = -y[0];
    return 0;
  }
  static Eigen::VectorXd exact(double t) { return Eigen::Vector2d(std::cos(t), -std::sin(t)); }
};

// Prothero-Robinson: y' = lambda (y - sin t) + cos t, y(0) = 0, exact y = sin t. Stiff for
// lambda << 0.
class ProtheroRobinson : public OdeSystem {
 public:
  explicit ProtheroRobinson(double lambda, bool analytic_jacobian = true)
      : lambda_(lambda), jac_(analytic_jacobian) {}
  int size() const override { return 1; }
  int rhs(double t, const double* y, double* yd) override {
    yd[0] = lambda_ * (y[0] - std::sin(t)) + std::cos(t);
    return 0;
  }
  bool hasJacobian() const override { return jac_; }
  int jacobian(double, const double*, const double*, Eigen::Ref<Eigen::MatrixXd> J) override {
    J(0, 0) = lambda_;
    ++jacobian_calls;
    return 0;
  }
  long jacobian_calls = 0;

 private:
  double lambda_;
  bool jac_;
};

// A damped 3-mass chain x' = A x with an analytic Jacobian (for the Jacobian-source tests).
class LinearChain : public OdeSystem {
 public:
  explicit LinearChain(bool analytic_jacobian) : jac_(analytic_jacobian) {
    a_ << -1.0, 0.5, 0.0, 0.5, -2.0, 0.5, 0.0, 0.5, -30.0;
  }
  int size() const override { return 3; }
  int rhs(double, const double* y, double* yd) override {
    Eigen::Map<Eigen::Vector3d> out(yd);
    out = a_ * Eigen::Map<const Eigen::Vector3d>(y);
    return 0;
  }
  bool hasJacobian() const override { return jac_; }
  int jacobian(double, const double*, const double*, Eigen::Ref<Eigen::MatrixXd> J) override {
    J = a_;
    ++jacobian_calls;
    return 0;
  }
  long jacobian_calls = 0;

 private:
  bool jac_;
  Eigen::Matrix3d a_;
};

// Oscillator (x0, x1) plus a decaying x2' = -x2, with one injected fault from t_fault on.
class Faulty : public OdeSystem {
 public:
  enum class Fault { None, RecoverableOnce, Fatal, NaN, Throw };
  Faulty(Fault f, double t_fault) : fault_(f), t_fault_(t_fault) {}
  int size() const override { return 3; }
  int rhs(double t, const double* y, double* yd) override {
    ++calls;
    yd[0] = y[1];
    yd[1] = -y[0];
    yd[2] = -y[2];
    if (t < t_fault_) return 0;
    switch (fault_) {
      case Fault::RecoverableOnce:
        if (!fired) {
          fired = true;
          error_ = "contact point outside the table";
          return 1;
        }
        break;
      case Fault::Fatal:
        error_ = "injected fatal failure";
        return -1;
      case Fault::NaN:
        yd[2] = std::numeric_limits<double>::quiet_NaN();
        break;
      case Fault::Throw:
        throw std::runtime_error("injected exception");
      case Fault::None:
        break;
    }
    return 0;
  }
  std::string componentName(int i) const override { return "x" + std::to_string(i); }
  std::string lastError() const override { return error_; }
  static Eigen::VectorXd exact(double t) {
    return Eigen::Vector3d(std::cos(t), -std::sin(t), std::exp(-t));
  }
  bool fired = false;
  long calls = 0;

 private:
  Fault fault_;
  double t_fault_;
  std::string error_;
};

// Index-1 DAE: y0' = -y0 + y1, 0 = y1 - sin t; y0(0) = 1:
// y0 = 1.5 e^-t + (sin t - cos t) / 2, y1 = sin t.
class SimpleDae : public DaeSystem {
 public:
  int size() const override { return 2; }
  int residual(double t, const double* y, const double* yp, double* r) override {
    r[0] = yp[0] - (-y[0] + y[1]);
    r[1] = y[1] - std::sin(t);
    return 0;
  }
  bool isDifferential(int i) const override { return i == 0; }
  static Eigen::VectorXd exact(double t) {
    return Eigen::Vector2d(1.5 * std::exp(-t) + 0.5 * (std::sin(t) - std::cos(t)), std::sin(t));
  }
};

}  // namespace rb::integ::test
