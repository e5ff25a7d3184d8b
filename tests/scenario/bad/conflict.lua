track { segments = { tangent { length = 30 } } }
solver { method = "rk4", step = 1e-3, rtol = 1e-6 }
vehicle (require "vehicles.manchester_wagon1" { speed = 10 })
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
