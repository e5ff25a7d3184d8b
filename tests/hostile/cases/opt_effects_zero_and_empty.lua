-- hostile: args="effects {case} --duration 0 --quantities \"\" --jobs 100000"
-- hostile: expect="--duration 0: must be a finite number"
-- hostile: expect="--quantities: no quantity"
-- hostile: expect="--jobs 100000: must be in 0.."
-- hostile: expect="3 problems found"
-- hostile: timeout=20
-- A typed 0 and an empty list were read as the defaults.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
