#pragma once
// Running an ODE model into a result file: output series at fixed output times, a progress line,
// /stats for every run, and failure as a result: a failed run keeps every output written so far,
// /stats/status = "failed" with the message, and the caller exits non-zero. A non-finite output
// value stops the run as a failure (a NaN is never written as a result).
#include <Eigen/Dense>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "workbench/integrators/integrator.hpp"
#include "workbench/integrators/spec.hpp"
#include "workbench/io/result_file.hpp"

namespace rb::run {

// One output time series: dataset `path` [units].
struct OutputChannel {
  std::string path;     // "/bodies/ws1/y"
  std::string units;    // "m"
  std::string meaning;  // what it is, for the result's /schema
  std::string codes;    // the /schema/enums entry of a code-valued channel, else empty
};
// Fills one value per channel at an output time (state y at time t). Called only at output
// times, so what it computes costs nothing between outputs.
using OutputSampler = std::function<void(double t, const Eigen::VectorXd& y, double* values)>;

// A second list of sample times at its own interval, t0 + k every (k = 1..n, the last clipped to
// t_end), merged with the output times: the caller keeps what it samples in memory (the signals
// of an assessment). A time shared with an output time is sampled once by each sampler, at the
// output time's value. Nothing is sampled when every == 0.
struct ExtraSampling {
  double every = 0.0;  // [s]
  std::function<void(double t, const Eigen::VectorXd& y)> sample;
  std::size_t samples = 0;  // filled by simulate(): how many times sample was called
};

struct SimulationRequest {
  integ::OdeSystem* system = nullptr;
  integ::SolverSpec solver;
  double t0 = 0.0;
  Eigen::VectorXd y0;
  double t_end = 0.0;          // [s]
  double output_every = 0.01;  // [s]
  std::vector<OutputChannel> outputs;
  OutputSampler sample;  // required when outputs is not empty
  // Arc length of the leading wheelset [m] at (t, y), for progress and failure messages;
  // optional (vehicle runs).
  std::function<double(double, const Eigen::VectorXd&)> distance;
  bool progress = false;  // progress line on stderr (the app enables it for terminals)
  // The line appears only on runs longer than progress_after [s] of wall time (a short run prints
  // its summary alone) and is rewritten at most every progress_every [s].
  double progress_after = 2.0, progress_every = 0.25;
  // Optional: called with each sample after the finiteness check; a non-empty return is a
  // failure message that stops the run (a model leaving its validity, seen in its outputs).
  std::function<std::string(double t, const double* values)> check;
  ExtraSampling* extra = nullptr;  // optional
};

// The merged, strictly increasing observation times of outputs (every) and extra samples
// (extra_every, 0 = none), with what to do at each: bit 0 output, bit 1 extra sample. Times
// closer than 1e-9 of the smaller interval are one time (the output time's value).
struct ObservationTimes {
  std::vector<double> times;
  std::vector<unsigned char> what;
};
ObservationTimes observationTimes(double t0, double t_end, double every, double extra_every);

// Integrates and writes /time, the requested series and /stats into `file` (not finalized).
// Throws InputError for inconsistent options (e.g. output interval not on a fixed-step grid).
integ::RunResult simulate(const SimulationRequest& request, io::ResultFile& file);

// Where a failed run ended: the time of the failure, the arc length of the leading body then
// (NaN without a vehicle) and the body the failure concerns ("" when none is named).
struct FailureRecord {
  double t = std::numeric_limits<double>::quiet_NaN();  // [s]
  double s = std::numeric_limits<double>::quiet_NaN();  // [m]
  std::string body;
};
// /stats attributes of a run (architecture.md): status, message, the failure record
// (failure_kind, failure_reason, failure_body; failure_t and failure_s when known), times and
// counters.
void writeStats(io::ResultFile& file, const integ::RunResult& result, const std::string& method,
                const FailureRecord& failure = {});
// /stats/warnings (one per line) and /stats/warning_count: what a run found questionable without
// failing; the summary line prints them.
void writeWarnings(io::ResultFile& file, const std::vector<std::string>& warnings);

// Output times t0 + k * every (k = 1..n), the last one clipped to t_end.
std::vector<double> outputTimes(double t0, double t_end, double every);

// One line summary of the statistics, printed at the end of a run.
std::string statsLine(const integ::RunResult& result, double simulated_s);

}  // namespace rb::run
