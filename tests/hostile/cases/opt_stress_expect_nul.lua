-- hostile: args="stress {case} --quick --expect expect.txt --out {work}/s" timeout=60
-- hostile: expect="expect.txt:1: unknown outcome" reject="stress.csv"
-- An expectation file with a NUL byte after an outcome: not cut at the NUL, refused at its line.
track { segments = { tangent { length = 500 } } }
contact { method = "elastic" }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
