track { segments = { tangent { length = 100 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
run { duration = -1 }
contact { method = "kec" }
