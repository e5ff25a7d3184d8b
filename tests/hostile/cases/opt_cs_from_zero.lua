-- hostile: args="critical-speed {case} --from 0 --no-plots"
-- hostile: expect="--from 0: must be a speed in (0, 200] m/s"
-- hostile: timeout=20
-- --from 0 was taken as "not given" and the search ran from the scene speed.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
