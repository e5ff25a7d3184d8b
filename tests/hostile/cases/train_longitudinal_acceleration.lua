-- hostile: expect="train_longitudinal_acceleration.lua:9: train.vehicles[2]: vehicle.acceleration must be 0 with train.longitudinal"
-- hostile: expect="train_longitudinal_acceleration.lua:8: train.vehicles[1]: vehicle.acceleration must be 0"
-- A prescribed acceleration given to a vehicle file together with train.longitudinal = {} (a
-- computed motion): refused as docs/trains.md says. The vehicle files dropped the option
-- `acceleration` silently, so the train ran with its motion computed and the option unused.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 400 } } }
train { vehicles = { { name = "a", vehicle = wagon { speed = 20, start = 60, acceleration = 0.5 } },
                     { name = "b", vehicle = wagon { speed = 20, start = 35, acceleration = 0.5 } } },
        longitudinal = {} }
contact { method = "kec" }
run { duration = 1 }
