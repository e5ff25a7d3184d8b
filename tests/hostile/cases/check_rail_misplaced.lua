-- hostile: expect="check_rail_misplaced.lua:11: profiles.extra_rails.right[1] (check rail 'guard'), slice 1 at s = 10 m: it reaches"
-- hostile: expect="mm into the back of the centred wheel's flange; a check rail lies on the track-centre side of the flange back (move it by dy < 0)"
-- A check rail laid where the wheel runs (its first slice under the tread: no offset).
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 20 })
profiles { r0 = 0.46,
  extra_rails = {
    right = { { name = "guard", check = true, slices = {
      { s = 10, rail = "60e1" }, { s = 50, rail = "60e1", dy = -0.11 } } } } } }
