-- hostile: args="check {case} --set contact.elastic.damping_ratio=nan --set contact.elastic.sample_step=-1" expect="<command line>: contact.elastic: damping_ratio must be finite" expect="<command line>: contact.elastic: sample_step must be >= 2e-05 m"
-- Command-line overrides of the elastic block with a NaN and a negative step: refused naming the
-- option, nothing is run.
track { segments = { tangent { length = 100 } } }
contact { method = "elastic", creep = "polach" }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
