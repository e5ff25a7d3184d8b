-- hostile: args="effects {case} --repeats 5 --quick"
-- hostile: expect="--repeats 5: --quick runs one repeat per case"
-- hostile: timeout=20
-- An option --quick overrides is refused, not dropped.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
