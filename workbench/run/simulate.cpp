#include "workbench/run/simulate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "workbench/core/strings.hpp"
#include "workbench/integrators/registry.hpp"

namespace rb::run {
namespace {

// Output data buffered in memory before it is written (at most, unless one chunk of every series
// is more): every flush writes each series and the file's metadata, so its cost grows with the
// number of flushes times the number of series, not with the data.
constexpr std::size_t kFlushBytes = std::size_t{32} << 20;
constexpr double kFlushSeconds = 10.0;  // [s] wall time between flushes at most

double wallNow() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Keeps results on disk as the run goes, by data volume (about kFlushBytes of buffered output, in
// whole HDF5 chunks of every series, so no chunk is rewritten, and the same work in every run of
// a scene, which keeps callgrind counts reproducible) and at least every kFlushSeconds of wall
// time.
struct Flusher {
  explicit Flusher(std::size_t series) {
    const std::size_t chunkRow =
        io::kSeriesChunk * sizeof(double) * std::max<std::size_t>(series, 1);
    every = io::kSeriesChunk * std::max<std::size_t>(1, kFlushBytes / chunkRow);
  }
  std::size_t every = io::kSeriesChunk;  // output times between flushes by volume
  double last = wallNow();
  std::size_t unflushed = 0;  // output times appended since the last flush
  void appended(io::ResultFile& f) {
    if (++unflushed < every && wallNow() - last <= kFlushSeconds) return;
    f.flush();
    last = wallNow();
    unflushed = 0;
  }
};

}  // namespace

std::vector<double> outputTimes(double t0, double t_end, double every) {
  RB_CHECK(every > 0 && t_end > t0, "output interval and end time must be positive");
  const long n = static_cast<long>(std::ceil((t_end - t0) / every - 1e-9));
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(n));
  for (long k = 1; k <= n; ++k)
    times.push_back(std::min(t0 + static_cast<double>(k) * every, t_end));
  return times;
}

ObservationTimes observationTimes(double t0, double t_end, double every, double extra_every) {
  ObservationTimes o;
  const std::vector<double> out = outputTimes(t0, t_end, every);
  if (extra_every <= 0.0) {
    o.times = out;
    o.what.assign(out.size(), 1);
    return o;
  }
  const std::vector<double> extra = outputTimes(t0, t_end, extra_every);
  const double tol = 1e-9 * std::min(every, extra_every);
  std::size_t i = 0, j = 0;
  while (i < out.size() || j < extra.size()) {
    const bool take_out = j == extra.size() || (i < out.size() && out[i] <= extra[j] + tol);
    const bool same = i < out.size() && j < extra.size() && std::abs(out[i] - extra[j]) <= tol;
    if (same) {
      o.times.push_back(out[i++]);
      o.what.push_back(3);
      ++j;
    } else if (take_out) {
      o.times.push_back(out[i++]);
      o.what.push_back(1);
    } else {
      o.times.push_back(extra[j++]);
      o.what.push_back(2);
    }
  }
  return o;
}

namespace {

// Why the sample `values` at t stops the run (a non-finite value, or the request's check); empty
// when it is valid.
// The body a dataset path is about: /bodies/ws1/y, /contact/ws1/left/Q -> "ws1";
// /vehicles/front/bodies/ws1/y -> "front.ws1"; "" for the run's own datasets.
std::string bodyOfPath(const std::string& path) {
  std::vector<std::string> parts = pathParts(path);
  std::string vehicle;
  if (parts.size() > 2 && parts[0] == "vehicles") {
    vehicle = parts[1] + ".";
    parts.erase(parts.begin(), parts.begin() + 2);
  }
  const bool of_body =
      parts.size() > 2 && (parts[0] == "bodies" || parts[0] == "contact" || parts[0] == "elements");
  return of_body ? vehicle + parts[1] : std::string();
}

// An output sample the run cannot write: its kind, the body it is about and why ("" when valid).
struct InvalidSample {
  integ::FailureKind kind = integ::FailureKind::None;
  std::string body, why;
};
InvalidSample invalidSample(const SimulationRequest& r, double t,
                            const std::vector<double>& values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::isfinite(values[i])) continue;
    return {integ::FailureKind::NonFinite, bodyOfPath(r.outputs[i].path),
            "non-finite output " + r.outputs[i].path + " = " + std::to_string(values[i]) +
                " at t = " + std::to_string(t) + " s"};
  }
  std::string why = r.check ? r.check(t, values.data()) : std::string();
  if (why.empty()) return {};
  return {integ::FailureKind::Validity, "", std::move(why)};
}

