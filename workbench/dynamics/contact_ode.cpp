#include "workbench/dynamics/contact_ode.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

#include "workbench/core/bits.hpp"
#include "workbench/dynamics/contact_evaluate.hpp"
#include "workbench/dynamics/contact_methods.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/dynamics/rail_support.hpp"
#include "workbench/vehicle/equilibrium.hpp"

namespace rb::dynamics {

using internal::ContactModels;
using internal::ContactWorkspace;
using internal::EvalMode;
using internal::StageInput;
using internal::Vec7;
using internal::WheelsetWork;

namespace {

// Elastic contact over running rails of slices: the start's height and roll are the centred
// wheelset's on profiles.rail. Where the slice under a wheel at the start stands lower than that
// (the centred wheel clears it by more than the static approach the start sinks it by), the wheel
// would start in the air, with no contact stiffness for the static equilibrium's Newton steps: the
// wheelset is lowered and rolled so that each wheel comes down by its own clearance d, its height
// by -(d_l + d_r) / 2 and its roll by -(d_l - d_r) / (2 Lw). A few passes, as the clearance is
// measured along the rail's normal. Rails that meet the centred wheels are left as they are.
void lowerOntoSlices(const ContactModel& c, double s, double& dz, double& dphi) {
  const ElasticContactModel& e = *c.elastic;
  const double lw = c.geometry.wheel_lw;
  for (int pass = 0; pass < 4; ++pass) {
    double d[2] = {0.0, 0.0};
    for (std::size_t side = 0; side < 2; ++side) {
      if (!e.sliced[side]) continue;
      const contact::SlicedRailSearch::Place at = e.sliced[side]->at(s);
      if (at.search == nullptr) continue;
      contact::ElasticPose pose = c.centredPoseOver(at, side);
      pose.z += dz;
      pose.phi += dphi;
      contact::ElasticWheelGeometry g;
      contact::ElasticSearchWorkspace ws;
      at.search->search(pose, g, ws);
      if (g.count == 0 && g.min_gap > e.static_approach) d[side] = g.min_gap;
    }
    if (d[0] == 0.0 && d[1] == 0.0) return;
    dz -= 0.5 * (d[0] + d[1]);
    dphi -= (d[0] - d[1]) / (2.0 * lw);
  }
}

}  // namespace

vehicle::VehicleLayout contactLayout(const vehicle::VehicleModel& m, WheelsetSpin spin,
                                     ContactMethod method, bool rail_masses) {
  const bool prescribed = spin == WheelsetSpin::Prescribed;
  vehicle::VehicleLayout l =
      vehicle::vehicleLayout(m, methodInfo(method).wheelset_dof[prescribed ? 1 : 0]);
  if (rail_masses) {
    l.rail_masses = l.n_ws;
    l.size += 8 * l.n_ws;
  }
  return l;
}

ContactVehicleOde::ContactVehicleOde(const vehicle::VehicleModel& vehicle,
                                     const ContactModel& contact, const track::TrackModel& track)
    : VehicleOde(vehicle,
                 contactLayout(vehicle, contact.spin, contact.method, contact.railSupport())),
      contact_(&contact),
      work_(std::make_unique<ContactWorkspace>()) {
  RB_CHECK(layout_.n_ws > 0, "ContactVehicleOde: the vehicle has no wheelset");
  using vehicle::Stage;
  if (contact.method == ContactMethod::Elastic)
    stages_.use({Stage::Coordinates, Stage::Constraints, Stage::VehicleForces, Stage::FreeBodies,
                 Stage::ContactPatches, Stage::Checks, Stage::SeriesRates});
  else
    stages_.use({Stage::Coordinates, Stage::Constraints, Stage::VehicleForces, Stage::FreeBodies,
                 Stage::ContactPatches, Stage::Augmented, Stage::Coupling, Stage::Checks,
                 Stage::SeriesRates});
  RB_CHECK(contact.method == ContactMethod::Kec   ? contact.kec != nullptr
           : contact.method == ContactMethod::Lut ? contact.lut != nullptr
                                                  : contact.elastic != nullptr,
           "ContactVehicleOde: the contact model lacks the data of its method");
  if (track.irregularities()) irr_ = &*track.irregularities();
  ContactWorkspace& work = *work_;
  work.bodies = vehicle::makeWorkspace(vehicle);
  work.scratch.assign(static_cast<std::size_t>(layout_.size), 0.0);
  work.next_y.assign(static_cast<std::size_t>(layout_.size), 0.0);
  work.next_ydot.assign(static_cast<std::size_t>(layout_.size), 0.0);
  work.wheelsets.resize(static_cast<std::size_t>(layout_.n_ws));
  work.wheels.resize(2 * static_cast<std::size_t>(layout_.n_ws));
  work.qdd.assign(vehicle.bodies.size(), vehicle::Vector6d::Zero());
  for (int w = 0; w < layout_.n_ws; ++w) {
    WheelsetWork& ww = work.wheelset(w);
    ww.body = layout_.wheelset(w);
    ww.height = vehicle.bodies[ww.body].height;
    ww.contact = &contact.forWheelset(static_cast<std::size_t>(w));
    RB_CHECK(ww.contact->method == contact.method && ww.contact->creep == contact.creep &&
                 (ww.contact->elastic != nullptr) == (contact.elastic != nullptr) &&
                 (ww.contact->kec != nullptr) == (contact.kec != nullptr) &&
                 (ww.contact->lut != nullptr) == (contact.lut != nullptr),
             "ContactVehicleOde: a wheelset's own contact model differs in method or law");
    if (const ElasticContactModel* e = ww.contact->elastic.get()) {
      // The search's candidate lists hold at most one entry per wheel sample: reserved here, the
      // evaluations never allocate (their number of candidates changes from one to the next).
      for (std::size_t side = 0; side < 2; ++side) {
        const contact::ElasticContactSearch& search = e->search[side];
        const profiles::Profile& wheel = *search.pair().wheel;
        const auto n = static_cast<std::size_t>(
            (wheel.sMax() - wheel.sMin()) / search.spec().sample_step + 3.0);
        const auto reserve = [n](contact::ElasticSearchWorkspace& sw) {
          sw.gap.reserve(n);
          sw.bound.reserve(n);
          sw.minima.reserve(n);
          sw.depth.reserve(n);
          sw.sw.reserve(n);
          sw.sr.reserve(n);
          sw.ok.reserve(n);
        };
        reserve(ww.elastic[side].search);
        for (std::size_t r = 0; r < e->extra[side].size(); ++r)
          reserve(ww.elastic[side].extra_search[r]);
      }
    }
  }
  // The evaluation compiled for the model's contact method and creep law (the registries,
  // contact_methods.hpp and creep_laws.hpp); their rows decide, nothing else names them.
  // The elastic method's evaluations live in contact_ode_elastic.cpp (contact_evaluate.hpp).
  const auto choose = [&]<class... Methods, class... Laws>(MethodList<Methods...>,
                                                           LawList<Laws...>) {
    const auto pickLaw = [&]<class Method>() {
      if constexpr (Method::kMethod == ContactMethod::Elastic) {
        eval_ = elasticEvaluation(contact.creep);
        return true;
      } else {
        const auto pick = [&]<class Law>() {
          eval_ = &ContactVehicleOde::evaluateT<Method::kMethod, Law>;
          return true;
        };
        return ((contact.creep == Laws::kModel && pick.template operator()<Laws>()) || ...);
      }
    };
    ((contact.method == Methods::kMethod && pickLaw.template operator()<Methods>()) || ...);
  };
  choose(ContactMethods{}, CreepLaws{});
  RB_CHECK(eval_ != nullptr,
           "ContactVehicleOde: the contact method or creep law is not in its registry");
}

ContactVehicleOde::~ContactVehicleOde() = default;
ContactVehicleOde::ContactVehicleOde(ContactVehicleOde&&) noexcept = default;

std::string ContactVehicleOde::lastError() const {
  return work_->error;
}
integ::ModelFailure ContactVehicleOde::lastFailure() const {
  if (work_->failure == ContactFailure::None) return {};
  return {std::string(nameOf(work_->failure)), work_->failure_body};
}
const vehicle::Workspace& ContactVehicleOde::workspace() const {
  return work_->bodies;
}
double ContactVehicleOde::railForce() const {
  return work_->rail_force;
}
vehicle::Workspace& ContactVehicleOde::bodyWorkspace() {
  return work_->bodies;
}
void ContactVehicleOde::inputsChanged() {
  work_->next_valid = false;
}
const ContactStats& ContactVehicleOde::stats() const {
  return work_->stats;
}
void ContactVehicleOde::resetStats() {
  work_->stats = {};
}

int ContactVehicleOde::rhs(double t, const double* y, double* ydot) {
  internal::ContactWorkspace& work = *work_;
  if (work.next_valid && sameState(t, y, work.next_t, work.next_y)) {
    // Evaluated already, as this very call, by the observer of the state (outputs()).
    work.next_valid = false;
    ++work.stats.shared_evaluations;
    std::copy(work.next_ydot.begin(), work.next_ydot.end(), ydot);
    return 0;
  }
  return evaluate(t, y, ydot, EvalMode::Rhs);
}

int ContactVehicleOde::evaluate(double t, const double* y, double* ydot, EvalMode mode) {
  work_->next_valid = false;  // any evaluation moves the memory the kept rhs was made with
  return (this->*eval_)(t, y, ydot, mode);
}

void ContactVehicleOde::shareOutputEvaluations(bool on) {
  share_outputs_ = on;
  work_->next_valid = false;
}

int ContactVehicleOde::setCoordinates(double t, const double* y) {
  const ContactModels models{*model_, *contact_, layout_, irr_};
  const vehicle::ForwardMotion fm = vehicle::forwardMotion(*model_, work_->bodies, t);
  const StageInput in{t, y, fm.speed, fm.acceleration, EvalMode::Output, fm.travel};
  if (const int rc = internal::setIndependentCoordinates(models, in, *work_); rc != 0) return rc;
  return internal::solveConstraints(models, in, *work_);
}

// ---- Initial state -----------------------------------------------------------------------------

// What unloads a wheel in the static equilibrium: the lifted wheel and its normal force, and the
// rails' vertical irregularity under every wheelset (the design cant is followed by the
// suspension's equilibrium; a twist of the irregular rails over the wheelbase is what a stiff
// suspension cannot follow).
namespace {
std::string equilibriumLift(const vehicle::VehicleModel& m, const vehicle::VehicleLayout& layout,
                            const ContactModel& contact, const track::Irregularities* irr,
                            const ContactWorkspace& work, double t0) {
  const auto& [wheel, normal] = work.init_lifts.front();
  const int w = wheel / 2;
  std::ostringstream os;
  os << "wheel lift in the static equilibrium: wheelset '" << m.bodies[layout.wheelset(w)].name
     << "', " << (wheel % 2 == 0 ? "left" : "right") << " wheel: constraint normal force "
     << normal / 1e3 << " kN < contact.min_normal_force = " << contact.min_normal_force / 1e3
     << " kN; the rails under the wheelsets at the start (vertical irregularity left / right):";
  for (int k = 0; k < layout.n_ws; ++k) {
    const double s = m.bodyS(static_cast<int>(layout.wheelset(k)), t0);
    const track::IrregularityPoint p = irr != nullptr ? irr->at(s) : track::IrregularityPoint{};
    os << (k == 0 ? " " : ", ") << m.bodies[layout.wheelset(k)].name << " at s = " << s
       << " m: " << p.z_l * 1e3 << " / " << p.z_r * 1e3 << " mm";
  }
  os << "; a start elsewhere on the track, softer primary suspension or smaller vehicle.initial "
        "offsets may not unload it";
  return os.str();
}
}  // namespace

Eigen::VectorXd ContactVehicleOde::initialState(double t0) {
  const vehicle::VehicleLayout& l = layout_;
  const vehicle::VehicleModel& m = *model_;
  ContactWorkspace& work = *work_;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(l.size);
  if (l.spinFree())
    for (int w = 0; w < l.n_ws; ++w)
      y[l.wsRate(w, 1)] = m.speedAt(t0) / work.wheelset(w).contact->centredRadius();
  // The static equilibrium below solves the car bodies and bogies and, on elastic contact, the
  // wheelsets' height and roll.
  std::vector<int> unknowns;
  for (int i = 0; i < 5 * l.n_free; ++i) unknowns.push_back(i);
  for (int w = 0; w < l.n_ws; ++w) {
    const ContactModel& c = *work.wheelset(w).contact;
    const track::IrregularityPoint rail =
        irr_ != nullptr ? irr_->at(m.bodyS(static_cast<int>(l.wheelset(w)), t0))
                        : track::IrregularityPoint{};
    // Each wheelset starts centred between its two rails, parallel to them and following them:
    // on an irregular track the rails' mid-line is displaced by the alignment xi_a (Eq. 18:
    // ybar = y - xi_a), and a wheelset at y = 0 would start up to several millimetres off centre,
    // against a flange.
    if (irr_ != nullptr) {
      const double a_s = 0.5 * (rail.y_l_s + rail.y_r_s);
      y[l.wsPosition(w, 0)] = 0.5 * (rail.y_l + rail.y_r);
      y[l.wsRate(w, 0)] = m.speedAt(t0) * a_s;
      y[l.wsPosition(w, 2)] = a_s;
      y[l.wsRate(w, 2)] =
          m.speedAt(t0) * rail.xi_ss[static_cast<std::size_t>(track::Channel::Alignment)];
    }
    // Elastic contact: the centred height and roll over the rails, sunk by the Hertz approach of
    // the nominal wheel load (so that the tread patches exist and the equilibrium iteration has a
    // contact stiffness to work with).
    if (l.wheelsetVertical()) {
      const double height = m.bodies[l.wheelset(w)].height;
      double dz = 0.0, dphi = 0.0;
      lowerOntoSlices(c, m.bodyS(static_cast<int>(l.wheelset(w)), t0), dz, dphi);
      y[l.wsPosition(w, 3)] =
          c.centred_z + dz - height - c.elastic->static_approach + 0.5 * (rail.z_l + rail.z_r);
      y[l.wsPosition(w, 4)] =
          c.centred_phi + dphi + (rail.z_l - rail.z_r) / (2.0 * c.geometry.rail_lr);
      unknowns.push_back(l.wsPosition(w, 3));
      unknowns.push_back(l.wsPosition(w, 4));
    }
    // The track under the rail: each rail mass at its equilibrium under the wheel too (from the
    // static deflection of the nominal wheel load), and the wheelset down with it.
    if (l.rail_masses > 0) {
      const RailSupportPoint sp =
          railSupportAt(c.elastic->support, m.bodyS(static_cast<int>(l.wheelset(w)), t0));
      const double sag = c.elastic->static_load / sp.k_z;
      y[l.wsPosition(w, 3)] -= sag;
      for (int side = 0; side < 2; ++side) {
        y[l.railPosition(w, side, 1)] = -sag;
        unknowns.push_back(l.railPosition(w, side, 0));
        unknowns.push_back(l.railPosition(w, side, 1));
      }
    }
  }
  equilibrium_unknowns_ = unknowns;
  solveEquilibrium(t0, y, unknowns);
  return y;
}

void ContactVehicleOde::settle(double t0, Eigen::VectorXd& y, std::span<const int> held) {
  RB_CHECK(y.size() == layout_.size, "settle needs a state of this vehicle");
  std::vector<int> unknowns;
  for (const int i : equilibrium_unknowns_)
    if (std::find(held.begin(), held.end(), i) == held.end()) unknowns.push_back(i);
  solveEquilibrium(t0, y, unknowns);
}

void ContactVehicleOde::solveEquilibrium(double t0, Eigen::VectorXd& y,
                                         const std::vector<int>& unknowns) {
  const vehicle::VehicleLayout& l = layout_;
  const vehicle::VehicleModel& m = *model_;
  ContactWorkspace& work = *work_;
  for (WheelsetWork& ww : work.wheelsets) {
    ww.memory.forget();
    ww.kec_warm = false;
  }
  Eigen::VectorXd yd(l.size);
  const auto fail = [&](const std::string& why) {
    throw InputError(m.loc, "vehicle '" + m.name + "': initial state: " + why);
  };
  const int n = static_cast<int>(unknowns.size());
  if (n > 0) {
    // Static equilibrium of the car bodies and bogies (and, on elastic contact, of the wheelsets'
    // height and roll) on the wheelsets placed above: the accelerations of the unknowns vanish.
    const auto rateOf = [&](int position) { return l.rateOf(position); };
    Eigen::VectorXd full = y;
    const auto residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
      for (int i = 0; i < n; ++i) full[unknowns[static_cast<std::size_t>(i)]] = x[i];
      if (evaluate(t0, full.data(), yd.data(), EvalMode::Init) != 0) fail(work.error);
      r.resize(n);
      for (int i = 0; i < n; ++i) r[i] = yd[rateOf(unknowns[static_cast<std::size_t>(i)])];
    };
    Eigen::VectorXd x(n);
    for (int i = 0; i < n; ++i) x[i] = y[unknowns[static_cast<std::size_t>(i)]];
    const vehicle::EquilibriumResult eq = vehicle::solveStaticEquilibrium(
        x, n, residual,
        [&](int i) { return componentName(unknowns[static_cast<std::size_t>(i)]); });
    for (int i = 0; i < n; ++i) y[unknowns[static_cast<std::size_t>(i)]] = x[i];
    if (eq.status == vehicle::EquilibriumResult::Status::Singular)
      fail(
          "no static equilibrium: a car body or bogie coordinate is not restrained by any "
          "suspension element" +
          (eq.unrestrained.empty() ? std::string() : ":" + eq.unrestrained));
    if (eq.status == vehicle::EquilibriumResult::Status::NotConverged) {
      std::ostringstream os;
      os << "static equilibrium did not converge (|acceleration| = " << eq.residual
         << " after 50 Newton iterations)";
      fail(os.str());
    }
  }
  // Normal forces at t0 (consistent), the memory of the Lagged coupling for the first step.
  for (WheelsetWork& ww : work.wheelsets) ww.memory.forget();
  if (evaluate(t0, y.data(), yd.data(), EvalMode::Init) != 0) fail(work.error);
  // A wheel unloaded in the equilibrium itself (not only in a trial state of the iteration) is
  // real: the rails under the wheelsets twist the vehicle more than its suspension can follow.
  if (!work.init_lifts.empty()) fail(equilibriumLift(m, l, *contact_, irr_, work, t0));
}

