-- hostile: args="modes {case} --contact kec --no-plots --out {work}/m" timeout=60
-- hostile: expect="<command line>: --contact kec: the scenario refuses contact.method=kec" reject="wrote"
-- A contact method the scene's rails do not allow (KEC on rails that change along the track):
-- refused naming the option, before anything runs (it was reported at the scenario's line).
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
profiles { r0 = 0.46, rail_slices = { left = { { s = 0, rail = "60e1" }, { s = 400, rail = "60e1", dz = 0.001 } } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 20 })
solver { method = "abm", step = 2.5e-4 }
run { duration = 0.1 }
