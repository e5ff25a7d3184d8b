-- hostile: args="precision {case} --quick --methods kec --out {work}/p" expect="--methods kec: the scenario refuses contact.method=kec" expect="a rail that changes along the track needs contact.method = \"elastic\"" reject="wrote"
-- hostile: timeout=60
-- A sliced (turnout-like) scene with --methods kec: the constraint methods hold one rail profile,
-- so every case would fail (exit 2). Refused before anything runs (exit 1).
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
profiles { r0 = 0.46, rail_slices = { left = { { s = 0, rail = "60e1" }, { s = 400, rail = "60e1", dz = 0.001 } } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 20 })
solver { method = "abm", step = 2.5e-4 }
run { duration = 0.1 }
