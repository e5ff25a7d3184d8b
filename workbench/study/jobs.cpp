#include "workbench/study/jobs.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>
#include <stdexcept>
#include <thread>

#include "workbench/core/error.hpp"
#include "workbench/core/files.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/io/read_stats.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/io/root_text.hpp"
#include "workbench/io/track_store.hpp"
#include "workbench/study/metrics.hpp"

namespace fs = std::filesystem;

namespace rb::study::detail {

bool isDone(const std::string& h5, const std::string& hash) {
  if (hash.empty() || !isRegularFile(h5)) return false;
  // One open of the file for the three questions (every run of a study is asked at planning).
  const io::ResultReader r(h5);
  if (!r.text("/stats", "status")) return false;
  const auto stamp = r.text("/", "input_hash");
  if (!stamp || *stamp != hash) return false;
  // A compact result whose stored track is gone (a deleted tracks/ folder) is run again: its
  // readers could not load it.
  const auto in = r.text("/track", "stored_in");
  const auto trackHash = r.text("/track", "track_hash");
  if (!in) return true;
  return trackHash &&
         io::isStoredTrack((std::filesystem::path(h5).parent_path() / *in).string(), *trackHash);
}

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
std::string CaseHasher::operator()(const scenario::StudyCase& c) const {
  try {
    scenario::LoadOptions lo;
    lo.root = o.root;
    lo.overrides = c.overrides;
    return caseInputHash(scenario::loadScenario(c.base, lo), build,
                         study ? study->output : std::string("full"));
  } catch (const InputError&) {
    return std::string();
  }
}

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

namespace {

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
pid_t launch(const StudyOptions& o, const scenario::StudySpec* study, const Job& j) {
  std::vector<std::string> args = {o.program, "--root", o.root, "run",
                                   j.c->base, "--out",  j.work, "--quiet"};
  if (study && study->output == "compact") {
    // The track once per distinct track, beside the results (the reference is relative to the
    // result's folder, so the study folder can be moved).
    args.insert(args.end(),
                {"--compact", "--track-store", (fs::path(j.h5).parent_path() / "tracks").string()});
  }
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

// The process pool of one runner: starts the runs that are not done and no other runner holds,
// `jobs` at a time, and gives each finished run its final name.
class Pool {
 public:
  Pool(const StudyOptions& o, const fs::path& dir, const CaseHasher& hashOf, std::size_t total,
       std::string who)
      : o_(o),
        dir_(dir),
        hashOf_(hashOf),
        total_(total),
        stray_(leftovers(dir)),
        who_(std::move(who)) {}

  // Starts the run `index` of `all`, or reports why not (held by another runner, done, error).
  void start(std::vector<Job>& all, std::size_t index) {
    Job& j = all[index];
    std::string why;
    Lock l = tryLock(j, why);
    // A summary written beside this runner (outcomesFromDisk) holds a run's lock for a moment
    // to see whether a runner has it: try again briefly before leaving the run to another
    // runner, which holds it for the whole run.
    for (int attempt = 0; l == Lock::Busy && attempt < 5; ++attempt) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      l = tryLock(j, why);
    }
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
    fs::remove(noResultPath(j), ignored);
    j.work = (dir_ / (j.name + ".run-" + uniqueSuffix() + ".h5")).string();
    pid_t pid = launch(o_, hashOf_.study, j);
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
      all[index].note = "killed after " + formatNumber(o_.run_timeout_s) +
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
    bool kept = false;
    if (overdue) {
      // Killed mid-write: its result and the temporary files of its writer are incomplete.
      auto files = leftovers(dir_);
      for (const auto& stray : files[j.name]) fs::remove(stray, ignored);
    } else if (isRegularFile(j.work) && code != 0 && code != 2) {
      fs::remove(j.work, ignored);
    } else if (isRegularFile(j.work)) {
      j.note = keep(j);
      kept = j.note.empty();
      if (!kept) fs::remove(j.work, ignored);
    }
    if (!kept) recordNoResult(j);
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
    // The metrics are computed by the runner that ran the case, so the farm's workers share
    // the work; a failure here loses nothing (the summary computes them from the file).
    if (const scenario::StudySpec* st = hashOf_.study; st && !st->metrics.empty()) {
      std::string why;
      if (!storeCaseMetrics(*st, *j.c, j.work, why))
        std::cerr << "  " << j.name << ": metrics not stored (" << why
                  << "); the summary computes them\n";
    }
    if (!io::writeRootText(j.work, "input_hash", *j.hash))
      return "cannot stamp the input hash into " + j.work;
    std::error_code ec;
    fs::rename(j.work, j.h5, ec);
    return ec ? "cannot rename " + j.work + " to " + j.h5 + ": " + ec.message() : std::string();
  }

  // Written under the run's lock, so a summary written elsewhere reads a complete record.
  static void recordNoResult(const Job& j) {
    try {
      writeAtomically(noResultPath(j), *j.hash + "\n" + j.note);
    } catch (const std::exception&) {  // the summary of another runner then says "missing"
    }
  }

  void report(const Job& j, const std::string& what) {
    std::cerr << who_ << "  [" << ++done_ << "/" << total_ << "] " << j.c->id << " r" << j.repeat
              << ": " << what << "  " << j.c->label << "\n";
  }

  const StudyOptions& o_;
  fs::path dir_;
  const CaseHasher& hashOf_;
  std::size_t total_;
  std::map<std::string, std::vector<fs::path>> stray_;
  std::size_t done_ = 0;
  std::string who_;
};

// Runs the runs `todo` of `all`, `jobs` at a time; the number skipped (held by another runner).
std::size_t runPool(Pool& pool, std::vector<Job>& all, const std::vector<std::size_t>& todo,
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

}  // namespace

struct SerialRunner::Impl {
  Pool pool;
};

SerialRunner::SerialRunner(const StudyOptions& o, const fs::path& dir, const CaseHasher& hashOf,
                           std::size_t total, const std::string& who)
    : impl_(new Impl{Pool(o, dir, hashOf, total, who)}) {}

SerialRunner::~SerialRunner() = default;

void SerialRunner::run(std::vector<Job>& all, std::size_t index) {
  runPool(impl_->pool, all, {index}, 1);
}

std::size_t runJobs(const StudyOptions& o, const fs::path& dir, const CaseHasher& hashOf,
                    std::vector<Job>& all, const std::vector<std::size_t>& todo, int jobs,
                    const std::string& who) {
  Pool pool(o, dir, hashOf, todo.size(), who);
  return runPool(pool, all, todo, jobs);
}

std::string noResultPath(const Job& j) {
  const std::string suffix = ".lock";
  return j.lock.substr(0, j.lock.size() - suffix.size()) + ".noresult";
}

void outcomesFromDisk(std::vector<Job>& all) {
  for (Job& j : all) {
    if (j.outcome != Outcome::Pending || isDone(j.h5, *j.hash)) continue;
    std::string why;
    const Lock l = tryLock(j, why);
    if (l == Lock::Busy) {
      j.outcome = Outcome::Skipped;
      continue;
    }
    std::string why2;
    auto record = readRegularFile(noResultPath(j), why2);
    unlock(j);
    if (!record) continue;
    const auto eol = record->find('\n');
    if (eol == std::string::npos || record->substr(0, eol) != *j.hash) continue;
    j.outcome = Outcome::Ran;
    j.note = record->substr(eol + 1);
  }
}

}  // namespace rb::study::detail
