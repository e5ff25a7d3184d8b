#pragma once
// `workbench tables SCENARIO.lua`: builds the contact tables of a scenario's profiles (LUT, paper
// Eq. 14, Table 10; KEC, Eq. 22-23, Table 9), derived geometry (rolling-radius difference,
// contact-angle difference, EN 15302 equivalent conicity) and stores them with build times and
// sizes under /tables (and the profiles under /profiles) in an HDF5 file.
#include "workbench/app/run.hpp"

namespace rb::app {

int buildTables(const RunOptions& options);

}  // namespace rb::app
