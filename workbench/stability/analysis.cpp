// Steady state, Jacobian and modes of the vehicle on wheel/rail contact (stability.hpp).
#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <numbers>
#include <optional>

#include "workbench/core/eigen_decomposition.hpp"
#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/contact_model.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/integrators/integrator.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/stability/stability.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/modal.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::stability {

namespace {

using Eigen::VectorXd;

double cpuSeconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

// Every state but the wheelset spin angles (cyclic coordinates).
std::vector<int> keptStates(const vehicle::VehicleLayout& l) {
  std::vector<int> spin;
  for (int w = 0; w < l.n_ws; ++w)
    if (l.wsPosition(w, 1) >= 0) spin.push_back(l.wsPosition(w, 1));
  std::vector<int> keep;
  for (int i = 0; i < l.size; ++i)
    if (std::find(spin.begin(), spin.end(), i) == spin.end()) keep.push_back(i);
  return keep;
}

// The finite-difference step of every state (StepRule).
VectorXd fdSteps(const vehicle::VehicleLayout& l, const VectorXd& y, double scale) {
  const StepRule r;
  VectorXd h(l.size);
  const int np = l.positions();
  for (int i = 0; i < l.size; ++i) {
    if (i < np)
      h[i] = r.position;
    else if (i < 2 * np)
      h[i] = r.rate * std::max(1.0, std::abs(y[i]));
    else
      h[i] = r.series * std::max(1.0, std::abs(y[i]) / r.series_ref);
  }
  return h * scale;
}

// Scale of each rhs row in the convergence test: velocities [m/s] and accelerations [m/s^2] as
// they are, series-force rates [N/s] against 1e6 N/s (a series spring of 1e6 N/m at 1 m/s).
VectorXd residualScale(const vehicle::VehicleLayout& l) {
  VectorXd s = VectorXd::Ones(l.size);
  for (int e = 0; e < l.n_series; ++e) s[l.series(e)] = 1e6;
  return s;
}

struct Residual {
  bool ok = false;
  double scaled = 0.0, raw = 0.0;
  VectorXd f;  // kept rows
};

Residual residual(integ::OdeSystem& ode, double t, const VectorXd& y, const std::vector<int>& keep,
                  const VectorXd& scale) {
  VectorXd f(ode.size());
  Residual r;
  r.f.resize(static_cast<Eigen::Index>(keep.size()));
  if (ode.rhs(t, y.data(), f.data()) != 0) return r;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    const int k = keep[i];
    r.f[static_cast<Eigen::Index>(i)] = f[k];
    r.raw = std::max(r.raw, std::abs(f[k]));
    r.scaled = std::max(r.scaled, std::abs(f[k]) / scale[k]);
  }
  r.ok = std::isfinite(r.scaled);
  return r;
}

// Newton on the kept states with a backtracking line search. Returns true when converged.
bool newton(dynamics::ContactVehicleOde& ode, Steady& st, const std::vector<int>& keep,
            const Options& o, long* evals) {
  const vehicle::VehicleLayout& l = ode.layout();
  const VectorXd scale = residualScale(l);
  Residual r = residual(ode, st.t, st.y, keep, scale);
  if (!r.ok) return false;
  for (int it = 0; it < o.max_newton; ++it) {
    st.residual = r.scaled;
    st.residual_raw = r.raw;
    if (r.scaled < o.newton_tol) return true;
    const VectorXd h = fdSteps(l, st.y, o.step_scale);
    const Eigen::MatrixXd J = vehicle::finiteDifferenceJacobian(ode, st.t, st.y, h, keep, evals);
    const VectorXd dz = J.fullPivLu().solve(-r.f);
    ++st.iterations;
    bool accepted = false;
    for (double alpha = 1.0; alpha > 1e-4 && !accepted; alpha *= 0.5) {
      VectorXd y = st.y;
      for (std::size_t i = 0; i < keep.size(); ++i)
        y[keep[i]] += alpha * dz[static_cast<Eigen::Index>(i)];
      const Residual rt = residual(ode, st.t, y, keep, scale);
      if (rt.ok && rt.scaled < r.scaled) {
        st.y = y;
        r = rt;
        accepted = true;
      }
    }
    if (!accepted) break;
  }
  st.residual = r.scaled;
  st.residual_raw = r.raw;
  return r.scaled < o.newton_tol;
}

