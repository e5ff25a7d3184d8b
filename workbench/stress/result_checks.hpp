#pragma once
// The checks of one run's result file, the verdict of `workbench stress` (verdict.hpp) and of the
// hard-case suite (`workbench check-result`, docs/hard_cases.md, docs/stress.md):
//
// * the file is readable and /stats/status agrees with the run's exit code (0 ok, 2 failed);
//   after a failure the failure record (/stats failure_kind, failure_t, failure_s) is there,
//   t_reached < t_end and the partial time history ends at or before t_reached;
// * no NaN/Inf in any dataset or numeric attribute;
// * plausibility bounds (Bounds): wheelset |y| against the centre of its rails, wheel normal
//   forces, flange forces and indentation, |Y/Q|; required of a finished run, noted for a failed
//   run's partial results (the last outputs before a failure may show the divergence that caused
//   it, e.g. RK4 at 1 ms into the stiff flange).
#include <limits>
#include <string>
#include <vector>

namespace rb::stress {

// Plausibility bounds. |y| of a wheelset relative to the centre of its rails (its lateral
// displacement less the rails' at its s: alignment irregularities move the rails and the wheelset
// follows them): the flange clearance of S1002 on 60E1 (7-10 mm; the LUT flange is reached at
// y ~ -10 mm) plus a few mm; the LUT table ends at 18 mm. Wheel loads: static ~54 kN (wagon),
// 45 kN (single wheelset); ten times static is not plausible. Y/Q: the Nadal limit of a 70 deg
// flange is 1.5 at mu = 0.2364 and 0.95 at mu = 0.5; short impact peaks may exceed it, 4 may not.
struct Bounds {
  double y_mm = 14.0;
  double normal_kN = 600.0;
  double lift_kN = 30.0;  // largest tensile normal force (a wheel pulled onto its rail)
  double flange_kN = 800.0;
  double indent_mm = 1.0;
  double yq = 4.0;
};

// Sets one bound from "NAME=VALUE" (NAME a field of Bounds: y_mm, normal_kN, lift_kN, flange_kN,
// indent_mm, yq; VALUE a number > 0). Throws InputError naming `option`.
void setBound(Bounds& bounds, const std::string& assignment, const std::string& option);
// "y_mm (14), normal_kN (600), ...": the names setBound takes and their defaults.
std::string boundsHelp();

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct ResultCheck {
  bool readable = false;  // the file opened and has /stats
  // /stats as the run wrote it.
  std::string status, message;
  std::string failure_kind, failure_reason, failure_body;
  double failure_t = kNaN, failure_s = kNaN;
  std::string failure_text;  // the record in words (failureText), "" for a run that did not fail
  double t_reached = kNaN, t_end = 0.0;
  double cpu_s = kNaN, rhs_evals = kNaN, rhs_evals_jac = kNaN, steps = kNaN;
  double rejected_steps = kNaN, jacobian_evals = kNaN;
  // Extremes over the run, every wheelset and wheel.
  double max_abs_y_mm = 0.0;  // relative to the centre of the rails
  double max_normal_kN = 0.0, min_normal_kN = 0.0;
  double max_flange_kN = 0.0, max_normal_flange_kN = 0.0;
  double flange_time_share = 0.0;  // share of output times with a flange force on any wheel
  double max_indent_mm = 0.0, max_abs_yq = 0.0;
  // Hunting: peak-to-peak of ws1's y over the last second, and the first time (and speed, from
  // /vehicle/speed when written) its peak-to-peak over the trailing second exceeds 4 mm (a stable
  // wagon stays near 1 mm at 60 m/s, hunting reaches ~7.5 mm).
  double ws1_y_pp_last_mm = kNaN, onset_t = kNaN, onset_speed = kNaN;
  std::vector<std::string> problems;  // the file fails the checks
  std::vector<std::string> notes;     // implausible partial results of a failed run
};

// `exitCode`: the run's exit code (0 or 2); `t_end`: its end time [s], 0 when unknown (a run
// given by distance). A file that cannot be read is a problem, never an exception.
ResultCheck checkResult(const std::string& path, int exitCode, const Bounds& bounds, double t_end);

// The check as one JSON object (`workbench check-result`): every field of ResultCheck under its
// name, NaN as null, problems and notes as arrays of strings.
std::string toJson(const ResultCheck& check);

// A failure record in words, from the name tables' descriptions (the contact model's reason when
// it gave one, else the integrator's kind), with its time and distance when known:
// "a wheel's normal force fell below the minimum at t = 0.6242 s, s = 49.94 m".
std::string failureText(const std::string& kind, const std::string& reason, double t, double s);

// The contact model's reasons past which it is not valid (docs/contact_dynamics.md): a run that
// fails with one has found where the model stops, not a numerical problem.
bool leavesValidity(const std::string& reason);

}  // namespace rb::stress