// The body a failure concerns: the model's own word, else the body of the first blamed state
// component ("ws1.y" -> "ws1", "front.ws1.y" -> "front.ws1").
std::string failureBody(const integ::RunResult& res, const integ::OdeSystem& sys) {
  if (!res.cause.body.empty()) return res.cause.body;
  if (res.offending_components.empty()) return {};
  const std::string name = sys.componentName(res.offending_components.front());
  const std::size_t dot = name.rfind('.');
  return dot == std::string::npos ? std::string() : name.substr(0, dot);
}

}  // namespace

integ::RunResult simulate(const SimulationRequest& r, io::ResultFile& f) {
  RB_CHECK(r.system != nullptr, "no system to simulate");
  auto integrator = integ::makeIntegrator(r.solver);
  const bool extra = r.extra != nullptr && r.extra->every > 0.0 && r.extra->sample;
  const ObservationTimes obs =
      observationTimes(r.t0, r.t_end, r.output_every, extra ? r.extra->every : 0.0);
  const std::vector<double>& times = obs.times;
  std::size_t next = 0;  // index of the observation the observer sees next

  io::Series& time = f.series("/time", "s");
  std::vector<io::Series*> series;
  for (const auto& o : r.outputs) series.push_back(&f.series(o.path, o.units));
  RB_CHECK(r.outputs.empty() || r.sample, "output channels need a sampler");
  std::vector<double> values(r.outputs.size());
  Flusher flusher(series.size() + 1);  // with /time
  double start = wallNow();
  double lastDistance = 0.0;

  InvalidSample invalid;  // why the observer stopped the run, if it did
  double t_invalid = 0.0;
  double t_written = r.t0;
  auto observer = [&](double t, const Eigen::VectorXd& y) {
    // The integrators observe `times` in order (some also t0, which is an output as before).
    unsigned char what = 1;
    if (next < times.size() && std::abs(t - times[next]) <= 1e-12 * std::max(1.0, std::abs(t)))
      what = obs.what[next++];
    if ((what & 2) != 0) {
      r.extra->sample(t, y);
      ++r.extra->samples;
    }
    if ((what & 1) == 0) return true;
    if (!series.empty()) {
      r.sample(t, y, values.data());
      invalid = invalidSample(r, t, values);
      if (!invalid.why.empty()) {
        t_invalid = t;
        return false;  // not written: the file ends at the last valid sample
      }
    }
    time.append(t);
    t_written = t;
    for (std::size_t i = 0; i < series.size(); ++i) series[i]->append(values[i]);
    if (r.distance) lastDistance = r.distance(t, y);
    flusher.appended(f);
    return true;
  };
  double lastPrint = start;
  bool printed = false;
  auto progress = [&](double t, const integ::Stats& s) {
    double now = wallNow();
    if (!r.progress || now - start < r.progress_after || now - lastPrint < r.progress_every) return;
    lastPrint = now;
    printed = true;
    double rtf = (t - r.t0) / std::max(now - start, 1e-9);
    std::fprintf(stderr, "\r  t = %8.3f s  s = %8.1f m  %6.1fx real time  %ld evaluations   ", t,
                 lastDistance, rtf, s.rhs_evals + s.rhs_evals_jac);
    std::fflush(stderr);
  };
  integ::RunResult res =
      integ::integrate(*r.system, *integrator, r.t0, r.y0, times, observer, progress);
  if (printed) std::fprintf(stderr, "\n");
  std::string body;
  if (!invalid.why.empty() && res.stopped_by_observer) {
    res.ok = false;
    res.stopped_by_observer = false;
    res.t_fail = t_invalid;
    res.t_reached = t_written;
    res.failure = invalid.kind;
    body = invalid.body;
    res.message = std::string(integrator->name()) +
                  ": stopped at t = " + std::to_string(t_invalid) + " s: " + invalid.why;
  }
  FailureRecord record;
  if (!res.ok) {
    std::ostringstream os;
    os << res.message;
    record.t = std::isfinite(res.t_fail) ? res.t_fail : res.t_reached;
    if (r.distance) {
      record.s = r.distance(record.t, r.y0);
      os << " (leading wheelset at s = " << record.s << " m)";
    }
    res.message = os.str();
    record.body = body.empty() ? failureBody(res, *r.system) : body;
  }
  writeStats(f, res, std::string(integrator->name()), record);
  f.flush();
  return res;
}

