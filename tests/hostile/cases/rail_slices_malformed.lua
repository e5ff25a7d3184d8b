-- hostile: expect="rail_slices_malformed.lua:14: profiles: rail_slices: unknown side 'middle'"
-- hostile: expect="rail_slices.left[2].s = 5 m: the slices' s must increase strictly"
-- hostile: expect="rail_slices.left[3] must be { s = <m>, rail ="
-- hostile: expect="rail_slices.left[4].s must be a track arc length >= 0"
-- hostile: expect="rail_slices.right[1].rail: "
-- hostile: expect="not found"
-- A rail that changes along the track, malformed: an unknown side, slices out of order, an entry
-- that is not a slice, a negative or non-finite position, a missing file.
track { segments = { tangent { length = 100 } } }
contact { method = "elastic" }
vehicle { speed = 10, bodies = { { name = "ws1", kind = "wheelset", mass = 1000, inertia = { 500, 100, 500 } } } }
local bad = { { s = 10, rail = "60e1" }, { s = 5, rail = "60e1" }, { 12, "60e1" },
              { s = -1, rail = "60e1" }, { s = 0 / 0, rail = "60e1" } }
profiles { rail_slices = { left = bad, middle = {}, right = { { s = 0, rail = "missing.txt" } } } }
