-- hostile: args="stress {case} --axes bogus,speed --values nominal=1 --values friction=0,2 --tolerance 0"
-- hostile: expect="--tolerance 0: must be a finite error > 0 mm"
-- hostile: expect="--axes: unknown axis 'bogus'"
-- hostile: expect="--values: unknown axis 'nominal'"
-- hostile: expect="--values 'friction=0,2': '0' is not a positive finite number"
-- hostile: expect="4 problems found; nothing was run."
-- hostile: timeout=20
-- Every bad option at once (they were refused one per attempt).
require("validation.common").wagon("study", true)
