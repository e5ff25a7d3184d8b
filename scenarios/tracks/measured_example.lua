-- The paper's case 2 track (Manchester wagon, R = 500 m) with irregularities read from a CSV file
-- instead of synthesised from a PSD. The file's header names its columns (any order, any subset
-- of alignment, vertical, gauge, cross_level; a missing channel is zero) and their unit.
local lib = require "tracks.lib"

track {
  segments = lib.manchester_r500(),
  step = 0.5,
  irregularities = measured {
    file = "measured_example.csv",  -- relative to this scenario
    unit = "mm",                    -- the irregularity columns (s is always in metres)
    beyond = "error",               -- the file must cover the whole track (or "zero")
  },
}
