-- hostile: args="precision {case} --steps 1e-12 --integrators rk4 --quick"
-- hostile: expect="--steps 1e-12: "
-- hostile: expect="more than run.output.max_samples"
-- hostile: timeout=20
-- A step of 1e-12 s divides every output interval and asked for 1e13 steps per run.
track { segments = { tangent { length = 500 } } }
contact { method = "guided" }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