void writeStats(io::ResultFile& f, const integ::RunResult& res, const std::string& method,
                const FailureRecord& failure) {
  const auto& s = res.stats;
  f.attr("/stats", "status", std::string(res.ok ? "ok" : "failed"));
  f.attr("/stats", "message", res.message);
  // The failure record (docs/architecture.md, "Failed runs and exit codes"): what ended the run
  // as names a reader can branch on, beside the message for a person.
  const integ::FailureKind kind =
      res.ok ? integ::FailureKind::None
             : (res.failure == integ::FailureKind::None ? integ::FailureKind::Solver : res.failure);
  f.attr("/stats", "failure_kind", std::string(nameOf(kind)));
  f.attr("/stats", "failure_reason", res.ok ? std::string() : res.cause.reason);
  f.attr("/stats", "failure_body", res.ok ? std::string() : failure.body);
  // Only what is known: an ok run has no failure time, a run without a vehicle no distance (no
  // NaN is written as a value).
  if (!res.ok && std::isfinite(failure.t)) f.attr("/stats", "failure_t", failure.t);
  if (!res.ok && std::isfinite(failure.s)) f.attr("/stats", "failure_s", failure.s);
  f.attr("/stats", "method", method);
  f.attr("/stats", "t_reached", res.t_reached);
  f.attr("/stats", "cpu_time_s", s.cpu_time_s);
  f.attr("/stats", "wall_time_s", s.wall_time_s);
  f.attr("/stats", "callback_wall_time_s", s.callback_wall_time_s);
  f.attr("/stats", "rhs_evals", std::int64_t{s.rhs_evals});
  f.attr("/stats", "rhs_evals_jac", std::int64_t{s.rhs_evals_jac});
  f.attr("/stats", "steps", std::int64_t{s.steps});
  f.attr("/stats", "rejected_steps", std::int64_t{s.rejected_steps});
  f.attr("/stats", "jacobian_evals", std::int64_t{s.jacobian_evals});
  f.attr("/stats", "nonlinear_iters", std::int64_t{s.nonlinear_iters});
  f.attr("/stats", "nonlinear_conv_fails", std::int64_t{s.nonlinear_conv_fails});
  f.attr("/stats", "recoverable_rhs_failures", std::int64_t{s.recoverable_rhs_failures});
}

void writeWarnings(io::ResultFile& f, const std::vector<std::string>& warnings) {
  std::string all;
  for (const auto& w : warnings) all += (all.empty() ? "" : "\n") + w;
  f.attr("/stats", "warnings", all);
  f.attr("/stats", "warning_count", static_cast<std::int64_t>(warnings.size()));
}

std::string statsLine(const integ::RunResult& res, double simulated_s) {
  const auto& s = res.stats;
  std::ostringstream os;
  os << (res.ok ? "ok" : "FAILED") << ": " << simulated_s << " s simulated in " << s.cpu_time_s
     << " s CPU (" << (s.cpu_time_s > 0 ? simulated_s / s.cpu_time_s : 0.0) << "x real time), "
     << s.rhs_evals << " rhs evaluations + " << s.rhs_evals_jac << " for Jacobians, " << s.steps
     << " steps, " << s.rejected_steps << " rejected, " << s.jacobian_evals << " Jacobians, "
     << s.nonlinear_iters << " Newton iterations (" << s.nonlinear_conv_fails << " failed)";
  return os.str();
}

}  // namespace rb::run
