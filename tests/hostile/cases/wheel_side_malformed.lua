-- hostile: expect="wheel_side_malformed.lua:9: profiles.wheel_left: cannot use"
-- hostile: expect="half.txt:2:"
-- A wheel's own profile file that is not a profile: its own file:line under the key that names it.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 100 } } }
contact { method = "kec" }
vehicle (wagon { speed = 10 })
-- the left wheels' profile below
profiles { wheel = "s1002", wheel_left = "half.txt" }
