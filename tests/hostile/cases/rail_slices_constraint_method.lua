-- hostile: expect="rail_slices_constraint_method.lua:9: profiles.rail_slices / extra_rails: a rail that changes along the track needs contact.method = \"elastic\""
-- hostile: expect="kec method's tables hold one rail profile"
-- Rail slices on a constraint contact method: refused where the slices are given, before any
-- table is built.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 100 } } }
contact { method = "kec" }
vehicle (wagon { speed = 20, start = 30 })
profiles { rail_slices = { left = { { s = 10, rail = "60e1" } } } }
