#include "workbench/study/runner.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string_view>
#include <thread>
#include <tuple>

#include "railbench/version.hpp"
#include "workbench/contact/table_io.hpp"
#include "workbench/core/error.hpp"
#include "workbench/core/files.hpp"
#include "workbench/io/read_stats.hpp"
#include "workbench/run/vehicle_run.hpp"
#include "workbench/study/jobs.hpp"
#include "workbench/study/option_checks.hpp"
#include "workbench/study/summary.hpp"
#include "workbench/track/spec.hpp"
#ifdef RB_HAVE_MPI
#include "workbench/study/mpi.hpp"
#endif

namespace fs = std::filesystem;

namespace rb::study {
using namespace detail;
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
  std::error_code ec;
  if (!fs::exists(python, ec) || !fs::exists(plots / "railbench" / "__main__.py", ec)) return -1;
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

namespace {

// A data file by content (its path may differ between machines with the same inputs).
void hashDataFile(Hasher& h, const std::string& role, const std::string& path) {
  std::string why;
  auto bytes = readRegularFile(path, why);
  h.field("data " + role, bytes ? *bytes : "unreadable: " + why);
}

// Every profile file one vehicle runs on, once (`hashed` holds the paths already in the key): its
// wheels and rails, each wheel side's own, the rails along the track and the wheelsets' own
// wheels (a file edited between two runs of a study is a new case).
void hashProfileFiles(Hasher& h, std::set<std::string>& hashed, const std::string& prefix,
                      const dynamics::ProfilesSpec& p) {
  auto once = [&](const std::string& role, const std::string& path, const char* builtin) {
    if (!path.empty() && path != builtin && hashed.insert(path).second)
      hashDataFile(h, prefix + role, path);
  };
  once("wheel", p.wheel, "s1002");
  once("rail", p.rail, "60e1");
  once("wheel_left", p.wheel_left, "s1002");
  once("wheel_right", p.wheel_right, "s1002");
  // CONTACT slices-files (their slice positions; the slice files are hashed below).
  for (const dynamics::SliceListSpec& l : p.slice_lists) once("slice_list", l.path, "");
  for (const dynamics::WheelsetProfilesSpec& w : p.wheelsets)
    for (const std::string* path : {&w.wheel, &w.wheel_left, &w.wheel_right})
      once("wheelset_wheel", *path, "s1002");
  // Rails along the track: every slice file of the running rails and of the further rails.
  auto slices = [&](const std::vector<dynamics::RailSliceSpec>& list) {
    for (const dynamics::RailSliceSpec& sl : list) once("rail_slice", sl.rail, "60e1");
  };
  for (std::size_t side = 0; side < 2; ++side) {
    slices(p.rail_slices[side]);
    for (const dynamics::ExtraRailSpec& r : p.extra_rails[side]) slices(r.slices);
  }
}

}  // namespace

std::string caseInputHash(const scenario::ScenarioSpec& spec, const std::string& build_id,
                          const std::string& output) {
  Hasher h;
  h.field("railbench case inputs", "1");
  h.field("workbench", kVersion);
  h.field("table_algorithm", std::to_string(contact::kTableAlgorithmVersion));
  h.field("build", build_id);
  if (output != "full") h.field("output", output);
  h.field("scenario", spec.text);
  for (const auto& [path, text] : spec.modules) h.field("module " + path, text);
  for (const auto& ov : spec.overrides) h.field("set", ov);
  // The leading vehicle's profiles (the scenario's), then those of the train's other vehicles.
  std::set<std::string> hashed;
  hashProfileFiles(h, hashed, "", spec.profiles);
  for (std::size_t k = 1; k < spec.train.size(); ++k)
    if (spec.train[k].has_profiles)
      hashProfileFiles(h, hashed, "train[" + std::to_string(k + 1) + "] ", spec.train[k].profiles);
  if (spec.track.irregularities.source == track::IrregularitySource::Csv)
    hashDataFile(h, "irregularities", spec.track.irregularities.csv_path);
  return hex16(h.value());
}

int runStudy(const StudyOptions& o) {
  // A typed --jobs is checked before the study file is read: 0 or a negative number is no default
  // (it was read as "the study's jobs, else the cores"), and more runs than the cores can take
  // only queue and multiply the memory in flight.
  Diagnostics d;
  if (o.jobs_given) checkJobs(d, o.jobs, false);
  if (!(std::isfinite(o.run_timeout_s) && o.run_timeout_s >= 0.0))
    badOption(d, "--run-timeout", o.run_timeout_s, "must be a finite time >= 0 s (0: no limit)");
  d.throwIfAny();
  const scenario::StudySpec st = scenario::loadStudy(o.file, o.root);
  StudyOptions so = o;
  if (so.out.empty()) so.out = (fs::path("out") / fs::path(o.file).stem()).string();
  return runStudySpec(st, so, {"study", so.out});
}

Shard parseShard(const std::string& text, const std::string& file) {
  Shard sh;
  const auto slash = text.find('/');
  auto number = [&](std::string_view part, int& v) {
    const char* end = part.data() + part.size();
    auto [ptr, ec] = std::from_chars(part.data(), end, v);
    return !part.empty() && ec == std::errc() && ptr == end;
  };
  const std::string_view all(text);
  if (slash == std::string::npos || !number(all.substr(0, slash), sh.k) ||
      !number(all.substr(slash + 1), sh.n) || sh.n < 1 || sh.k < 1 || sh.k > sh.n)
    throw InputError({file, 0}, "--shard " + text +
                                    ": expected K/N with integers 1 <= K <= N (e.g. --shard 2/8)");
  return sh;
}

namespace detail {

void makePlan(const scenario::StudySpec& st, const StudyOptions& o, StudyPlan& plan) {
  plan.dir = o.out;
  std::error_code ec;
  fs::create_directories(plan.dir / ".locks", ec);
  if (ec)
    throw InputError({o.file, 0}, "cannot create the study's output folder " +
                                      (plan.dir / ".locks").string() + ": " + ec.message());
  plan.jobs = o.jobs > 0    ? o.jobs
              : st.jobs > 0 ? st.jobs
                            : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  plan.hashOf.study = &st;
  for (const auto& c : st.cases) plan.hashes[c.id] = plan.hashOf(c);
  plan.all = listJobs(st, plan.dir, plan.hashes);
  for (std::size_t i = 0; i < plan.all.size(); ++i)
    if (!isDone(plan.all[i].h5, *plan.all[i].hash)) plan.todo.push_back(i);
}

int summarizeStudy(const scenario::StudySpec& st, const StudyOptions& o, StudyPlan& plan,
                   const std::vector<std::string>& plotArgs, std::size_t skipped) {
  const fs::path& dir = plan.dir;
  // Summaries of everything this folder holds for the study, written under a study-wide lock so
  // that runners finishing together do not interleave them.
  int summaryLock = ::open((dir / ".locks" / "summary.lock").c_str(),
                           O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (summaryLock >= 0) ::flock(summaryLock, LOCK_EX);
  SummaryCounts sm;
  try {
    sm = writeSummaries(st, plan.all, dir);
  } catch (const std::exception& e) {
    if (summaryLock >= 0) ::close(summaryLock);
    std::cerr << "study: cannot write the summary in " << dir.string() << ": " << e.what() << "\n";
    return 2;
  }
  if (summaryLock >= 0) ::close(summaryLock);
  std::cout << "study " << st.file << ": " << plan.all.size() << " runs, summary in "
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

}  // namespace detail

namespace {

// The command that summarises a folder, as the user would type it.
std::string summarizeCommand(const StudyOptions& o) {
  return "workbench study " + o.file + " --out " + o.out + " --summarize";
}

// --summarize: the summaries and figures of what is on disk; nothing is run.
int summarizeOnly(const scenario::StudySpec& st, const StudyOptions& o, StudyPlan& plan,
                  const std::vector<std::string>& plotArgs) {
  outcomesFromDisk(plan.all);
  std::size_t missing = 0, busy = 0;
  for (const Job& j : plan.all) {
    missing += j.outcome == Outcome::Pending && !isDone(j.h5, *j.hash) ? 1 : 0;
    busy += j.outcome == Outcome::Skipped ? 1 : 0;
  }
  std::cerr << st.file << ": summarising " << plan.all.size() << " runs in " << o.out << ": "
            << plan.all.size() - plan.todo.size() << " done, " << missing << " missing, " << busy
            << " being run\n";
  if (missing > 0)
    std::cerr << "study: " << missing
              << " runs have no result of the current inputs (status \"missing\"); run the "
                 "study, its shards or the MPI farm again to complete them\n";
  return summarizeStudy(st, o, plan, plotArgs, 0);
}

// --shard K/N: the runs i with i mod N == K - 1, through the local pool; no summary.
int runShard(const scenario::StudySpec& st, const StudyOptions& o, StudyPlan& plan) {
  const Shard sh = parseShard(o.shard, o.file);
  auto ofShard = [&](std::size_t i) {
    return static_cast<int>(i % static_cast<std::size_t>(sh.n)) == sh.k - 1;
  };
  std::vector<std::size_t> mine, todo;
  for (std::size_t i = 0; i < plan.all.size(); ++i)
    if (ofShard(i)) mine.push_back(i);
  for (std::size_t i : plan.todo)  // not done at planning
    if (ofShard(i)) todo.push_back(i);
  std::cerr << st.file << ": shard " << o.shard << ": " << mine.size() << " of " << plan.all.size()
            << " runs, " << mine.size() - todo.size() << " already done, running " << todo.size()
            << " with " << plan.jobs << " jobs\n";
  const std::size_t skipped = runJobs(o, plan.dir, plan.hashOf, plan.all, todo, plan.jobs);
  std::size_t known = 0, ok = 0;
  for (std::size_t i : mine) {
    const Job& j = plan.all[i];
    const bool done = isDone(j.h5, *j.hash);
    if (!done && j.outcome != Outcome::Ran) continue;
    ++known;
    const auto rec = done ? io::readStats(j.h5) : std::nullopt;
    if (rec && rec->text.count("status") && rec->text.at("status") == "ok") ++ok;
  }
  std::cout << "study " << st.file << ": shard " << o.shard << " ran " << todo.size() - skipped
            << " runs (" << mine.size() - todo.size() << " were done, " << skipped
            << " being run by another runner), " << ok << " of its " << mine.size()
            << " runs ok; no summary written. Once every shard has finished:\n  "
            << summarizeCommand(o) << "\n";
  if (known > 0 && ok == 0) {
    std::cerr << "study: no run of shard " << o.shard << " is ok (" << known
              << " failed or could not run)\n";
    return 2;
  }
  return 0;
}

// "case 'a'", "cases 'a', 'b' and 'c'", "cases 'a', 'b', 'c' and 7 more", "every case".
std::string casesText(const std::vector<std::string>& labels, std::size_t total) {
  if (labels.size() == total && total > 1) return "every case";
  if (labels.size() == 1) return "case '" + labels.front() + "'";
  constexpr std::size_t kShown = 3;
  std::string out = "cases ";
  for (std::size_t i = 0; i < labels.size() && i < kShown; ++i)
    out += (i == 0 ? "'" : i + 1 == labels.size() ? " and '" : ", '") + labels[i] + "'";
  if (labels.size() > kShown) out += " and " + std::to_string(labels.size() - kShown) + " more";
  return out;
}

// One problem of the cases, with the cases that have it.
struct CaseProblem {
  SourceLoc loc;
  std::string message;
  std::vector<std::string> cases;
};

// Every case's scenario, loaded with its overrides before any run starts, and every signal a
// metric reads checked against it: a bad matrix value or case entry (a negative mass, "heavy"
// for a number, a key that names nothing) would otherwise fail each of its runs, or show only
// when the summary is written. All problems are reported at once: a problem of an override at
// the line of the study file where the value is written, any other problem of a case (its base
// scenario's, or one that only the combination of overrides makes) at the line of the case's
// entry, naming the scenario's own file:line. A study whose cases do not load runs nothing.
// What needs a built model (contact tables, the start equilibrium, the step limit) is checked
// by each run.
void checkCases(const scenario::StudySpec& st, const StudyOptions& o) {
  std::vector<CaseProblem> problems;
  std::map<std::string, std::size_t> index;  // loc + message -> position in problems
  auto add = [&](const SourceLoc& loc, const std::string& message, const std::string& label) {
    const std::string key = loc.str() + "\n" + message;
    auto [it, fresh] = index.emplace(key, problems.size());
    if (fresh) problems.push_back({loc, message, {}});
    auto& cases = problems[it->second].cases;
    if (cases.empty() || cases.back() != label) cases.push_back(label);
  };
  std::set<std::string> loaded;  // base + overrides already checked
  for (const auto& c : st.cases) {
    std::string key = c.base;
    for (const auto& ov : c.overrides) key += "\n" + ov;
    if (!loaded.insert(key).second) continue;
    scenario::ScenarioSpec spec;
    try {
      scenario::LoadOptions lo;
      lo.root = o.root;
      lo.overrides = c.overrides;
      lo.override_locs = c.override_locs;
      spec = scenario::loadScenario(c.base, lo);
    } catch (const InputError& e) {
      for (const auto& dg : e.diagnostics())
        if (dg.loc.file == st.file && dg.loc.line > 0)
          add(dg.loc, dg.message, c.label);
        else
          add(c.loc, "in the scenario of the case: " + dg.str(), c.label);
      continue;
    }
    for (const auto& m : st.metrics) {
      std::vector<std::pair<std::string, std::string>> paths;
      if (!m.signal.empty()) paths.emplace_back("signal", m.signal);
      for (const auto& [name, path] : m.signals) paths.emplace_back("signals." + name, path);
      for (const auto& [what, path] : paths) {
        const std::string why = run::signalProblem(spec, path);
        if (!why.empty())
          add(m.loc,
              "study.metrics[" + std::to_string(m.index) + "] (" + m.name + "): " + what + " '" +
                  path + "': " + why,
              c.label);
      }
    }
  }
  Diagnostics d;
  for (const auto& p : problems)
    d.add(p.loc, p.message +
                     (st.cases.size() > 1 ? " (" + casesText(p.cases, st.cases.size()) + ")" : ""));
  d.throwIfAny();
}

}  // namespace

std::size_t checkStudy(const StudyOptions& o) {
  const scenario::StudySpec st = scenario::loadStudy(o.file, o.root);
  checkCases(st, o);
  return st.cases.size();
}

int runStudySpec(const scenario::StudySpec& st, const StudyOptions& o,
                 const std::vector<std::string>& plotArgs) {
  if (!o.shard.empty()) parseShard(o.shard, o.file);  // a bad shard runs nothing
  if (!o.summarize) checkCases(st, o);
  if (o.mpi) {
#ifdef RB_HAVE_MPI
    return runStudyMpi(st, o, plotArgs);
#else
    throw InputError({o.file, 0},
                     "--mpi: this workbench was built without MPI (install libopenmpi-dev and "
                     "openmpi-bin and configure with cmake -DRB_MPI=ON)");
#endif
  }
  StudyPlan plan(o, buildId(o.program));
  makePlan(st, o, plan);
  if (o.summarize) return summarizeOnly(st, o, plan, plotArgs);
  if (!o.shard.empty()) return runShard(st, o, plan);
  std::cerr << st.file << ": " << st.cases.size() << " cases x " << st.repeats << " repeats, "
            << plan.all.size() - plan.todo.size() << " already done, running " << plan.todo.size()
            << " with " << plan.jobs << " jobs\n";
  const std::size_t skipped = runJobs(o, plan.dir, plan.hashOf, plan.all, plan.todo, plan.jobs);
  return summarizeStudy(st, o, plan, plotArgs, skipped);
}

}  // namespace rb::study
