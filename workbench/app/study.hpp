#pragma once
// `workbench study FILE.lua`: runs every case of a study as its own `workbench run` process (so a
// crash or failure of one case never aborts the study), at most `jobs` at once, each writing its
// own HDF5; finished cases are skipped when the study is run again; a summary CSV and HDF5
// collect /stats of every run:
//   summary.csv        one row per run: case, repeat, label, role, base, overrides, status, the
//                      /stats numbers, message (the reason of a failure), file
//   summary_cases.csv  one row per case: label, role, status (ok only if every repeat is), median
//                      / min / max CPU time over the repeats, the counts of its first run,
//                      message, file
//   summary.h5         the per-run numbers as datasets under /runs
// Then plots/plot_study.py draws the study's figures and tables into the same folder (skipped with
// RAILBENCH_STUDY_PLOTS=0; RAILBENCH_PYTHON names another interpreter than /usr/bin/python3).
#include <string>

namespace rb::app {

struct StudyOptions {
  std::string file;     // study file
  std::string out;      // output folder (default out/<study stem>)
  std::string root;     // project root
  std::string program;  // path of the workbench executable that runs the cases
  int jobs = 0;         // 0: from the study file, else the number of cores
};

// Returns 0 when every case ran (ok or failed: a failed case is a result), 1 on bad input, 4 when
// the figures failed (the summaries are complete).
int runStudy(const StudyOptions& options);

}  // namespace rb::app
