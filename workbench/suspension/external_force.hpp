#pragma once
// The law of an external force element (vehicle::ExternalForceSpec, Lua external_force{}): the
// value F [N] of a force along its direction, as a pure function of the time t and of the track
// position s of the body it acts on. Nothing here knows about bodies or frames; the vehicle
// module turns F into a force at a point of a body (vehicle/dynamics.cpp).
//
// - constant: F = value.
// - ramp: F = initial until `start`, then linear to `value` over `duration` (a rate in N/s is
//   turned into the duration |value - initial| / rate when the scenario is read), held at `value`
//   for `hold` seconds (infinite: to the end of the run), then linear back to `initial` over the
//   same duration: a trapezoid. The release is a ramp because a step would excite the vehicle's
//   modes with a shock the load it stands for (a gust, a push that is let go) does not have.
// - table: linear between the points (x_k, F_k) of a table over the time t [s] or over the body's
//   track position s [m] (a gust at a place of the line reaches each body as it passes),
//   abscissae strictly increasing, the end values held beyond the ends.
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "workbench/core/names.hpp"
#include "workbench/core/range.hpp"

namespace rb::suspension {

enum class ForceLawKind { Constant, Ramp, Table };
inline constexpr std::array<NameEntry<ForceLawKind>, 3> kForceLawKindNames = {{
    {ForceLawKind::Constant, "constant", "F = value from the start of the run"},
    {ForceLawKind::Ramp, "ramp",
     "from initial at start to value at rate (N/s) or over duration (s), held for hold (s; "
     "default to the end), then back to initial over the same time"},
    {ForceLawKind::Table, "table",
     "linear between the points of table over time or distance (over), the end values beyond "
     "the ends"},
}};
constexpr const auto& nameTable(ForceLawKind /*tag*/) {
  return kForceLawKindNames;
}

// The abscissa of a table law.
enum class ForceAbscissa { Time, Distance };
inline constexpr std::array<NameEntry<ForceAbscissa>, 2> kForceAbscissaNames = {{
    {ForceAbscissa::Time, "time", "the table is {{t [s], F [N]}, ...}"},
    {ForceAbscissa::Distance, "distance",
     "the table is {{s [m], F [N]}, ...}, s the body's track position (/bodies/<body>/s)"},
}};
constexpr const auto& nameTable(ForceAbscissa /*tag*/) {
  return kForceAbscissaNames;
}

// Admissible values, stated once for the scenario schema and checkForceLaw. 100 MN is far beyond
// any load on a rail vehicle (a coupler's breaking load is about 1-3 MN): a larger value is a
// typing error of the exponent, not a load.
inline constexpr double kForceInf = std::numeric_limits<double>::infinity();
inline constexpr Range kForceValueRange{-1e8, 1e8};                // [N]
inline constexpr Range kForceRateRange{0.0, kForceInf, true};      // [N/s]
inline constexpr Range kForceStartRange{0.0, kForceInf};           // [s]
inline constexpr Range kForceDurationRange{0.0, kForceInf, true};  // [s]
inline constexpr Range kForceHoldRange{0.0, kForceInf};            // [s]

struct ForceLaw {
  ForceLawKind kind = ForceLawKind::Constant;
  double value = 0.0;     // [N] constant: the force; ramp: the value it ramps to
  double initial = 0.0;   // [N] ramp: before `start` and after the ramp back
  double start = 0.0;     // [s] ramp: when it leaves `initial`
  double duration = 0.0;  // [s] ramp: from initial to value (0 only when value == initial)
  double hold = std::numeric_limits<double>::infinity();  // [s] ramp: at value; inf: to the end
  ForceAbscissa over = ForceAbscissa::Time;               // table
  std::vector<double> at;     // table: abscissae [s or m], strictly increasing
  std::vector<double> force;  // table: forces [N]
};

// Every problem of a law as a message ("table: t must be strictly increasing (t[3] = 2 after
// t[2] = 2)"); empty when it is valid. forceAt needs a valid law.
std::vector<std::string> checkForceLaw(const ForceLaw& law);

// F [N] at time t [s] with the body at track position s [m].
double forceAt(const ForceLaw& law, double t, double s);

}  // namespace rb::suspension
