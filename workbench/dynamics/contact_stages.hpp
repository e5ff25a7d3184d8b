#pragma once
// The stages of one ContactVehicleOde evaluation, in their order (docs/contact_dynamics.md):
//   1. setIndependentCoordinates   coordinates of every body from the state (s imposed)
//   2. solveConstraints            wheelset z, phi from the contact constraints (KEC Eq. 22;
//                                  LUT Eq. 17-18), their rates and G qddot = gamma
//   3. evaluateVehicleForces       vehicle::evaluate: mass matrices, applied and inertia forces
//   4. freeBodyAccelerations       car bodies and bogies: M_pp pddot = Q_p - M_ps a
//   per wheelset:
//   5. contactPatches              contact_patches.hpp: KEC patches (regularised band, Eq. 26) or
//                                  LUT tread patch + Hertz flange (Eq. 20-21)
//   6. augmentedSystem             factor [M -N; G 0] (Eq. 16, 24)
//   7. coupleNormalAndTangential   contact_coupling.hpp: normal/tangential force coupling
//                                  (Lagged or Consistent) and the augmented solve
//   8. checkSolution, writeWheelsetRates, checkWheelLift, wheelsetOutputs
//   9. writeSeriesRates            Maxwell forces of the series dampers
// Every stage reads the models and the inputs and writes the workspace; a stage that returns
// non-zero has written ContactWorkspace::error. Internal to workbench/dynamics.
#include <string>

#include "workbench/contact/lut.hpp"
#include "workbench/dynamics/augmented.hpp"
#include "workbench/dynamics/contact_workspace.hpp"

