-- hostile: args="stress {case} --axes flange_stiffness --quick --out {work}/s" timeout=60
-- hostile: expect="axis flange_stiffness skipped: the contact method is elastic"
-- hostile: expect="--axes: no axis applies to" reject="stress.csv"
-- An axis the scene cannot use (the LUT's Hertz flange stiffness on an elastic scene): refused
-- before anything runs.
track { segments = { tangent { length = 500 } } }
contact { method = "elastic" }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
