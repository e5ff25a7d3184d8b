-- hostile: args="critical-speed {case} --contact lut --no-plots --out {work}/c" timeout=60
-- hostile: expect="<command line>: --contact lut: the scenario refuses contact.method=lut" reject="wrote"
-- A contact method the scene's rails do not allow (LUT on rails that change along the track):
-- refused naming the option, before anything runs.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
profiles { r0 = 0.46, rail_slices = { left = { { s = 0, rail = "60e1" }, { s = 400, rail = "60e1", dz = 0.001 } } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 20 })
solver { method = "abm", step = 2.5e-4 }
run { duration = 0.1 }
