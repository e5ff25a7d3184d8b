#include "workbench/app/study.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "railbench/version.hpp"
#include "workbench/contact/table_io.hpp"
#include "workbench/core/error.hpp"
#include "workbench/core/files.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/io/read_stats.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/io/root_text.hpp"
#include "workbench/scenario/study.hpp"
#include "workbench/track/spec.hpp"
#include "workbench/vehicle/stage_clock.hpp"

namespace fs = std::filesystem;

namespace rb::app {
namespace {

// FNV-1a 64 over length-prefixed fields: no two different field lists give the same byte stream.
class Hasher {
 public:
  void field(const std::string& name, const std::string& bytes) {
    raw(name);
    raw(std::string(1, '\0') + std::to_string(bytes.size()) + '\0');
    raw(bytes);
  }
  std::uint64_t value() const { return h_; }

 private:
  void raw(const std::string& s) {
    for (unsigned char c : s) {
      h_ ^= c;
      h_ *= 1099511628211ull;
    }
  }
  std::uint64_t h_ = 1469598103934665603ull;
};

std::string hex16(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// What is known about one run of a case.
enum class Outcome { Pending, Ran, Skipped };

struct Job {
  const scenario::StudyCase* c = nullptr;
  int repeat = 0;
  std::string name;  // <id>_r<k>
  std::string h5, log, lock, work;
  const std::string* hash = nullptr;  // the case's input hash ("" when it does not load)
  int lock_fd = -1;
  Outcome outcome = Outcome::Pending;
  std::string note;  // why a run left no result (stamping, changed inputs, no process)
};

// Is `h5` a complete result of exactly these inputs?
bool isDone(const std::string& h5, const std::string& hash) {
  if (hash.empty() || !isRegularFile(h5)) return false;
  auto rec = io::readStats(h5);
  if (!rec || !rec->text.count("status")) return false;
  auto stamp = io::readRootText(h5, "input_hash");
  return stamp && *stamp == hash;
}

// A name no other process or call uses.
std::string uniqueSuffix() {
  static std::uint64_t counter = 0;
  std::uint64_t salt =
      static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
      (++counter << 40);
  try {
    std::random_device rd;
    salt ^= (static_cast<std::uint64_t>(rd()) << 32) ^ rd();
  } catch (const std::exception&) {  // no entropy source: clock and counter only
  }
  return std::to_string(getpid()) + "-" + hex16(salt).substr(8);
}

enum class Lock { Held, Busy, Error };

// Exclusive, non-blocking lock on the job's lock file. The descriptor is close-on-exec so that
// no case's run holds the lock of another case.
Lock tryLock(Job& j, std::string& why) {
  int fd = ::open(j.lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd < 0) {
    why = "cannot open the lock file " + j.lock + ": " + std::strerror(errno);
    return Lock::Error;
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd);
    if (err == EWOULDBLOCK) return Lock::Busy;
    why = "cannot lock " + j.lock + ": " + std::strerror(err);
    return Lock::Error;
  }
  j.lock_fd = fd;
  return Lock::Held;
}

void unlock(Job& j) {
  if (j.lock_fd >= 0) ::close(j.lock_fd);  // releases the flock
  j.lock_fd = -1;
}

// Files of earlier, killed attempts (<name>.run-*, with the runs' own .tmp files), by job name,
// from one listing of the folder (a listing per case would cost O(cases^2) on a big study).
std::map<std::string, std::vector<fs::path>> leftovers(const fs::path& dir) {
  std::map<std::string, std::vector<fs::path>> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string f = it->path().filename().string();
    if (auto at = f.find(".run-"); at != std::string::npos) out[f.substr(0, at)].push_back(*it);
  }
  return out;
}

// Removes them for one job; called only while holding the job's lock, when no live process can
// be writing them.
void removeLeftovers(std::map<std::string, std::vector<fs::path>>& stray, const Job& j) {
  auto it = stray.find(j.name);
  if (it == stray.end()) return;
  for (const fs::path& p : it->second) {
    std::error_code ignored;
    fs::remove(p, ignored);
  }
  stray.erase(it);
}

// Starts `workbench run` for one job with stdout/stderr to its log; returns the pid. The run is
// killed when the runner dies (PR_SET_PDEATHSIG), so a killed runner leaves no orphan writing
// into the folder after its locks are gone.
pid_t launch(const StudyOptions& o, const Job& j) {
  std::vector<std::string> args = {o.program, "--root", o.root, "run",
                                   j.c->base, "--out",  j.work, "--quiet"};
  for (const auto& ov : j.c->overrides) {
    args.push_back("--set");
    args.push_back(ov);
  }
  const pid_t parent = getpid();
  pid_t pid = fork();
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);  // the runner died before prctl
    int fd = open(j.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
      close(fd);
    }
    int devnull = open("/dev/null", O_RDONLY);
    if (devnull >= 0) dup2(devnull, 0);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(o.program.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

// Writes `text` to `path` through a unique temporary file and a rename, so a reader (or another
// runner writing the same summary) never sees a partial file.
void writeAtomically(const fs::path& path, const std::string& text) {
  const std::string tmp = path.string() + ".tmp." + uniqueSuffix();
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw std::runtime_error("cannot write " + tmp);
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error("cannot rename " + tmp + " to " + path.string() + ": " + ec.message());
  }
}

std::string csvField(std::string s) {
  bool quote = s.find_first_of(",\"\n") != std::string::npos;
  std::string out;
  for (char ch : s) {
    if (ch == '"') out += '"';
    out += ch == '\n' ? ' ' : ch;
  }
  return quote ? "\"" + out + "\"" : out;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The solver part of a case's label (caseLabel of its solver.* overrides: "rk4 h=0.25ms",
// "bdf tol=1e-6 hmax=1ms"), "" when the case keeps the base scenario's solver. The figures
// group cases by it, so they read it from summary_cases.csv instead of deriving it again.
std::string solverLabel(const std::vector<std::string>& overrides) {
  std::vector<std::string> solver;
  for (const auto& o : overrides)
    if (o.rfind("solver.", 0) == 0) solver.push_back(o);
  const std::string label = scenario::caseLabel(solver);
  return solver.empty() || label == "base" ? std::string() : label;
}

// The environment of the figures' python: this one with <root>/plots first on PYTHONPATH, so
// that `python3 -m railbench` finds the package (built before fork: the child only execs).
std::vector<std::string> plotsEnvironment(const fs::path& plots) {
  std::vector<std::string> env;
  std::string path = plots.string();
  for (char** e = environ; e && *e; ++e) {
    std::string kv = *e;
    if (kv.rfind("PYTHONPATH=", 0) == 0) {
      if (kv.size() > 11) path += ":" + kv.substr(11);
      continue;
    }
    env.push_back(std::move(kv));
  }
  env.push_back("PYTHONPATH=" + path);
  return env;
}

}  // namespace

int runRbplot(const StudyOptions& o, const std::vector<std::string>& args) {
  const char* env = std::getenv("RAILBENCH_PYTHON");
  std::string python = env && *env ? env : "/usr/bin/python3";
  const fs::path plots = fs::path(o.root) / "plots";
  if (!fs::exists(python) || !fs::exists(plots / "railbench" / "__main__.py")) return -1;
  std::vector<std::string> all = {python, "-m", "railbench"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<std::string> envs = plotsEnvironment(plots);
  std::vector<char*> argv;
  std::vector<char*> envp;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (auto& e : envs) envp.push_back(e.data());
  envp.push_back(nullptr);
  std::cout.flush();
  pid_t pid = fork();
  if (pid == 0) {
    execve(python.c_str(), argv.data(), envp.data());
    _exit(127);
  }
  int status = 0;
  if (pid < 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status)) return 128;
  return WEXITSTATUS(status);
}

int runPlots(const StudyOptions& o, const std::vector<std::string>& plotArgs) {
  if (const char* e = std::getenv("RAILBENCH_STUDY_PLOTS"); e && std::string(e) == "0") return 0;
  const int code = runRbplot(o, plotArgs);
  if (code < 0) {
    std::cerr << "study: note: no figures (python3 or " << o.root
              << "/plots/railbench not found)\n";
    return 0;
  }
  if (code != 0) {
    std::cerr << "study: the figures failed: PYTHONPATH=" << o.root
              << "/plots python3 -m railbench";
    for (const auto& a : plotArgs) std::cerr << " " << a;
    std::cerr << "\n";
    return 4;
  }
  return 0;
}

std::string buildId(const std::string& program) {
  std::string why;
  auto bytes = readRegularFile(program, why, std::size_t{1} << 31);
  if (!bytes) return "build:unknown";
  Hasher h;
  h.field("program", *bytes);
  return "build:" + hex16(h.value());
}

std::string caseInputHash(const scenario::ScenarioSpec& spec, const std::string& build_id) {
  Hasher h;
  h.field("railbench case inputs", "1");
  h.field("workbench", kVersion);
  h.field("table_algorithm", std::to_string(contact::kTableAlgorithmVersion));
  h.field("build", build_id);
  h.field("scenario", spec.text);
  for (const auto& [path, text] : spec.modules) h.field("module " + path, text);
  for (const auto& ov : spec.overrides) h.field("set", ov);
  // Data files by content (their paths may differ between machines with the same inputs).
  auto data = [&](const std::string& role, const std::string& path) {
    std::string why;
    auto bytes = readRegularFile(path, why);
    h.field("data " + role, bytes ? *bytes : "unreadable: " + why);
  };
  if (spec.profiles.wheel != "s1002") data("wheel", spec.profiles.wheel);
  if (spec.profiles.rail != "60e1") data("rail", spec.profiles.rail);
  if (spec.track.irregularities.source == track::IrregularitySource::Csv)
    data("irregularities", spec.track.irregularities.csv_path);
  return hex16(h.value());
}

namespace {

// The input hash of a case, from the scenario as the run will load it. A case that does not load
// gets no hash: it is always run (and its log says why it fails).
struct CaseHasher {
  const StudyOptions& o;
  std::string build;
  std::string operator()(const scenario::StudyCase& c) const {
    try {
      scenario::LoadOptions lo;
      lo.root = o.root;
      lo.overrides = c.overrides;
      return caseInputHash(scenario::loadScenario(c.base, lo), build);
    } catch (const InputError&) {
      return std::string();
    }
  }
};

// Every run of the study (case x repeat) with its file names in `dir`.
std::vector<Job> listJobs(const scenario::StudySpec& st, const fs::path& dir,
                          std::map<std::string, std::string>& hashes) {
  std::vector<Job> all;
  for (const auto& c : st.cases)
    for (int r = 0; r < st.repeats; ++r) {
      Job j;
      j.c = &c;
      j.repeat = r;
      j.name = c.id + "_r" + std::to_string(r);
      j.h5 = (dir / (j.name + ".h5")).string();
      j.log = (dir / (j.name + ".log")).string();
      j.lock = (dir / ".locks" / (j.name + ".lock")).string();
      j.hash = &hashes[c.id];
      all.push_back(j);
    }
  return all;
}

// The process pool of one runner: starts the runs that are not done and no other runner holds,
// `jobs` at a time, and gives each finished run its final name.
class Pool {
 public:
  Pool(const StudyOptions& o, const fs::path& dir, const CaseHasher& hashOf, std::size_t total)
      : o_(o), dir_(dir), hashOf_(hashOf), total_(total), stray_(leftovers(dir)) {}

