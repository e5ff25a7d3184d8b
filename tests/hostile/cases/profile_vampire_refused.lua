-- hostile: expect="profile_vampire_refused.lua:8: profiles.wheel: cannot use"
-- hostile: expect='w.whe:1: VAMPIRE profile files (.whe, .rai) are not read'
-- A VAMPIRE wheel file: not read (no public example to verify a reader), refused with a message.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "kec" }
vehicle (wagon { speed = 20, start = 20 })
profiles { wheel = "w.whe" }
