#pragma once
// A study file (issue 7): study { base = "...", matrix = {...}, cases = {...}, repeats, jobs }.
// Loading expands it into the list of cases, each a list of --set overrides on the base scenario.
#include <string>
#include <vector>

#include "workbench/core/error.hpp"

namespace rb::scenario {

struct StudyCase {
  std::string id;                      // stable name: "case_<hash of the overrides>"
  std::vector<std::string> overrides;  // "key=value", in a fixed order
};

struct StudySpec {
  std::string file;  // the study file as given
  std::string base;  // resolved base scenario path
  std::vector<StudyCase> cases;
  int repeats = 1;
  int jobs = 0;
  SourceLoc loc;
};

// Throws InputError (file:line) for a bad study file.
StudySpec loadStudy(const std::string& path, const std::string& root);

}  // namespace rb::scenario
