-- hostile: expect="profile_miniprof_nul_byte.lua:8: profiles.wheel: cannot use"
-- hostile: expect='w.whl:11: NUL byte in the file'
-- A malformed MiniProf wheel (nul byte): an input error at the file's line, never a crash.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "kec" }
vehicle (wagon { speed = 20, start = 20 })
profiles { wheel = "w.whl" }
