#pragma once
// Sampled timing of the named stages of a vehicle right-hand side (docs/run_stats.md): one rhs
// evaluation in `period` is timed stage by stage with the steady clock; the others only count
// down. The shares of a run are the sampled times scaled to every evaluation. Timing is an
// observation only: nothing the dynamics computes reads it, so results are the same with any
// period (0: off).
//
// Cost: an untimed evaluation pays a decrement and a predicted branch per stage boundary; a timed
// one a steady-clock read (vDSO, ~25 ns) per boundary, 1 in 64 evaluations by default, against
// ~20 us per evaluation of the wagon on contact. The out-of-line begin()/mark() keep the whole
// cost of the timed evaluations in two named functions (callgrind can sum them).
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>

#include "workbench/core/names.hpp"

namespace rb::vehicle {

// The stages of ContactVehicleOde::evaluateT (dynamics/contact_stages.hpp) and of the guided
// vehicle's rhs (guided.hpp: coordinates, vehicle forces, free bodies, series rates).
enum class Stage : std::uint8_t {
  Coordinates,     // 1. setIndependentCoordinates (guided: guidedCoordinates)
  Constraints,     // 2. solveConstraints: wheelset z, phi (KEC Eq. 22; LUT Eq. 17-18)
  VehicleForces,   // 3. vehicle::evaluate: mass matrices, applied and inertia forces
  FreeBodies,      // 4. freeBodyAccelerations: M_pp pddot = Q_p - M_ps a
  ContactPatches,  // 5. contactPatches (KEC Eq. 26; LUT tread + Hertz flange Eq. 20-21)
  Augmented,       // 6. augmentedSystem: factor [M -N; G 0] (Eq. 16, 24)
  Coupling,        // 7. coupleNormalAndTangential: creep forces and the augmented solve
  Checks,          // 8. checkSolution, writeWheelsetRates, checkWheelLift, outputs
  SeriesRates,     // 9. writeSeriesRates: Maxwell forces of the series dampers
};
inline constexpr std::size_t kStageCount = 9;

inline constexpr std::array<NameEntry<Stage>, kStageCount> kStageNames = {{
    {Stage::Coordinates, "coordinates", "coordinates of every body from the state"},
    {Stage::Constraints, "constraints", "wheelset z, phi from the contact constraints"},
    {Stage::VehicleForces, "vehicle_forces", "mass matrices, suspension and inertia forces"},
    {Stage::FreeBodies, "free_bodies", "accelerations of the car bodies and bogies"},
    {Stage::ContactPatches, "contact_patches", "contact points, creepages, Hertz patches"},
    {Stage::Augmented, "augmented_system", "factoring the wheelsets' augmented systems"},
    {Stage::Coupling, "coupling", "normal/tangential coupling: creep forces and solve"},
    {Stage::Checks, "checks_outputs", "finite solution, wheel lift, rates, outputs"},
    {Stage::SeriesRates, "series_rates", "Maxwell force rates of the series dampers"},
}};
constexpr const auto& nameTable(Stage /*tag*/) {
  return kStageNames;
}

class StageClock {
 public:
  static constexpr unsigned kDefaultPeriod = 64;

  // Times one evaluation in `period` (0: none). Resets the counters.
  void setPeriod(unsigned period);
  unsigned period() const { return period_; }
  // The stages this right-hand side has (the others stay out of its shares).
  void use(std::initializer_list<Stage> stages);
  bool uses(Stage s) const { return (used_ & bit(s)) != 0; }

  // Called once at the start of every rhs evaluation: true when this evaluation is timed (then
  // mark() is called at the end of each of its stages).
  bool start() {
    ++evaluations_;
    if (--countdown_ != 0) return false;
    return begin();
  }
  // The time since the previous mark (or begin) belongs to stage s.
  void mark(Stage s);
  // The end of a timed evaluation: its stage times are kept unless it took more than
  // kOutlierFactor times the mean of those kept (the process was descheduled: a time slice of
  // milliseconds against an evaluation of microseconds would dominate the scaled share). An
  // evaluation that fails before its end is not kept either.
  void finish();
  static constexpr std::int64_t kOutlierFactor = 50;

  long evaluations() const { return evaluations_; }  // rhs evaluations seen
  long samples() const { return samples_; }          // timed evaluations kept
  long rejected() const { return rejected_; }        // timed evaluations not kept
  double sampledSeconds(Stage s) const {
    return 1e-9 * static_cast<double>(ns_[static_cast<std::size_t>(s)]);
  }

 private:
  static constexpr std::uint32_t bit(Stage s) { return 1U << static_cast<unsigned>(s); }
  bool begin();
  unsigned period_ = kDefaultPeriod;
  // The first timed evaluation is the (period/2)-th: the first evaluations warm the caches.
  unsigned countdown_ = kDefaultPeriod / 2;
  std::uint32_t used_ = 0;
  long evaluations_ = 0;
  long samples_ = 0;
  long rejected_ = 0;
  std::int64_t begin_ns_ = 0, last_ns_ = 0;
  std::int64_t kept_ns_ = 0;                         // sum of the kept evaluations' times
  std::array<std::int64_t, kStageCount> pending_{};  // of the evaluation being timed
  std::array<std::int64_t, kStageCount> ns_{};
};

}  // namespace rb::vehicle
