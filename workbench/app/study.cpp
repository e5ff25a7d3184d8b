#include "workbench/app/study.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <thread>

#include "workbench/core/strings.hpp"
#include "workbench/io/read_stats.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/scenario/study.hpp"

namespace fs = std::filesystem;

namespace rb::app {
namespace {

struct Job {
  const scenario::StudyCase* c = nullptr;
  int repeat = 0;
  std::string h5, log;
};

// Starts `workbench run` for one job with stdout/stderr to its log; returns the pid.
pid_t launch(const StudyOptions& o, const scenario::StudySpec& st, const Job& j) {
  std::vector<std::string> args = {o.program, "--root", o.root, "run",
                                   st.base,   "--out",  j.h5,   "--quiet"};
  for (const auto& ov : j.c->overrides) {
    args.push_back("--set");
    args.push_back(ov);
  }
  pid_t pid = fork();
  if (pid == 0) {
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

}  // namespace

int runStudy(const StudyOptions& o) {
  scenario::StudySpec st = scenario::loadStudy(o.file, o.root);
  fs::path dir = o.out.empty() ? fs::path("out") / fs::path(o.file).stem() : fs::path(o.out);
  fs::create_directories(dir);
  int jobs = o.jobs > 0    ? o.jobs
             : st.jobs > 0 ? st.jobs
                           : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

  std::vector<Job> all, todo;
  for (const auto& c : st.cases)
    for (int r = 0; r < st.repeats; ++r) {
      Job j{&c, r, (dir / (c.id + "_r" + std::to_string(r) + ".h5")).string(),
            (dir / (c.id + "_r" + std::to_string(r) + ".log")).string()};
      all.push_back(j);
      // A result file exists only once its run finished (written as .tmp, renamed at the end),
      // ok or failed: such cases are not run again.
      if (!fs::exists(j.h5)) todo.push_back(j);
    }
  std::cerr << st.file << ": " << st.cases.size() << " cases x " << st.repeats << " repeats, "
            << all.size() - todo.size() << " already done, running " << todo.size() << " with "
            << jobs << " jobs\n";

  std::map<pid_t, std::size_t> running;
  std::map<std::string, int> exitCode;
  std::size_t next = 0, done = 0;
  while (next < todo.size() || !running.empty()) {
    while (next < todo.size() && static_cast<int>(running.size()) < jobs) {
      pid_t pid = launch(o, st, todo[next]);
      if (pid < 0) {
        std::cerr << "cannot start a process for " << todo[next].c->id << "\n";
        exitCode[todo[next].h5] = -1;
      } else {
        running[pid] = next;
      }
      ++next;
    }
    int status = 0;
    pid_t pid = wait(&status);
    if (pid < 0) break;
    auto it = running.find(pid);
    if (it == running.end()) continue;
    const Job& j = todo[it->second];
    int code = WIFEXITED(status) ? WEXITSTATUS(status)
                                 : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    exitCode[j.h5] = code;
    running.erase(it);
    ++done;
    std::cerr << "  [" << done << "/" << todo.size() << "] " << j.c->id << " r" << j.repeat << ": "
              << (code == 0   ? "ok"
                  : code == 2 ? "failed (result kept)"
                              : "error " + std::to_string(code))
              << "  " << join(j.c->overrides, " ") << "\n";
  }

  // Summary: one row per run, then per case the median CPU time over the repeats.
  std::ofstream csv(dir / "summary.csv");
  const std::vector<std::string> nums = {"cpu_time_s",     "wall_time_s",     "rhs_evals",
                                         "rhs_evals_jac",  "steps",           "rejected_steps",
                                         "jacobian_evals", "nonlinear_iters", "t_reached"};
  csv << "case,repeat,overrides,status";
  for (const auto& k : nums) csv << "," << k;
  csv << ",message,file\n";
  std::map<std::string, std::vector<double>> cpu;
  std::vector<double> colStatus;
  std::map<std::string, std::vector<double>> cols;
  for (const auto& j : all) {
    auto rec = fs::exists(j.h5) ? io::readStats(j.h5) : std::nullopt;
    std::string status = rec ? rec->text["status"] : "error";
    std::string message = rec ? rec->text["message"] : "";
    if (!rec) {
      // No result file: the run stopped on bad input or crashed; its log says why.
      std::ifstream log(j.log);
      std::string line, last;
      while (std::getline(log, line))
        if (!line.empty()) last += (last.empty() ? "" : " | ") + line;
      message = last.substr(0, 500);
    }
    csv << j.c->id << "," << j.repeat << "," << csvField(join(j.c->overrides, " ")) << ","
        << status;
    for (const auto& k : nums) {
      double v = rec && rec->number.count(k) ? rec->number[k] : 0.0;
      csv << "," << v;
      cols[k].push_back(v);
    }
    csv << "," << csvField(message) << "," << csvField(j.h5) << "\n";
    colStatus.push_back(status == "ok" ? 1.0 : 0.0);
    if (status == "ok" && rec) cpu[j.c->id].push_back(rec->number["cpu_time_s"]);
  }
  std::ofstream cases(dir / "summary_cases.csv");
  cases << "case,overrides,runs_ok,median_cpu_time_s\n";
  for (const auto& c : st.cases)
    cases << c.id << "," << csvField(join(c.overrides, " ")) << "," << cpu[c.id].size() << ","
          << median(cpu[c.id]) << "\n";

  io::ResultFile h5((dir / "summary.h5").string());
  h5.attr("/", "study_file", st.file);
  h5.attr("/", "base", st.base);
  std::string caseIds, overrides;
  for (const auto& j : all) {
    caseIds += (caseIds.empty() ? "" : "\n") + j.c->id + "_r" + std::to_string(j.repeat);
    overrides += (overrides.empty() ? "" : "\n") + join(j.c->overrides, " ");
  }
  h5.attr("/runs", "ids", caseIds);
  h5.attr("/runs", "overrides", overrides);
  h5.dataset("/runs/ok", colStatus, "-");
  for (const auto& k : nums)
    h5.dataset("/runs/" + k, cols[k],
               k == "cpu_time_s" || k == "wall_time_s" || k == "t_reached" ? "s" : "-");
  h5.finalize();
  std::cout << "study " << st.file << ": " << all.size() << " runs, summary in "
            << (dir / "summary.csv").string() << "\n";
  return 0;
}

}  // namespace rb::app
