-- hostile: args="check {case} --set track.step=1e999"
-- hostile: expect="<command line>: track: step must be finite"
-- An infinite value from the command line.
track { segments = { tangent { length = 100 } } }
