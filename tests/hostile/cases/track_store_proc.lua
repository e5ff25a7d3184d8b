-- hostile: args="run {case} --quiet --track-store /proc --out {work}/r.h5" expect="--track-store: the folder '/proc' is not writable"
-- A track store in a folder where no file can be made (/proc: access() says writable to root, but
-- creating a file fails): refused as a bad option before the run (exit 1), not a failed run.
track { segments = { tangent { length = 100 } } }
contact { method = "kec" }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
run { duration = 0.01 }
