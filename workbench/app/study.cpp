#include "workbench/app/study.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <thread>

#include "railbench/version.hpp"
#include "workbench/app/study_jobs.hpp"
#include "workbench/app/study_summary.hpp"
#include "workbench/contact/table_io.hpp"
#include "workbench/core/error.hpp"
#include "workbench/core/files.hpp"
#include "workbench/track/spec.hpp"

namespace fs = std::filesystem;

namespace rb::app {
using namespace study_detail;
namespace {

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
  const std::size_t skipped = runJobs(o, dir, hashOf, all, todo, jobs);

  // Summaries of everything this folder holds for the study, written under a study-wide lock so
  // that runners finishing together do not interleave them.
  int summaryLock = ::open((dir / ".locks" / "summary.lock").c_str(),
                           O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (summaryLock >= 0) ::flock(summaryLock, LOCK_EX);
  SummaryCounts sm;
  try {
    sm = writeSummaries(st, all, dir);
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