// Fallback: let the transients die with BDF, then Newton again from there.
bool settle(dynamics::ContactVehicleOde& ode, Steady& st, const Options& o, std::string& why) {
  integ::SolverSpec s;
  s.method = integ::kBdf;
  s.rtol = 1e-6;
  s.atol = 1e-9;
  s.step = 0.0;
  s.max_steps = 1000000;
  auto integrator = integ::makeIntegrator(s);
  VectorXd last = st.y;
  const double t1 = st.t + o.settle_time;
  const integ::RunResult res =
      integ::integrate(ode, *integrator, st.t, st.y, {t1}, [&](double, const VectorXd& y) {
        last = y;
        return true;
      });
  if (!res.ok) {
    why = res.message;
    return false;
  }
  st.y = last;
  st.t = t1;
  return true;
}

// The curvature of the track under the vehicle when every body lies on tangents or on one
// constant-radius curve with a constant cant from t0 to t1 (a fixed point in the track frame
// exists only there); throws Failure naming the body otherwise.
double uniformCurvature(const vehicle::VehicleModel& vm, const track::TrackGeometry& g, double t0,
                        double t1) {
  double kappa = 0.0, cant = 0.0;
  bool first = true;
  for (std::size_t b = 0; b < vm.bodies.size(); ++b)
    for (const double t : {t0, t1}) {
      const double s = vm.bodyS(static_cast<int>(b), t);
      const track::Segment& seg = g.segments()[g.segmentIndex(s)];
      const bool same = first || (seg.kappa0 == kappa && seg.u0 == cant);
      if (seg.kappa0 != seg.kappa1 || seg.u0 != seg.u1 || !same)
        throw Failure("no steady state: body '" + vm.bodies[b].name +
                      "' at s = " + formatNumber(s) +
                      " m is not on the tangent or constant-radius curve of the rest of the "
                      "vehicle (a transition, or a change of radius or cant); choose a distance "
                      "with the whole vehicle on one tangent or curve");
      kappa = seg.kappa0;
      cant = seg.u0;
      first = false;
    }
  return kappa;
}

std::vector<Coordinate> bodyCoordinates(const vehicle::VehicleOde& ode) {
  const vehicle::VehicleModel& m = ode.model();
  std::vector<Coordinate> out;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const vehicle::Body& body = m.bodies[b];
    for (int c = vehicle::kY; c <= vehicle::kYaw; ++c) {
      const int r = ode.index(static_cast<int>(b), static_cast<vehicle::Coord>(c), true);
      if (r < 0) continue;
      Coordinate k;
      k.body = static_cast<int>(b);
      k.kind = static_cast<int>(body.kind);
      k.coord = c;
      k.rate_index = r;
      const bool spin = body.kind == vehicle::BodyKind::Wheelset && c == vehicle::kPitch;
      k.name =
          body.name + "." + (spin ? "spin" : vehicle::kCoordNames[static_cast<std::size_t>(c)]);
      k.weight = c <= vehicle::kZ ? body.mass : body.inertia[c - vehicle::kRoll];
      out.push_back(std::move(k));
    }
  }
  return out;
}

struct Eig {
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;
};

Eig eigen(const Eigen::MatrixXd& J, bool vectors) {
  EigenDecomposition es = eigenDecomposition(J, vectors);
  if (!es.ok) throw Failure("the eigenvalue solver did not converge");
  Eig e;
  e.values = std::move(es.values);
  if (vectors) e.vectors = std::move(es.vectors);
  return e;
}

// The modes (one per real eigenvalue and per conjugate pair) with shares and labels.
std::vector<Mode> modesOf(const Eig& e, const dynamics::ContactVehicleOde& ode,
                          const std::vector<Coordinate>& coords, const std::vector<int>& keep) {
  const vehicle::VehicleLayout& l = ode.layout();
  std::vector<int> pos(static_cast<std::size_t>(l.size), -1);
  for (std::size_t i = 0; i < keep.size(); ++i)
    pos[static_cast<std::size_t>(keep[i])] = static_cast<int>(i);
  int car = -1;
  for (std::size_t b = 0; b < ode.model().bodies.size() && car < 0; ++b)
    if (ode.model().bodies[b].kind == vehicle::BodyKind::CarBody) car = static_cast<int>(b);
  const int car_y = car < 0 ? -1 : pos[static_cast<std::size_t>(ode.index(car, vehicle::kY, true))];
  const int car_r =
      car < 0 ? -1 : pos[static_cast<std::size_t>(ode.index(car, vehicle::kRoll, true))];
  std::vector<Mode> out;
  for (Eigen::Index i = 0; i < e.values.size(); ++i) {
    const std::complex<double> lam = e.values[i];
    if (lam.imag() < 0.0) continue;
    Mode m;
    m.eigenvalue = lam;
    m.oscillatory = lam.imag() > 1e-9 && lam.imag() > 1e-3 * std::abs(lam);
    m.frequency_hz = lam.imag() / (2.0 * std::numbers::pi);
    m.damping_ratio = std::abs(lam) > 0.0 ? -lam.real() / std::abs(lam) : 0.0;
    const Eigen::VectorXcd v = e.vectors.col(i);
    double kinetic = 0.0;
    for (const Coordinate& c : coords) {
      const double s = c.weight * std::norm(v[pos[static_cast<std::size_t>(c.rate_index)]]);
      m.participation.push_back(s);
      kinetic += s;
    }
    double spring = 0.0;
    for (int k = 0; k < l.n_series; ++k)
      spring += std::norm(v[pos[static_cast<std::size_t>(l.series(k))]]) /
                ode.model().series_dampers[static_cast<std::size_t>(k)].series_stiffness;
    // Kinetic energy of the rates 1/2 M |v|^2 against the series springs' 1/2 |f|^2 / K.
    m.series_share = spring + kinetic > 0.0 ? spring / (spring + kinetic) : 0.0;
    if (kinetic > 0.0)
      for (double& p : m.participation) p /= kinetic;
    labelMode(m, coords, car_y < 0 ? 0.0 : v[car_y], car_r < 0 ? 0.0 : v[car_r]);
    out.push_back(std::move(m));
  }
  std::sort(out.begin(), out.end(), [](const Mode& a, const Mode& b) {
    return a.eigenvalue.imag() != b.eigenvalue.imag() ? a.eigenvalue.imag() < b.eigenvalue.imag()
                                                      : a.eigenvalue.real() > b.eigenvalue.real();
  });
  return out;
}

