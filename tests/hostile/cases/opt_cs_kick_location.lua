-- hostile: args="critical-speed {case} --kick 0.015 --from 30 --no-plots"
-- hostile: expect="<command line>: --kick 0.015 (vehicle.initial.ws1.y=0.015): "
-- hostile: expect="beyond its flangeway"
-- hostile: timeout=20
-- A kick beyond the flangeway was refused as vehicle.initial by the first run.
track { segments = { tangent { length = 2000 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
contact { method = "kec" }