  // Starts the run `index` of `all`, or reports why not (held by another runner, done, error).
  void start(std::vector<Job>& all, std::size_t index) {
    Job& j = all[index];
    std::string why;
    const Lock l = tryLock(j, why);
    if (l == Lock::Busy) {
      j.outcome = Outcome::Skipped;
      ++skipped;
      report(j, "skipped: being run by another runner");
      return;
    }
    if (l == Lock::Error) {
      j.outcome = Outcome::Ran;
      j.note = why;
      report(j, "error: " + why);
      return;
    }
    if (isDone(j.h5, *j.hash)) {  // finished by another runner since the listing
      unlock(j);
      j.outcome = Outcome::Ran;
      report(j, "done by another runner");
      return;
    }
    removeLeftovers(stray_, j);
    std::error_code ignored;
    fs::remove(j.h5, ignored);  // a result of other inputs: never to be mistaken for this one
    j.work = (dir_ / (j.name + ".run-" + uniqueSuffix() + ".h5")).string();
    pid_t pid = launch(o_, j);
    if (pid < 0) {
      j.outcome = Outcome::Ran;
      j.note = "cannot start a process: " + std::string(std::strerror(errno));
      unlock(j);
      report(j, "error: " + j.note);
      return;
    }
    running[pid] = index;
    started[pid] = std::chrono::steady_clock::now();
  }

