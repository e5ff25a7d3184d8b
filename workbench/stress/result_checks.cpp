#include "workbench/stress/result_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/integrators/integrator.hpp"
#include "workbench/io/result_reader.hpp"

namespace rb::stress {

namespace fs = std::filesystem;

namespace {

template <class... A>
std::string formatted(const char* format, A... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

// What a text or number attribute of /stats holds ("" / NaN when absent).
std::string text(const io::ResultReader& f, const char* name) {
  return f.text("/stats", name).value_or("");
}
double number(const io::ResultReader& f, const char* name) {
  return f.number("/stats", name).value_or(kNaN);
}

// np.interp: y(x) linear in xs (increasing), clamped to the end values outside.
double interpClamped(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  const std::size_t n = std::min(xs.size(), ys.size());
  if (n == 0) return 0.0;
  // A NaN position (a forged or diverged file; nonFinite() reports it) is below no sample: the
  // search below would end past the last one.
  if (std::isnan(x)) return kNaN;
  if (x <= xs[0]) return ys[0];
  if (x >= xs[n - 1]) return ys[n - 1];
  const auto it = std::upper_bound(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(n), x);
  const std::size_t j = static_cast<std::size_t>(it - xs.begin());
  const double w = (x - xs[j - 1]) / (xs[j] - xs[j - 1]);
  return ys[j - 1] + w * (ys[j] - ys[j - 1]);
}

// The lateral displacement of the centre of the rails along s [m] from the run's track
// irregularities, in the file or in the track store it references (io/track_store.hpp); an empty
// pair without irregularities. A store that is missing or holds another track is a problem.
struct RailCentre {
  std::vector<double> s, y;
};
RailCentre railCentre(const io::ResultReader& f, const std::string& path,
                      std::vector<std::string>& problems) {
  RailCentre out;
  const auto readFrom = [&](const io::ResultReader& r) {
    const std::string g = "/track/irregularities";
    auto s = r.dataset(g + "/s");
    auto left = r.dataset(g + "/left_y");
    auto right = r.dataset(g + "/right_y");
    if (!s) return;
    if (left && right && left->size() == right->size()) {
      out.y.resize(left->size());
      for (std::size_t i = 0; i < left->size(); ++i) out.y[i] = 0.5 * ((*left)[i] + (*right)[i]);
    } else if (auto a = r.dataset(g + "/alignment")) {
      out.y = std::move(*a);
    } else {
      return;
    }
    out.s = std::move(*s);
  };
  const auto stored = f.text("/track", "stored_in");
  if (!stored) {
    readFrom(f);
    return out;
  }
  const fs::path store = fs::path(path).parent_path() / *stored;
  const auto openStore = [&] {
    try {
      return std::make_unique<io::ResultReader>(store.string());
    } catch (const io::BadResult& e) {
      throw io::BadResult(path +
                          ": the track store its /track@stored_in names is refused: " + e.what());
    }
  };
  const auto storeFile = openStore();
  const io::ResultReader& sf = *storeFile;
  const std::string want = f.text("/track", "track_hash").value_or("");
  const std::string got = sf.ok() ? sf.text("/track", "track_hash").value_or("") : "";
  if (!sf.ok() || want.empty() || got != want) {
    problems.push_back("its track store file " + store.string() +
                       (sf.ok() ? " holds track '" + got + "', the result references '" + want + "'"
                                : " cannot be read"));
    return out;
  }
  readFrom(sf);
  return out;
}

// The consistency of /stats and /time with the exit code.
void checkConsistency(const io::ResultReader& f, int exitCode, ResultCheck& r,
                      const std::vector<double>& t) {
  auto& p = r.problems;
  if (t.empty()) p.emplace_back("no /time samples (no partial result)");
  const double t_end = r.t_end;
  if (exitCode == 0) {
    if (r.status != "ok") p.push_back("exit 0 but /stats/status = '" + r.status + "'");
    if (t_end > 0.0 && !t.empty() && std::abs(t.back() - t_end) > 1e-6 * std::max(1.0, t_end))
      p.push_back(formatted("ok run ends at t = %g, not %g", t.back(), t_end));
    return;
  }
  if (r.status != "failed") p.push_back("exit 2 but /stats/status = '" + r.status + "'");
  const std::string head = r.message.substr(0, 120);
  if (r.failure_kind.empty() || r.failure_kind == "none")
    p.push_back("failed without a failure kind: '" + head + "'");
  if (!f.number("/stats", "failure_t"))
    p.push_back("failure record without failure time: '" + head + "'");
  if (!f.number("/stats", "failure_s")) p.emplace_back("failure record without distance");
  if (t_end > 0.0 && !(r.t_reached < t_end))
    p.push_back(formatted("failed but t_reached = %g >= t_end", r.t_reached));
  if (!t.empty() && t.back() > r.t_reached + 1e-9)
    p.emplace_back("partial output beyond t_reached");
}

double peakToPeak(const std::vector<double>& y, std::size_t from, std::size_t to) {
  const auto [lo, hi] = std::minmax_element(y.begin() + static_cast<std::ptrdiff_t>(from),
                                            y.begin() + static_cast<std::ptrdiff_t>(to));
  return *hi - *lo;
}

// Hunting of the leading vehicle's ws1 (ResultCheck::ws1_y_pp_last_mm, onset_t, onset_speed).
void hunting(const io::ResultReader& f, const std::string& lead, const std::vector<double>& t,
             ResultCheck& r) {
  const auto y1 = f.dataset(lead + "/bodies/ws1/y");
  if (!y1 || t.size() < 2) return;
  const std::size_t n = std::min(t.size(), y1->size());
  if (n < 2) return;
  const double dt = t[1] - t[0];
  const std::size_t win =
      dt > 0.0 ? std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(1.0 / dt))) : 1;
  const auto speed = f.dataset("/vehicle/speed");
  for (std::size_t k = win; k < n; ++k) {
    if (peakToPeak(*y1, k - win, k + 1) > 4e-3) {
      r.onset_t = t[k];
      if (speed && k < speed->size()) r.onset_speed = (*speed)[k];
      break;
    }
  }
}

// Running extremes over every wheelset and wheel [SI].
struct Extremes {
  double ymax = 0.0, nmax = 0.0, fmax = 0.0, nfmax = 0.0, imax = 0.0, yqmax = 0.0;
  double nmin = std::numeric_limits<double>::infinity();
  std::vector<char> inFlange;  // per output time: a flange force on any wheel
};

double maxOf(const std::optional<std::vector<double>>& v, double m, bool abs) {
  if (v)
    for (double x : *v) m = std::max(m, abs ? std::abs(x) : x);
  return m;
}

// A wheelset's |y| against the centre of its rails, and the leading vehicle's ws1 peak-to-peak
// over the last second. `g`: the vehicle's group.
void wheelsetExtremes(const io::ResultReader& f, const std::string& g, bool lead,
                      const std::string& ws, const RailCentre& rails, const std::vector<double>& t,
                      Extremes& e, ResultCheck& r) {
  const auto y = f.dataset(g + "/bodies/" + ws + "/y");
  if (!y || y->empty()) return;
  const auto s = f.dataset(g + "/bodies/" + ws + "/s");
  for (std::size_t i = 0; i < y->size(); ++i) {
    const double centre =
        rails.s.empty() || !s || i >= s->size() ? 0.0 : interpClamped(rails.s, rails.y, (*s)[i]);
    e.ymax = std::max(e.ymax, std::abs((*y)[i] - centre));
  }
  if (!lead || (ws != "ws1" && ws != "ws")) return;
  std::size_t from = 0;
  const std::size_t n = std::min(t.size(), y->size());
  while (from < n && t[from] < t.back() - 1.0) ++from;
  r.ws1_y_pp_last_mm = from < n ? peakToPeak(*y, from, n) * 1e3 : kNaN;
}

// One wheel's forces (group /contact/<ws>/<side>/).
void wheelExtremes(const io::ResultReader& f, const std::string& g, Extremes& e) {
  const auto normal = f.dataset(g + "normal_force");
  if (!normal || normal->empty()) return;
  for (double x : *normal) {
    e.nmax = std::max(e.nmax, x);
    e.nmin = std::min(e.nmin, x);
  }
  const auto ff = f.dataset(g + "flange_force");
  const auto nf = f.dataset(g + "normal_flange");
  e.fmax = maxOf(ff, e.fmax, false);
  e.nfmax = maxOf(nf, e.nfmax, false);
  const std::size_t n = e.inFlange.size();
  for (std::size_t i = 0; i < n; ++i)
    if ((ff && ff->size() == n && (*ff)[i] > 0.0) || (nf && nf->size() == n && (*nf)[i] > 0.0))
      e.inFlange[i] = 1;
  e.imax = maxOf(f.dataset(g + "flange_indentation"), e.imax, false);
  e.yqmax = maxOf(f.dataset(g + "y_over_q"), e.yqmax, true);
}

// The extremes over every wheelset and wheel of every vehicle (ResultCheck's max_* and
// min_normal_kN).
void extremes(const io::ResultReader& f, const std::string& path,
              const std::vector<std::string>& vehicles, const std::vector<double>& t,
              ResultCheck& r) {
  Extremes e;
  e.inFlange.assign(t.size(), 0);
  const RailCentre rails = railCentre(f, path, r.problems);
  for (const auto& g : vehicles)
    for (const auto& ws : f.members(g + "/contact")) {
      wheelsetExtremes(f, g, g == vehicles.front(), ws, rails, t, e, r);
      for (const char* side : {"left", "right"})
        wheelExtremes(f, g + "/contact/" + ws + "/" + side + "/", e);
    }
  r.max_abs_y_mm = e.ymax * 1e3;
  r.max_normal_kN = e.nmax / 1e3;
  r.min_normal_kN = (std::isfinite(e.nmin) ? e.nmin : 0.0) / 1e3;
  r.max_flange_kN = e.fmax / 1e3;
  r.max_normal_flange_kN = e.nfmax / 1e3;
  r.flange_time_share =
      t.empty() ? 0.0
                : static_cast<double>(std::count(e.inFlange.begin(), e.inFlange.end(), 1)) /
                      static_cast<double>(t.size());
  r.max_indent_mm = e.imax * 1e3;
  r.max_abs_yq = e.yqmax;
}

// The plausibility bounds on the extremes.
std::vector<std::string> implausible(const ResultCheck& r, const Bounds& b) {
  std::vector<std::string> p;
  if (r.max_abs_y_mm > b.y_mm)
    p.push_back(formatted("|y| relative to the rails = %.2f mm > %.1f mm", r.max_abs_y_mm, b.y_mm));
  if (r.max_normal_kN > b.normal_kN)
    p.push_back(formatted("normal force %.0f kN > %.0f kN", r.max_normal_kN, b.normal_kN));
  if (-r.min_normal_kN > b.lift_kN)
    p.push_back(
        formatted("normal force %.0f kN (wheel lift beyond %.0f kN)", r.min_normal_kN, b.lift_kN));
  if (r.max_flange_kN > b.flange_kN)
    p.push_back(formatted("flange force %.0f kN > %.0f kN", r.max_flange_kN, b.flange_kN));
  if (r.max_indent_mm > b.indent_mm)
    p.push_back(formatted("flange indentation %.3f mm > %.1f mm", r.max_indent_mm, b.indent_mm));
  if (r.max_abs_yq > b.yq) p.push_back(formatted("|Y/Q| = %.2f > %.1f", r.max_abs_yq, b.yq));
  return p;
}

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (static_cast<unsigned char>(ch) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(ch));
      out += buf;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

std::string jsonNumber(double v) {
  return std::isfinite(v) ? formatNumber(v, 17) : "null";
}

std::string jsonList(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + jsonString(items[i]);
  return out + "]";
}

}  // namespace

