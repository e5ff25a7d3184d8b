#pragma once
// `mpirun -np N workbench study STUDY.lua --mpi` (or `srun ... --mpi`): the runs of a study as an
// MPI task farm. Every rank loads the study and lists the same runs (study/jobs.hpp); rank 0
// hands them out one at a time to the ranks that ask, in the order of the study, so a rank that
// drew a cheap case asks again at once (case costs differ by two orders of magnitude: a static
// split would leave ranks idle behind the dearest shard). Each rank runs its run through the
// local pool's code: the run's lock (a run held by another runner is skipped), a child
// `workbench run`, the stamp and the rename, so the farm resumes, and shares a folder with local
// runners and shards, as they do.
//
// Rank 0 runs runs too, from a thread of its own, while its main thread answers the other ranks
// (every MPI call is on the main thread): with -np 1 it runs the whole study, and on a cluster it
// does not leave one core per farm idle. Answering costs rank 0 a message per run and a 2 ms
// poll (MPI_Iprobe, then sleep) instead of a busy MPI_Recv, which would take a core from the
// runs. RAILBENCH_MPI_RANK0_RUNS=0 makes rank 0 a pure dispatcher (with more than one rank).
//
// Once every run is done rank 0 leaves MPI and writes the summaries and figures exactly as a
// local run (study/runner.hpp); the other ranks return 0. Every rank dies with its launcher
// (PR_SET_PDEATHSIG), and every run with its rank, so killing mpirun leaves no run behind; a
// relaunch runs only what was not finished.
#include <string>
#include <vector>

#include "workbench/study/runner.hpp"

namespace rb::study {

// Runs the study `st` as one rank of the farm; returns as runStudy on rank 0, 0 on the others.
int runStudyMpi(const scenario::StudySpec& st, const StudyOptions& o,
                const std::vector<std::string>& plotArgs);

}  // namespace rb::study
