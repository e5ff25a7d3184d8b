-- hostile: args="precision {case} --quick --model-reference kec --out {work}/p" expect="--model-reference kec: the scenario refuses contact.method=kec" reject="none reaches it"
-- hostile: timeout=60
-- A model reference the scene cannot run (KEC on sliced rails): refused before anything runs
-- (exit 1); it ended with exit 0 and "none reaches it".
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
profiles { r0 = 0.46, rail_slices = { left = { { s = 0, rail = "60e1" }, { s = 400, rail = "60e1", dz = 0.001 } } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 20 })
solver { method = "abm", step = 2.5e-4 }
run { duration = 0.1 }
