#pragma once
// `workbench critical-speed SCENARIO.lua`: the nonlinear critical speed of the vehicle
// (docs/stability.md) by the ramp-down method (a kicked run above the critical speed that
// decelerates until the limit cycle dies) or by bisection on constant-speed runs (the kicked
// motion decays or grows), with the limit-cycle amplitude versus speed (bifurcation diagram).
//
// Every run starts from the static equilibrium with the first wheelset displaced laterally by
// --kick. The start speed must show hunting: a kicked constant-speed run there (the probe) is
// judged first; without hunting the command reports it (exit 2) and, when --from was not given,
// first tries higher speeds (x 1.2 per probe up to --max-speed).
//
// Output folder: critical_speed.h5 (workbench/io/critical_speed_file.hpp), critical_speed.csv
// (one row per window of every run), runs/*.h5 (each kicked run, an ordinary result file),
// scene.lua for a vehicle file, critical_speed.png (plots/railbench/critical_speed.py).
#include <limits>
#include <optional>
#include <string>

#include "workbench/stability/scene.hpp"
#include "workbench/study/command.hpp"

namespace rb::critical_speed {

struct CriticalSpeedOptions : study::ScenarioCommandOptions {
  std::string method = "ramp";          // "ramp", "bisection" or "both"
  std::string criterion = "amplitude";  // "amplitude" (wheelset lateral) or "en14363" (bogie
                                        // frame lateral acceleration, EN 14363 stability)
  std::string contact;                  // "kec" / "lut" ("" = the scenario's; kec for a vehicle
                                        // file)
  bool no_plots = false;
  double from = 0.0;          // [m/s] start speed (0: 1.1 x the linear critical speed, else
                              // defaultStartSpeed and upwards)
  double to = 0.0;            // [m/s] end speed of the ramp, low end of the bracket (0: from / 2)
  bool from_given = false;    // --from was typed (then 0 is refused, not the default)
  bool to_given = false;      // --to was typed
  double max_speed = 150.0;   // [m/s] highest probe when --from is not given
  double kick = 5e-3;         // [m] lateral offset of the first wheelset at t = 0
  double deceleration = 0.5;  // [m/s^2] of the ramp
  double duration = 10.0;     // [s] of a constant-speed run (probe, bisection)
  double window = 1.0;        // [s] amplitude window
  double transient = 1.0;     // [s] after the kick, left out of the windows
  // [m] limit-cycle amplitude below which the motion is stable; unset: thresholdOf()
  std::optional<double> threshold;
  double decay = 0.8;      // [-] last / middle window amplitude below which it decays
  double tolerance = 0.5;  // [m/s] bracket width at which the bisection stops
  bool irregular = false;  // keep the scenario's irregularities
};

// Without --from the search first probes 1.1 x the linear critical speed (linearCriticalSpeed);
// when that run does not hunt (or there is no linear critical speed below --max-speed), it probes
// upwards from the scene's vehicle speed (defaultStartSpeed) by factors of 1.2.
double defaultStartSpeed(const stability::StabilityScene& scene);
// The linear answers of the scene (workbench/stability) between 10 m/s and max_speed: the lowest
// speed at which any mode is unstable (with that mode), and the speed at which the least damped
// hunting mode loses its damping (where the nonlinear search starts). NaN with a note saying why
// when there is none (no contact, none in range or below it, no steady state).
struct LinearAnswer {
  double any = std::numeric_limits<double>::quiet_NaN();      // [m/s]
  double hunting = std::numeric_limits<double>::quiet_NaN();  // [m/s]
  std::string mode;          // the first unstable mode (stability::describe)
  std::string note;          // why `any` is NaN
  std::string hunting_note;  // why `hunting` is NaN
};
LinearAnswer linearCriticalSpeed(const stability::StabilityScene& scene, double max_speed,
                                 const std::string& table_cache);

// The amplitude threshold: --threshold, else 0.1 mm on a track without irregularities (no forced
// response: any motion that stays above the numerical noise, orders of magnitude below, after the
// kick is self-sustained, so the ramp finds where the last limit cycle dies; the small cycles of
// the S1002/60E1 tread, 0.1..1 mm, count), else 1 mm (above the forced response to the hard
// suite's 0.1-scaled ORE B176 irregularities, at most 0.7 mm at 60 m/s, docs/hard_cases.md).
double thresholdOf(const CriticalSpeedOptions& options, bool irregular_track);

// Refuses an inconsistent option (InputError naming it) before anything runs.
void checkCriticalSpeedOptions(const CriticalSpeedOptions& options);

// Returns the process exit code (0 ok, 1 bad input, 2 the search failed, 4 figures failed).
// Throws InputError for a bad scenario or option.
int runCriticalSpeed(const CriticalSpeedOptions& options);

}  // namespace rb::critical_speed
