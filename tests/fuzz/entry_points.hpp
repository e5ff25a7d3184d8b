#pragma once
// The fuzzed entry points: each feeds one input to a reader of user files the way the workbench
// does, and treats rb::InputError (a diagnosed bad input) as the normal outcome. Anything else
// escaping (another exception: an internal check tripped by input), a crash, a sanitizer report
// or a hang is a finding. The libFuzzer harnesses (fuzz_*.cpp) and the replay test of the kept
// inputs (test_replay.cpp) call the same functions.
#include <string>
#include <string_view>

namespace rb::fuzz {

// A Lua scenario: the input is written to a private temporary folder as a .lua file and loaded
// with scenario::loadScenario (project root = the source tree, so `require "vehicles...."` works).
// Leading lines `--@set key=value` (Lua comments) become --set overrides.
void scenario(std::string_view data);

// A wheel or rail profile file. The first byte chooses the format (SIMPACK .prw / .prr, text wheel
// or rail), the unit and the processing options; the rest is the file. Points that parse go through
// profileFromPoints, and the Profile is evaluated.
void profile(std::string_view data);

// A measured-irregularity CSV, parsed and, when accepted, splined and evaluated.
void irregularityCsv(std::string_view data);

// A contact-table cache file. The first byte chooses LUT or KEC and whether the rest is a whole
// file (magic, header, checksum as given) or only a payload that the harness wraps in a valid
// header and checksum, so that the fuzzer reaches the payload checks; a loaded table is evaluated.
void tables(std::string_view data);
// The same, true when the table was loaded (the seeds must load, or the harness only fuzzes the
// rejection of stale files).
bool loadTable(std::string_view data);

// The entry point of a harness by its name ("scenario", "profile", "csv", "tables"); nullptr if
// there is none.
using EntryPoint = void (*)(std::string_view);
EntryPoint entryPoint(const std::string& harness);

}  // namespace rb::fuzz