  // Kills every run that has run longer than the options' run_timeout_s (a hang: the run would
  // never end by itself); its summary row says so.
  void killOverdue(std::vector<Job>& all) {
    if (o_.run_timeout_s <= 0) return;
    const auto now = std::chrono::steady_clock::now();
    for (const auto& [pid, index] : running) {
      const double age = std::chrono::duration<double>(now - started[pid]).count();
      if (age <= o_.run_timeout_s || !all[index].note.empty()) continue;
      char limit[32];
      std::snprintf(limit, sizeof limit, "%g", o_.run_timeout_s);
      all[index].note = std::string("killed after ") + limit +
                        " s of wall time (run timeout): the run did not end (a hang?)";
      ::kill(pid, SIGKILL);
    }
  }

  double timeout() const { return o_.run_timeout_s; }

  // The run `j` exited with `status`.
  void finish(Job& j, int status) {
    j.outcome = Outcome::Ran;
    const int code = WIFEXITED(status) ? WEXITSTATUS(status)
                                       : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    const bool overdue = !j.note.empty();
    // A run that exits with another code than ok (0) or failed (2) has no result: its log says
    // why, and whatever file it left is removed.
    std::error_code ignored;
    if (overdue) {
      // Killed mid-write: its result and the temporary files of its writer are incomplete.
      auto files = leftovers(dir_);
      for (const auto& stray : files[j.name]) fs::remove(stray, ignored);
    } else if (isRegularFile(j.work) && code != 0 && code != 2) {
      fs::remove(j.work, ignored);
    } else if (isRegularFile(j.work)) {
      j.note = keep(j);
      if (!j.note.empty()) fs::remove(j.work, ignored);
    }
    unlock(j);
    report(j, !j.note.empty() ? "error: " + j.note
              : code == 0     ? "ok"
              : code == 2     ? "failed (result kept)"
                              : "error " + std::to_string(code));
  }

