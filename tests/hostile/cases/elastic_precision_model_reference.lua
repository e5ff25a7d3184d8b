-- hostile: args="precision {case} --quick --model-reference fem --out {work}/p" expect="--model-reference: unknown 'fem'"
-- An unknown model reference of precision: refused naming the option before anything runs.
track { segments = { tangent { length = 100 } } }
contact { method = "elastic", creep = "polach" }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
