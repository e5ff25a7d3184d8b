-- The tiny test vehicle with its own groups.
track { segments = { tangent { length = 100 } } }
vehicle (require "vehicles.tiny" ())
