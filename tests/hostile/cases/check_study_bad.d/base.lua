-- The base scenario of the study case beside it (valid on its own).
track { segments = { tangent { length = 100 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
contact { method = "kec" }
run { duration = 0.1 }
