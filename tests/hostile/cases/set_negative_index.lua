-- hostile: args="check {case} --set track.segments[-1].length=5"
-- hostile: expect="<command line>: --set track.segments[-1].length=5: '-1' is neither a key name nor a list position"
-- hostile: reject="set_negative_index.lua:4:"
-- A negative list position was blamed on line 1 of the scenario.
track { segments = { tangent { length = 100 } } }
