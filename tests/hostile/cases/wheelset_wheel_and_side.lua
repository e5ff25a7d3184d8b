-- hostile: expect="wheelset_wheel_and_side.lua:7: profiles: wheelsets.ws1: give wheel (both wheels) or wheel_left / wheel_right, not both"
-- One wheelset given both its wheels (wheel) and its left wheel (wheel_left): two profiles for one
-- wheel, one of them silently unused for that side. Refused where the entry is.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 100 } } }
profiles { r0 = 0.46,
  wheelsets = { ws1 = { wheel = "s1002", wheel_left = "s1002" } } }
contact { method = "kec" }
vehicle (wagon { speed = 20, start = 30 })
