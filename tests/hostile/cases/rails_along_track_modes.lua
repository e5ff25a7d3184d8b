-- hostile: args="modes {case}"
-- hostile: expect="rails_along_track_modes.lua:8: profiles: the rails change along the track"
-- hostile: expect="no steady state to linearise about"
-- Rails that change along the track have no steady state: `workbench modes` refuses the scene.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "elastic" }
profiles { rail_slices = { left = { { s = 10, rail = "60e1" } } } }
vehicle (wagon { speed = 20, start = 30 })
