-- hostile: args="critical-speed {case}"
-- hostile: expect="has rails that change along the track (profiles.rail_slices / extra_rails): a critical speed needs the same rails everywhere"
-- Rails that change along the track: `workbench critical-speed` refuses the scene.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "elastic" }
profiles { extra_rails = { right = { { name = "nose", slices = { { s = 10, rail = "60e1" } } } } } }
vehicle (wagon { speed = 20, start = 30 })
