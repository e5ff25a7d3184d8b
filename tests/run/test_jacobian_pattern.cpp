// The vehicle's structural Jacobian pattern (vehicle/sparsity.hpp) and the grouped difference
// Jacobian (integrators/fd_jacobian.hpp) on the contact wagon: no dependency missed, fewer
// evaluations, and the same entries as the column-by-column differences.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/integrators/fd_jacobian.hpp"
#include "workbench/run/compile.hpp"

namespace {

struct Case {
  const char* method;
  const char* spin;
  const char* creep;
};

rb::run::Model compileWagon(const Case& c) {
  rb::run::CompileOptions o;
  o.scenario = std::string("scenarios/validation/case3_") + c.method + ".lua";
  o.root = RB_SOURCE_DIR;
  o.overrides = {std::string("contact.wheelset_spin=") + c.spin,
                 std::string("contact.creep=") + c.creep, "contact.normal_forces=consistent",
                 "run.distance=10"};
  return rb::run::compile(o);
}

// A random state near the initial one: positions within +-0.5 mm (+-0.5 mrad), rates within
// +-5 mm/s, series forces within +-100 N.
Eigen::VectorXd randomState(rb::dynamics::ContactVehicleOde& ode, unsigned seed) {
  Eigen::VectorXd y = ode.initialState(0.0);
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto& l = ode.layout();
  for (int i = 0; i < l.size; ++i) {
    const bool theta = ode.componentName(i).find("theta") != std::string::npos;
    if (i < l.positions())
      y(i) += theta ? 0.0 : 5e-4 * u(gen);
    else if (i < 2 * l.positions())
      y(i) += 5e-3 * u(gen);
    else
      y(i) += 100.0 * u(gen);
  }
  return y;
}

struct Jacobians {
  Eigen::MatrixXd plain, grouped;
  long groups = 0;
};

Jacobians differences(rb::dynamics::ContactVehicleOde& ode, const Eigen::VectorXd& y0) {
  const long n = ode.size();
  Eigen::VectorXd y = y0, f0(n), ft(n), ft0(n), inc(n);
  // Increments well above the iterative solvers' tolerances (the KEC Newton iteration, the
  // Consistent normal-force iteration), whose residue each quotient divides by the increment.
  for (long j = 0; j < n; ++j) inc(j) = 1e-7 * std::max(std::abs(y0(j)), 1.0);
  // Every perturbed evaluation follows one at y0: the KEC solver's warm start and the normal
  // forces the Consistent iteration starts from are then those of y0 for every column, so the
  // quotients do not depend on the order of the evaluations.
  const auto rhs = [&](double* yp, double* f) {
    const int rc = ode.rhs(0.0, y0.data(), ft0.data());
    return rc != 0 ? rc : ode.rhs(0.0, yp, f);
  };
  EXPECT_EQ(ode.rhs(0.0, y.data(), f0.data()), 0);
  Jacobians out;
  out.plain.resize(n, n);
  out.grouped.resize(n, n);
  const rb::integ::GroupedDifferences plain(n, {});
  const rb::integ::GroupedDifferences grouped(n, ode.jacobianPattern());
  out.groups = grouped.groups();
  EXPECT_EQ(plain.groups(), n);
  EXPECT_EQ(plain.forward(rhs, y.data(), f0.data(), inc.data(), ft.data(), out.plain), 0);
  EXPECT_EQ(grouped.forward(rhs, y.data(), f0.data(), inc.data(), ft.data(), out.grouped), 0);
  EXPECT_EQ(y, y0);  // restored exactly
  return out;
}

// Quotients outside the pattern are at most tol; the copy rows are e_k^T.
void expectWithinPattern(const rb::dynamics::ContactVehicleOde& ode, const Eigen::MatrixXd& jac,
                         double tol, const std::string& what) {
  const rb::integ::JacobianPattern p = ode.jacobianPattern();
  const long n = ode.size();
  ASSERT_EQ(static_cast<long>(p.rows.size()), n);
  Eigen::MatrixXd mask = Eigen::MatrixXd::Zero(n, n);
  for (long col = 0; col < n; ++col)
    for (const int i : p.rows[static_cast<std::size_t>(col)]) mask(i, col) = 1.0;
  const Eigen::MatrixXd outside = (mask.array() == 0.0).select(jac, 0.0);
  Eigen::Index i = 0, col = 0;
  EXPECT_LE(outside.cwiseAbs().maxCoeff(&i, &col), tol)
      << what << ": d " << ode.componentName(static_cast<int>(i)) << " / d "
      << ode.componentName(static_cast<int>(col)) << " outside the pattern";
  for (long r = 0; r < n; ++r) {
    const int k = p.copy_of[static_cast<std::size_t>(r)];
    if (k < 0) continue;
    EXPECT_NEAR(jac(r, k), 1.0, 1e-6) << what;
    EXPECT_EQ(jac.row(r).cwiseAbs().sum(), std::abs(jac(r, k))) << what;
  }
}

}  // namespace

// Every column's quotients are exact zeros outside the pattern, and the grouped ones equal the
// column-by-column ones (the other columns of a group do not enter the column's rows).
TEST(JacobianPattern, WagonPatternIsConservativeAndGroupedEqualsPlain) {
  for (const char* method : {"kec", "lut"}) {
    for (const char* spin : {"free", "prescribed"}) {
      const rb::run::Model m = compileWagon({method, spin, "none"});
      rb::dynamics::ContactVehicleOde ode(m.lead().vehicle, *m.lead().contact, *m.track);
      const Jacobians j = differences(ode, randomState(ode, 17));
      // LUT without creep forces is free of iterations: exact zeros, equal quotients. KEC: the
      // residue of its Newton iteration.
      const double tol = std::string(method) == "lut" ? 0.0 : 1e-8 * j.plain.cwiseAbs().maxCoeff();
      const std::string what = std::string(method) + " " + spin;
      expectWithinPattern(ode, j.plain, tol, what);
      EXPECT_LE((j.grouped - j.plain).cwiseAbs().maxCoeff(), tol) << what;
      EXPECT_LT(j.groups, ode.size() * 3 / 4) << what << ": " << j.groups << " groups";
    }
  }
}

// The same with creep forces (Polach, normal forces solved consistently with them).
TEST(JacobianPattern, GroupedEqualsPlainWithCreepForces) {
  for (const char* method : {"kec", "lut"}) {
    for (const char* spin : {"free", "prescribed"}) {
      const rb::run::Model m = compileWagon({method, spin, "polach"});
      rb::dynamics::ContactVehicleOde ode(m.lead().vehicle, *m.lead().contact, *m.track);
      const Eigen::VectorXd y = randomState(ode, 5);
      const Jacobians j = differences(ode, y);
      const double scale = j.plain.cwiseAbs().maxCoeff();
      EXPECT_LE((j.grouped - j.plain).cwiseAbs().maxCoeff(), 1e-8 * scale) << method << " " << spin;
    }
  }
}
