#include "workbench/study/mpi.hpp"

#include <mpi.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>

#include "workbench/study/jobs.hpp"

namespace rb::study {
using namespace detail;
namespace {

constexpr int kAsk = 1;  // a rank asks rank 0 for a run
constexpr int kRun = 2;  // rank 0 answers with the index of a run, or -1: nothing left

// The runs not done at listing, handed out in the order of the study to whoever asks first:
// the other ranks through rank 0's main thread, and rank 0's own runner thread.
class Dispenser {
 public:
  explicit Dispenser(const std::vector<std::size_t>& todo) : todo_(todo) {}
  long long take() {
    const std::lock_guard<std::mutex> guard(mutex_);
    return next_ < todo_.size() ? static_cast<long long>(todo_[next_++]) : -1;
  }

 private:
  const std::vector<std::size_t>& todo_;
  std::size_t next_ = 0;
  std::mutex mutex_;
};

// Rank 0's main thread: answers every ask until each of the other ranks has been told that
// nothing is left.
void dispatch(Dispenser& runs, int ranks) {
  int working = ranks - 1;
  while (working > 0) {
    int asked = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kAsk, MPI_COMM_WORLD, &asked, &status);
    if (!asked) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      continue;
    }
    long long ignored = 0;
    MPI_Recv(&ignored, 1, MPI_LONG_LONG, status.MPI_SOURCE, kAsk, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    long long index = runs.take();
    MPI_Send(&index, 1, MPI_LONG_LONG, status.MPI_SOURCE, kRun, MPI_COMM_WORLD);
    if (index < 0) --working;
  }
}

// A rank other than 0: asks for a run, runs it, asks again.
void work(const StudyOptions& o, StudyPlan& plan, const std::string& who) {
  SerialRunner runner(o, plan.dir, plan.hashOf, plan.todo.size(), who);
  for (;;) {
    long long ask = 0, index = -1;
    MPI_Send(&ask, 1, MPI_LONG_LONG, 0, kAsk, MPI_COMM_WORLD);
    MPI_Recv(&index, 1, MPI_LONG_LONG, 0, kRun, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (index < 0) return;
    runner.run(plan.all, static_cast<std::size_t>(index));
  }
}

// Whether rank 0 runs runs itself besides answering (see the header): from a second thread,
// which needs an MPI that allows threads (the thread itself makes no MPI call).
bool rankZeroRuns(int ranks, int provided) {
  const char* env = std::getenv("RAILBENCH_MPI_RANK0_RUNS");
  return ranks == 1 || (provided >= MPI_THREAD_FUNNELED && (!env || std::string(env) != "0"));
}

// A rank that cannot go on takes the whole farm down: the others would wait for it forever
// under a launcher that does not end a job when one rank exits (srun without
// --kill-on-bad-exit).
[[noreturn]] void abortFarm(int rank, const std::string& what) {
  std::cerr << "study: MPI rank " << rank << ": " << what << "\n";
  std::cerr.flush();
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::_Exit(1);  // MPI_Abort does not return
}

// Rank 0: the farm, then (out of MPI) the summaries.
int lead(const scenario::StudySpec& st, const StudyOptions& o, StudyPlan& plan,
         const std::vector<std::string>& plotArgs, int ranks, int provided) {
  const bool runs = rankZeroRuns(ranks, provided);
  std::cerr << st.file << ": " << st.cases.size() << " cases x " << st.repeats << " repeats, "
            << plan.all.size() - plan.todo.size() << " already done, running " << plan.todo.size()
            << " on " << ranks << " MPI ranks (rank 0 "
            << (runs ? "runs runs too" : "only hands them out") << ")\n";
  Dispenser runsLeft(plan.todo);
  std::thread own;
  if (runs)
    own = std::thread([&] {
      try {
        SerialRunner runner(o, plan.dir, plan.hashOf, plan.todo.size(), "rank 0:");
        for (long long i = runsLeft.take(); i >= 0; i = runsLeft.take())
          runner.run(plan.all, static_cast<std::size_t>(i));
      } catch (const std::exception& e) {
        abortFarm(0, e.what());
      }
    });
  dispatch(runsLeft, ranks);
  if (own.joinable()) own.join();
  MPI_Finalize();
  outcomesFromDisk(plan.all);  // the runs of the other ranks, as they left them
  return summarizeStudy(st, o, plan, plotArgs, 0);
}

}  // namespace

int runStudyMpi(const scenario::StudySpec& st, const StudyOptions& o,
                const std::vector<std::string>& plotArgs) {
  // A rank dies with the process that launched it (mpirun, orted, srun's step daemon), and its
  // runs with it (jobs.cpp), so a killed farm leaves no run writing into the folder.
  const pid_t launcher = getppid();
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != launcher) return 1;
  // The runs are children that exec at once; OpenMPI's warning about fork does not apply.
  ::setenv("OMPI_MCA_mpi_warn_on_fork", "0", 0);
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  StudyPlan plan(o, buildId(o.program));
  try {
    makePlan(st, o, plan);
  } catch (const std::exception& e) {
    abortFarm(rank, e.what());
  }
  // Rank 0 writes the summaries after MPI_Finalize: a problem there is reported as by a local run.
  if (rank == 0) return lead(st, o, plan, plotArgs, ranks, provided);
  try {
    work(o, plan, "rank " + std::to_string(rank) + ":");
  } catch (const std::exception& e) {
    abortFarm(rank, e.what());
  }
  MPI_Finalize();
  return 0;
}

}  // namespace rb::study
