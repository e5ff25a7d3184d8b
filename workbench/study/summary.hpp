#pragma once
// The summaries of a study folder (study/runner.hpp): summary.csv (one row per run),
// summary_cases.csv (one row per case), summary.h5 and summary_errors.csv (reference_errors.hpp),
// from the result files on disk, so that a local run, shards merged by --summarize and the MPI farm
// write the same summaries.
#include <cstddef>
#include <filesystem>
#include <vector>

#include "workbench/study/jobs.hpp"

namespace rb::study::detail {

struct SummaryCounts {
  std::size_t runsOk = 0, runsKnown = 0, runsElsewhere = 0;
};

// Writes the summaries into `dir` (each atomically); throws std::runtime_error when one
// cannot be written.
SummaryCounts writeSummaries(const scenario::StudySpec& st, const std::vector<Job>& all,
                             const std::filesystem::path& dir);

}  // namespace rb::study::detail
