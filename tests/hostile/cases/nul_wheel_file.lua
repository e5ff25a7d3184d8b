-- hostile: expect="nul_wheel_file.lua:6: profiles.wheel must not hold a NUL byte (\\0), got \"worn.txt\\0.prw\""
-- A wheel file name with an embedded NUL: the C library would cut it at the NUL and read
-- worn.txt, which the scenario does not name. Refused where it is written.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 100 } } }
profiles { r0 = 0.46, wheel = "worn.txt\0.prw" }
contact { method = "kec" }
vehicle (wagon { speed = 20, start = 30 })
