-- hostile: expect="rtol_one.lua:5: solver: rtol must be < 1, got 1"
-- help says rtol is in (0, 1); the validator must agree (it took 1 and failed later).
track { segments = { tangent { length = 200 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 10 })
solver { method = "bdf", rtol = 1 }
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
