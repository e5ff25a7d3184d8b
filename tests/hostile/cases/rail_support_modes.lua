-- hostile: args="modes {case}"
-- hostile: expect="rail_support_modes.lua:8: contact.elastic.rail_support (the track under the rail) is not part of the modes analysis"
-- The track under the rail adds states the linearised analysis does not have: `workbench modes`
-- refuses the scene with the line of its elastic block.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
profiles { rail = "60e1" }
contact { method = "elastic", elastic = { rail_support = { mass = 150, k_z = 1e8, k_y = 4e7 } } }
vehicle (wagon { speed = 20, start = 30 })
