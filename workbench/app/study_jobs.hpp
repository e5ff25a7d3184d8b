#pragma once
// The runs of a study (app/study.hpp): listing them with their file names and input hashes, the
// per-run locks, and running them as `workbench run` processes. Shared by the local runner, the
// shards and the MPI task farm, so every way of running a study resumes and locks the same way.
#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "workbench/app/study.hpp"
#include "workbench/scenario/study.hpp"

namespace rb::app::study_detail {

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
  std::string operator()(const scenario::StudyCase& c) const;
};

// Every run of the study (case x repeat) with its file names in `dir`.
std::vector<Job> listJobs(const scenario::StudySpec& st, const std::filesystem::path& dir,
                          std::map<std::string, std::string>& hashes);

// Runs the runs `todo` of `all`, `jobs` at a time, each under its lock (a run another runner
// holds is skipped), and gives each finished run its final, stamped name. Returns the number
// skipped.
std::size_t runJobs(const StudyOptions& o, const std::filesystem::path& dir,
                    const CaseHasher& hashOf, std::vector<Job>& all,
                    const std::vector<std::size_t>& todo, int jobs);

}  // namespace rb::app::study_detail
