-- hostile: args="modes {case} --distance 1e9 --no-plots"
-- hostile: expect="--distance 1e+09: puts the leading body beyond the end of the track (at most 489.22 m)"
-- hostile: timeout=20
-- A linearisation point beyond the track integrated its settling run before failing.
track { segments = { tangent { length = 500 } } }
contact { method = "guided" }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
