-- hostile: expect="profile_miniprof_truncated_points.lua:8: profiles.wheel: cannot use"
-- hostile: expect='w.whl:23: XYPoints = 20 (line 4) but the file holds 15 point lines'
-- A malformed MiniProf wheel (truncated points): an input error at the file's line, never a crash.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "kec" }
vehicle (wagon { speed = 20, start = 20 })
profiles { wheel = "w.whl" }
