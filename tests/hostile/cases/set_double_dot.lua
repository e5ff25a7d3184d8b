-- hostile: args="check {case} --set solver..step=1e-3"
-- hostile: expect="--set solver..step=1e-3: 'solver..step' is not a key path"
-- "--set solver..step" was read as solver.step.
track { segments = { tangent { length = 100 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
contact { method = "kec" }
