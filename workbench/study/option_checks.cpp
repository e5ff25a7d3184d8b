#include "workbench/study/option_checks.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "workbench/core/strings.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/track/track.hpp"

namespace rb::study {

int maxJobs() {
  return kJobsPerCore * static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void badOption(Diagnostics& d, const std::string& option, const std::string& value,
               const std::string& why) {
  d.add(kOptionLoc, option + " " + value + ": " + why);
}

void badOption(Diagnostics& d, const std::string& option, double value, const std::string& why) {
  badOption(d, option, formatNumber(value), why);
}

double trackReach(const scenario::ScenarioSpec& spec) {
  track::TrackSpec t = spec.track;
  t.irregularities = track::IrregularitySpec{};
  const double length = track::compileTrack(t).geometry().length();
  double lead = 0.0;
  for (const auto& b : spec.vehicle.bodies) lead = std::max(lead, b.x);
  return std::max(0.0, length - spec.vehicle.start - lead);
}

std::string notPositive(double v, double most) {
  if (std::isfinite(v) && v > 0.0 && v <= most) return "";
  return "must be a finite number in (0, " + formatNumber(most) + "]";
}

void checkJobs(Diagnostics& d, int jobs, bool zero_is_cores) {
  const int most = maxJobs();
  if (jobs < (zero_is_cores ? 0 : 1) || jobs > most)
    badOption(d, "--jobs", std::to_string(jobs),
              "must be in " + std::string(zero_is_cores ? "0" : "1") + ".." + std::to_string(most) +
                  " (" + std::to_string(kJobsPerCore) + " x the cores of this machine" +
                  (zero_is_cores ? "; 0: every core" : "") + ")");
}

double checkOptionOverrides(const ScenarioCommandOptions& o, const std::vector<std::string>& base,
                            const std::vector<OptionOverride>& options) {
  run::CompileOptions co;
  co.scenario = o.scenario;
  co.root = o.root;
  co.overrides = base;
  for (const auto& opt : options) co.overrides.push_back(opt.key_value);
  try {
    return run::compile(co).t_end;
  } catch (const InputError& e) {
    if (options.empty()) throw;
    // The scenario with the user's own --set alone: its problems are the user's, as they are.
    co.overrides = base;
    (void)run::compile(co);
    std::string typed;
    for (const auto& opt : options)
      typed +=
          (typed.empty() ? "" : ", ") + opt.option + " " + opt.value + " (" + opt.key_value + ")";
    std::vector<Diagnostic> out;
    for (const auto& d : e.diagnostics()) out.push_back({kOptionLoc, typed + ": " + d.str()});
    throw InputError(std::move(out));
  }
}

}  // namespace rb::study
