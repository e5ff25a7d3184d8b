-- hostile: args="precision {case} --methods kec,hertz --integrators rk5 --tolerances 3"
-- hostile: expect="--methods: unknown 'hertz' (one of kec, lut, elastic)"
-- hostile: expect="--integrators: unknown 'rk5'"
-- hostile: expect="--tolerances 3: a relative tolerance must be in [1e-14, 1)"
-- hostile: expect="3 problems found; nothing was run."
-- hostile: timeout=20
-- The lists were refused one per attempt, the tolerance not at all.
require("validation.common").wagon("study", true)
