-- hostile: args="stress {case} --integrators rk4:1e-12,dopri5:2 --quick"
-- hostile: expect="--integrators rk4:1e-12: 2e+12 steps over the run"
-- hostile: expect="--integrators dopri5:2: a relative tolerance must be in [1e-14, 1)"
-- hostile: timeout=20
-- A step of 1e-12 s is unbounded work, a tolerance of 2 accepts anything.
require("validation.common").wagon("study", true)
