-- hostile: expect="train_rear_before_track.lua:9: train.vehicles[2] 'b': the rearmost body starts at s = -0.78 m, before the start of the track"
-- hostile: expect="give its vehicle.start >= 10.78 m" reject="train_rear_before_track.lua:8:"
-- The rear vehicle of a train starts partly before a track that does not begin with a level
-- tangent: reported at that vehicle's entry, naming it, with the start it needs (it was reported
-- at the first vehicle's line, with the first vehicle's start corrected).
local wagon = require "vehicles.manchester_wagon1"
track { segments = { curve { length = 400, radius = 1000 } } }
train { vehicles = { { name = "a", vehicle = wagon { speed = 20, start = 40 } },
                     { name = "b", vehicle = wagon { speed = 20, start = 10 } } } }
contact { method = "kec" }
run { duration = 1 }