  std::map<pid_t, std::size_t> running;
  std::map<pid_t, std::chrono::steady_clock::time_point> started;
  std::size_t skipped = 0;

 private:
  // Only a complete result of unchanged inputs gets the final name, stamped with their hash;
  // "" when it got it, else why not.
  std::string keep(const Job& j) const {
    const auto rec = io::readStats(j.work);
    if (!rec || !rec->text.count("status"))
      return "the run left an incomplete result file (no /stats/status); discarded";
    if (j.hash->empty() || hashOf_(*j.c) != *j.hash)
      return "the case's input files changed while it ran; its result was discarded (run the "
             "study again)";
    if (!io::writeRootText(j.work, "input_hash", *j.hash))
      return "cannot stamp the input hash into " + j.work;
    std::error_code ec;
    fs::rename(j.work, j.h5, ec);
    return ec ? "cannot rename " + j.work + " to " + j.h5 + ": " + ec.message() : std::string();
  }

  void report(const Job& j, const std::string& what) {
    std::cerr << "  [" << ++done_ << "/" << total_ << "] " << j.c->id << " r" << j.repeat << ": "
              << what << "  " << j.c->label << "\n";
  }

  const StudyOptions& o_;
  fs::path dir_;
  const CaseHasher& hashOf_;
  std::size_t total_;
  std::map<std::string, std::vector<fs::path>> stray_;
  std::size_t done_ = 0;
};

// Runs the runs `todo` of `all`, `jobs` at a time; the number skipped (held by another runner).
std::size_t runJobs(Pool& pool, std::vector<Job>& all, const std::vector<std::size_t>& todo,
                    int jobs) {
  std::size_t next = 0;
  while (next < todo.size() || !pool.running.empty()) {
    while (next < todo.size() && static_cast<int>(pool.running.size()) < jobs)
      pool.start(all, todo[next++]);
    if (pool.running.empty()) continue;
    int status = 0;
    // With a run timeout, poll so that a hung run is noticed; else block until a run ends.
    const bool poll = pool.timeout() > 0;
    pid_t pid = waitpid(-1, &status, poll ? WNOHANG : 0);
    if (pid == 0) {
      pool.killOverdue(all);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    if (pid < 0 && errno == EINTR) continue;
    if (pid < 0) break;
    auto it = pool.running.find(pid);
    if (it == pool.running.end()) continue;
    Job& j = all[it->second];
    pool.running.erase(it);
    pool.started.erase(pid);
    pool.finish(j, status);
  }
  return pool.skipped;
}

// The /stats numbers of every run in the summaries: the counts, then the share of the run's cost
// per rhs stage (docs/run_stats.md; 0 for a stage the run does not have or when no evaluation was
// timed), the integrator's and the observer's.
std::vector<std::string> summaryNumbers() {
  std::vector<std::string> k = {"cpu_time_s",        "wall_time_s",     "rhs_evals",
                                "rhs_evals_jac",     "steps",           "rejected_steps",
                                "jacobian_evals",    "nonlinear_iters", "t_reached",
                                "model_evaluations", "stage_samples"};
  for (const auto& e : vehicle::kStageNames) k.push_back("stage_share_" + std::string(e.name));
  k.emplace_back("stage_share_integrator");
  k.emplace_back("stage_share_observer");
  return k;
}
const std::vector<std::string> kSummaryNumbers = summaryNumbers();

// Per case: the CPU times of its ok repeats, and the status, reason and counts of its first
// problem (or of its first run when every repeat is ok).
struct CaseSum {
  std::vector<double> cpu;
  int runs = 0;
  std::string status, message, file;
  std::map<std::string, double> first;  // counts of the first run (exact, equal over repeats)
};

// What the summaries hold: summary.csv's text, the per-case sums, the columns of summary.h5.
struct Summary {
  std::ostringstream csv;
  std::map<std::string, CaseSum> cases;
  std::vector<double> ok;
  std::map<std::string, std::vector<double>> cols;
  std::size_t runsOk = 0, runsKnown = 0, runsElsewhere = 0;
};

// The status of a run in the summary, and its reason.
struct RunState {
  std::string status, message;
};

// The state of a run that left no valid result.
RunState noResult(const Job& j, Summary& sm) {
  if (j.outcome == Outcome::Skipped) {
    ++sm.runsElsewhere;
    return {"skipped", "being run by another runner when this summary was written"};
  }
  if (!j.note.empty()) return {"error", j.note};
  // The run stopped on bad input or crashed; its log says why.
  std::ifstream log(j.log);
  std::string line, last;
  while (std::getline(log, line))
    if (!line.empty()) last += (last.empty() ? "" : " | ") + line;
  return {"error", last.empty() ? "no result" : last.substr(0, 500)};
}

// One row of summary.csv per run, and the per-case sums.
void summariseRuns(const std::vector<Job>& all, Summary& sm) {
  sm.csv.precision(12);  // counts above 1e6 exactly, CPU times to the nanosecond
  sm.csv << "case,repeat,label,role,base,overrides,status";
  for (const auto& k : kSummaryNumbers) sm.csv << "," << k;
  sm.csv << ",message,file\n";
  for (const auto& j : all) {
    const bool valid = isDone(j.h5, *j.hash);
    auto rec = valid ? io::readStats(j.h5) : std::nullopt;
    const RunState run =
        rec ? RunState{rec->text["status"], rec->text["message"]} : noResult(j, sm);
    const std::string& status = run.status;
    const std::string& message = run.message;
    if (status != "skipped") ++sm.runsKnown;
    if (status == "ok") ++sm.runsOk;
    sm.csv << j.c->id << "," << j.repeat << "," << csvField(j.c->label) << "," << j.c->role << ","
           << csvField(j.c->base) << "," << csvField(join(j.c->overrides, " ")) << "," << status;
    std::map<std::string, double> numbers;
    for (const auto& k : kSummaryNumbers) {
      numbers[k] = rec && rec->number.count(k) ? rec->number[k] : 0.0;
      sm.csv << "," << numbers[k];
      sm.cols[k].push_back(numbers[k]);
    }
    sm.csv << "," << csvField(message) << "," << csvField(valid ? j.h5 : "") << "\n";
    sm.ok.push_back(status == "ok" ? 1.0 : 0.0);
    CaseSum& cs = sm.cases[j.c->id];
    ++cs.runs;
    if (status == "ok" && rec) cs.cpu.push_back(numbers["cpu_time_s"]);
    // The case's status: ok only when every repeat is ok; else the first problem and its reason.
    if (cs.status.empty() || (cs.status == "ok" && status != "ok")) {
      cs.status = status;
      cs.message = message;
      cs.file = valid ? j.h5 : "";
      cs.first = numbers;
    }
  }
}

// summary_cases.csv: one row per case, the median CPU time over its repeats.
std::string casesCsv(const scenario::StudySpec& st, std::map<std::string, CaseSum>& sum) {
  std::ostringstream cases;
  cases.precision(12);
  cases << "case,label,role,base,overrides,solver,runs,runs_ok,status,median_cpu_time_s,"
           "min_cpu_time_s,max_cpu_time_s";
  for (const auto& k : kSummaryNumbers)
    if (k != "cpu_time_s" && k != "wall_time_s") cases << "," << k;
  cases << ",message,file\n";
  for (const auto& c : st.cases) {
    CaseSum& cs = sum[c.id];
    auto [lo, hi] =
        cs.cpu.empty() ? std::pair<double, double>{0.0, 0.0}
                       : std::pair<double, double>{*std::min_element(cs.cpu.begin(), cs.cpu.end()),
                                                   *std::max_element(cs.cpu.begin(), cs.cpu.end())};
    cases << c.id << "," << csvField(c.label) << "," << c.role << "," << csvField(c.base) << ","
          << csvField(join(c.overrides, " ")) << "," << csvField(solverLabel(c.overrides)) << ","
          << cs.runs << "," << cs.cpu.size() << "," << cs.status << "," << median(cs.cpu) << ","
          << lo << "," << hi;
    for (const auto& k : kSummaryNumbers)
      if (k != "cpu_time_s" && k != "wall_time_s") cases << "," << cs.first[k];
    cases << "," << csvField(cs.message) << "," << csvField(cs.file) << "\n";
  }
  return cases.str();
}

// summary.h5: the per-run numbers as datasets under /runs.
void writeSummaryH5(const fs::path& path, const scenario::StudySpec& st,
                    const std::vector<Job>& all, Summary& sm) {
  io::ResultFile h5(path.string());
  h5.attr("/", "study_file", st.file);
  h5.attr("/", "base", st.base);
  std::string caseIds, overrides, labels;
  for (const auto& j : all) {
    caseIds += (caseIds.empty() ? "" : "\n") + j.name;
    overrides += (overrides.empty() ? "" : "\n") + join(j.c->overrides, " ");
    labels += (labels.empty() ? "" : "\n") + j.c->label;
  }
  h5.attr("/runs", "labels", labels);
  h5.attr("/runs", "ids", caseIds);
  h5.attr("/runs", "overrides", overrides);
  h5.dataset("/runs/ok", sm.ok, "-");
  for (const auto& k : kSummaryNumbers)
    h5.dataset("/runs/" + k, sm.cols[k],
               k == "cpu_time_s" || k == "wall_time_s" || k == "t_reached" ? "s" : "-");
  h5.finalize();
}

}  // namespace

int runStudy(const StudyOptions& o) {
  const scenario::StudySpec st = scenario::loadStudy(o.file, o.root);
  StudyOptions so = o;
  if (so.out.empty()) so.out = (fs::path("out") / fs::path(o.file).stem()).string();
  return runStudySpec(st, so, {"study", so.out});
}

int runStudySpec(const scenario::StudySpec& st, const StudyOptions& o,
                 const std::vector<std::string>& plotArgs) {
  const fs::path dir = o.out;
  std::error_code ec;
  fs::create_directories(dir / ".locks", ec);
  if (ec)
    throw InputError({o.file, 0}, "cannot create the study's output folder " +
                                      (dir / ".locks").string() + ": " + ec.message());
  int jobs = o.jobs > 0    ? o.jobs
             : st.jobs > 0 ? st.jobs
                           : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

  const CaseHasher hashOf{o, buildId(o.program)};
  std::map<std::string, std::string> hashes;
  for (const auto& c : st.cases) hashes[c.id] = hashOf(c);
  std::vector<Job> all = listJobs(st, dir, hashes);
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (!isDone(all[i].h5, *all[i].hash)) todo.push_back(i);
  std::cerr << st.file << ": " << st.cases.size() << " cases x " << st.repeats << " repeats, "
            << all.size() - todo.size() << " already done, running " << todo.size() << " with "
            << jobs << " jobs\n";
  Pool pool(o, dir, hashOf, todo.size());
  const std::size_t skipped = runJobs(pool, all, todo, jobs);

  // Summaries of everything this folder holds for the study, written under a study-wide lock so
  // that runners finishing together do not interleave them.
  int summaryLock = ::open((dir / ".locks" / "summary.lock").c_str(),
                           O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (summaryLock >= 0) ::flock(summaryLock, LOCK_EX);
  Summary sm;
  summariseRuns(all, sm);
  try {
    writeAtomically(dir / "summary.csv", sm.csv.str());
    writeAtomically(dir / "summary_cases.csv", casesCsv(st, sm.cases));
    writeSummaryH5(dir / "summary.h5", st, all, sm);
  } catch (const std::exception& e) {
    if (summaryLock >= 0) ::close(summaryLock);
    std::cerr << "study: cannot write the summary in " << dir.string() << ": " << e.what() << "\n";
    return 2;
  }
  if (summaryLock >= 0) ::close(summaryLock);
  std::cout << "study " << st.file << ": " << all.size() << " runs, summary in "
            << (dir / "summary.csv").string() << "\n";
  if (skipped > 0 || sm.runsElsewhere > 0)
    std::cerr << "study: " << sm.runsElsewhere
              << " runs were being run by another runner; run the study again once it has "
                 "finished to summarise them\n";
  const int plots = plotArgs.empty() ? 0 : runPlots(o, plotArgs);
  if (sm.runsKnown > 0 && sm.runsOk == 0) {
    std::cerr << "study: no run of the study is ok (" << sm.runsKnown
              << " failed or could not run)\n";
    return 2;
  }
  return plots;
}

}  // namespace rb::app
