#pragma once
// The cases of `workbench stress` (docs/stress.md): the user's scenario hardened along named axes
// (flange stiffness, KEC transition lengths, speed, irregularity amplitude, friction, curve
// radius), each hardened case run with a set of integrator settings and with its own reference.
#include <map>
#include <string>
#include <vector>

#include "workbench/scenario/scenario.hpp"

namespace rb::stress {

// One integrator setting: "rk4 1 ms", "bdf 1e-9"; its --set overrides.
struct Setting {
  std::string label;
  std::vector<std::string> overrides;
  bool adaptive = false;  // dopri5, BDF or IDA (a tolerance); else a fixed step
};

// One hardened case: the scenario with `overrides` (axis "nominal": the scenario as given).
struct Hardened {
  std::string axis;
  double value = 0.0;      // the axis value (absolute or a factor over the nominal, see axis)
  std::string valueLabel;  // as printed in the map: "7.075e13", "x1.5", "0.1 mm"
  std::vector<std::string> overrides;
  double tEnd = 0.0;  // [s] end time of the hardened run, 0 when the run is given by distance
};

struct PlanRequest {
  std::vector<std::string> axes;                      // empty: every axis
  std::map<std::string, std::vector<double>> values;  // --values AXIS=v1,v2
  bool quick = false;                                 // the hardest value of each axis only
};

struct Plan {
  std::vector<Hardened> cases;
  std::vector<std::string> notes;  // axes that do not apply to the scenario, and why
};

// The axes in the order of the map, "nominal" first.
const std::vector<std::string>& axisNames();

// Throws InputError naming the option for an unknown axis.
Plan planAxes(const scenario::ScenarioSpec& spec, const PlanRequest& request);

// "METHOD:VALUE[:paper]": VALUE is the step [s] of rk4/abm and rtol = atol of dopri5/bdf/ida;
// ":paper" runs the paper's set-up (lagged normal forces, section 2.5; fixed steps integrate the
// stiff components explicitly, as RK4/ABM in the paper, also beyond the check's stability limit).
// bdf and ida always run consistent normal forces (CVODE's Newton iteration cannot follow the
// lagged memory, docs/contact_dynamics.md section 4). The adaptive methods run with the paper's
// maximum step of 1 ms (section 5.4), or the scenario's `maxStep` when smaller: without it a
// step-size controller may step over a short excitation of a track that starts in equilibrium.
// Throws InputError naming `option`.
// `couplings`: the key prefixes of the contact models that have a normal-force coupling to set
// (normalForceCouplings).
Setting parseSetting(const std::string& text, const std::vector<std::string>& couplings,
                     const std::string& option, double maxStep);
// The key prefixes ("contact.", in a train also "train.vehicles[k].contact." of a vehicle's own
// contact{}) of the contact models with a normal-force coupling (the constraint methods; the
// elastic method's normal forces follow from the approach).
std::vector<std::string> normalForceCouplings(const scenario::ScenarioSpec& spec);

// Overrides that shorten the run to at most `seconds` (quick mode): run.duration, or run.distance
// for a run given by distance; empty when it is already that short.
std::vector<std::string> shortenRun(const scenario::ScenarioSpec& spec, double seconds);

// The end time [s] of a run of `spec` when it is given by duration, else 0.
double endTime(const scenario::ScenarioSpec& spec);

}  // namespace rb::stress
