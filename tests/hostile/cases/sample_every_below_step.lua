-- hostile: expect="sample_every_below_step.lua:9: run.assessment: sample_every 1e-09 s is below the abm step 0.0002 s"
-- An assessment sample interval far below the fixed step: it silently became one step. Refused at
-- the key, with the step it would be.
track { segments = { tangent { length = 100 } } }
contact { method = "kec" }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
run { duration = 0.1, assessment = { safety = true,
                                     sample_every = 1e-9 } }
