-- hostile: args="check {case} --set vehicle.elements.push.value=1e12 --set vehicle.elements.push.hold=-1 --set vehicle.elements.push.frame=trakc"
-- hostile: expect="<command line>: vehicle.elements[51] (external_force): value must be <= 1e+08 N, got 1e+12"
-- hostile: expect="<command line>: vehicle.elements[51] (external_force): frame: unknown value 'trakc' (did you mean 'track'?)"
-- hostile: expect="<command line>: vehicle.elements[51] (external_force): hold must be >= 0 s, got -1"
-- An external force's keys set from the command line: a force of 1 TN, a negative hold, a
-- misspelt frame, each refused with the command line as its place.
local c = require "validation.common"
track { segments = { tangent { length = 300 } } }
c.profiles() c.contact("kec")
local v = require "vehicles.manchester_wagon1" { speed = 20, start = 20 }
v.elements[#v.elements + 1] = external_force { name = "push", body = "car", direction = { 0, 1, 0 },
  law = "ramp", value = 1e3, rate = 1e3 }
vehicle (v)
