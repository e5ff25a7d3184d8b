#pragma once
// Checks shared by the options of the analysis commands (modes, critical-speed, precision, stress,
// effects, study): every option is refused before anything runs when it is not finite, out of its
// range or asks for unbounded work, and the refusal names the option and the value the user
// typed, also where the option becomes a scenario override (--duration -> run.duration).
#include <string>
#include <vector>

#include "workbench/core/error.hpp"
#include "workbench/study/command.hpp"

namespace rb::study {

inline const SourceLoc kOptionLoc{"<command line>", 0};

// [m/s] Highest speed an option may ask for: the range of vehicle.speed in the scenario schema.
inline constexpr double kMaxOptionSpeed = 200.0;

// Runs at once: at most this many per core (more only queue on the cores and multiply the
// memory of the runs in flight).
inline constexpr int kJobsPerCore = 4;

// The largest --jobs: kJobsPerCore x the cores (at least kJobsPerCore).
int maxJobs();

// Adds a problem with --jobs to `d`: below 1 (or 0 when `zero_is_cores`: every core) or above
// maxJobs().
void checkJobs(Diagnostics& d, int jobs, bool zero_is_cores);

// "--option VALUE: why" at <command line>.
void badOption(Diagnostics& d, const std::string& option, const std::string& value,
               const std::string& why);
void badOption(Diagnostics& d, const std::string& option, double value, const std::string& why);

// An option given as `text` that is not a positive finite number at most `most`; "" when it is.
std::string notPositive(double v, double most);

// [m] How far the vehicle's reference point can travel on the track of `spec` before its leading
// body reaches the end (the design track, irregularities off; 0 when it starts beyond it).
double trackReach(const scenario::ScenarioSpec& spec);

// A scenario override made from an option: "--duration 1e9" -> "run.duration=1e9".
struct OptionOverride {
  std::string option;     // "--duration"
  std::string value;      // as the user typed it (formatted)
  std::string key_value;  // "run.duration=1e9"
};

// Compiles (no run: the checks of `workbench check`, among them the track's end and the output
// bound) the scenario of `o` with `base` and then with `base` plus the options' overrides. A
// problem of the second only is reported against the options the user typed, not against the
// scenario key they became. Throws InputError. Returns the simulated time of the compiled run
// [s] (0 without a vehicle).
double checkOptionOverrides(const ScenarioCommandOptions& o, const std::vector<std::string>& base,
                            const std::vector<OptionOverride>& options);

}  // namespace rb::study
