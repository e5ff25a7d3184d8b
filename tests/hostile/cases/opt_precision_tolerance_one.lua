-- hostile: args="precision {case} --tolerances 1e-3,2 --quick"
-- hostile: expect="--tolerances 2: a relative tolerance must be in [1e-14, 1)"
-- hostile: timeout=20
-- A relative tolerance of 2 accepts any answer; it was run.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
