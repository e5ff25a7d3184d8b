-- hostile: expect="external_force_frame.lua:8: element 'on_frame' (external_force): body 'frame' is a frame, whose motion is prescribed: a force on it does nothing"
-- A force on the kinematic frame of the single-wheelset set-up moves nothing: refused.
local c = require "validation.common"
track { segments = { tangent { length = 100 } } }
c.profiles() c.contact("kec")
local v = require "vehicles.single_wheelset" { speed = 10 }
v.elements[#v.elements + 1] =
  external_force { name = "on_frame", body = "frame", direction = { 0, 1, 0 }, value = 1e3 }
vehicle (v)
