-- hostile: expect="profile_miniprof_metres.lua:9: profiles.wheel: cannot use"
-- hostile: expect='all coordinates are below 1 mm'
-- hostile: expect='MiniProf files are in millimetres'
-- A malformed MiniProf wheel (metres): an input error at the file's line, never a crash.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "kec" }
vehicle (wagon { speed = 20, start = 20 })
profiles { wheel = "w.whl" }
