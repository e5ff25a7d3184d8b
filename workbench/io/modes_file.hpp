#pragma once
// The /modes group of `workbench modes` (docs/stability.md), written through io::ResultFile:
//   /modes/speeds [m/s]; per speed i a group /modes/speed_<i> with the eigenvalues (re, im [1/s]),
//   frequencies [Hz], damping ratios, labels, dominant coordinates, hunting flags (1/0), the
//   kinetic-energy participations (modes x coordinates) and the coordinate names, and as
//   attributes the speed, the steady-state residual, Newton iterations, the Jacobian step check
//   and the cost; /modes attributes: the linear critical speed (or "none in range"), contact
//   method, creep law, wheelset spin and the total cost.
#include <cstdint>
#include <string>
#include <vector>

namespace rb::io {

struct ModesAtSpeed {
  double speed = 0.0;
  std::vector<double> re, im, frequency, damping, step_change;
  std::vector<std::string> labels, dominant;
  std::vector<double> hunting;   // 1 hunting mode, 0 other
  std::vector<double> unstable;  // 1 unstable mode (Re lambda > 0, stability::unstable), 0 other
  std::vector<std::string> coordinates;
  std::vector<double> participation;  // row-major modes x coordinates
  double residual = 0.0, residual_raw = 0.0, max_ws_lateral = 0.0;
  std::int64_t iterations = 0, states = 0, rhs_evaluations = 0;
  bool fallback = false;
  double step_check = 0.0;
  bool step_check_ok = true;
  double hunting_damping = 0.0;  // NaN written as "none" attribute when no hunting mode
  double least_damping = 0.0;    // least damped mode of any kind (NaN: none)
  double cpu_s = 0.0;
};

struct ModesSummary {
  std::string method, creep, spin, scenario;
  std::string critical;         // "none in range", or the speed as text
  double critical_speed = 0.0;  // [m/s], 0 when none
  std::string critical_mode;    // the mode that loses its damping first (any kind)
  std::string hunting;          // the hunting modes' critical speed as text, or why none
  double hunting_speed = 0.0;   // [m/s], 0 when none
  // One line per speed with an unstable mode: "V m/s: mode; mode" (every unstable mode).
  std::vector<std::string> unstable;
  double bracket_lo = 0.0, bracket_hi = 0.0;
  double step_uncertainty = 0.0;  // [m/s] of the critical speed from the FD step (-1: unknown)
  std::vector<double> refinement_speeds, refinement_damping;
  double cpu_s = 0.0;
  std::int64_t rhs_evaluations = 0;
  std::vector<std::string> notes;
};

// Writes `path` (replaced atomically). Throws io::WriteError.
void writeModesFile(const std::string& path, const std::vector<ModesAtSpeed>& speeds,
                    const ModesSummary& summary);

}  // namespace rb::io
