-- hostile: exit=0
-- hostile: expect="warning_once.lua:9: warning: KEC:"
-- hostile: reject="warning: warning_once.lua"
-- hostile: timeout=300
-- Contact-table warnings carried their "file:line: warning:" prefix twice.
local hard = require "hard.lib"
hard.curve_track(150)
hard.profiles()
contact { method = "kec", dhat = 1e-4, dbar = 1e-4 }
vehicle (require "vehicles.manchester_wagon1" { speed = 16 })
