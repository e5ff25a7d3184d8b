-- hostile: args="check {case} --set run.output.every=1e-9" expect="<command line>: run.output.every: 1e-09 s over 0.1 s gives 1e+08 output times" reject="set_output_every_location.lua:8:"
-- An output interval given on the command line that gives too many output times: reported at the
-- command line, where the value is (it was reported at the scenario's run { line).
track { segments = { tangent { length = 100 } } }
contact { method = "kec" }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
run { duration = 0.1 }
