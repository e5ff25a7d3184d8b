-- The tiny test vehicle with its own groups.
track { segments = { tangent { length = 100 } } }
vehicle (require "vehicles.tiny" ())
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
