#pragma once
// What `workbench run` and `workbench check` do, separated from argument parsing so that tests
// can drive them.
#include <memory>
#include <string>
#include <vector>

namespace rb::io {
class ResultFile;
}

namespace rb::app {

struct RunOptions {
  std::string scenario;
  std::vector<std::string> overrides;
  std::string out;   // result file; default out/<scenario stem>.h5
  std::string root;  // project root
  bool quiet = false;
  // Folder of the track store (io/track_store.hpp): the track is written there once per distinct
  // track and the result's /track only references it. Empty: /track is written in full.
  std::string track_store;
  // Leave out what a study case does not need (kCompactOmits); the root attribute `compact` of
  // the result says what.
  bool compact = false;
  // Rhs stage timing (workbench/run/run_stats.hpp): 1 evaluation in stage_period is timed, 0 off;
  // < 0: the environment's RAILBENCH_STAGE_SAMPLING, else 64.
  int stage_period = -1;
};

// What --compact leaves out, as the result's root attribute `compact` states it.
inline constexpr const char* kCompactOmits =
    "per-patch contact datasets /contact/<wheelset>/<side>/patch0, patch1 (as "
    "run.output.patches = false); the per-wheel /contact datasets, /bodies, /elements and "
    "/assessment are complete; time series stored shuffled and deflate-compressed (lossless)";

// Loads, validates and compiles everything the scenario asks for; throws InputError.
void checkScenario(const RunOptions& options);
// Runs the scenario and writes the result. Returns the process exit code (0 ok, 2 run failed).
int runScenario(const RunOptions& options);

// The result file `out` opened for writing (compact: Storage::Compact), its folder created first:
// a folder that cannot be made or a name the system refuses (too long, no permission) is bad
// input (InputError naming --out), found before anything runs, so an earlier result stays as it
// was.
std::unique_ptr<io::ResultFile> openResultFile(const std::string& out, bool compact = false);

}  // namespace rb::app
