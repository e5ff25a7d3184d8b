-- hostile: args="effects {case} --repeats 1000000000 --quick"
-- hostile: expect="--repeats 1000000000: must be in 1..100"
-- hostile: timeout=20
-- --quick dropped a huge --repeats without a word.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