namespace rb::dynamics::internal {

// ---- Named reads of the LUT (channel layout of contact/lut.hpp) --------------------------------

// Flange indentation delta of one wheel (Eq. 21).
inline void readFlangeIndentation(const contact::LutTable& lut, double ybar, double xi_g,
                                  contact::Side side, contact::LutSample& sample) {
  const std::size_t delta = contact::lutChannel(side, contact::FlangeQuantity::Delta);
  lut.evalValues(ybar, xi_g, sample, delta, delta + 1);
}
// Tread contact points of both wheels and their flange indentations: two range reads (the left
// and right tread channels and the left delta are adjacent in the channel layout, the right delta
// follows the left flange block), the same values as a read of each wheel's tread
// block and of each delta.
inline void readTreadsAndFlangeIndentations(const contact::LutTable& lut, double ybar, double xi_g,
                                            contact::LutSample& sample) {
  using contact::Side;
  static_assert(contact::lutChannel(Side::Right, contact::TreadQuantity::Sw) ==
                contact::lutChannel(Side::Left, contact::TreadQuantity::KrTrans) + 1);
  static_assert(contact::lutChannel(Side::Left, contact::FlangeQuantity::Delta) ==
                contact::lutChannel(Side::Right, contact::TreadQuantity::KrTrans) + 1);
  lut.evalValues(ybar, xi_g, sample, contact::lutChannel(Side::Left, contact::TreadQuantity::Sw),
                 contact::lutChannel(Side::Left, contact::FlangeQuantity::Delta) + 1);
  readFlangeIndentation(lut, ybar, xi_g, Side::Right, sample);
}
// Flange contact point of one wheel and the indentation's derivatives (Eq. 20-21): read only
// when the flange indents.
inline void readFlangeContact(const contact::LutTable& lut, double ybar, double xi_g,
                              contact::Side side, contact::LutSample& sample) {
  lut.evalValues(ybar, xi_g, sample, contact::lutChannel(side, contact::FlangeQuantity::Sw),
                 contact::lutChannel(side, contact::FlangeQuantity::DdeltaDphi) + 1);
}
inline double treadValue(const contact::LutSample& sample, contact::Side side,
                         contact::TreadQuantity q) {
  return sample.value[contact::lutChannel(side, q)];
}
inline double flangeValue(const contact::LutSample& sample, contact::Side side,
                          contact::FlangeQuantity q) {
  return sample.value[contact::lutChannel(side, q)];
}

constexpr contact::Side sideOf(int side) {
  return side == 0 ? contact::Side::Left : contact::Side::Right;
}

// ---- Stages ------------------------------------------------------------------------------------

// 1. Full coordinates of every body from the state: s imposed (VehicleModel::bodyS), car bodies
// and bogies (y .. psi), wheelset y, psi and the spin (a state, or rolling at the centred radius
// when prescribed). Fails when a free body's pitch reaches the Euler-angle guard.
int setIndependentCoordinates(const ContactModels& models, const StageInput& in,
                              ContactWorkspace& work);

// 2. Dependent coordinates of every wheelset: z, phi from the contact constraints (KEC Eq. 22,
// warm-started; LUT Eq. 17-18), their rates by coordinate partitioning, and the acceleration-level
// constraints G qddot = gamma. Fails when the KEC solver does not converge or a knife or the LUT
// entry leaves its table.
int solveConstraints(const ContactModels& models, const StageInput& in, ContactWorkspace& work);

// 3. Mass matrices, applied and inertia forces of every body and the series damper rates.
inline void evaluateVehicleForces(const ContactModels& models, const StageInput& in,
                                  ContactWorkspace& work) {
  const vehicle::VehicleLayout& l = models.layout;
  vehicle::evaluate(models.vehicle, in.t, l.n_series > 0 ? in.y + l.series(0) : nullptr,
                    work.bodies);
}

// 4. Car bodies and bogies: M_pp pddot = Q_p - M_ps a (s imposed, sddot = a), as the guided model.
// Writes their position and rate derivatives into ydot (Output: also ContactWorkspace::qdd).
int freeBodyAccelerations(const ContactModels& models, const StageInput& in, double* ydot,
                          ContactWorkspace& work);

// 5 (LUT). Eq. (16), (19): N lambda = -C_q^T lambda. The wheel normal forces N_l, N_r reproduce
// its vertical and roll components: A (N_l, N_r) = (N lambda)_{z, phi}, A = the z and roll
// components of the two tread patches' unit normal forces. Sets N and the tread patches' ql.
int lutNormalMap(const ContactModels& models, const StageInput& in, WheelsetWork& ww,
                 ContactWorkspace& work);

// 6. The wheelset's augmented system [M -N; G 0] [qddot; lambda] = [Q - M_qs a + Q_fla; gamma]
// without the tangential forces: factored, with its right-hand side.
struct AugmentedSystem {
  AugmentedSolver solver;
  Vec7 rhs0;  // right-hand side without the tangential forces
};
int augmentedSystem(const ContactModels& models, const StageInput& in, const WheelsetWork& ww,
                    ContactWorkspace& work, AugmentedSystem& system);

// 8. The solution x = (qddot, lambda) of a wheelset must be finite.
int checkSolution(const ContactModels& models, const StageInput& in, const WheelsetWork& ww,
                  const Vec7& x, ContactWorkspace& work);
// Position and rate derivatives of wheelset w (ydot may be null: nothing to write).
void writeWheelsetRates(const vehicle::VehicleLayout& layout, int w, const double* y, const Vec7& x,
                        double* ydot);
// Wheel lift (see checkWheelLift in contact_ode.cpp): the refusal of a state whose constraint
// normal force of wheel `side` is qn < contact.min_normal_force.
int refuseWheelLift(const ContactModels& models, const StageInput& in, const WheelsetWork& ww,
                    int side, double qn, ContactWorkspace& work);
// Output: accelerations and the per-wheel contact outputs of a wheelset (patch creep data only
// with a creep law).
void wheelsetOutputs(const StageInput& in, int w, const WheelsetWork& ww, const Vec7& x, bool creep,
                     bool lut, ContactWorkspace& work);
// One patch's output on the wheel of side sigma (normal force at the multipliers lambda); adds its
// normal force to the wheel's totals in o and its force to the resultant F (track comps).
void patchOutput(const Patch& pp, const Eigen::Vector2d& lambda, bool creep, double sigma,
                 double speed, PatchOutput& po, WheelOutput& o, Eigen::Vector3d& F);

// 9. Maxwell force rates of the series dampers.
inline void writeSeriesRates(const vehicle::VehicleLayout& layout, const ContactWorkspace& work,
                             double* ydot) {
  if (!ydot) return;
  for (int e = 0; e < layout.n_series; ++e)
    ydot[layout.series(e)] = work.bodies.series_rate[static_cast<std::size_t>(e)];
}

}  // namespace rb::dynamics::internal
