-- hostile: expect="vehicle_file_unknown_option.lua:6: vehicles.manchester_wagon1: unknown option 'sped' (options: "
-- A misspelt option of a vehicle file was dropped silently (the wagon ran at its default speed):
-- each vehicle file refuses an option it does not take, at the line that gives it.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 400 } } }
vehicle (wagon { sped = 30 })
contact { method = "kec" }
