#include "workbench/io/modes_file.hpp"

#include <cmath>

#include "workbench/io/result_file.hpp"

namespace rb::io {

namespace {

void writeSpeed(ResultFile& f, const std::string& g, const ModesAtSpeed& s) {
  f.dataset(g + "/re", s.re, "1/s");
  f.dataset(g + "/im", s.im, "1/s");
  f.dataset(g + "/frequency", s.frequency, "Hz");
  f.dataset(g + "/damping_ratio", s.damping, "-");
  f.dataset(g + "/step_change", s.step_change, "-");
  f.dataset(g + "/hunting", s.hunting, "-");
  f.dataset(g + "/unstable", s.unstable, "-");
  f.stringDataset(g + "/label", s.labels);
  f.stringDataset(g + "/dominant", s.dominant);
  f.stringDataset(g + "/coordinates", s.coordinates);
  f.dataset2d(g + "/participation", s.re.size(), s.coordinates.size(), s.participation, "-");
  f.attr(g, "speed", s.speed);
  f.attr(g, "steady_residual", s.residual);
  f.attr(g, "steady_residual_raw", s.residual_raw);
  f.attr(g, "steady_iterations", s.iterations);
  f.attr(g, "steady_fallback", std::string(s.fallback ? "bdf settle" : "none"));
  f.attr(g, "max_wheelset_lateral", s.max_ws_lateral);
  f.attr(g, "states", s.states);
  f.attr(g, "step_check", s.step_check);
  f.attr(g, "step_check_passed", std::string(s.step_check_ok ? "yes" : "no"));
  if (std::isfinite(s.hunting_damping))
    f.attr(g, "hunting_damping", s.hunting_damping);
  else
    f.attr(g, "hunting_damping", std::string("none"));
  if (std::isfinite(s.least_damping))
    f.attr(g, "least_damping", s.least_damping);
  else
    f.attr(g, "least_damping", std::string("none"));
  f.attr(g, "rhs_evaluations", s.rhs_evaluations);
  f.attr(g, "cpu_s", s.cpu_s);
}

}  // namespace

void writeModesFile(const std::string& path, const std::vector<ModesAtSpeed>& speeds,
                    const ModesSummary& sum) {
  ResultFile f(path);
  std::vector<double> v, hd;
  for (const auto& s : speeds) {
    v.push_back(s.speed);
    hd.push_back(std::isfinite(s.hunting_damping) ? s.hunting_damping : 1.0);
  }
  f.dataset("/modes/speeds", v, "m/s");
  // The least damped hunting mode's damping ratio per speed (1 where no hunting mode was found).
  f.dataset("/modes/hunting_damping", hd, "-");
  if (!sum.refinement_speeds.empty()) {
    f.dataset("/modes/refinement_speeds", sum.refinement_speeds, "m/s");
    f.dataset("/modes/refinement_damping", sum.refinement_damping, "-");
  }
  for (std::size_t i = 0; i < speeds.size(); ++i)
    writeSpeed(f, "/modes/speed_" + std::to_string(i), speeds[i]);
  f.attr("/modes", "critical_speed", sum.critical);
  if (sum.critical_speed > 0.0) {
    f.attr("/modes", "critical_speed_value", sum.critical_speed);
    f.attr("/modes", "critical_bracket_lo", sum.bracket_lo);
    f.attr("/modes", "critical_bracket_hi", sum.bracket_hi);
    f.attr("/modes", "critical_speed_step_uncertainty", sum.step_uncertainty);
  }
  f.attr("/modes", "critical_mode", sum.critical_mode);
  f.attr("/modes", "hunting_critical_speed", sum.hunting);
  if (sum.hunting_speed > 0.0) f.attr("/modes", "hunting_critical_speed_value", sum.hunting_speed);
  std::string unstable;
  for (const auto& u : sum.unstable) unstable += u + "\n";
  f.attr("/modes", "unstable_modes", unstable.empty() ? std::string("none") : unstable);
  f.attr("/modes", "contact_method", sum.method);
  f.attr("/modes", "creep_law", sum.creep);
  f.attr("/modes", "wheelset_spin", sum.spin);
  f.attr("/modes", "scenario", sum.scenario);
  f.attr("/modes", "cpu_s", sum.cpu_s);
  f.attr("/modes", "rhs_evaluations", sum.rhs_evaluations);
  std::string notes;
  for (const auto& n : sum.notes) notes += n + "\n";
  f.attr("/modes", "notes", notes);
  f.finalize();
}

}  // namespace rb::io
