#include "workbench/app/study.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
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
pid_t launch(const StudyOptions& o, const Job& j) {
  std::vector<std::string> args = {o.program, "--root", o.root, "run",
                                   j.c->base, "--out",  j.h5,   "--quiet"};
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

// Figures and tables of the study (plots/plot_study.py, Debian's python3 as in ./wb run): 0 when
// drawn or switched off (RAILBENCH_STUDY_PLOTS=0) or when python3 / the script is missing (a
// note), 4 when the script failed (the study's results are complete all the same).
int plotStudy(const StudyOptions& o, const std::string& dir) {
  if (const char* e = std::getenv("RAILBENCH_STUDY_PLOTS"); e && std::string(e) == "0") return 0;
  const char* env = std::getenv("RAILBENCH_PYTHON");
  std::string python = env && *env ? env : "/usr/bin/python3";
  fs::path script = fs::path(o.root) / "plots" / "plot_study.py";
  if (!fs::exists(python) || !fs::exists(script)) {
    std::cerr << "study: note: no figures (" << (fs::exists(python) ? script.string() : python)
              << " not found)\n";
    return 0;
  }
  std::cout.flush();
  pid_t pid = fork();
  if (pid == 0) {
    std::vector<std::string> args = {python, script.string(), dir};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(python.c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  if (pid < 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::cerr << "study: the figures failed: " << python << " " << script.string() << " " << dir
              << "\n";
    return 4;
  }
  return 0;
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
      pid_t pid = launch(o, todo[next]);
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
              << "  " << j.c->label << "\n";
  }

  // Summary: one row per run, then per case the median CPU time over the repeats.
  std::ofstream csv(dir / "summary.csv");
  csv.precision(12);  // counts above 1e6 exactly, CPU times to the nanosecond
  const std::vector<std::string> nums = {
      "cpu_time_s",     "wall_time_s",    "rhs_evals",       "rhs_evals_jac", "steps",
      "rejected_steps", "jacobian_evals", "nonlinear_iters", "t_reached",     "model_evaluations"};
  csv << "case,repeat,label,role,base,overrides,status";
  for (const auto& k : nums) csv << "," << k;
  csv << ",message,file\n";
  struct CaseSum {
    std::vector<double> cpu;
    int runs = 0;
    std::string status, message, file;
    std::map<std::string, double> first;  // counts of the first run (exact, equal over repeats)
  };
  std::map<std::string, CaseSum> sum;
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
    csv << j.c->id << "," << j.repeat << "," << csvField(j.c->label) << "," << j.c->role << ","
        << csvField(j.c->base) << "," << csvField(join(j.c->overrides, " ")) << "," << status;
    for (const auto& k : nums) {
      double v = rec && rec->number.count(k) ? rec->number[k] : 0.0;
      csv << "," << v;
      cols[k].push_back(v);
    }
    csv << "," << csvField(message) << "," << csvField(j.h5) << "\n";
    colStatus.push_back(status == "ok" ? 1.0 : 0.0);
    CaseSum& cs = sum[j.c->id];
    ++cs.runs;
    if (status == "ok" && rec) cs.cpu.push_back(rec->number["cpu_time_s"]);
    // The case's status: ok only when every repeat is ok; else the first problem and its reason.
    if (cs.status.empty() || (cs.status == "ok" && status != "ok")) {
      cs.status = status;
      cs.message = message;
      cs.file = fs::exists(j.h5) ? j.h5 : "";
      for (const auto& k : nums) cs.first[k] = rec && rec->number.count(k) ? rec->number[k] : 0.0;
    }
  }
  std::ofstream cases(dir / "summary_cases.csv");
  cases.precision(12);
  cases << "case,label,role,base,overrides,runs,runs_ok,status,median_cpu_time_s,min_cpu_time_s,"
           "max_cpu_time_s";
  for (const auto& k : nums)
    if (k != "cpu_time_s" && k != "wall_time_s") cases << "," << k;
  cases << ",message,file\n";
  for (const auto& c : st.cases) {
    CaseSum& cs = sum[c.id];
    auto [lo, hi] =
        cs.cpu.empty() ? std::pair<double, double>{0.0, 0.0}
                       : std::pair<double, double>{*std::min_element(cs.cpu.begin(), cs.cpu.end()),
                                                   *std::max_element(cs.cpu.begin(), cs.cpu.end())};
    cases << c.id << "," << csvField(c.label) << "," << c.role << "," << csvField(c.base) << ","
          << csvField(join(c.overrides, " ")) << "," << cs.runs << "," << cs.cpu.size() << ","
          << cs.status << "," << median(cs.cpu) << "," << lo << "," << hi;
    for (const auto& k : nums)
      if (k != "cpu_time_s" && k != "wall_time_s") cases << "," << cs.first[k];
    cases << "," << csvField(cs.message) << "," << csvField(cs.file) << "\n";
  }
  csv.close();
  cases.close();

  io::ResultFile h5((dir / "summary.h5").string());
  h5.attr("/", "study_file", st.file);
  h5.attr("/", "base", st.base);
  std::string caseIds, overrides;
  for (const auto& j : all) {
    caseIds += (caseIds.empty() ? "" : "\n") + j.c->id + "_r" + std::to_string(j.repeat);
    overrides += (overrides.empty() ? "" : "\n") + join(j.c->overrides, " ");
  }
  std::string labels;
  for (const auto& j : all) labels += (labels.empty() ? "" : "\n") + j.c->label;
  h5.attr("/runs", "labels", labels);
  h5.attr("/runs", "ids", caseIds);
  h5.attr("/runs", "overrides", overrides);
  h5.dataset("/runs/ok", colStatus, "-");
  for (const auto& k : nums)
    h5.dataset("/runs/" + k, cols[k],
               k == "cpu_time_s" || k == "wall_time_s" || k == "t_reached" ? "s" : "-");
  h5.finalize();
  std::cout << "study " << st.file << ": " << all.size() << " runs, summary in "
            << (dir / "summary.csv").string() << "\n";
  return plotStudy(o, dir.string());
}

}  // namespace rb::app
