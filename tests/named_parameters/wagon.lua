-- The Manchester wagon with its groups on a short tangent: the base of the named-parameter tests.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 100 } } }
vehicle (wagon { speed = 20 })
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
