-- hostile: expect="profile_miniprof_missing_columns.lua:8: profiles.wheel: cannot use"
-- hostile: expect='w.whl:9: expected 4 values (ColumnDef, line 3), got 2'
-- A malformed MiniProf wheel (missing columns): an input error at the file's line, never a crash.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "kec" }
vehicle (wagon { speed = 20, start = 20 })
profiles { wheel = "w.whl" }
