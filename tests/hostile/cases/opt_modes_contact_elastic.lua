-- hostile: args="modes {case} --contact elastic --speeds 20:20:1 --no-plots --out {work}/m" exit=0
-- hostile: expect="wrote" reject="--contact must be" timeout=60
-- The help offers --contact kec, lut or elastic, and the elastic method linearises: it was
-- refused as "must be kec or lut". Accepted now (one speed: a fraction of a second).
track { segments = { tangent { length = 500 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
