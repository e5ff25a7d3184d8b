-- hostile: expect="check_rail_malformed.lua:10: profiles: extra_rails.left[1] must be { name = \"nose\" (1-32 letters, digits or '_'), slices = { ... }, check = true or false (optional) }, got table"
-- A further rail whose `check` is not a boolean.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 20 })
profiles { r0 = 0.46,
  extra_rails = {
    left = {
      { name = "guard", check = "yes", slices = { { s = 10, rail = "60e1" } } } } } }
