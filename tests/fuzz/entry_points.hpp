#pragma once
// The fuzzed entry points: each feeds one input to a reader of user files the way the workbench
// does, and treats rb::InputError (a diagnosed bad input) as the normal outcome. Anything else
// escaping (another exception: an internal check tripped by input), a crash, a sanitizer report
// or a hang is a finding. The libFuzzer harnesses (fuzz_*.cpp) and the replay test of the kept
// inputs (test_replay.cpp) call the same functions.
#include <string>
#include <string_view>

#include "workbench/contact/config.hpp"

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
// The small S1002 / 60E1 configuration the table seeds were built for (coarse grids): the cache
// key the harness loads every file against, and what fuzz_make_table_seeds builds.
const contact::ContactGeometryConfig& seedTableConfig();

// A study file: the input is written as study.lua to the private temporary folder, beside two
// base scenarios it can name (base.lua: the single wheelset of the paper's case 1,
// scenarios/validation/case1_R300_kec.lua; wagon.lua: the Manchester wagon with its named groups,
// scenarios/vehicle/manchester_guided_r500.lua), and loaded with scenario::loadStudy.
void study(std::string_view data);

// A study file with metrics: loaded as by study(); when it loads, each metric is evaluated on
// small synthetic signals (ordinary, NaN / inf, empty, a single sample): the statistics of the
// signal, steady and error kinds, and every function metric (kind "lua") through
// scenario::LuaMetrics with lowered budgets, so that the metric sandbox is fuzzed too. A metric
// that fails is reported by its `why`, as the study summary does; no exception but InputError.
void metric(std::string_view data);

// Forged result files (result_files.cpp; README.md has the grammar): the input is decoded into
// HDF5 files (the result, a reference, a track store it may name, a victim outside its folder)
// of groups, datasets of declared sizes and types, attributes, soft, external and hard links and
// non-finite samples, then read by check-result, the readers of /stats, /metrics and the track
// store, the comparison of runs, a study summary's metrics and assess. Beyond InputError and
// io::BadResult (exit 1) a finding is also: assess writing a non-finite value, changing the
// victim or (when it fails) the result, a metric value without a reason that is not finite, a
// NaN error of two runs, an HDF5 object left open.
void resultFiles(std::string_view data);

// The entry point of a harness by its name ("scenario", "profile", "csv", "tables", "study",
// "metric", "result"); nullptr if there is none.
using EntryPoint = void (*)(std::string_view);
EntryPoint entryPoint(const std::string& harness);

}  // namespace rb::fuzz
