track { segments = { tangent { length = 30 } } }
solver { method = "rk4", step = 1e-3, rtol = 1e-6 }
vehicle (require "vehicles.manchester_wagon1" { speed = 10 })
