-- hostile: args="check {case} --set track.segments[99999999999999999999999].length=5"
-- hostile: expect="<command line>: --set track.segments[99999999999999999999999].length=5: list position"
-- hostile: expect="out of range 1..1"
-- A huge list position was an exception from the conversion (exit 3).
track { segments = { tangent { length = 100 } } }
