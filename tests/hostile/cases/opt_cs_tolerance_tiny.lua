-- hostile: args="critical-speed {case} --method bisection --tolerance 1e-300 --no-plots"
-- hostile: expect="--tolerance 1e-300: must be in ["
-- hostile: expect="nothing was run"
-- hostile: timeout=20
-- A bisection tolerance far below the speed resolution repeated one probe forever.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