// ---- Outputs -----------------------------------------------------------------------------------

int ContactVehicleOde::bodyCoordinates(double t, const double* y, std::span<vehicle::Vector6d> q) {
  const int rc = setCoordinates(t, y);
  if (rc != 0) return rc;
  const std::vector<vehicle::Vector6d>& coordinates = work_->bodies.q;
  for (std::size_t b = 0; b < q.size() && b < coordinates.size(); ++b) q[b] = coordinates[b];
  return 0;
}

int ContactVehicleOde::bodyAccelerations(double t, const double* y,
                                         std::span<vehicle::Vector6d> qdd) {
  const int rc = evaluate(t, y, work_->scratch.data(), EvalMode::Output);
  if (rc != 0) return rc;
  for (std::size_t b = 0; b < qdd.size() && b < work_->qdd.size(); ++b) qdd[b] = work_->qdd[b];
  return 0;
}

int ContactVehicleOde::wheelOutputs(double t, const double* y, std::span<WheelOutput> out) {
  const int rc = evaluate(t, y, work_->scratch.data(), EvalMode::Output);
  if (rc != 0) return rc;
  for (std::size_t i = 0; i < out.size() && i < work_->wheels.size(); ++i)
    out[i] = work_->wheels[i];
  return 0;
}

int ContactVehicleOde::outputs(double t, const double* y, std::span<WheelOutput> wheels,
                               std::span<vehicle::Vector6d> qdd) {
  internal::ContactWorkspace& work = *work_;
  int rc = 1;
  if (share_outputs_ && !(work.next_valid && sameState(t, y, work.next_t, work.next_y))) {
    // The integrator's next right-hand side, at this state, made now and kept for it (rhs()).
    rc = evaluate(t, y, work.next_ydot.data(), EvalMode::RhsOutput);
    if (rc == 0) {
      work.next_valid = true;
      work.next_t = t;
      std::copy(y, y + work.next_y.size(), work.next_y.begin());
    }
  }
  // A state whose rhs fails (a lifted wheel, a derailment) gets its outputs as before, and the
  // integrator's own call reports the failure. Not through evaluate(): a right-hand side kept for
  // this very state stays kept (an Output evaluation leaves the memory as it is).
  if (rc != 0) rc = (this->*eval_)(t, y, work.scratch.data(), EvalMode::Output);
  if (rc != 0) return rc;
  for (std::size_t i = 0; i < wheels.size() && i < work.wheels.size(); ++i)
    wheels[i] = work.wheels[i];
  for (std::size_t b = 0; b < qdd.size() && b < work.qdd.size(); ++b) qdd[b] = work.qdd[b];
  return 0;
}

int ContactVehicleOde::elementOutputs(double t, const double* y,
                                      std::span<const vehicle::ElementId> ids,
                                      std::span<vehicle::ElementValue> out) {
  const int rc = evaluate(t, y, work_->scratch.data(), EvalMode::Output);
  for (std::size_t i = 0; i < ids.size() && i < out.size(); ++i) {
    out[i] = work_->bodies.value(ids[i]);
    if (rc != 0) out[i].force = out[i].d = std::numeric_limits<double>::quiet_NaN();
  }
  return rc;
}

}  // namespace rb::dynamics
