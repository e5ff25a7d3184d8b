#include "tests/wickens/wickens_linear.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "workbench/creep/kalker.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/vehicle/modal.hpp"

namespace rbtest::wickens {

using namespace rb;

Case compileCase(const std::string& scenario, const std::vector<std::string>& overrides) {
  run::CompileOptions o;
  o.root = RB_SOURCE_DIR;
  o.scenario = std::string(RB_SOURCE_DIR) + "/scenarios/stability/" + scenario;
  o.overrides = overrides;
  Case c;
  c.model = std::make_unique<run::Model>(run::compile(o));
  return c;
}

namespace {

dynamics::ContactVehicleOde& contactOde(std::unique_ptr<vehicle::VehicleOde>& ode) {
  auto* c = dynamic_cast<dynamics::ContactVehicleOde*>(ode.get());
  if (c == nullptr) throw std::runtime_error("the Wickens case has no wheel/rail contact");
  return *c;
}

// The contact outputs of both wheels with the wheelset displaced laterally by y (rates as in the
// centred state: rolling at V / r0, no lateral or yaw motion).
std::array<dynamics::WheelOutput, 2> wheelsAt(dynamics::ContactVehicleOde& ode,
                                              const Eigen::VectorXd& centred, double y) {
  Eigen::VectorXd s = centred;
  s[ode.layout().wsPosition(0, 0)] += y;
  std::array<dynamics::WheelOutput, 2> w;
  if (ode.wheelOutputs(0.0, s.data(), w) != 0)
    throw std::runtime_error("wheel outputs failed: " + ode.lastError());
  return w;
}

// Normal-force-weighted mean of a patch quantity over the active patches of a wheel.
template <class F>
double wheelMean(const dynamics::WheelOutput& w, F f) {
  double sum = 0.0, n = 0.0;
  for (const auto& p : w.patch)
    if (p.active) {
      sum += p.normal * f(p);
      n += p.normal;
    }
  return sum / n;
}

// Lateral force (track frame, left positive) of the normal forces and of the creep forces of
// both wheels.
struct LateralForces {
  double normal = 0.0, creep = 0.0;
};
LateralForces lateralForces(const std::array<dynamics::WheelOutput, 2>& w) {
  LateralForces f;
  for (int side = 0; side < 2; ++side) {
    const double sigma = side == 0 ? 1.0 : -1.0;
    for (const auto& p : w[static_cast<std::size_t>(side)].patch)
      if (p.active) {
        // The normal leans toward the track centre by gamma_track: its lateral component on the
        // left wheel points right (-y), on the right wheel left.
        const double fn = -sigma * p.normal * std::sin(p.gamma_track);
        f.normal += fn;
        f.creep += p.force.y_track - fn;
      }
  }
  return f;
}

}  // namespace

CentredParameters centredParameters(Case& c, double dy) {
  auto ode_ptr = run::makeVehicleOde(*c.model);
  dynamics::ContactVehicleOde& ode = contactOde(ode_ptr);
  const Eigen::VectorXd y0 = ode.initialState(0.0);
  const auto w0 = wheelsAt(ode, y0, 0.0);
  const auto wp = wheelsAt(ode, y0, dy);
  const auto wm = wheelsAt(ode, y0, -dy);
  CentredParameters p;
  const dynamics::WheelOutput& left = w0[0];
  for (const auto& patch : left.patch) p.patches_per_wheel += patch.active ? 1 : 0;
  const auto radius = [](const dynamics::PatchOutput& q) { return q.radius; };
  const auto gamma = [](const dynamics::PatchOutput& q) { return q.gamma; };
  const auto lateral = [](const dynamics::PatchOutput& q) { return q.y; };
  p.r0 = 0.5 * (wheelMean(w0[0], radius) + wheelMean(w0[1], radius));
  p.l0 = 0.5 * (wheelMean(w0[0], lateral) - wheelMean(w0[1], lateral));
  const auto delta = [&](const std::array<dynamics::WheelOutput, 2>& w, auto f) {
    return wheelMean(w[0], f) - wheelMean(w[1], f);
  };
  p.lambda = (delta(wp, radius) - delta(wm, radius)) / (4.0 * dy);
  p.dgamma_dy = (delta(wp, gamma) - delta(wm, gamma)) / (2.0 * dy);
  p.gamma0 = wheelMean(left, gamma);
  // One patch per wheel is the closed form's picture; with two (a KEC band) the first patch's
  // ellipse is reported and the creep coefficients are summed over the patches.
  const dynamics::PatchOutput& first = left.patch[0];
  p.normal = left.normal;
  p.a = first.a;
  p.b = first.b;
  const double nu = c.model->lead().contact->material.nu;
  const double G = c.model->lead().contact->creep_params.G;
  for (const auto& q : left.patch) {
    if (!q.active) continue;
    const creep::KalkerCoefficients k = creep::kalkerCoefficients(q.a / q.b, nu);
    const double cc = std::sqrt(q.a * q.b);
    p.f11 += G * cc * cc * k.c11;
    p.f22 += G * cc * cc * k.c22;
    p.f23 += G * cc * cc * cc * k.c23;
    p.f33 += G * cc * cc * cc * cc * k.c33;
    if (&q == &first) {
      p.c11 = k.c11;
      p.c22 = k.c22;
      p.c23 = k.c23;
      p.c33 = k.c33;
    }
  }
  const LateralForces fp = lateralForces(wp), fm = lateralForces(wm);
  p.k_gravity = -(fp.normal - fm.normal) / (2.0 * dy);
  p.k_spin = -(fp.creep - fm.creep) / (2.0 * dy);
  const int ws = ode.layout().wheelsets.at(0);
  const auto& body = c.model->spec.vehicle.bodies.at(static_cast<std::size_t>(ws));
  p.mass = body.mass;
  p.yaw_inertia = body.inertia.z();
  p.roll_inertia = body.inertia.x();
  p.spin_inertia = body.inertia.y();
  const auto roll = [&](double y) {
    Eigen::VectorXd s = y0;
    s[ode.layout().wsPosition(0, 0)] += y;
    std::vector<vehicle::Vector6d> q(c.model->lead().vehicle.bodies.size());
    if (ode.bodyCoordinates(0.0, s.data(), q) != 0)
      throw std::runtime_error("body coordinates failed: " + ode.lastError());
    return q[static_cast<std::size_t>(ws)][vehicle::kRoll];
  };
  p.roll_slope = (roll(dy) - roll(-dy)) / (2.0 * dy);
  return p;
}

Springs springs(const Case& c) {
  Springs s;
  for (const auto& e : c.model->spec.vehicle.elements) {
    if (e.kind != vehicle::ElementKind::SpringDamper) continue;
    if (e.direction == vehicle::Direction::Y) s.ky += e.stiffness;
    if (e.direction == vehicle::Direction::X) s.kpsi += e.stiffness * e.point2.y() * e.point2.y();
  }
  return s;
}

double closedFormCriticalSpeed(const CentredParameters& p, const Springs& s,
                               double k_lateral_extra) {
  // README.md: total creep coefficients of the wheelset F1 = 2 f11, F2 = 2 f22.
  const double m = p.mass, I = p.yaw_inertia, F1 = 2.0 * p.f11, F2 = 2.0 * p.f22;
  const double ky = s.ky + k_lateral_extra, kpsi = s.kpsi, l0 = p.l0;
  const double A3 = m * F1 * l0 * l0 + I * F2;
  const double A1 = F2 * kpsi + ky * F1 * l0 * l0;
  const double B0 = m * kpsi + I * ky;
  const double B2 = F1 * F2 * l0 * l0;
  const double a0 = ky * kpsi + F1 * F2 * l0 * p.lambda / p.r0;
  if (!(A1 > 0.0)) return 0.0;
  const double den = m * I * A1 * A1 + a0 * A3 * A3 - A1 * A3 * B0;
  if (!(den > 0.0)) return std::numeric_limits<double>::infinity();
  return std::sqrt(A1 * A3 * B2 / den);
}

std::vector<std::complex<double>> twoDofEigenvalues(const CentredParameters& p, const Springs& s,
                                                    double v, bool spin) {
  const double F1 = 2.0 * p.f11, F2 = 2.0 * p.f22, l0 = p.l0, m = p.mass, I = p.yaw_inertia;
  // x = (y, psi, y_dot, psi_dot):
  //   m y''   = -F2 (y'/V - psi) - ky y                      [- 2 f23 psi'/V - (k_grav + k_spin) y]
  //   I psi'' = -F1 l0 (l0 psi'/V + lambda y / r0) - kpsi psi
  //             [+ 2 f23 (y'/V - psi) - 2 f33 psi'/V + f33 d(gamma_l - gamma_r)/dy y / r0]
  const double ky = s.ky + (spin ? p.k_gravity + p.k_spin : 0.0);
  const double f23 = spin ? p.f23 : 0.0, f33 = spin ? p.f33 : 0.0;
  const double rho = spin ? 1.0 + p.r0 * p.roll_slope : 1.0;
  const double mr = m + (spin ? p.roll_inertia * p.roll_slope * p.roll_slope : 0.0);
  // Gyroscopic moments of the spinning wheelset (spin V / r0): I_zz psi'' + I_yy Omega phi' =
  // M_z, I_xx phi'' - I_yy Omega psi' = M_x, with phi = d(roll)/dy y on the constraints.
  const double gyro = spin ? p.spin_inertia * v / p.r0 * p.roll_slope : 0.0;
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  A(0, 2) = A(1, 3) = 1.0;
  A(2, 0) = -ky / mr;
  A(2, 1) = rho * F2 / mr;
  A(2, 2) = -rho * rho * F2 / (v * mr);
  A(2, 3) = (-2.0 * rho * f23 / v + gyro) / mr;
  A(3, 0) = (-F1 * l0 * p.lambda + f33 * p.dgamma_dy) / (p.r0 * I);
  A(3, 1) = -(s.kpsi + 2.0 * f23) / I;
  A(3, 2) = (2.0 * rho * f23 / v - gyro) / I;
  A(3, 3) = -(F1 * l0 * l0 + 2.0 * f33) / (v * I);
  const Eigen::EigenSolver<Eigen::Matrix4d> es(A, false);
  return {es.eigenvalues().begin(), es.eigenvalues().end()};
}

double twoDofCriticalSpeed(const CentredParameters& p, const Springs& s, bool spin, double v_lo,
                           double v_hi, double rel_tol) {
  const auto growth = [&](double v) {
    double g = -std::numeric_limits<double>::infinity();
    for (const auto& e : twoDofEigenvalues(p, s, v, spin))
      if (e.imag() > 0.0) g = std::max(g, e.real());
    return g;
  };
  if (!(growth(v_lo) < 0.0 && growth(v_hi) > 0.0))
    throw std::runtime_error("the 2-dof model's critical speed is not bracketed");
  while (v_hi - v_lo > rel_tol * v_hi) {
    const double mid = 0.5 * (v_lo + v_hi);
    (growth(mid) < 0.0 ? v_lo : v_hi) = mid;
  }
  return 0.5 * (v_lo + v_hi);
}

std::complex<double> Linearisation::leastDamped() const {
  std::complex<double> best(-std::numeric_limits<double>::infinity(), 0.0);
  for (const auto& e : eigenvalues)
    if (e.imag() > 0.0 && e.real() > best.real()) best = e;
  return best;
}

Linearisation linearise(Case& c, double v) {
  c.setSpeed(v);
  auto ode = run::makeVehicleOde(*c.model);
  auto& contact = contactOde(ode);
  const Eigen::VectorXd y0 = ode->initialState(0.0);
  Linearisation lin;
  // The centred rolling state is a steady state of the lateral and yaw motion on tangent track.
  Eigen::VectorXd f(ode->size());
  if (ode->rhs(0.0, y0.data(), f.data()) != 0)
    throw std::runtime_error("rhs failed: " + ode->lastError());
  const vehicle::VehicleLayout& l = ode->layout();
  for (const int coord : {0, 2})
    for (const int i : {l.wsPosition(0, coord), l.wsRate(0, coord)})
      lin.residual = std::max(lin.residual, std::abs(f[i]));
  const int spin = l.wsPosition(0, 1);
  if (spin >= 0) lin.spin_acceleration = f[l.wsRate(0, 1)];
  contact.resetStats();
  const Eigen::MatrixXd J = vehicle::finiteDifferenceJacobian(*ode, 0.0, y0);
  lin.evaluations = contact.stats().evaluations + 1;
  const Eigen::EigenSolver<Eigen::MatrixXd> es(J, false);
  // The spin angle theta is cyclic (nothing depends on it): its column of J is zero and gives
  // one zero eigenvalue, dropped here (the one of smallest modulus).
  std::vector<std::complex<double>> ev(es.eigenvalues().begin(), es.eigenvalues().end());
  if (spin >= 0) {
    const auto smallest = std::min_element(
        ev.begin(), ev.end(), [](auto a, auto b) { return std::abs(a) < std::abs(b); });
    ev.erase(smallest);
  }
  lin.eigenvalues = ev;
  return lin;
}

double klingelFrequency(const CentredParameters& p, double v) {
  return v * std::sqrt(p.lambda / (p.r0 * p.l0));
}

double linearCriticalSpeed(Case& c, double v_lo, double v_hi, double rel_tol, long* evaluations) {
  const auto growth = [&](double v) {
    const Linearisation lin = linearise(c, v);
    if (evaluations != nullptr) *evaluations += lin.evaluations;
    return lin.leastDamped().real();
  };
  if (!(growth(v_lo) < 0.0)) throw std::runtime_error("not stable at the lower bracket speed");
  if (!(growth(v_hi) > 0.0)) throw std::runtime_error("not unstable at the upper bracket speed");
  while (v_hi - v_lo > rel_tol * v_hi) {
    const double mid = 0.5 * (v_lo + v_hi);
    (growth(mid) < 0.0 ? v_lo : v_hi) = mid;
  }
  return 0.5 * (v_lo + v_hi);
}

}  // namespace rbtest::wickens
