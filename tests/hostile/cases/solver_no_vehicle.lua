-- hostile: expect="solver_no_vehicle.lua:4: solver{} has no effect without a vehicle{} block"
-- A solver with nothing to integrate was ignored.
track { segments = { tangent { length = 100 } } }
solver { method = "rk4", step = 1e-3 }
