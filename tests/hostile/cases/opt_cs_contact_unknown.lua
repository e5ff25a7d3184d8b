-- hostile: args="critical-speed {case} --contact nan --no-plots --out {work}/c" timeout=30
-- hostile: expect="--contact must be kec, lut or elastic, got 'nan'" reject="wrote"
-- An unknown contact method: refused with the methods the help names.
track { segments = { tangent { length = 500 } } }
contact { method = "kec" }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
