local make = require "vehicles.two_body"
track { segments = { tangent { length = 100 } } }
vehicle (make { speed = 12 })
solver { method = "abm", step = 1e-3 }
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
