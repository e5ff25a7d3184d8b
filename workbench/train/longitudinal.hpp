#pragma once
// The longitudinal motion of a train's vehicles (train_ode.hpp): each vehicle moves along the track
// as one rigid mass, with its distance travelled and speed as states,
//   m_k dv_k/dt = F_traction,k(t or s) - (A_k + B_k v_k + C_k v_k^2) - m_k g sin(slope)
//                 + (the connections' forces along the track),
// the running resistance in the Davis form (Davis 1926; the coefficients per vehicle as the user
// gives them), the slope from the track's vertical alignment under the car body. The mass is the
// vehicle's bodies' plus the rotating-mass allowance of its wheelsets, sum I_yy / r0^2 (they roll
// with the travel).
//
// Traction and braking: a force per vehicle at the rails (traction > 0, braking < 0) against time
// or distance travelled, linear between points and held beyond them, applied one of two ways
// (TractionPath):
// - wheelsets: as a torque F r0 / n on each of the vehicle's n wheelsets (free spin), reacted on
//   the body its primary suspension hangs from (the bogie frame: brake rigging and traction
//   motors are mounted there). The wheels' creep forces then carry the effort, and the
//   longitudinal equation takes the contact forces along the track (creep and normal forces of
//   every wheel) instead of F: wheel slide at the adhesion limit and the curving resistance are
//   in it. The vehicle's own equations use the acceleration with the nominal F for their inertia
//   of the longitudinal acceleration (the terms M_qs a, a small coupling on curves), so that the
//   right-hand side stays a function of the state; they differ from the state's acceleration
//   only while the creep forces differ from F.
// - vehicle: as a force on the longitudinal equation directly (guided wheelsets, or a prescribed
//   spin); the contact forces along the track are then not in it.
// The bodies of one vehicle share one longitudinal motion: a vehicle's longitudinal suspension
// does not deflect, so the load transfer between bogies from the car body's inertia under
// braking is not modelled (the brake torque's reaction on each bogie is).
#include <array>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/core/names.hpp"

namespace rb::train {

enum class TractionPath { Wheelsets, Vehicle };
inline constexpr std::array<NameEntry<TractionPath>, 2> kTractionPathNames = {{
    {TractionPath::Wheelsets, "wheelsets",
     "a torque on every wheelset's spin, reacted on its bogie: the creep forces carry it"},
    {TractionPath::Vehicle, "vehicle", "a force on the vehicle's longitudinal equation"},
}};
constexpr const auto& nameTable(TractionPath /*tag*/) {
  return kTractionPathNames;
}

struct TractionSpec {
  bool by_distance = false;  // at = distance travelled [m] (else time [s])
  std::vector<double> at, force;
  SourceLoc loc;
  bool given() const { return !at.empty(); }
};

struct ResistanceSpec {
  double a = 0.0;  // [N]
  double b = 0.0;  // [N s/m]
  double c = 0.0;  // [N s^2/m^2]
  SourceLoc loc;
};

// What train.longitudinal and the vehicles' traction and resistance give.
struct LongitudinalSpec {
  bool on = false;
  // [m/s] a vehicle slower than this ends the run: the creepages of the contact models are
  // referred to the forward speed, and the train is not simulated to a stand.
  double min_speed = 1.0;
  TractionPath traction_at = TractionPath::Wheelsets;
  SourceLoc loc;
};

void validateTraction(const TractionSpec& t, const std::string& what, Diagnostics& d);
void validateResistance(const ResistanceSpec& r, const std::string& what, Diagnostics& d);

// F(t) or F(s) of the table; 0 when none is given.
double tractionForce(const TractionSpec& t, double time, double travel);
// Davis running resistance at speed v >= 0 [N].
inline double resistanceForce(const ResistanceSpec& r, double v) {
  return r.a + r.b * v + r.c * v * v;
}

// The jerk da/dt [m/s^3] of an acceleration a sampled at the times t (increasing), one value per
// sample. window = 0: at the samples' own spacing (central differences, one-sided at the ends),
// the rate the output resolves, a slack run-in's spike included. window > 0: the change of
// acceleration over `window` seconds centred on each sample, (a(t + w/2) - a(t - w/2)) / w with a
// interpolated linearly and the window shortened to fit inside the samples at the ends: the jerk
// that comfort limits for passengers (about 1 to 1.5 m/s^3) are stated over, a ramp of about one
// second. Fewer than two samples: zeros.
std::vector<double> jerk(const std::vector<double>& t, const std::vector<double>& a, double window);

}  // namespace rb::train