std::string toJson(const ResultCheck& r) {
  const std::pair<const char*, std::string> fields[] = {
      {"readable", r.readable ? "true" : "false"},
      {"status", jsonString(r.status)},
      {"message", jsonString(r.message)},
      {"failure_kind", jsonString(r.failure_kind)},
      {"failure_reason", jsonString(r.failure_reason)},
      {"failure_body", jsonString(r.failure_body)},
      {"failure_t", jsonNumber(r.failure_t)},
      {"failure_s", jsonNumber(r.failure_s)},
      {"failure_text", jsonString(r.failure_text)},
      {"t_reached", jsonNumber(r.t_reached)},
      {"t_end", jsonNumber(r.t_end)},
      {"cpu_s", jsonNumber(r.cpu_s)},
      {"rhs_evals", jsonNumber(r.rhs_evals)},
      {"rhs_evals_jac", jsonNumber(r.rhs_evals_jac)},
      {"steps", jsonNumber(r.steps)},
      {"rejected_steps", jsonNumber(r.rejected_steps)},
      {"jacobian_evals", jsonNumber(r.jacobian_evals)},
      {"max_abs_y_mm", jsonNumber(r.max_abs_y_mm)},
      {"max_normal_kN", jsonNumber(r.max_normal_kN)},
      {"min_normal_kN", jsonNumber(r.min_normal_kN)},
      {"max_flange_kN", jsonNumber(r.max_flange_kN)},
      {"max_normal_flange_kN", jsonNumber(r.max_normal_flange_kN)},
      {"flange_time_share", jsonNumber(r.flange_time_share)},
      {"max_indent_mm", jsonNumber(r.max_indent_mm)},
      {"max_abs_yq", jsonNumber(r.max_abs_yq)},
      {"ws1_y_pp_last_mm", jsonNumber(r.ws1_y_pp_last_mm)},
      {"onset_t", jsonNumber(r.onset_t)},
      {"onset_speed", jsonNumber(r.onset_speed)},
      {"problems", jsonList(r.problems)},
      {"notes", jsonList(r.notes)},
  };
  std::string out = "{";
  for (const auto& [name, value] : fields)
    out += std::string(out.size() > 1 ? ",\n " : "") + jsonString(name) + ": " + value;
  return out + "}\n";
}

