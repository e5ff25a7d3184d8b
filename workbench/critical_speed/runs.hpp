#pragma once
// The kicked runs of `workbench critical-speed`: one ordinary vehicle run of the command's scene
// (compiled in-process, run::runVehicle into <out>/runs/NAME.h5, so each run can be inspected or
// run again alone), started with a lateral offset of the first wheelset, at a constant speed or
// with a constant deceleration. The result file is read back for the wheelsets' lateral motion
// (and, with the EN 14363 criterion, the bogie-frame sliding rms of /assessment/stability).
// A run that fails (wheel lift, solver failure) is a finding: its time and speed are kept with
// the windows it produced.
#include <limits>
#include <string>
#include <vector>

#include "workbench/critical_speed/analysis.hpp"

namespace rb::critical_speed {

struct RunSetup {
  std::string scenario;                // the scene (scenario file)
  std::vector<std::string> overrides;  // the scene's overrides, applied first
  std::string root;                    // project root
  std::string table_cache;             // contact-table disk cache shared by the runs
  std::string run_dir;                 // folder of the run results
  double kick = 5e-3;                  // [m] lateral offset of the first wheelset at t = 0
  std::string first_wheelset;          // its name (the kick is checked as vehicle.initial)
  bool drop_irregularities = false;    // run.effects.irregularities = false
  bool en14363 = false;                // run.assessment.stability = true, read back
  double window = 1.0;                 // [s] amplitude window
  double transient = 1.0;              // [s] left out after the kick
  double threshold = 1e-3;             // [m] amplitude of a limit cycle (judgeKickedRun)
  double decay = 0.8;                  // [-] decay factor of judgeKickedRun
  double step_grid = 0.0;  // [s] the fixed step of rk4 / abm (0: adaptive): a fixed-step run must
                           // end on its step grid, so run durations are rounded up to it
};

struct KickedRun {
  std::string kind;           // "probe", "bracket", "bisection" or "ramp"
  std::string file;           // result file of the run
  double v0 = 0.0;            // [m/s] start speed
  double acceleration = 0.0;  // [m/s^2]
  double duration = 0.0;      // [s]
  bool ok = false;
  std::string message;     // failure message (empty when ok)
  double t_reached = 0.0;  // [s]
  double v_reached = 0.0;  // [m/s] speed at t_reached
  double cpu_s = 0.0;      // [s] process CPU time of the integration
  long rhs_evals = 0;      // rhs evaluations (+ those of finite-difference Jacobians)
  long steps = 0;          // accepted steps
  std::vector<Window> windows;
  KickedVerdict verdict;  // criterion "amplitude" (constant-speed runs)
  // Criterion "en14363": sliding rms / limit at each window end (largest over the bogies and
  // wheelsets), and the speed there.
  std::vector<double> en_speed;
  std::vector<double> en_ratio;
  double en_max_ratio = std::numeric_limits<double>::quiet_NaN();  // after the transient
  // The lateral displacement of the first wheelset against the speed (the ramp's figure).
  std::vector<double> speed;
  std::vector<double> y_lead;
};

// Compiles and runs one kicked run named `name` (<run_dir>/<name>.h5). Throws InputError when the
// scene refuses the run's settings (e.g. a track too short for its distance): nothing ran.
KickedRun runKicked(const RunSetup& setup, const std::string& kind, const std::string& name,
                    double v0, double acceleration, double duration);

// The amplitude criterion on the run's windows, or EN 14363 (unstable when the sliding rms
// exceeds its limit after the transient); a failed run that stopped early is judged on what it
// produced, a run that failed before any window counts as unstable (it could not stay on the
// rails: the finding is reported with it).
bool runUnstable(const KickedRun& run, bool en14363);

}  // namespace rb::critical_speed
