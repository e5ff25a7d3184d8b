-- hostile: args="critical-speed {case} --max-speed 1e9 --no-plots"
-- hostile: expect="--max-speed 1e+09: must be a speed in (0, 200] m/s"
-- hostile: timeout=20
-- A probe limit beyond the speed range swept the linear critical speed over 1e8 speeds.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
