-- hostile: args="critical-speed {case} --to 0 --duration 1e9 --deceleration 1e-9 --window 1e-12 --jobs -1 --no-plots"
-- hostile: expect="--to 0: must be a speed"
-- hostile: expect="--duration 1e+09: must be in (0, 600] s"
-- hostile: expect="--deceleration 1e-09: must be in [0.05, 20] m/s^2"
-- hostile: expect="--window 1e-12: must be in [0.05, 200] s"
-- hostile: expect="--jobs -1: must be in 0.."
-- hostile: expect="5 problems found; nothing was run."
-- hostile: timeout=20
-- Every bad option is reported at once, each with its value; a 1e9 s run or ramp is unbounded work.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
