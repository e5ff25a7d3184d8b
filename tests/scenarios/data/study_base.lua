local lib = require "tracks.lib"
local wagon = require "vehicles.manchester_wagon1"
track { segments = lib.manchester_r500() }
vehicle (wagon { speed = 20 })
solver { method = "abm", step = 1e-3 }
run { duration = 0.2, output = { every = 0.01 } }
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
