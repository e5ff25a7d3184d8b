-- hostile: expect="profile_miniprof_non_monotone.lua:8: profiles.wheel: cannot use"
-- hostile: expect='w.whl:13: profile X values must advance: X = 23 mm follows X = 29 mm'
-- A malformed MiniProf wheel (non monotone): an input error at the file's line, never a crash.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "kec" }
vehicle (wagon { speed = 20, start = 20 })
profiles { wheel = "w.whl" }
