-- The test vehicle whose groups name nothing.
track { segments = { tangent { length = 100 } } }
vehicle (require "vehicles.tiny_bad" ())
