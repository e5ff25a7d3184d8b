-- hostile: expect="wheelsets_in_train.lua:7: profiles.wheelsets with a train: give a vehicle's wheelsets their own wheels in that vehicle's own profiles{}"
-- Wheelsets with wheels of their own in the scenario's profiles{} of a train, which every
-- vehicle without its own profiles{} takes: each wagon's ws1 would get them.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 400 } } }
profiles { r0 = 0.46,
  wheelsets = { ws1 = { wheel = "s1002" } } }
contact { method = "lut" }
train { vehicles = { { name = "a", vehicle = wagon { speed = 20, start = 60 } },
                     { name = "b", vehicle = wagon { speed = 20, start = 30 } } } }
