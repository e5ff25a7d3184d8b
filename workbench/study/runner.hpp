#pragma once
// `workbench study FILE.lua`: runs every case of a study as its own `workbench run` process (so a
// crash or failure of one case never aborts the study), at most `jobs` at once, each writing its
// own HDF5; a summary CSV and HDF5 collect /stats of every run.
//
// Reuse is keyed on content. Every result file carries the root attribute `input_hash`: a 64-bit
// hash of everything that determines the case's result (caseInputHash: the base scenario's text
// and every module it requires, the overrides, the bytes of every profile and irregularity CSV it
// reads, the workbench version, the table-algorithm version and the build, i.e. the bytes of the
// workbench program). A case counts as done only when its file <id>_r<k>.h5 is a readable result
// with /stats/status and an `input_hash` equal to the one computed now; anything else is run again,
// so editing one number of the base scenario re-runs every case and changing nothing re-runs none.
//
// Several runners may share one output folder: each case is run under an exclusive lock
// (flock on .locks/<id>_r<k>.lock, released by the kernel when its holder dies); a runner that
// finds a case locked skips it and says so. A case's run writes <id>_r<k>.run-<unique>.h5; the
// runner stamps `input_hash` into it and renames it to <id>_r<k>.h5, so the final name only ever
// holds a complete, stamped file (a runner or run killed at any point leaves at most a stray
// .run-* file, removed the next time the case is run). Runs die with their runner.
//
// Three ways of running one study share those locks, the resume and the summaries, so any mix of
// them on one folder gives the summaries of a local run (cost columns aside):
//   local     (default)     a pool of `jobs` processes on this machine, then the summaries.
//   --shard K/N             only the K-th of N deterministic shards: run i of the expanded
//                           (case, repeat) list (0-based) belongs to shard (i mod N) + 1, so the
//                           shards of any N cover every run once; writes no summary.
//   --summarize             runs nothing: the summaries and figures of what is on disk; a run with
//                           no result of the current inputs has status "missing", one locked by
//                           a runner at work "skipped".
//   --mpi                   an MPI task farm (study/mpi.hpp): rank 0 hands out the runs one at
//                           a time to the ranks that ask, runs runs itself while idle and writes
//                           the summaries once every run is done.
// A run that left no result records why in .locks/<id>_r<k>.noresult (the input hash, then the
// runner's note), so that a summary written by another runner reports it as the local one does.
//
// Outputs:
//   summary.csv        one row per run: case, repeat, label, role, base, overrides, status, the
//                      /stats numbers, message (the reason of a failure), file
//   summary_cases.csv  one row per case: label, role, solver (the solver part of the label),
//                      status (ok only if every repeat is), median / min / max CPU time over
//                      the repeats, the counts of its first run, message, file
//   summary.h5         the per-run numbers as datasets under /runs
// Then `plots/rbplot study` (python3 -m railbench study) draws the study's figures and tables into
// the same folder (skipped with RAILBENCH_STUDY_PLOTS=0; RAILBENCH_PYTHON names another
// interpreter than /usr/bin/python3).
#include <string>
#include <vector>

#include "workbench/scenario/scenario.hpp"
#include "workbench/scenario/study.hpp"

namespace rb::study {

struct StudyOptions {
  std::string file;         // study file
  std::string out;          // output folder (default out/<study stem>)
  std::string root;         // project root
  std::string program;      // path of the workbench executable that runs the cases
  int jobs = 0;             // 0: from the study file, else the number of cores
  bool jobs_given = false;  // --jobs was typed: then it must be in 1..maxJobs()
  // Wall time after which a run is killed and reported as an error (a hang); 0 = no limit.
  double run_timeout_s = 0.0;
  std::string shard;       // "K/N": run only the K-th of N shards and write no summary
  bool summarize = false;  // run nothing: summaries and figures of what is on disk
  bool mpi = false;        // MPI task farm (study/mpi.hpp)
};

// A shard "K/N" (1 <= K <= N) of the runs of a study.
struct Shard {
  int k = 1, n = 1;
};

// Parses "K/N"; throws InputError naming `file` when it is not two integers with 1 <= K <= N.
Shard parseShard(const std::string& text, const std::string& file);

// Returns 0 when the study ran and at least one of its runs is ok (a failed case is a result),
// 1 on bad input (nothing was run; also a bad --shard, --mpi in a build without MPI), 2 when every
// run of the study failed or could not run, 4 when the figures failed (the summaries are
// complete). A shard returns 0 when it ran its runs (or they were done) and at least one of
// them is ok or it has none, 2 when every run of the shard with a result failed or could not run.
// --summarize returns 0 when at least one run on disk is ok, 2 when none is (all missing or
// failed), 4 when the figures failed. Under --mpi rank 0 returns as a local run, the other ranks
// 0 (1 on bad input, as every rank).
int runStudy(const StudyOptions& options);

// `workbench check STUDY.lua`: what `workbench study` checks before its first run (the study
// file, every case's scenario with its overrides, the metrics' signals), running nothing.
// Returns the number of cases; throws InputError with every problem.
std::size_t checkStudy(const StudyOptions& options);

// Runs the cases of an already expanded study `st` (a study file's, or one a command such as
// `workbench precision` made from a scenario) into the folder options.out (required), with the
// same content-addressed resume, locks and summaries as runStudy; then runs `python3 -m railbench
// <plotArgs...>` (nothing when plotArgs is empty). Returns as runStudy.
int runStudySpec(const scenario::StudySpec& st, const StudyOptions& options,
                 const std::vector<std::string>& plotArgs);

// Runs `python3 -m railbench <args...>` (plots/rbplot; Debian's python3 as in ./wb run,
// RAILBENCH_PYTHON names another interpreter) and returns its exit code: -1 when python3 or the
// package is missing, 128 when it did not exit normally.
int runRbplot(const StudyOptions& options, const std::vector<std::string>& args);

// Figures and tables of a study folder: `python3 -m railbench <plotArgs...>` (plots/rbplot) with
// Debian's python3 as in ./wb run (RAILBENCH_PYTHON names another interpreter). 0 when drawn or
// switched off (RAILBENCH_STUDY_PLOTS=0) or when python3 / the package is missing (a note), 4 when
// the command failed (the study's results are complete all the same).
int runPlots(const StudyOptions& options, const std::vector<std::string>& plotArgs);

// Identifies the build that runs the cases: "build:<hash of the program's bytes>", or
// "build:unknown" when the program cannot be read.
std::string buildId(const std::string& program);

// 16 hex digits: the hash of everything that determines the result of a run of `spec` (see the
// header comment) by the build `build_id`.
// `output` is what the case writes ("full" = a plain run's file, hashed as nothing, or "compact").
std::string caseInputHash(const scenario::ScenarioSpec& spec, const std::string& build_id,
                          const std::string& output = "full");

}  // namespace rb::study