std::vector<std::pair<const char*, double*>> boundFields(Bounds& b) {
  return {{"y_mm", &b.y_mm},           {"normal_kN", &b.normal_kN}, {"lift_kN", &b.lift_kN},
          {"flange_kN", &b.flange_kN}, {"indent_mm", &b.indent_mm}, {"yq", &b.yq}};
}

std::string boundsHelp() {
  Bounds defaults;
  std::vector<std::string> out;
  for (const auto& [name, value] : boundFields(defaults))
    out.push_back(std::string(name) + " (" + formatNumber(*value) + ")");
  return join(out);
}

void setBound(Bounds& b, const std::string& assignment, const std::string& option) {
  const auto fields = boundFields(b);
  const auto eq = assignment.find('=');
  const std::string name = assignment.substr(0, eq);
  std::vector<std::string> names;
  for (const auto& [n, target] : fields) {
    names.emplace_back(n);
    if (name != n) continue;
    char* end = nullptr;
    const std::string text = eq == std::string::npos ? "" : assignment.substr(eq + 1);
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end == nullptr || *end != '\0' || !std::isfinite(v) || !(v > 0.0))
      throw InputError({option, 0}, "'" + assignment + "': the bound must be a finite number > 0");
    *target = v;
    return;
  }
  throw InputError({option, 0},
                   "'" + assignment + "': expected NAME=VALUE with NAME one of " + join(names));
}

