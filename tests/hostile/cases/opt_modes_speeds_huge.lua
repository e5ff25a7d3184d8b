-- hostile: args="modes {case} --speeds 10:1e300:3 --no-plots"
-- hostile: expect="--speeds b must be at most 200 m/s"
-- hostile: timeout=20
-- Speeds beyond the range of vehicle.speed.
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
