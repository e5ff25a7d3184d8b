-- hostile: expect="external_force_guided.lua:7: element 'push' (external_force): wheelset 'ws' follows the track kinematically with contact { method = \"guided\" }"
-- A force on a guided wheelset moves nothing (it follows the track): refused, naming the way out.
track { segments = { tangent { length = 100 } } }
contact { method = "guided" }
local v = require "vehicles.single_wheelset" { speed = 10 }
v.elements[#v.elements + 1] =
  external_force { name = "push", body = "ws", direction = { 0, 1, 0 }, value = 1e3 }
vehicle (v)
