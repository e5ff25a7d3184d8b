-- hostile: args="precision {case} --quantities \"\" --repeats 0 --jobs 100000 --budget inf --reference-tol 1e-300"
-- hostile: expect="--quantities: no entry"
-- hostile: expect="--repeats 0: must be in 1..100"
-- hostile: expect="--jobs 100000: must be in 0.."
-- hostile: expect="--budget inf: must be a finite time"
-- hostile: expect="--reference-tol 1e-300: must be in [1e-14, 1e-2)"
-- hostile: expect="5 problems found; nothing was run."
-- hostile: timeout=20
-- Every bad option at once, with its value.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
