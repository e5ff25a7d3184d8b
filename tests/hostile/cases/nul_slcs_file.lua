-- hostile: expect="nul_slcs_file.lua:6: profiles.rail_slices.right.slcs must not hold a NUL byte (\\0)"
-- A CONTACT slices-file name with an embedded NUL, refused where it is written (it was cut at the
-- NUL and one.slcs was read).
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
profiles { r0 = 0.46, rail_slices = { right = { slcs = "one.slcs\0x", s = 0, max_slope = 100 } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 20 })
