-- hostile: args="precision {case} --levels \"\" --quick"
-- hostile: expect="--levels: no entry"
-- hostile: timeout=20
-- An empty level list was read as the default list.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