// Relevant for the step check: the oscillatory modes below 30 Hz with a damping ratio below 0.9
// (the body and hunting modes; above are the stiff creep and series modes, and a pair split off a
// nearly double real root is as sensitive as the square root of the Jacobian's error, while the
// stability answer depends on neither).
bool relevant(const Mode& m) {
  return m.oscillatory && m.frequency_hz < 30.0 && m.damping_ratio < 0.9;
}

void stepCheck(Analysis& a, const Eigen::VectorXcd& finer, const Options& o) {
  a.step_check = 0.0;
  for (Mode& m : a.modes) {
    double best = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < finer.size(); ++i)
      best = std::min(best, std::abs(finer[i] - m.eigenvalue));
    m.step_change = best / std::abs(m.eigenvalue);
    if (relevant(m)) a.step_check = std::max(a.step_check, m.step_change);
  }
  a.step_check_ok = a.step_check <= o.step_check_limit;
}

}  // namespace

double Analysis::huntingDamping() const {
  return least_hunting < 0 ? std::numeric_limits<double>::quiet_NaN()
                           : modes[static_cast<std::size_t>(least_hunting)].damping_ratio;
}

double Analysis::leastDamping() const {
  return least_damped < 0 ? std::numeric_limits<double>::quiet_NaN()
                          : modes[static_cast<std::size_t>(least_damped)].damping_ratio;
}

std::vector<std::size_t> Analysis::unstableModes() const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < modes.size(); ++i)
    if (unstable(modes[i])) out.push_back(i);
  return out;
}

std::string describe(const Mode& m) {
  return m.label + " (" + m.dominant + "), " +
         (m.oscillatory ? formatNumber(m.frequency_hz, 4) + " Hz" : std::string("aperiodic")) +
         ", damping ratio " + formatNumber(m.damping_ratio, 3) + ", Re " +
         formatNumber(m.eigenvalue.real(), 3) + " 1/s";
}

struct Analyser::Impl {
  std::optional<track::TrackModel> track;
  dynamics::TableCache cache;
};

Analyser::Analyser(scenario::ScenarioSpec spec, Options options)
    : spec_(std::move(spec)), options_(std::move(options)), impl_(std::make_unique<Impl>()) {
  if (!spec_.has_vehicle || !spec_.has_contact)
    throw Failure("the scenario needs a vehicle{} and a contact{} block (wheel/rail contact)");
  // Irregularities off: the steady state is a fixed point of the rhs only on the design track.
  spec_.track.irregularities = track::IrregularitySpec{};
  spec_.run.effects[scenario::effectIndex(scenario::Effect::Irregularities)].on = false;
  spec_.vehicle.acceleration = 0.0;
  spec_.contact.normal_forces = dynamics::NormalForceCoupling::Consistent;
  impl_->track.emplace(track::compileTrack(spec_.track));
  if (!options_.table_cache.empty()) impl_->cache = dynamics::TableCache(options_.table_cache);
}

Analyser::~Analyser() = default;

