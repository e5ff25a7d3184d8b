-- hostile: expect="rail_slices_disjoint.lua:10: profiles.rail_slices.right[2]: its rail and the slice before it (at s = 10 m)"
-- hostile: expect="cover no common part of the profile"
-- Two neighbouring slices that cover no common part of the profile parameter: nothing to blend.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 100 } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 30 })
profiles { rail_slices = { right = {
  { s = 10, rail = "60e1" },
  { s = 20, rail = "far.txt" } } } }
