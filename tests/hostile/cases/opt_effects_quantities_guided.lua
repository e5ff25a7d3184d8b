-- hostile: args="effects {case} --quick --quantities Q,y,Fy --out {work}/e" timeout=60
-- hostile: expect="--quantities: 'Q' is a wheel/rail contact quantity" expect="--quantities: 'Fy' is"
-- hostile: expect="2 problems found" reject="effects.csv"
-- Wheel forces asked of a guided vehicle (no wheel/rail contact): every case ran and the table's
-- column was empty, in unit "-". Refused before anything runs.
track { segments = { tangent { length = 500 } } }
contact { method = "guided" }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
