-- hostile: expect="wheelsets_bad_profile.lua:9: profiles.wheelsets.ws2: these wheels give no contact model"
-- hostile: expect="broken.txt"
-- A wheelset's own wheel profile that is a file but not a profile.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "kec" }
vehicle (wagon { speed = 20, start = 20 })
profiles { r0 = 0.46, wheelsets = {
  ws2 = { wheel_right = "broken.txt" } } }
