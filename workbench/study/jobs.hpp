#pragma once
// The runs of a study (study/runner.hpp): listing them with their file names and input hashes, the
// per-run locks, and running them as `workbench run` processes. Shared by the local runner, the
// shards and the MPI task farm, so every way of running a study resumes and locks the same way.
#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "workbench/scenario/study.hpp"
#include "workbench/study/runner.hpp"

namespace rb::study::detail {

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

inline std::string hex16(std::uint64_t v) {
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
bool isDone(const std::string& h5, const std::string& hash);

// A name no other process or call uses.
std::string uniqueSuffix();

// Writes `text` to `path` through a unique temporary file and a rename, so a reader (or another
// runner writing the same summary) never sees a partial file. Throws std::runtime_error.
void writeAtomically(const std::filesystem::path& path, const std::string& text);

// The input hash of a case, from the scenario as the run will load it. A case that does not load
// gets no hash: it is always run (and its log says why it fails).
struct CaseHasher {
  const StudyOptions& o;
  std::string build;
  // The study (set by makePlan): its output mode is part of every case's hash, and its metrics
  // are stored into every result the runner keeps.
  const scenario::StudySpec* study = nullptr;
  std::string operator()(const scenario::StudyCase& c) const;
};

// Every run of the study (case x repeat) with its file names in `dir`.
std::vector<Job> listJobs(const scenario::StudySpec& st, const std::filesystem::path& dir,
                          std::map<std::string, std::string>& hashes);

// Runs the runs `todo` of `all`, `jobs` at a time, each under its lock (a run another runner
// holds is skipped), and gives each finished run its final, stamped name; a run that leaves no
// result records why (noResultPath). Progress lines start with `who` (e.g. "rank 2: ").
// Returns the number skipped.
std::size_t runJobs(const StudyOptions& o, const std::filesystem::path& dir,
                    const CaseHasher& hashOf, std::vector<Job>& all,
                    const std::vector<std::size_t>& todo, int jobs, const std::string& who = "");

// .locks/<id>_r<k>.noresult: the input hash of a run that left no result, then the runner's note
// ("" when its log says why).
// Runs single runs one after another through one pool, so the folder is listed for the
// leftovers of killed attempts once, not once per run (the MPI farm's ranks, given one run at a
// time).
class SerialRunner {
 public:
  SerialRunner(const StudyOptions& o, const std::filesystem::path& dir, const CaseHasher& hashOf,
               std::size_t total, const std::string& who);
  ~SerialRunner();
  SerialRunner(const SerialRunner&) = delete;
  SerialRunner& operator=(const SerialRunner&) = delete;
  void run(std::vector<Job>& all, std::size_t index);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

std::string noResultPath(const Job& j);

// What the folder says of the runs that another runner ran (shards, MPI ranks) or that nobody
// ran: a run with no result of its inputs whose lock is held is Skipped (being run); one whose
// .noresult holds its input hash is Ran with that note (as the runner that ran it knew it);
// any other stays Pending (missing). Runs that are done or whose outcome is known are unchanged.
void outcomesFromDisk(std::vector<Job>& all);

// Everything each way of running a study (local, shard, --summarize, every MPI rank) computes
// first, the same way: the output folder, the input hash of every case, every run and the runs
// not done at listing. Built in place (the jobs point into `hashes`): makePlan.
struct StudyPlan {
  explicit StudyPlan(const StudyOptions& o, std::string build) : hashOf{o, std::move(build)} {}
  std::filesystem::path dir;
  CaseHasher hashOf;
  std::map<std::string, std::string> hashes;
  std::vector<Job> all;
  std::vector<std::size_t> todo;
  int jobs = 1;  // runs at once on this runner
};

// (study/runner.cpp) Lists the runs of `st` in the folder o.out (created with its .locks). Throws
// InputError when the folder cannot be created.
void makePlan(const scenario::StudySpec& st, const StudyOptions& o, StudyPlan& plan);

// (study/runner.cpp) Writes the summaries of `plan` (under the folder's summary lock) and draws the
// figures (plotArgs; none when empty); returns the study's exit code (study/runner.hpp). `skipped`:
// how many runs this runner found held by another runner.
int summarizeStudy(const scenario::StudySpec& st, const StudyOptions& o, StudyPlan& plan,
                   const std::vector<std::string>& plotArgs, std::size_t skipped);

}  // namespace rb::study::detail
