-- hostile: args="critical-speed {case} --from 60 --no-plots"
-- hostile: expect="--duration 10: a constant-speed run at 60 m/s covers 600 m, beyond the end of the track"
-- hostile: expect="--deceleration 0.5: the ramp from 60 to 30 m/s covers 2700 m"
-- hostile: timeout=20
-- Runs that leave the track were refused as run.duration by the first run; now as the options.
track { segments = { tangent { length = 500 } } }
contact { method = "guided" }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
