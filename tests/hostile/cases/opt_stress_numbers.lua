-- hostile: args="stress {case} --tolerance inf --run-timeout -1 --jobs 100000 --quick"
-- hostile: expect="--tolerance inf: must be a finite error"
-- hostile: expect="--run-timeout -1: must be a finite time"
-- hostile: expect="--jobs 100000: must be in 0.."
-- hostile: expect="3 problems found"
-- hostile: timeout=20
-- Bad numbers are reported together, with their values.
require("validation.common").wagon("study", true)
