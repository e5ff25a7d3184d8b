-- hostile: expect="wheelsets_not_in_vehicle.lua:9: profiles.wheelsets: vehicle 'manchester_wagon1' has no wheelset named 'ws5' (did you mean 'ws1'?)"
-- hostile: expect="profiles.wheelsets: vehicle 'manchester_wagon1' has no wheelset named 'car'"
-- A wheelset's own wheels for a wheelset the vehicle does not have, and for its car body.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "lut" }
vehicle (wagon { speed = 20, start = 20 })
profiles { r0 = 0.46,
  wheelsets = { ws5 = { wheel = "s1002" },
                car = { wheel = "s1002" } } }
