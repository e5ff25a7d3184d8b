-- hostile: args="check {case} --set solver.method=bdf"
-- hostile: expect="<command line>: solver{} has no effect without a vehicle{} block"
-- The same block made on the command line.
track { segments = { tangent { length = 100 } } }
