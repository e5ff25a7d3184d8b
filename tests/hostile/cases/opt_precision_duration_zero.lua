-- hostile: args="precision {case} --duration 0 --quick"
-- hostile: expect="--duration 0: must be a finite number in (0, 1e+09] s"
-- hostile: timeout=20
-- --duration 0 was read as "not given": the whole run length, unasked.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