std::string failureText(const std::string& kind, const std::string& reason, double t, double s) {
  std::string words;
  if (!reason.empty() && reason != "none") {
    words = reason;
    for (const auto& e : dynamics::kContactFailureNames)
      if (e.name == reason) words = e.help;
  } else if (!kind.empty() && kind != "none") {
    words = kind;
    for (const auto& e : integ::kFailureKindNames)
      if (e.name == kind) words = e.help;
  } else {
    words = "failed";
  }
  std::vector<std::string> where;
  if (std::isfinite(t)) where.push_back("t = " + formatNumber(t, 4) + " s");
  if (std::isfinite(s)) where.push_back("s = " + formatNumber(s, 4) + " m");
  return where.empty() ? words : words + " at " + join(where, ", ");
}

bool leavesValidity(const std::string& reason) {
  return reason == nameOf(dynamics::ContactFailure::WheelLift) ||
         reason == nameOf(dynamics::ContactFailure::Derailment) ||
         reason == nameOf(dynamics::ContactFailure::TableRange);
}

ResultCheck checkResult(const std::string& path, int exitCode, const Bounds& bounds, double t_end) {
  ResultCheck r;
  r.t_end = t_end;
  const io::ResultReader f(path);
  if (!f.ok() || !f.has("/stats")) {
    r.problems.push_back("cannot read result: " + path +
                         (f.ok() ? " has no /stats" : " is not a readable HDF5 file"));
    return r;
  }
  r.readable = true;
  r.status = text(f, "status");
  r.message = text(f, "message");
  r.failure_kind = text(f, "failure_kind");
  r.failure_reason = text(f, "failure_reason");
  r.failure_body = text(f, "failure_body");
  r.failure_t = number(f, "failure_t");
  r.failure_s = number(f, "failure_s");
  if (r.status != "ok")
    r.failure_text = failureText(r.failure_kind, r.failure_reason, r.failure_t, r.failure_s);
  r.t_reached = number(f, "t_reached");
  r.cpu_s = number(f, "cpu_time_s");
  r.rhs_evals = number(f, "rhs_evals");
  r.rhs_evals_jac = number(f, "rhs_evals_jac");
  r.steps = number(f, "steps");
  r.rejected_steps = number(f, "rejected_steps");
  r.jacobian_evals = number(f, "jacobian_evals");

  if (const auto bad = f.nonFinite(5); !bad.empty())
    r.problems.push_back("NaN/Inf in " + join(bad, ", "));
  const std::vector<double> t = f.dataset("/time").value_or(std::vector<double>{});
  checkConsistency(f, exitCode, r, t);
  const std::vector<std::string> vehicles = f.vehicleGroups();
  extremes(f, path, vehicles, t, r);
  if (!vehicles.empty()) hunting(f, vehicles.front(), t, r);
  const std::vector<std::string> odd = implausible(r, bounds);
  if (exitCode == 0) {
    r.problems.insert(r.problems.end(), odd.begin(), odd.end());
  } else if (!odd.empty()) {
    r.notes.push_back("partial results before the failure: " + join(odd, "; "));
  }
  return r;
}

}  // namespace rb::stress
