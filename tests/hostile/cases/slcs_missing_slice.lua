-- hostile: expect="slcs_missing_slice.lua:10: profiles: rail_slices.left.slcs: "
-- hostile: expect="away.slcs:6: file '"
-- hostile: expect="is outside the folders a scenario may read"
-- hostile: expect="rail_slices.right: the slice at "
-- hostile: expect="is at s = -1 m, before the track's start"
-- A slices-file whose second slice lies outside the folders a scenario may read, and one placed
-- so that its first slice is before the track's start.
local wagon = require "vehicles.manchester_wagon1"
profiles { r0 = 0.46,
  rail_slices = { left = { slcs = "away.slcs", s = 10, units = "m" },
                  right = { slcs = "away.slcs", s = -1, units = "m" } } }
track { segments = { tangent { length = 300 } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 20 })
