#pragma once
// The evaluation of ContactVehicleOde (contact_ode.hpp), compiled per contact method and creep law:
// evaluateT and the per-wheelset stages 5-8. Included by the two translation units that
// instantiate it: contact_ode.cpp (the constraint methods) and contact_ode_elastic.cpp (the
// elastic method), so that adding the elastic method's code does not change how the compiler
// inlines the constraint methods' evaluations (their instruction counts stay the same).
// Internal to workbench/dynamics.
#include <limits>
#include <sstream>

#include "workbench/dynamics/contact_coupling.hpp"
#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/dynamics/contact_patches.hpp"
#include "workbench/dynamics/contact_stages.hpp"
#include "workbench/dynamics/contact_workspace.hpp"

namespace rb::dynamics {

namespace internal {

// Stages 5-8 of the elastic method (contact_elastic.hpp, compiled in contact_ode_elastic.cpp).
template <class Law>
int elasticWheelsetStages(const ContactModels& models, const StageInput& in, int w, double* ydot,
                          ContactWorkspace& work, vehicle::StageClock* clock);

// Rise of a wheel's tape circle above its centred height over its rail (contact_elastic.hpp).
double wheelLiftOf(const ContactModel& c, const WheelsetWork& ww, const vehicle::Vector6d& q,
                   int side);

// Wheel lift: the constraint normal force of a wheel (KEC: both patches, which share the wheel's
// lambda, Eq. 26; LUT: the tread patch, or the two next to a contact-point jump, the Hertz flange
// force being applied) below the threshold
// means the constraint pulls the wheel onto the rail, which no wheel/rail pair can do. The state
// is refused as recoverable: an adaptive method retries a smaller step, so an overshooting trial
// step is not taken for a lift, while a real lift stops the run here. Output evaluations only
// report it (lift = true); initial-state evaluations record it (ContactWorkspace::init_lifts), the
// equilibrium's trial states being no states of the run.
// Always inlined, as wheelPointForce (contact_patches.hpp): independent of the number of laws.
template <ContactMethod kMethod>
[[gnu::always_inline]] inline int checkWheelLift(const ContactModels& models, const StageInput& in,
                                                 const WheelsetWork& ww, ContactWorkspace& work,
                                                 bool& lift) {
  for (int s = 0; s < 2; ++s) {
    // LUT: slot 1 is a constraint patch when the wheel's tread force is split over a jump.
    const int constraint_patches = kMethod == ContactMethod::Kec || ww.lut_split[s] ? 2 : 1;
    double qn = 0.0;
    bool any = false;
    for (int p = 0; p < constraint_patches; ++p) {
      const Patch& patch = ww.patch[s][p];
      if (!patch.active) continue;
      any = true;
      qn += patch.normalAt(ww.lambda);
    }
    if (!any || qn >= models.contact.min_normal_force) continue;
    if (in.mode == EvalMode::Init) {
      work.init_lifts.emplace_back(2 * static_cast<int>(&ww - work.wheelsets.data()) + s, qn);
      continue;
    }
    lift = true;
    if (in.mode != EvalMode::Output) return refuseWheelLift(models, in, ww, s, qn, work);
  }
  return 0;
}

// Track-frame lateral position of the contact point of every active patch of wheelset w: the
// wheel material point u = (0, sigma Lw + s_w, -r) of the wheelset intermediate frame (Eq. 7, 10;
// as setupPatch places it), turned by the wheelset's roll and yaw, plus its lateral displacement.
inline void contactPositions(const WheelsetWork& ww, int w, ContactWorkspace& work) {
  const Eigen::Matrix3d& A = work.bodies.kin[ww.body].attach.A;
  const double y = work.bodies.q[ww.body][vehicle::kY];
  const double lw = ww.contact->geometry.wheel_lw;
  for (int s = 0; s < 2; ++s) {
    const double sigma = contact::kSideSign[s];
    WheelOutput& wo = work.wheels[2 * static_cast<std::size_t>(w) + static_cast<std::size_t>(s)];
    wo.wheel_lift = wheelLiftOf(*ww.contact, ww, work.bodies.q[ww.body], s);
    for (PatchOutput& po : wo.patch) {
      if (!po.active) continue;
      const Eigen::Vector3d u(0.0, sigma * lw + po.s_w, -po.radius);
      po.y = y + A.row(1).dot(u);
    }
  }
}

// Stages 5-8 (contact_stages.hpp) of wheelset w: patches, augmented system, normal/tangential
// coupling, checks, rates and outputs. A timed evaluation passes its clock.
template <ContactMethod kMethod, class Law>
inline int wheelsetStages(const ContactModels& models, const StageInput& in, int w, double* ydot,
                          ContactWorkspace& work, bool& lift, vehicle::StageClock* clock) {
  using vehicle::Stage;
  if constexpr (kMethod == ContactMethod::Elastic) {
    (void)lift;  // the elastic method lifts wheels physically (checkDerailment)
    return elasticWheelsetStages<Law>(models, in, w, ydot, work, clock);
  } else {
    WheelsetWork& ww = work.wheelset(w);
    if (const int rc = contactPatches<kMethod, Law>(models, in, ww, work); rc != 0) return rc;
    classifyRegimes(ww);
    if (clock) clock->mark(Stage::ContactPatches);
    AugmentedSystem system;
    if (const int rc = augmentedSystem(models, in, ww, work, system); rc != 0) return rc;
    if (clock) clock->mark(Stage::Augmented);
    Vec7 x;
    if (const int rc = coupleNormalAndTangential<Law>(models, in, system, ww, work, x); rc != 0)
      return rc;
    if (clock) clock->mark(Stage::Coupling);
    if (const int rc = checkSolution(models, in, ww, x, work); rc != 0) return rc;
    writeWheelsetRates(models.layout, w, in.y, x, ydot);
    if (const int rc = checkWheelLift<kMethod>(models, in, ww, work, lift); rc != 0) return rc;
    if (fillsOutputs(in.mode)) {
      wheelsetOutputs(in, w, ww, x, Law::kCreep, kMethod == ContactMethod::Lut, work);
      contactPositions(ww, w, work);
    }
    if (clock) clock->mark(Stage::Checks);
    return 0;
  }
}

// The contact forces of every active patch along the track (track-frame x), summed over the
// wheelsets: F = Q n + f_x e_x + f_y e_y per patch, Q at the solved multipliers (the elastic
// method's patches have none: Q = q0).
template <ContactMethod kMethod>
double railForceAlongTrack(const ContactWorkspace& work) {
  double sum = 0.0;
  const auto add = [&sum](const Patch& p, const Eigen::Vector2d& lambda) {
    sum += p.normalAt(lambda) * p.n.x() + p.fx * p.ex.x() + p.fy * p.ey.x();
  };
  for (const WheelsetWork& ww : work.wheelsets) {
    if constexpr (kMethod == ContactMethod::Elastic) {
      for (const ElasticWheelWork& ew : ww.elastic)
        for (int k = 0; k < ew.geometry.count; ++k)
          add(ew.patch[static_cast<std::size_t>(k)], Eigen::Vector2d::Zero());
    } else {
      for (const auto& wheel : ww.patch)
        for (const Patch& p : wheel)
          if (p.active) add(p, ww.lambda);
    }
  }
  return sum;
}

}  // namespace internal

// ---- The evaluation ----------------------------------------------------------------------------

template <ContactMethod kMethod, class Law>
int ContactVehicleOde::evaluateT(double t, const double* y, double* ydot, internal::EvalMode mode) {
  using internal::ContactModels;
  using internal::ContactWorkspace;
  using internal::EvalMode;
  using internal::StageInput;
  using vehicle::Stage;
  ContactWorkspace& work = *work_;
  ++work.stats.evaluations;
  work.init_lifts.clear();
  // Only the integrator's evaluations are timed: outputs belong to the observer's share.
  vehicle::StageClock* clock = mode == EvalMode::Rhs && stages_.start() ? &stages_ : nullptr;
  const ContactModels models{*model_, *contact_, layout_, irr_};
  const vehicle::ForwardMotion fm = vehicle::forwardMotion(*model_, work.bodies, t);
  const StageInput in{t, y, fm.speed, fm.acceleration, mode, fm.travel};
  if (const int rc = internal::setIndependentCoordinates(models, in, work); rc != 0) return rc;
  if (clock) clock->mark(Stage::Coordinates);
  if (const int rc = internal::solveConstraints(models, in, work); rc != 0) return rc;
  if (clock) clock->mark(Stage::Constraints);
  internal::evaluateVehicleForces(models, in, work);
  if (clock) clock->mark(Stage::VehicleForces);
  if (const int rc = internal::freeBodyAccelerations(models, in, ydot, work); rc != 0) return rc;
  if (clock) clock->mark(Stage::FreeBodies);
  bool lift = false;
  for (int w = 0; w < layout_.n_ws; ++w)
    if (const int rc =
            internal::wheelsetStages<kMethod, Law>(models, in, w, ydot, work, lift, clock);
        rc != 0)
      return rc;
  if (lift) ++work.stats.lift_evaluations;
  if (work.bodies.motion) work.rail_force = internal::railForceAlongTrack<kMethod>(work);
  internal::writeSeriesRates(layout_, work, ydot);
  if (clock) {
    clock->mark(Stage::SeriesRates);
    clock->finish();
  }
  return 0;
}

}  // namespace rb::dynamics
