-- hostile: expect="slice_max_slope_bad.lua:11: profiles: rail_slices.left[1].max_slope must be a slope |dz/dy| from 1 to 100"
-- hostile: expect="got number 0"
-- hostile: expect="rail_slices.left[2].max_slope must be a slope"
-- hostile: expect="got string \"steep\""
-- hostile: expect="rail_slices.right.max_slope must be a slope"
-- hostile: expect="got number 1e+300"
-- A slice's max_slope out of range (0, 1e300) or not a number, in a list of slices and on a
-- slices-file.
local wagon = require "vehicles.manchester_wagon1"
profiles { r0 = 0.46,
  rail_slices = { left = { { s = 0, rail = "60e1", max_slope = 0 },
                           { s = 400, rail = "60e1", max_slope = "steep" } },
                  right = { slcs = "one.slcs", s = 0, max_slope = 1e300 } } }
track { segments = { tangent { length = 300 } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 20 })
