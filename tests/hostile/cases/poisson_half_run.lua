-- hostile: args="run {case} --quiet --out {work}/r.h5" exit=0 reject="internal error"
-- hostile: timeout=120
-- contact.poisson = 0.5 runs (here FASTSIM on the elastic method, whose patches are made while
-- the run goes on): the range the schema states is the range the creep laws take.
track { segments = { tangent { length = 100 } } }
contact { method = "elastic", creep = "fastsim", poisson = 0.5 }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
run { duration = 0.01 }
