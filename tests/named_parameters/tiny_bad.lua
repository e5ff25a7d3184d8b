-- The test vehicle whose groups name nothing.
track { segments = { tangent { length = 100 } } }
vehicle (require "vehicles.tiny_bad" ())
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