Analysis Analyser::analyse(double speed) {
  const double cpu0 = cpuSeconds();
  scenario::ScenarioSpec s = spec_;
  s.vehicle.speed = speed;
  const track::TrackModel& tr = *impl_->track;
  const vehicle::VehicleModel vm = vehicle::compileVehicle(s.vehicle, tr);
  const dynamics::ContactModel cm =
      dynamics::compileContact(s.profiles, s.contact, vm, tr, &impl_->cache);
  dynamics::ContactVehicleOde ode(vm, cm, tr);
  Analysis a;
  a.speed = speed;
  a.method = dynamics::ContactModel::methodName(cm.method);
  a.creep = dynamics::ContactModel::creepName(cm.creep);
  a.spin = dynamics::ContactModel::spinName(cm.spin);
  a.notes.push_back(
      "normal-force coupling: consistent (the lagged coupling gives the rhs a memory)");
  a.notes.push_back("irregularities off");
  Steady& st = a.steady;
  st.t = options_.distance / speed;
  try {
    st.y = ode.initialState(st.t);
  } catch (const InputError& e) {
    throw Failure(std::string("no static equilibrium to start from: ") + e.what());
  }
  const std::vector<int> keep = keptStates(ode.layout());
  long fd_evals = 0;
  try {
    // On a tangent the centred start is the steady state up to the suspension's static
    // deflections: Newton from it. In a curve the wheelsets must first find their rolling-radius
    // difference (often on the flange): settle with BDF first, then Newton.
    const double kappa = uniformCurvature(vm, tr.geometry(), st.t, st.t);
    const VectorXd y0 = st.y;
    const bool converged = kappa == 0.0 && newton(ode, st, keep, options_, &fd_evals);
    if (!converged) {
      st.fallback = true;
      st.y = y0;  // the settle starts where Newton started, not where it got stuck
      a.notes.push_back(kappa == 0.0 ? "Newton did not converge from the static equilibrium: "
                                       "BDF settle, then Newton"
                                     : "curve: BDF settle from the static equilibrium, then "
                                       "Newton");
      (void)uniformCurvature(vm, tr.geometry(), st.t, st.t + options_.settle_time);
      std::string why;
      if (!settle(ode, st, options_, why))
        throw Failure("no steady state at " + formatNumber(speed) + " m/s: the BDF settle of " +
                      formatNumber(options_.settle_time) + " s failed: " + why);
      if (!newton(ode, st, keep, options_, &fd_evals))
        throw Failure("no steady state at " + formatNumber(speed) +
                      " m/s: Newton did not converge after a BDF settle of " +
                      formatNumber(options_.settle_time) + " s (scaled residual " +
                      formatNumber(st.residual) + " after " + std::to_string(st.iterations) +
                      " iterations)");
    }
    for (int w = 0; w < ode.layout().n_ws; ++w)
      st.max_ws_lateral =
          std::max(st.max_ws_lateral, std::abs(st.y[ode.layout().wsPosition(w, 0)]));
    const VectorXd h = fdSteps(ode.layout(), st.y, options_.step_scale);
    const Eigen::MatrixXd J =
        vehicle::finiteDifferenceJacobian(ode, st.t, st.y, h, keep, &fd_evals);
    a.states = static_cast<int>(J.rows());
    a.coordinates = bodyCoordinates(ode);
    a.modes = modesOf(eigen(J, true), ode, a.coordinates, keep);
    if (options_.step_check) {
      const Eigen::MatrixXd J10 = vehicle::finiteDifferenceJacobian(
          ode, st.t, st.y, h / options_.step_check_ratio, keep, &fd_evals);
      stepCheck(a, eigen(J10, false).values, options_);
    }
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const Failure*>(&e) != nullptr) throw;
    throw Failure(std::string("the model cannot be evaluated near the steady state: ") + e.what());
  }
  double least = std::numeric_limits<double>::infinity();
  double least_any = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.modes.size(); ++i) {
    if (a.modes[i].hunting && a.modes[i].damping_ratio < least) {
      least = a.modes[i].damping_ratio;
      a.least_hunting = static_cast<int>(i);
    }
    // A neutral mode (|Re lambda| within the floor: a real eigenvalue of round-off size has the
    // damping ratio +-1 by its sign alone) neither grows nor decays in any run: it decides nothing.
    const bool neutral = std::abs(a.modes[i].eigenvalue.real()) <= kUnstableFloor;
    if (!neutral && a.modes[i].damping_ratio < least_any) {
      least_any = a.modes[i].damping_ratio;
      a.least_damped = static_cast<int>(i);
    }
  }
  a.rhs_evaluations = ode.stats().evaluations;
  a.cpu_s = cpuSeconds() - cpu0;
  return a;
}

Analysis analyse(const scenario::ScenarioSpec& spec, double speed, const Options& options) {
  Analyser an(spec, options);
  return an.analyse(speed);
}

}  // namespace rb::stability
