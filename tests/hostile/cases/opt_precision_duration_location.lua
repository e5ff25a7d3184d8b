-- hostile: args="precision {case} --duration 1e9 --quick"
-- hostile: expect="<command line>: --duration 1e+09 (run.duration=1e+09): "
-- hostile: expect="beyond the end of the track"
-- hostile: timeout=20
-- The refusal names the option the user typed, not only the scenario key it became.
track { segments = { tangent { length = 500 } } }
contact { method = "guided" }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
