-- hostile: expect="nul_rail_slice.lua:7: profiles.rail_slices.left[1].rail must not hold a NUL byte (\\0)"
-- A rail slice's file name with an embedded NUL (one.txt\0junk), refused where it is written: it
-- was cut at the NUL and one.txt was read.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
profiles { r0 = 0.46,
  rail_slices = { left = { { s = 0, rail = "one.txt\0junk", max_slope = 100 },
                           { s = 400, rail = "60e1" } } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 20 })
