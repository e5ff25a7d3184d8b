#pragma once
// `workbench assess FILE.h5 [--set run.assessment.KEY=VALUE ...]`: recomputes /assessment of a
// result file from its datasets (the signals its run's assessment sampled, or the run's /contact
// outputs at an interval of at most 5 ms for safety and wear) and replaces the group. The file is
// updated through a copy renamed over it, so a failed assess never damages it.
#include <string>
#include <vector>

namespace rb::app {

struct AssessOptions {
  std::string file;
  std::vector<std::string> overrides;  // run.assessment.KEY=VALUE
  bool quiet = false;                  // no summary print
};

// Returns the exit code (0 ok); throws InputError (missing signals, bad --set: the file is not
// touched) or io::WriteError.
int assessFile(const AssessOptions& options);

}  // namespace rb::app
