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
#include "workbench/dynamics/rails_along_track.hpp"
#include "workbench/integrators/integrator.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/scenario/any_vehicle.hpp"
#include "workbench/stability/stability.hpp"
#include "workbench/track/track.hpp"
#include "workbench/train/train_ode.hpp"
#include "workbench/vehicle/modal.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::stability {

namespace {

using Eigen::VectorXd;

double cpuSeconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

// The linearised system: one vehicle's ODE, or a train's (train::TrainOde) whose vehicles'
// states follow one another. Each part is a vehicle with its layout, where its states begin and
// the prefix of its coordinates' names ("wagon2." in a train, "" alone).
struct System {
  struct Part {
    vehicle::VehicleOde* ode = nullptr;
    dynamics::ContactVehicleOde* contact = nullptr;
    int offset = 0;
    std::string prefix;
  };
  integ::OdeSystem* ode = nullptr;
  std::vector<Part> parts;
  int size() const { return ode->size(); }
};

// Every state but the wheelset spin angles (cyclic coordinates).
std::vector<int> keptStates(const System& sys) {
  std::vector<int> spin;
  for (const auto& p : sys.parts) {
    const vehicle::VehicleLayout& l = p.ode->layout();
    for (int w = 0; w < l.n_ws; ++w)
      if (l.wsPosition(w, 1) >= 0) spin.push_back(p.offset + l.wsPosition(w, 1));
  }
  std::vector<int> keep;
  for (int i = 0; i < sys.size(); ++i)
    if (std::find(spin.begin(), spin.end(), i) == spin.end()) keep.push_back(i);
  return keep;
}

// The finite-difference step of every state (StepRule).
VectorXd fdSteps(const System& sys, const VectorXd& y, double scale) {
  const StepRule r;
  VectorXd h = VectorXd::Constant(sys.size(), r.position);
  for (const auto& p : sys.parts) {
    const vehicle::VehicleLayout& l = p.ode->layout();
    const int np = l.positions();
    for (int j = 0; j < l.size; ++j) {
      const int i = p.offset + j;
      if (j < np)
        h[i] = r.position;
      else if (j < 2 * np)
        h[i] = r.rate * std::max(1.0, std::abs(y[i]));
      else
        h[i] = r.series * std::max(1.0, std::abs(y[i]) / r.series_ref);
    }
  }
  return h * scale;
}

// Scale of each rhs row in the convergence test: velocities [m/s] and accelerations [m/s^2] as
// they are, series-force rates [N/s] against 1e6 N/s (a series spring of 1e6 N/m at 1 m/s).
VectorXd residualScale(const System& sys) {
  VectorXd s = VectorXd::Ones(sys.size());
  for (const auto& p : sys.parts)
    for (int e = 0; e < p.ode->layout().n_series; ++e)
      s[p.offset + p.ode->layout().series(e)] = 1e6;
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
bool newton(System& sys, Steady& st, const std::vector<int>& keep, const Options& o, long* evals) {
  integ::OdeSystem& ode = *sys.ode;
  const VectorXd scale = residualScale(sys);
  Residual r = residual(ode, st.t, st.y, keep, scale);
  if (!r.ok) return false;
  for (int it = 0; it < o.max_newton; ++it) {
    st.residual = r.scaled;
    st.residual_raw = r.raw;
    if (r.scaled < o.newton_tol) return true;
    const VectorXd h = fdSteps(sys, st.y, o.step_scale);
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
bool settle(integ::OdeSystem& ode, Steady& st, const Options& o, std::string& why) {
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
                        double t1, const std::string& prefix = "") {
  double kappa = 0.0, cant = 0.0;
  bool first = true;
  for (std::size_t b = 0; b < vm.bodies.size(); ++b)
    for (const double t : {t0, t1}) {
      const double s = vm.bodyS(static_cast<int>(b), t);
      const track::Segment& seg = g.segments()[g.segmentIndex(s)];
      const bool same = first || (seg.kappa0 == kappa && seg.u0 == cant);
      if (seg.kappa0 != seg.kappa1 || seg.u0 != seg.u1 || !same)
        throw Failure("no steady state: body '" + prefix + vm.bodies[b].name +
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

void addBodyCoordinates(const vehicle::VehicleOde& ode, int offset, const std::string& prefix,
                        std::vector<Coordinate>& out) {
  const vehicle::VehicleModel& m = ode.model();
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const vehicle::Body& body = m.bodies[b];
    for (int c = vehicle::kY; c <= vehicle::kYaw; ++c) {
      const int r = ode.index(static_cast<int>(b), static_cast<vehicle::Coord>(c), true);
      if (r < 0) continue;
      Coordinate k;
      k.body = static_cast<int>(b);
      k.kind = static_cast<int>(body.kind);
      k.coord = c;
      k.rate_index = offset + r;
      const bool spin = body.kind == vehicle::BodyKind::Wheelset && c == vehicle::kPitch;
      k.name = prefix + body.name + "." +
               (spin ? "spin" : vehicle::kCoordNames[static_cast<std::size_t>(c)]);
      k.weight = c <= vehicle::kZ ? body.mass : body.inertia[c - vehicle::kRoll];
      out.push_back(std::move(k));
    }
  }
}

std::vector<Coordinate> bodyCoordinates(const System& sys) {
  std::vector<Coordinate> out;
  for (const auto& p : sys.parts) addBodyCoordinates(*p.ode, p.offset, p.prefix, out);
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

// The car body's lateral and roll rate components of each part (-1: the part has no car body).
struct CarRates {
  int y = -1, roll = -1;
};

// The modes (one per real eigenvalue and per conjugate pair) with shares and labels. The sway
// of a car body is told from the car body of the vehicle with the largest share of the mode.
std::vector<Mode> modesOf(const Eig& e, const System& sys, const std::vector<Coordinate>& coords,
                          const std::vector<int>& keep) {
  std::vector<int> pos(static_cast<std::size_t>(sys.size()), -1);
  for (std::size_t i = 0; i < keep.size(); ++i)
    pos[static_cast<std::size_t>(keep[i])] = static_cast<int>(i);
  std::vector<CarRates> cars;
  std::vector<std::size_t> part_of;  // per coordinate, its part
  for (std::size_t k = 0; k < sys.parts.size(); ++k) {
    const auto& p = sys.parts[k];
    int car = -1;
    for (std::size_t b = 0; b < p.ode->model().bodies.size() && car < 0; ++b)
      if (p.ode->model().bodies[b].kind == vehicle::BodyKind::CarBody) car = static_cast<int>(b);
    CarRates c;
    if (car >= 0) {
      const int y = p.offset + p.ode->index(car, vehicle::kY, true);
      const int roll = p.offset + p.ode->index(car, vehicle::kRoll, true);
      c.y = pos[static_cast<std::size_t>(y)];
      c.roll = pos[static_cast<std::size_t>(roll)];
    }
    cars.push_back(c);
  }
  for (const Coordinate& c : coords) {
    std::size_t k = 0;
    while (k + 1 < sys.parts.size() && c.rate_index >= sys.parts[k + 1].offset) ++k;
    part_of.push_back(k);
  }
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
    std::vector<double> by_part(sys.parts.size(), 0.0);
    for (std::size_t j = 0; j < coords.size(); ++j) {
      const Coordinate& c = coords[j];
      const double s = c.weight * std::norm(v[pos[static_cast<std::size_t>(c.rate_index)]]);
      m.participation.push_back(s);
      by_part[part_of[j]] += s;
      kinetic += s;
    }
    double spring = 0.0;
    for (const auto& p : sys.parts)
      for (int k = 0; k < p.ode->layout().n_series; ++k) {
        const int row = p.offset + p.ode->layout().series(k);
        spring += std::norm(v[pos[static_cast<std::size_t>(row)]]) /
                  p.ode->model().series_dampers[static_cast<std::size_t>(k)].series_stiffness;
      }
    // Kinetic energy of the rates 1/2 M |v|^2 against the series springs' 1/2 |f|^2 / K.
    m.series_share = spring + kinetic > 0.0 ? spring / (spring + kinetic) : 0.0;
    if (kinetic > 0.0)
      for (double& p : m.participation) p /= kinetic;
    const auto most = static_cast<std::size_t>(std::max_element(by_part.begin(), by_part.end()) -
                                               by_part.begin());
    const CarRates& car = cars[most];
    labelMode(m, coords, car.y < 0 ? 0.0 : v[car.y], car.roll < 0 ? 0.0 : v[car.roll]);
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

// The track's curvature under every vehicle at [t0, t1]: one tangent or curve for all, else
// Failure naming the vehicle.
double commonCurvature(const System& sys, const track::TrackGeometry& g, double t0, double t1) {
  std::optional<double> kappa;
  for (const auto& p : sys.parts) {
    const double k = uniformCurvature(p.ode->model(), g, t0, t1, p.prefix);
    if (kappa && k != *kappa)
      throw Failure(
          "no steady state: the vehicles of the train are not on one tangent or "
          "constant-radius curve ('" +
          p.prefix.substr(0, p.prefix.size() - 1) +
          "' is not where the first is); choose a distance with the whole train on one");
    kappa = k;
  }
  return kappa.value_or(0.0);
}

// Analysis::least_hunting and least_damped.
void findLeastDamped(Analysis& a) {
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
  // A train: its vehicles, contact models and connections, compiled once (the speed is set on
  // the vehicles for each analysis).
  std::optional<run::Model> train;
};

Analyser::Analyser(scenario::ScenarioSpec spec, Options options)
    : spec_(std::move(spec)), options_(std::move(options)), impl_(std::make_unique<Impl>()) {
  if (!spec_.has_vehicle || !spec_.has_contact)
    throw Failure("the scenario needs a vehicle{} and a contact{} block (wheel/rail contact)");
  // Rails that change along the track (a turnout) have no steady state to linearise about.
  if (scenario::anyProfiles(spec_, dynamics::railsAlongTrack))
    throw Failure(
        "the rails change along the track (profiles.rail_slices / extra_rails): there is no "
        "steady state to linearise about; run the scene (workbench run) instead");
  // The track under the rail adds states the linearisation does not know yet.
  if (scenario::anyContact(
          spec_, [](const dynamics::ContactSpec& c) { return !c.elastic.rail_support.empty(); }))
    throw Failure(
        "contact.elastic.rail_support (the track under the rail) is not part of the modes "
        "analysis: remove it for the modes, or run the scene (workbench run, critical-speed)");
  // Irregularities off: the steady state is a fixed point of the rhs only on the design track.
  spec_.track.irregularities = track::IrregularitySpec{};
  spec_.run.effects[scenario::effectIndex(scenario::Effect::Irregularities)].on = false;
  spec_.vehicle.acceleration = 0.0;
  spec_.contact.normal_forces = dynamics::NormalForceCoupling::Consistent;
  if (spec_.train.size() > 1) {
    // Every vehicle on wheel/rail contact at the constant speed of the analysis: a fixed point
    // of the train exists only when no vehicle accelerates.
    for (auto& e : spec_.train) {
      if (!e.has_contact)
        throw Failure("vehicle '" + e.name +
                      "' of the train has guided wheelsets: the modes need every vehicle on "
                      "wheel/rail contact");
      e.vehicle.acceleration = 0.0;
      e.contact.normal_forces = dynamics::NormalForceCoupling::Consistent;
    }
    spec_.train_longitudinal.on = false;
    run::CompileOptions co;
    co.table_cache = options_.table_cache;
    impl_->train.emplace(run::compileModel(spec_, co));
    return;
  }
  impl_->track.emplace(track::compileTrack(spec_.track));
  if (!options_.table_cache.empty()) impl_->cache = dynamics::TableCache(options_.table_cache);
}

Analyser::~Analyser() = default;

namespace {

// The contact methods (creep laws, spin models) of a train's vehicles: one name when they agree,
// else every vehicle's joined by "+".
std::string joined(const run::Model& m, const char* (*name)(const dynamics::ContactModel&)) {
  std::vector<std::string> out;
  for (const auto& v : m.vehicles) {
    const std::string n = name(*v.contact);
    if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
  }
  return join(out, "+");
}

}  // namespace

Analysis Analyser::analyse(double speed) {
  const double cpu0 = cpuSeconds();
  Analysis a;
  a.speed = speed;
  System sys;
  // One vehicle: its model and ODE here; a train: the compiled train at this speed.
  std::optional<vehicle::VehicleModel> vm;
  std::optional<dynamics::ContactModel> cm;
  std::unique_ptr<dynamics::ContactVehicleOde> single;
  std::unique_ptr<train::TrainOde> train;
  const track::TrackModel& tr = impl_->train ? *impl_->train->track : *impl_->track;
  if (!impl_->train) {
    scenario::ScenarioSpec s = spec_;
    s.vehicle.speed = speed;
    vm.emplace(vehicle::compileVehicle(s.vehicle, tr));
    cm.emplace(dynamics::compileContact(s.profiles, s.contact, *vm, tr, &impl_->cache));
    single = std::make_unique<dynamics::ContactVehicleOde>(*vm, *cm, tr);
    sys.ode = single.get();
    sys.parts.push_back({single.get(), single.get(), 0, ""});
    a.method = dynamics::ContactModel::methodName(cm->method);
    a.creep = dynamics::ContactModel::creepName(cm->creep);
    a.spin = dynamics::ContactModel::spinName(cm->spin);
  } else {
    run::Model& m = *impl_->train;
    for (auto& v : m.vehicles) v.vehicle.speed = speed;
    train = run::makeRunOde(m);
    sys.ode = train.get();
    for (int k = 0; k < train->vehicles(); ++k) {
      vehicle::VehicleOde& v = train->vehicle(k);
      sys.parts.push_back({&v, dynamic_cast<dynamics::ContactVehicleOde*>(&v), train->offset(k),
                           train->name(k) + "."});
      RB_CHECK(sys.parts.back().contact != nullptr, "a train's modes need contact vehicles");
    }
    a.method = joined(m, [](const dynamics::ContactModel& c) {
      return dynamics::ContactModel::methodName(c.method);
    });
    a.creep = joined(m, [](const dynamics::ContactModel& c) {
      return dynamics::ContactModel::creepName(c.creep);
    });
    a.spin = joined(m, [](const dynamics::ContactModel& c) {
      return dynamics::ContactModel::spinName(c.spin);
    });
    a.notes.push_back("train of " + std::to_string(m.vehicles.size()) +
                      " vehicles and their connections, at a constant speed (no longitudinal "
                      "motion): its modes together");
    if (spec_.train_longitudinal.loc.line > 0)
      a.notes.push_back(
          "train.longitudinal is off in the analysis: its traction, braking, resistance and "
          "gradient forces are not in the steady state");
  }
  a.notes.push_back(
      "normal-force coupling: consistent (the lagged coupling gives the rhs a memory)");
  a.notes.push_back("irregularities off");
  Steady& st = a.steady;
  st.t = options_.distance / speed;
  try {
    st.y = VectorXd::Zero(sys.size());
    for (const auto& p : sys.parts) {
      const VectorXd yk = p.ode->initialState(st.t);
      st.y.segment(p.offset, yk.size()) = yk;
    }
  } catch (const InputError& e) {
    throw Failure(std::string("no static equilibrium to start from: ") + e.what());
  }
  const std::vector<int> keep = keptStates(sys);
  long fd_evals = 0;
  try {
    // On a tangent the centred start is the steady state up to the suspension's static
    // deflections: Newton from it. In a curve the wheelsets must first find their rolling-radius
    // difference (often on the flange): settle with BDF first, then Newton.
    const double kappa = commonCurvature(sys, tr.geometry(), st.t, st.t);
    const VectorXd y0 = st.y;
    const bool converged = kappa == 0.0 && newton(sys, st, keep, options_, &fd_evals);
    if (!converged) {
      st.fallback = true;
      st.y = y0;  // the settle starts where Newton started, not where it got stuck
      a.notes.push_back(kappa == 0.0 ? "Newton did not converge from the static equilibrium: "
                                       "BDF settle, then Newton"
                                     : "curve: BDF settle from the static equilibrium, then "
                                       "Newton");
      (void)commonCurvature(sys, tr.geometry(), st.t, st.t + options_.settle_time);
      std::string why;
      if (!settle(*sys.ode, st, options_, why))
        throw Failure("no steady state at " + formatNumber(speed) + " m/s: the BDF settle of " +
                      formatNumber(options_.settle_time) + " s failed: " + why);
      if (!newton(sys, st, keep, options_, &fd_evals))
        throw Failure("no steady state at " + formatNumber(speed) +
                      " m/s: Newton did not converge after a BDF settle of " +
                      formatNumber(options_.settle_time) + " s (scaled residual " +
                      formatNumber(st.residual) + " after " + std::to_string(st.iterations) +
                      " iterations)");
    }
    for (const auto& p : sys.parts)
      for (int w = 0; w < p.ode->layout().n_ws; ++w)
        st.max_ws_lateral = std::max(st.max_ws_lateral,
                                     std::abs(st.y[p.offset + p.ode->layout().wsPosition(w, 0)]));
    const VectorXd h = fdSteps(sys, st.y, options_.step_scale);
    const Eigen::MatrixXd J =
        vehicle::finiteDifferenceJacobian(*sys.ode, st.t, st.y, h, keep, &fd_evals);
    a.states = static_cast<int>(J.rows());
    a.coordinates = bodyCoordinates(sys);
    a.modes = modesOf(eigen(J, true), sys, a.coordinates, keep);
    if (options_.step_check) {
      const Eigen::MatrixXd J10 = vehicle::finiteDifferenceJacobian(
          *sys.ode, st.t, st.y, h / options_.step_check_ratio, keep, &fd_evals);
      stepCheck(a, eigen(J10, false).values, options_);
    }
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const Failure*>(&e) != nullptr) throw;
    throw Failure(std::string("the model cannot be evaluated near the steady state: ") + e.what());
  }
  findLeastDamped(a);
  for (const auto& p : sys.parts) a.rhs_evaluations += p.contact->stats().evaluations;
  a.cpu_s = cpuSeconds() - cpu0;
  return a;
}

Analysis analyse(const scenario::ScenarioSpec& spec, double speed, const Options& options) {
  Analyser an(spec, options);
  return an.analyse(speed);
}

}  // namespace rb::stability
