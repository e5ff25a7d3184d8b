#include "workbench/precision/precision.hpp"

#include <functional>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/io/read_stats.hpp"
#include "workbench/precision/answer.hpp"
#include "workbench/precision/plan.hpp"
#include "workbench/study/runner.hpp"

namespace fs = std::filesystem;

namespace rb::precision {
namespace {

using precision::Ladder;
using precision::Plan;

// Runs `cases` as one expanded study into `dir` (no figures); the study runner's exit code.
int runStage(const Plan& p, const PrecisionOptions& o, const fs::path& dir,
             const std::vector<scenario::StudyCase>& cases, int repeats) {
  scenario::StudySpec st;
  st.file = "precision " + fs::path(p.scenario).filename().string();
  st.base = p.scenario;
  st.cases = cases;
  st.repeats = repeats;
  st.loc = {o.scenario, 0};
  study::StudyOptions so = commandStudyOptions(o, "precision");
  so.out = dir.string();
  return study::runStudySpec(st, so, {});
}

// Median CPU time [s] of the repeats of a case (of the part it ran, for a failed run); 0 when no
// repeat left a result.
double medianCpu(const fs::path& dir, const std::string& id, int repeats) {
  std::vector<double> cpu;
  for (int r = 0; r < repeats; ++r) {
    const auto rec = io::readStats((dir / (id + "_r" + std::to_string(r) + ".h5")).string());
    if (rec && rec->number.count("cpu_time_s")) cpu.push_back(rec->number.at("cpu_time_s"));
  }
  if (cpu.empty()) return 0.0;
  std::sort(cpu.begin(), cpu.end());
  const std::size_t n = cpu.size();
  return n % 2 ? cpu[n / 2] : 0.5 * (cpu[n / 2 - 1] + cpu[n / 2]);
}

// The budget rule's estimate of the CPU time of a ladder's next rung [s] (one repeat), < 0 when
// nothing is known yet. Fixed steps: the cost is proportional to the number of steps, 1 / h.
// Tolerances: the growth of the last two rungs (between 1 and 10), else 2 per rung.
double estimateNext(const Ladder& l) {
  const std::size_t k = l.next;
  if (k == 0 || l.rungs[k - 1].cpu <= 0.0) return -1.0;
  const double prev = l.rungs[k - 1].cpu;
  if (l.fixed) return prev * l.rungs[k - 1].value / l.rungs[k].value;
  double growth = 2.0;
  if (k >= 2 && l.rungs[k - 2].cpu > 0.0) growth = std::clamp(prev / l.rungs[k - 2].cpu, 1.0, 10.0);
  return prev * growth;
}

struct Candidate {
  Ladder* ladder;
  double estimate;  // CPU time of all repeats [s], < 0 unknown
};

// The rungs of the next stage: the next rung of every ladder, cheapest estimate first, as long
// as the estimated wall time (CPU time of the stage / jobs) fits in what is left of the budget.
// A ladder whose next rung does not fit is closed: its later rungs cost more.
std::vector<Ladder*> nextStage(Plan& p, const PrecisionOptions& o, double left, int jobs) {
  std::vector<Candidate> cand;
  for (auto& l : p.ladders)
    if (l.next < l.rungs.size()) {
      const double e = estimateNext(l);
      cand.push_back({&l, e < 0.0 ? -1.0 : e * o.repeats});
    }
  std::stable_sort(cand.begin(), cand.end(),
                   [](const Candidate& a, const Candidate& b) { return a.estimate < b.estimate; });
  std::vector<Ladder*> stage;
  double sum = 0.0;
  for (const auto& c : cand) {
    const bool fits = o.budget <= 0.0 || c.estimate < 0.0 || (sum + c.estimate) / jobs <= left;
    if (fits) {
      sum += std::max(c.estimate, 0.0);
      stage.push_back(c.ladder);
      continue;
    }
    std::ostringstream why;
    why.precision(3);
    why << "skipped (--budget): estimated " << c.estimate << " s CPU, " << std::max(left, 0.0)
        << " s of the budget left";
    for (std::size_t k = c.ladder->next; k < c.ladder->rungs.size(); ++k) {
      c.ladder->rungs[k].status = "skipped";
      c.ladder->rungs[k].note = why.str();
    }
    c.ladder->next = c.ladder->rungs.size();
  }
  return stage;
}

// Runs the ladders stage by stage (rung k of every ladder together) under the budget; the exit
// code of the last summary over every run case.
int runLadders(Plan& p, const PrecisionOptions& o, const fs::path& dir,
               std::chrono::steady_clock::time_point start) {
  const int jobs =
      o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (;;) {
    const double used =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<Ladder*> stage = nextStage(p, o, o.budget - used, jobs);
    if (stage.empty()) break;
    std::vector<scenario::StudyCase> cases;
    for (auto* l : stage) cases.push_back(l->rungs[l->next].c);
    runStage(p, o, dir, cases, o.repeats);
    for (auto* l : stage) {
      auto& r = l->rungs[l->next++];
      r.status = "run";
      r.cpu = medianCpu(dir, r.c.id, o.repeats);
    }
  }
  std::vector<scenario::StudyCase> all;
  for (const auto& l : p.ladders)
    for (const auto& r : l.rungs)
      if (r.status == "run") all.push_back(r.c);
  // Every case is done: this only writes the summaries over all of them.
  return all.empty() ? 2 : runStage(p, o, dir, all, o.repeats);
}

void printPlan(const Plan& p, const PrecisionOptions& o) {
  std::cout << "precision " << o.scenario << ": " << p.models.size() << " models, "
            << p.references.size() << " reference runs, " << p.ladders.size() << " ladders";
  std::size_t n = 0;
  for (const auto& l : p.ladders) n += l.rungs.size();
  std::cout << " (" << n << " settings x " << o.repeats << " repeats)\n";
  for (const auto& l : p.ladders)
    std::cout << "  " << l.model << " " << l.integrator << ": " << l.rungs.size() << " "
              << (l.fixed ? "steps" : "tolerances") << "\n";
  for (const auto& nt : p.notes)
    std::cout << "  note: " << nt.model << (nt.integrator.empty() ? "" : " " + nt.integrator)
              << ": " << nt.text << "\n";
  for (const auto& a : p.adaptations) std::cout << "  adapted: " << a << "\n";
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << text;
  if (!f) throw std::runtime_error("cannot write " + path.string());
}

std::vector<std::string> plotArgs(const Plan& p, const PrecisionOptions& o, const fs::path& out) {
  std::ostringstream levels, limit;
  levels.precision(12);
  limit.precision(12);
  for (std::size_t i = 0; i < p.levels.size(); ++i) levels << (i ? "," : "") << p.levels[i];
  limit << p.limit;
  std::vector<std::string> a = {"precision", out.string(), "--quantities", join(p.quantities, ","),
                                "--levels",  levels.str(), "--limit",      limit.str()};
  if (o.callgrind) {
    a.insert(a.end(), {"--callgrind", "--workbench", o.program, "--root", o.root});
  }
  return a;
}

}  // namespace

int runPrecision(const PrecisionOptions& given) {
  const auto start = std::chrono::steady_clock::now();
  PrecisionOptions o = given;
  if (o.quick && !o.given.contains("--repeats")) o.repeats = 1;
  Plan p = precision::makePlan(o);
  const fs::path out = commandStudyOptions(o, "precision").out;
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec)
    throw InputError({"<command line>", 0},
                     "--out: cannot create " + out.string() + ": " + ec.message());
  // One table cache for the reference and case folders (the same tables are built once).
  if (!std::getenv("RAILBENCH_TABLE_CACHE"))
    setenv("RAILBENCH_TABLE_CACHE", fs::absolute(out / ".table-cache").c_str(), 1);
  printPlan(p, o);

