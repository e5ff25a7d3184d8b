-- hostile: args="effects {case} --distance 1e12 --quick"
-- hostile: expect="<command line>: --distance 1e+12 (run.distance=1e+12): "
-- hostile: expect="beyond the end of the track"
-- hostile: timeout=20
-- A distance beyond the track: refused up front, naming the option.
track { segments = { tangent { length = 500 } } }
contact { method = "guided" }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