  std::vector<scenario::StudyCase> refs;
  for (const auto& r : p.references) refs.push_back(r.c);
  const int refCode = runStage(p, o, out / "reference", refs, 1);
  const int caseCode = runLadders(p, o, out / "cases", start);
  writeText(out / "precision_plan.csv", precision::planCsv(p));
  // The answer is the engine's: computed, written and printed here whether or not figures follow.
  const precision::Answer answer = precision::computeAnswer(p, out.string(), o.repeats);
  writeText(out / "precision_recommendation.csv", precision::recommendationCsv(answer));
  writeText(out / "precision.csv", precision::casesCsv(answer));
  writeText(out / "precision_references.csv", precision::referencesCsv(answer));
  precision::writeAnswerH5(answer, (out / "precision.h5").string());
  precision::printAnswer(answer, std::cout);
  for (const auto& r : answer.references)
    if (!r.verified)
      std::cerr << "precision: WARNING: the reference of " << r.model << " is UNVERIFIED: " << r.why
                << "; its errors are not trustworthy below that difference\n";

  study::StudyOptions so;
  so.root = o.root;
  const int plots = study::runPlots(so, plotArgs(p, o, out));
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "precision: results in " << out.string() << " (" << formatNumber(wall, 3)
            << " s wall time)\n";
  if (refCode == 2 && caseCode == 2) {
    std::cerr << "precision: no run is ok\n";
    return 2;
  }
  return plots;
}

}  // namespace rb::precision
